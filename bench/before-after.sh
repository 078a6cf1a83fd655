#!/usr/bin/env bash
# Side-by-side timing of two `lattice` binaries (before and after a change),
# for the "no slowdown" and "what this step bought" rows in the docs.
#
# Method: for each case, runs BEFORE and AFTER alternately (so load drifts hit
# both alike), N times each, and reports each one's median CPU time (user +
# system of the whole process, GNU time: on a shared machine it moves far less
# with the load than the wall clock does), the min-max, the ratio after/before
# of the medians, and the load average at the start and the end. Outputs must
# be identical: the script compares them and says so ("same pixels" when the
# PNG files differ in their bytes but AFTER's `lattice diff` finds no pixel
# apart, as when the PNG encoder changes).
#   bench/before-after.sh BEFORE AFTER [--runs N] [--threads T] [--size WxH]
#                         [--case "NAME:RENDER ARGUMENTS"]...
# --case replaces the built-in cases (repeat it for more than one; the word
# STREAM stands for a stream file of each side's), e.g.
#   --case "plate7:scenes/fuzzy-sphere-5000.toml"
set -euo pipefail
source "$(dirname "$0")/lib.sh"
[[ $# -ge 2 ]] || { bench_help; exit 2; }
before="$1"; after="$2"; shift 2
runs=5; threads=1; size=256x256
given_cases=()
bench_parse --runs=runs --threads=threads --size=size --case+=given_cases -- "$@"
for b in "$before" "$after"; do [[ -x $b ]] || bench_die "$b is not an executable"; done
w=${size%x*}; h=${size#*x}
bench_workdir out
cases=(
  "fuzzy-sphere-1000 double:$root/scenes/fuzzy-sphere-1000.toml --arith double"
  "fuzzy-sphere-1000 --full:$root/scenes/fuzzy-sphere-1000.toml --full"
  "fuzzy-sphere-1000 fixed:$root/scenes/fuzzy-sphere-1000.toml --arith fixed"
  "torus-floor double:$root/scenes/torus-floor.toml"
  "thistle float:$root/scenes/thistle.toml --arith float"
  "sphere-hole tek4125:$root/scenes/sphere-hole.toml --device tek4125 --stream STREAM"
)
((${#given_cases[@]} == 0)) || cases=("${given_cases[@]}")
echo "# $(date -u +%F' '%H:%M) UTC, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(bench_loadavg)"
echo "# ${size}, --threads $threads, $runs alternating runs each; CPU seconds (user + system) of the whole process"
printf '%-28s %18s %18s %8s %s\n' case before after ratio output
for c in "${cases[@]}"; do
  name=${c%%:*}; args=${c#*:}
  declare -a tb=() ta=()
  for ((i = 0; i < runs; i++)); do
    for side in before after; do
      bin=$before; [[ $side == after ]] && bin=$after
      # shellcheck disable=SC2086
      /usr/bin/time -f '%U %S' -o "$out/time" "$bin" render ${args//STREAM/$out/$side.stream} --width "$w" \
        --height "$h" --threads "$threads" --quiet -o "$out/$side.png" 2>/dev/null
      t=$(awk '{printf "%.2f", $1 + $2}' "$out/time")
      if [[ $side == before ]]; then tb+=("$t"); else ta+=("$t"); fi
    done
  done
  mb=$(bench_median "${tb[@]}"); ma=$(bench_median "${ta[@]}")
  same=identical
  if ! cmp -s "$out/before.png" "$out/after.png"; then
    same=DIFFERENT
    "$after" diff "$out/before.png" "$out/after.png" 2>/dev/null | grep -q '^differing *0 pixels' && same="same pixels"
  fi
  if [[ -f $out/before.stream ]]; then cmp -s "$out/before.stream" "$out/after.stream" || same="stream DIFFERENT"; rm -f "$out"/*.stream; fi
  printf '%-28s %8s (%s) %8s (%s) %8.3f %s\n' "$name" "$mb" "$(bench_range "${tb[@]}")" "$ma" "$(bench_range "${ta[@]}")" \
    "$(awk -v a="$ma" -v b="$mb" 'BEGIN {print a / b}')" "$same"
done
echo "# load at the end $(bench_loadavg)"
