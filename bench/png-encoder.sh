#!/usr/bin/env bash
# PNG encoders side by side (docs/architecture.md, "How the work is split"):
# a scene (default Plate 7, scenes/fuzzy-sphere-5000.toml) rendered once at
# SIZE x SIZE, then
# encoded in memory by libpng (its simplified API as io/png.cpp used it, and
# one pass at two settings), libspng where libspng-dev is installed, and our
# banded encoder (io/png_encoder.hpp) at each zlib level, strategy and filter
# it offers; build/bench/png_encoder_bench's opening comment gives the method.
# Every output is decoded and must hold the rendered pixels.
#   bench/png-encoder.sh [--build DIR] [--scene FILE] [--size N] [--runs N] [--out FILE]
set -euo pipefail

source "$(dirname "$0")/lib.sh"
build="$root/build"
scene="$root/scenes/fuzzy-sphere-5000.toml"
size=2048
runs=7
out=""
bench_parse --build=build --scene=scene --size=size --runs=runs --out=out -- "$@"
bench_positive --size "$size"
bench_positive --runs "$runs"
bench_need_built "$build" lattice png_encoder_bench
bench_workdir work
bench_picture "$build" "$scene" "$size" "$work/picture.png"
report() {
  echo "scene: ${scene#"$root"/}"
  bench_loaded "$build/bench/png_encoder_bench" --runs "$runs" "$work/picture.png"
}
bench_write "$out" report
