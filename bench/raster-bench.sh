#!/usr/bin/env bash
# The rasterizer's own time, before and after a change to lht/raster, read to
# the microsecond in the process (bench/raster_bench.cpp) where `lattice
# rasterize --stats` prints whole milliseconds, for a row in bench/results/.
#
# Method: two raster_bench programs (one built from each tree: `cmake --build
# build --target raster_bench`, copied aside) alternate ROUNDS times per case,
# each round rasterizing the entry RUNS times and reporting its median; the
# table gives the median of the rounds' medians of the rasterizer's wall timer
# and of the process CPU over it, the min-max, after/before, the counts each
# made (the pairs, traced segments and hits must agree; a table's bytes are compared by
# bench/rasterize-before-after.sh), and the load average at the start and end.
#   bench/raster-bench.sh BEFORE AFTER [--rounds R] [--runs N] [--threads "1 2"]
#                         [--scene scenes/fuzzy-sphere-5000.toml] [--name hair] [--oversample "1 2"]
source "$(dirname "$0")/lib.sh"
rounds=7 runs=21 threads_list="1 2" scene=scenes/fuzzy-sphere-5000.toml name=hair oversamples=1
bench_parse --rounds=rounds --runs=runs --threads=threads_list --scene=scene --name=name \
  --oversample=oversamples @ -- "$@"
set -- "${bench_args[@]}"
(($# == 2)) || bench_die "give two raster_bench programs: BEFORE AFTER"
bench_positive --rounds "$rounds"
bench_positive --runs "$runs"
for b in "$1" "$2"; do [[ -x $b ]] || bench_die "$b is not an executable"; done
[[ $scene = /* ]] || scene="$root/$scene"
echo "# $(date -u '+%F %H:%M') UTC, $(nproc) cores, load $(bench_loadavg); $rounds alternating rounds of $runs runs"
echo "| f_lat | thr | binary | wall ms, median | min-max | x before | CPU ms, median | min-max | x before | counts |"
echo "|---:|---:|---|---:|---:|---:|---:|---:|---:|---|"
for f in $oversamples; do
  for t in $threads_list; do
    declare -A wall=() cpu=() counts=()
    for ((r = 0; r < rounds; r++)); do
      for side in before after; do
        bin=$1; [[ $side == after ]] && bin=$2
        out=$("$bin" "$scene" "$name" --runs "$runs" --threads "$t" --oversample "$f") || bench_die "$bin failed"
        wall[$side]+="$(sed -n 's/.*wall median \([0-9.]*\) ms.*/\1/p' <<<"$out") "
        cpu[$side]+="$(sed -n 's/.*CPU median \([0-9.]*\) ms.*/\1/p' <<<"$out") "
        counts[$side]=$(grep -o 'pairs=.*' <<<"$out")
      done
    done
    wb=$(bench_median ${wall[before]}) cb=$(bench_median ${cpu[before]})
    for side in before after; do
      w=$(bench_median ${wall[$side]}) c=$(bench_median ${cpu[$side]})
      same=${counts[$side]}
      [[ $side == after && ${counts[after]} != "${counts[before]}" ]] && same="DIFFERENT: $same"
      printf '| %s | %s | %s | %.3f | %s | %.3f | %.3f | %s | %.3f | %s |\n' "$f" "$t" "$side" "$w" \
        "$(bench_range ${wall[$side]})" "$(awk -v a="$w" -v b="$wb" 'BEGIN {print a / b}')" "$c" \
        "$(bench_range ${cpu[$side]})" "$(awk -v a="$c" -v b="$cb" 'BEGIN {print a / b}')" "$same"
    done
  done
done
echo "# load at the end $(bench_loadavg)"
