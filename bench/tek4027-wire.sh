#!/usr/bin/env bash
# Bytes on the wire for the Tek 4027, both profiles, every strategy, every
# example scene at the main job's size (bench/tek4027_wire_bench.cpp says
# what each column is). Writes bench/results/tek4027-wire.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ "${1:-}" == "--help" ]]; then
  echo "usage: bench/tek4027-wire.sh   (builds tek4027_wire_bench, runs it on scenes/*.toml)"
  exit 0
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target tek4027_wire_bench -j2 >/dev/null
out=bench/results/tek4027-wire.txt
{
  echo "# $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
  ./build/bench/tek4027_wire_bench --threads 2 scenes/*.toml
} > "$out.tmp"
mv "$out.tmp" "$out"
cat "$out"
