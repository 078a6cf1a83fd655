#!/usr/bin/env bash
# Quantizer quality/time/memory table for docs/quantize.md, with pngquant side
# by side when it is installed (Debian: apt-get install pngquant).
#   bench/quantize-quality.sh [BUILD_DIR] [extra.png ...]
set -euo pipefail
source "$(dirname "$0")/lib.sh"
bench_parse @ -- "$@"
build="${bench_args[0]:-$root/build}"
if ! command -v pngquant >/dev/null 2>&1; then
  echo "pngquant is not installed: its rows are skipped (apt-get install -y pngquant)" >&2
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target quantize_bench -j2 >&2
"$build/bench/quantize_bench" "${bench_args[@]:1}"
