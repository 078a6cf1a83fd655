#!/usr/bin/env bash
# The quantizer's passes over a kept frame on 1..N threads
# (quantize/frame_bands.hpp): a scene (default Plate 7,
# scenes/fuzzy-sphere-5000.toml) rendered once at SIZE x SIZE, then its
# histogram, its mapping (no dither, Bayer) and the whole Frame-mode pipeline
# timed at each thread count, alternating; build/bench/quantize_bands_bench's
# opening comment gives the method.
#   bench/quantize-bands.sh [--build DIR] [--scene FILE] [--size N] [--threads "1 2"] [--runs N] [--out FILE]
set -euo pipefail

source "$(dirname "$0")/lib.sh"
build="$root/build"
scene="$root/scenes/fuzzy-sphere-5000.toml"
size=2048
threads_list="1 $(nproc)"
runs=7
out=""
bench_parse --build=build --scene=scene --size=size --threads=threads_list --runs=runs --out=out -- "$@"
bench_positive --size "$size"
bench_positive --runs "$runs"
for t in $threads_list; do bench_positive --threads "$t"; done
bench_need_built "$build" lattice quantize_bands_bench
bench_workdir work
bench_picture "$build" "$scene" "$size" "$work/picture.png"
report() {
  echo "scene: ${scene#"$root"/}; $(nproc) cores"
  bench_loaded "$build/bench/quantize_bands_bench" --runs "$runs" --threads "$threads_list" "$work/picture.png"
}
bench_write "$out" report
