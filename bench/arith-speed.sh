#!/usr/bin/env bash
# Render time per arithmetic (--arith float|double|fixed) on the example
# scenes, one thread, median of 3 runs, for docs/fixed-point.md. The time is
# the renderer's own figure ("N s" on its summary line: scene load, build and
# every pixel; PNG writing excluded).
#   bench/arith-speed.sh [BUILD_DIR] [scene.toml ...]
set -euo pipefail
source "$(dirname "$0")/lib.sh"
bench_parse @ -- "$@"
build="${bench_args[0]:-$root/build}"
scenes=("${bench_args[@]:1}")
if [ ${#scenes[@]} -eq 0 ]; then
  scenes=("$root/scenes/sphere-hole.toml" "$root/scenes/torus-floor.toml" "$root/scenes/thesis-camera.toml"
          "$root/scenes/fuzzy-sphere-1000.toml")
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target lattice -j2 >&2
bench_workdir out
printf '%-24s %10s %10s %10s %12s\n' scene float double fixed fixed/double
for scene in "${scenes[@]}"; do
  declare -A median=()
  for arith in float double fixed; do
    times=()
    for run in 1 2 3; do
      line="$("$build/app/lattice" render "$scene" --threads 1 --arith "$arith" -o "$out/$arith.png" 2>&1 | tail -1)"
      times+=("$(sed -E 's/.*, ([0-9.]+) s, .*/\1/' <<<"$line")")
    done
    median[$arith]="$(bench_median "${times[@]}")"
  done
  printf '%-24s %10s %10s %10s %12s\n' "$(basename "$scene")" "${median[float]}" "${median[double]}" "${median[fixed]}" \
    "$(awk -v f="${median[fixed]}" -v d="${median[double]}" 'BEGIN { printf "%.2f", f / d }')"
done
