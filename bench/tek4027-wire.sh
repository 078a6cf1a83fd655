#!/usr/bin/env bash
# Bytes on the wire for the Tek 4027, both profiles, every strategy, every
# example scene at the main job's size (bench/tek4027_wire_bench.cpp says
# what each column is). Writes bench/results/tek4027-wire.txt.
#   bench/tek4027-wire.sh
set -euo pipefail
source "$(dirname "$0")/lib.sh"
cd "$root"
bench_parse -- "$@"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target tek4027_wire_bench -j2 >/dev/null
out=bench/results/tek4027-wire.txt
{
  echo "# $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, load average $(bench_loadavg)"
  ./build/bench/tek4027_wire_bench --threads 2 scenes/*.toml
} > "$out.tmp"
mv "$out.tmp" "$out"
cat "$out"
