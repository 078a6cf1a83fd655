#!/usr/bin/env bash
# The lattice look-ups against the double full ray trace (docs/lattices.md, "Look-ups"):
#   bench/lattice-lookup.sh [--build DIR] [--runs N (5)] [--size WxH (512x512)]
# For Plates 6 and 7 (scenes/fuzzy-sphere-1000 and -5000) at f_lat 1..4 it
# renders with `--lattice-lookup thesis` and `blend`, the two alternating run
# by run so a change in machine load falls on both, and prints one markdown
# row each: median CPU seconds (user + system, --threads 1, /usr/bin/time),
# the ratio to thesis at f_lat 1, and PSNR / SSIM against `render --full`
# (bench/trade_bench). The table is cached per f_lat (the first, untimed,
# render rasterizes it); the load average is printed at the start and end.
set -euo pipefail
source "$(dirname "$0")/lib.sh"
build="$root/build"
runs=5
size="512x512"
bench_parse --build=build --runs=runs --size=size -- "$@"
lattice="$build/app/lattice"
metric="$build/bench/trade_bench"
bench_need_built "$build" lattice trade_bench
bench_need_time
bench_positive --runs "$runs"
bench_size "$size"
bench_workdir work
render() {  # scene-file png args... -> cpu seconds
  /usr/bin/time -f "%U %S" -o "$work/time" "$lattice" render "$1" -o "$2" "${@:3}" --threads 1 --quiet \
    "${bench_size_args[@]}" >"$work/log" 2>&1 || { echo "lattice-lookup.sh: render $* failed:" >&2; cat "$work/log" >&2; exit 4; }
  awk '{ printf "%.3f\n", $1 + $2 }' "$work/time"
}
echo "load average at start: $(bench_loadavg)"
echo
echo "| plate | f_lat | look-up | CPU s (median of $runs) | x thesis f_lat 1 | PSNR dB | SSIM |"
echo "|---|---|---|---|---|---|---|"
for plate in "6 fuzzy-sphere-1000" "7 fuzzy-sphere-5000"; do
  set -- $plate
  ref="$work/ref-$1.png"
  render "$root/scenes/$2.toml" "$ref" --full --arith double >/dev/null
  base=""
  for f in 1 2 3 4; do
    scene="$work/$2-f$f.toml"
    # Both plates use the same hair, so they share its cache at each f_lat.
    sed -E "s/^oversample *= *[0-9.]+/oversample = $f\ncache = \"hair-f$f.lht\"/" "$root/scenes/$2.toml" >"$scene"
    grep -q "^oversample = $f" "$scene" || { echo "lattice-lookup.sh: scenes/$2.toml has no 'oversample =' line" >&2; exit 3; }
    render "$scene" "$work/warm.png" >/dev/null  # rasterizes and caches the table
    declare -A times=([thesis]="" [blend]="")
    for ((i = 0; i < runs; ++i)); do
      for lookup in thesis blend; do times[$lookup]+="$(render "$scene" "$work/$lookup.png" --lattice-lookup "$lookup") "; done
    done
    for lookup in thesis blend; do
      read -r -a runTimes <<<"${times[$lookup]}"
      t=$(bench_median -f %.3f "${runTimes[@]}")
      [[ -z $base ]] && base=$t
      read -r psnr _ ssim < <("$metric" "$ref" "$work/$lookup.png")
      echo "| $1 | $f | $lookup | $t | $(awk -v a="$t" -v b="$base" 'BEGIN { printf "%.2f", a / b }') | $psnr | $ssim |"
    done
  done
done
echo
echo "load average at end: $(bench_loadavg)"
