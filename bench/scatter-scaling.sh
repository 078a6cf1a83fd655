#!/usr/bin/env bash
# How `lattice_scatter` scales with its instance count (docs/limits.md): the
# fuzzy-sphere scene (scenes/fuzzy-sphere-5000.toml) with `count` replaced,
# rendered at 1x1 (what it costs to load the scene, place the instances and
# build the BVH: the time before the first ray, plus three rays) and at 64x64
# (what the rays then cost), one thread. Prints wall seconds and peak
# resident memory from /usr/bin/time.
#   bench/scatter-scaling.sh [--build DIR] [COUNT...]   (default: 5000 10000 20000 100000)
set -euo pipefail

source "$(dirname "$0")/lib.sh"
build="$root/build"
bench_parse --build=build @ -- "$@"
counts=("${bench_args[@]}")
((${#counts[@]} > 0)) || counts=(5000 10000 20000 100000)
lattice="$build/app/lattice"
bench_need_built "$build" lattice
bench_need_time
bench_workdir work

printf '%8s %12s %12s %12s %12s\n' count 1x1_s 1x1_peak_MiB 64x64_s 64x64_peak_MiB
for n in "${counts[@]}"; do
  sed "s/^count = 5000/count = $n/" "$root/scenes/fuzzy-sphere-5000.toml" > "$work/scene.toml"
  grep -q "^count = $n\$" "$work/scene.toml" || { echo "could not set count in the scene" >&2; exit 1; }
  row=()
  for size in 1 64; do
    /usr/bin/time -f '%e %M' -o "$work/time" "$lattice" render "$work/scene.toml" --width $size --height $size \
      --threads 1 -o "$work/out.png" >/dev/null 2>&1
    read -r seconds peak < <(tail -n 1 "$work/time")
    row+=("$seconds" "$(awk -v k="$peak" 'BEGIN { printf "%.1f", k / 1024 }')")
  done
  printf '%8s %12s %12s %12s %12s\n' "$n" "${row[@]}"
done
echo "load average: $(bench_loadavg)"
