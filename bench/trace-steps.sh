#!/usr/bin/env bash
# The trace alone of several `lattice` binaries side by side (the steps of an
# optimisation of the renderer's traversal), where the whole process's CPU
# time (bench/before-after.sh, 10 ms steps) is too coarse to see a step.
#
# Method: for each scene, one render with each binary in turn, N rounds (so
# load drifts hit all alike); each render's own "CPU ... trace S s" figure
# (renderImage's CPU seconds, all threads: steadier than wall time on a
# shared machine). Prints each binary's median and min-max and its ratio to
# the first binary's median, the load average at the start and the end, and
# whether every binary wrote the same PNG bytes as the first (or the same
# pixels, where a binary's PNG encoder differs: bench_same_picture).
#   bench/trace-steps.sh BIN1 BIN2 [BIN3 ...] [--runs N] [--threads T]
#                        [--scene "NAME:RENDER ARGUMENTS"]...
# e.g. --scene "plate7:scenes/fuzzy-sphere-5000.toml"
set -euo pipefail
source "$(dirname "$0")/lib.sh"
runs=9; threads=1
scenes=()
bench_parse @ --runs=runs --threads=threads --scene+=scenes -- "$@"
bins=("${bench_args[@]}")
((${#bins[@]} >= 2)) || bench_die "give at least two lattice binaries (see --help)"
for b in "${bins[@]}"; do [[ -x $b ]] || bench_die "$b is not an executable"; done
bench_positive --runs "$runs"
((${#scenes[@]} > 0)) || scenes=("plate7:$root/scenes/fuzzy-sphere-5000.toml" "plate6:$root/scenes/fuzzy-sphere-1000.toml")
bench_workdir out
echo "# $(date -u +%F' '%H:%M) UTC, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(bench_loadavg)"
echo "# --threads $threads, $runs rounds; trace CPU seconds by the renderer's own timer"
for s in "${scenes[@]}"; do
  name=${s%%:*}
  read -ra args <<<"${s#*:}"
  declare -A times=()
  for ((r = 0; r < runs; r++)); do
    for i in "${!bins[@]}"; do
      log=$("${bins[$i]}" render "${args[@]}" --threads "$threads" -o "$out/$i.png" 2>&1 >/dev/null)
      t=$(grep -o 'CPU[^)]*trace [0-9.]* s' <<<"$log" | grep -o 'trace [0-9.]*' | cut -d' ' -f2)
      [[ -n $t ]] || bench_die "no trace figure from ${bins[$i]}: $log"
      times[$i]="${times[$i]:-} $t"
    done
  done
  # shellcheck disable=SC2086 # the lists are words on purpose
  first=$(bench_median ${times[0]})
  for i in "${!bins[@]}"; do
    # shellcheck disable=SC2086
    m=$(bench_median ${times[$i]})
    same=$(bench_same_picture "$out/0.png" "$out/$i.png" "${bins[$i]}")
    printf '%-14s %-40s %.4f (%s) %.3f %s\n' "$name" "${bins[$i]}" "$m" "$(bench_range ${times[$i]})" \
      "$(awk -v a="$m" -v b="$first" 'BEGIN { print a / b }')" "$same"
  done
  unset times
done
echo "# load at the end $(bench_loadavg)"
