#!/usr/bin/env bash
# The trade on the wire (docs/trade.md, "On the wire"), one command:
#   bench/wire-trade.sh [--build DIR] [--scene NAME (fuzzy-sphere-1000)] [--size WxH (512x512)]
#                       [--out DIR (BUILD/wire)] [--no-docs]
# Renders the scene once and runs bench/wire_bench.cpp: every Tek 4125 form
# set x palette size x dithering x rate-distortion lambda through the real
# driver and emulator (bytes, seconds at 9600 and 38400 baud, PSNR and SSIM
# against the truecolour render), the wire-budget search at 57,600 and
# 76,800 bytes, and the progressive stream part-way. Then bench/plot_wire.py
# rewrites docs/images/wire-trade.svg and the table in docs/trade.md.
# The figures are deterministic (no timing), so one run is enough.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build"
scene="fuzzy-sphere-1000"
size="512x512"
out=""
docs=1
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --scene) scene=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --no-docs) docs=0; shift ;;
    -h|--help) sed -n 2,11p "$0"; exit 0 ;;
    *) echo "wire-trade.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done
bench="$build/bench/wire_bench"
[[ -x $bench ]] || { echo "wire-trade.sh: $bench is missing; build it: cmake --build $build --target wire_bench" >&2; exit 2; }
out=${out:-$build/wire}
"$bench" "$root/scenes/$scene.toml" --size "$size" --out "$out"
if [[ $docs == 1 ]]; then
  python3 "$root/bench/plot_wire.py" --results "$out" --docs "$root/docs"
fi
echo "wire-trade.sh: results in $out (wire.tsv, budget.tsv, progressive.tsv)"
