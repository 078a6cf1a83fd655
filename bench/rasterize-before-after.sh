#!/usr/bin/env bash
# Side-by-side rasterization speed of two `lattice` binaries (before and
# after a change to lht/raster/rasterize or its cull), for a before/after row in bench/results/.
#
# Method: for each case, `lattice rasterize ... --stats` with BEFORE and AFTER
# alternately (so load drifts hit both alike), N times each; reports each
# one's median build_ms (wall clock of the rasterization alone, as the
# command prints it) and median CPU seconds of the whole process (user +
# system, GNU time), the min-max, the ratios after/before, and the load
# average at the start and the end. The .lht files must be byte-identical:
# the script compares them and says so. Across a change of the file format
# (byte 8, the version) bytes cannot match; it then compares what
# `lattice lht-info` reports of the contents (N_lp, N_iz, entries, object
# hash) and says "vB -> vA" with the verdict.
#   bench/rasterize-before-after.sh BEFORE AFTER [--runs N] [--threads T]
set -euo pipefail
source "$(dirname "$0")/lib.sh"
[[ $# -ge 2 ]] || { bench_help; exit 2; }
before="$1"; after="$2"; shift 2
runs=5; threads=1
bench_parse --runs=runs --threads=threads -- "$@"
for b in "$before" "$after"; do
  [[ -x $b ]] || bench_die "$b is not an executable"
done
bench_workdir out
cases=(
  "hair f_lat 1:--scene $root/scenes/fuzzy-sphere-1000.toml --name hair --oversample 1"
  "hair f_lat 2:--scene $root/scenes/fuzzy-sphere-1000.toml --name hair --oversample 2"
  "hair f_lat 3:--scene $root/scenes/fuzzy-sphere-1000.toml --name hair --oversample 3"
  "thistle line f_lat 2:--scene $root/scenes/thistle.toml --name line --oversample 2"
  "capsule 100 f_lat 2:--shape capsule --length 100 --oversample 2"
)
echo "# $(date -u +%F' '%H:%M) UTC, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(bench_loadavg)"
echo "# --threads $threads, $runs alternating runs each; build_ms (rasterization, wall) and CPU s (whole process)"
printf '%-22s %22s %22s %6s %16s %16s %6s %s\n' case "build_ms before" "after" ratio "CPU s before" after ratio table
for c in "${cases[@]}"; do
  name=${c%%:*}; args=${c#*:}
  declare -a mb=() ma=() cb=() ca=()
  for ((i = 0; i < runs; i++)); do
    for side in before after; do
      bin=$before; [[ $side == after ]] && bin=$after
      # shellcheck disable=SC2086
      /usr/bin/time -f '%U %S' -o "$out/time" "$bin" rasterize $args --threads "$threads" --stats \
        -o "$out/$side.lht" > "$out/stats" 2>/dev/null
      ms=$(sed -n 's/.*build_ms=\([0-9.]*\).*/\1/p' "$out/stats")
      cpu=$(awk '{printf "%.2f", $1 + $2}' "$out/time")
      if [[ $side == before ]]; then mb+=("$ms"); cb+=("$cpu"); else ma+=("$ms"); ca+=("$cpu"); fi
    done
  done
  b=$(bench_median "${mb[@]}"); a=$(bench_median "${ma[@]}"); bc=$(bench_median "${cb[@]}"); ac=$(bench_median "${ca[@]}")
  same=identical
  cmp -s "$out/before.lht" "$out/after.lht" || same=DIFFERENT
  vb=$(od -An -tu1 -j8 -N1 "$out/before.lht" | tr -d ' '); va=$(od -An -tu1 -j8 -N1 "$out/after.lht" | tr -d ' ')
  if [[ $vb != "$va" ]]; then
    contents() { "$1" lht-info "$2" | grep -E '^(object hash|pairs|hits|entries):'; }
    if [[ "$(contents "$before" "$out/before.lht")" == "$(contents "$after" "$out/after.lht")" ]]; then
      same="v$vb -> v$va, same contents"
    else
      same="v$vb -> v$va, contents DIFFERENT"
    fi
  fi
  printf '%-22s %8s (%11s) %8s (%11s) %6.2f %5s (%9s) %5s (%9s) %6.2f %s\n' "$name" "$b" "$(bench_range "${mb[@]}")" \
    "$a" "$(bench_range "${ma[@]}")" "$(awk -v a="$a" -v b="$b" 'BEGIN {print a / b}')" "$bc" "$(bench_range "${cb[@]}")" \
    "$ac" "$(bench_range "${ca[@]}")" "$(awk -v a="$ac" -v b="$bc" 'BEGIN {print a / b}')" "$same"
done
echo "# load at the end $(bench_loadavg)"
