#!/usr/bin/env bash
# The whole process's CPU and wall milliseconds of two `lattice` binaries on
# small renders, where the set-up and what follows the picture (the exit)
# are nearly all of it: what a change to the serial tail bought.
#
# Method: BEFORE and AFTER alternate, N runs each per case (so load drifts
# hit both alike); each run's CPU is `perf stat`'s task-clock (every thread's,
# to the microsecond, where GNU time's user + system counts hundredths) and its
# wall the clock around the command; medians, min-max and after/before, with
# the load average at the start and the end. With --phase NAME the CPU
# column is instead the renderer's own CPU figure for that phase (set-up,
# trace, output or process, from its "(CPU ...)" report), for a change that
# touches one phase of a large render. The pictures must be the same bytes,
# or where a change re-encodes the PNG the same pixels (`lattice diff` of
# AFTER): the script compares them and says which.
#   bench/process-cpu.sh BEFORE AFTER [--runs N] [--threads "1 2"] [--size WxH]
#                        [--scenes "fuzzy-sphere-1000 fuzzy-sphere-5000"] [--phase NAME]
# Needs perf (linux-perf).
source "$(dirname "$0")/lib.sh"
runs=31 threads_list="1 2" size=2x2 scenes="fuzzy-sphere-1000 fuzzy-sphere-5000" phase=""
bench_parse --runs=runs --threads=threads_list --size=size --scenes=scenes --phase=phase @ -- "$@"
set -- "${bench_args[@]}"
(($# == 2)) || bench_die "give two binaries: BEFORE AFTER"
command -v perf >/dev/null || bench_die "perf is missing (apt-get install linux-perf)"
before=$1 after=$2 w=${size%x*} h=${size#*x}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
root=$(cd "$(dirname "$0")/.." && pwd)

case "$phase" in "" | set-up | trace | output | process) ;; *) bench_die "--phase: set-up, trace, output or process" ;; esac

# One run: "cpu_ms wall_ms" on stdout, the picture at $3.
one() {
  local bin=$1 scene=$2 png=$3 t=$4 t0 t1 cpu report
  t0=$(date +%s%N)
  report=$(perf stat -x, -e task-clock -o "$out/stat" "$bin" render "$root/scenes/$scene.toml" --threads "$t" \
    --width "$w" --height "$h" --quiet -o "$png" 2>&1 >/dev/null | tail -n 1)
  t1=$(date +%s%N)
  if [[ -n $phase ]]; then
    cpu=$(grep -o "(CPU .*)" <<<"$report" | grep -o "$phase [0-9.]* s" | awk '{ printf "%.3f", $2 * 1000 }')
  else
    cpu=$(grep task-clock "$out/stat" | cut -d, -f1)
  fi
  [[ -n $cpu ]] || bench_die "no ${phase:-task-clock} CPU figure from $bin: $report"
  echo "$cpu $(((t1 - t0) / 1000))"
}

echo "# $(date -u '+%F %H:%M') UTC, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); $runs alternating runs, ${w}x$h"
echo "| scene | thr | binary | ${phase:+$phase }CPU ms, median | min-max | x before | wall ms, median | min-max | x before | pictures |"
echo "|---|---:|---|---:|---:|---:|---:|---:|---:|---|"
for scene in $scenes; do
  for t in $threads_list; do
    : >"$out/before" && : >"$out/after"
    same=identical
    for ((r = 0; r < runs; r++)); do
      one "$before" "$scene" "$out/b.png" "$t" >>"$out/before"
      one "$after" "$scene" "$out/a.png" "$t" >>"$out/after"
      verdict=$(bench_same_picture "$out/b.png" "$out/a.png" "$after")
      [[ $same == DIFFERENT || $verdict == identical ]] || same=$verdict
    done
    python3 - "$scene" "$t" "$out/before" "$out/after" "$same" <<'PY'
import statistics, sys
scene, t, bf, af, same = sys.argv[1:]
def read(p):
    rows = [l.split() for l in open(p) if l.strip()]
    return [float(c) for c, _ in rows], [float(wl) / 1000 for _, wl in rows]
b, a = read(bf), read(af)
for name, (cpu, wall) in (("before", b), ("after", a)):
    mc, mw = statistics.median(cpu), statistics.median(wall)
    rc, rw = mc / statistics.median(b[0]), mw / statistics.median(b[1])
    print(f"| {scene} | {t} | {name} | {mc:.2f} | {min(cpu):.2f}-{max(cpu):.2f} | {rc:.3f} | {mw:.2f} | "
          f"{min(wall):.2f}-{max(wall):.2f} | {rw:.3f} | {same} |")
PY
  done
done
echo "# load at the end $(cut -d' ' -f1-3 /proc/loadavg)"
