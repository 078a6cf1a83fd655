#!/usr/bin/env bash
# How good --memory-budget's prediction is (docs/memory.md, "Calibration"):
# renders every example scene to every output device with a roomy budget and
# prints, per run, the plan's predicted peak, the measured peak (VmHWM) and
# their difference, sorted with the worst (most negative) first. A negative
# slack would mean a budget between the two could be broken.
#   bench/memory-calibration.sh [--build DIR]...   (default: build and build-static)
set -euo pipefail
source "$(dirname "$0")/lib.sh"
builds=()
bench_parse --build+=builds -- "$@"
((${#builds[@]})) || builds=("$root/build" "$root/build-static")
bench_workdir work
outputs=("--device tek4125 --stream $work/x.tek" "--device tek4125 --mode passes --stream $work/x.tek"
  "--device tek4125 --stream $work/x.tek -o $work/x.png" "--device tek4027 --stream $work/y.tek"
  "-o $work/t.png" "--device apollo -o $work/a.png")
for build in "${builds[@]}"; do
  bench_need_built "$build" lattice
  for scene in "$root"/scenes/*.toml; do
    for output in "${outputs[@]}"; do
      # shellcheck disable=SC2086 # the output flags are words on purpose
      log=$("$build/app/lattice" render "$scene" $output --threads 1 --quiet --memory-budget 1G 2>&1) ||
        { echo "memory-calibration.sh: $scene $output failed:" >&2; echo "$log" >&2; exit 1; }
      predicted=$(grep -o 'predicted peak [0-9.]* MiB' <<<"$log" | awk '{ print $3 }')
      measured=$(grep -o 'peak resident memory [0-9.]* MiB' <<<"$log" | awk '{ print $4 }')
      awk -v p="$predicted" -v m="$measured" -v b="$(basename "$build")" -v s="$(basename "$scene" .toml)" \
        -v o="${output//$work\//}" 'BEGIN { printf "%6.0f KiB  predicted %6.2f MiB  measured %6.2f MiB  %s %s %s\n", (p - m) * 1024, p, m, b, s, o }'
    done
  done
done | sort -n
