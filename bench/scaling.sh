#!/usr/bin/env bash
# How a render scales with its threads, phase by phase, and what its serial
# part allows on a machine with more cores (docs/architecture.md, "How the
# work is split"). For each size (square) and thread count it runs
#   lattice render SCENE --width S --height S --threads T -o PNG
# which prints "(set-up X s) (trace X s) (output X s)" (app/render_phases.hpp),
# and, for the quantize phase, the same picture to the sixel device (its
# screen set to S x S, 256 registers, --mode frame so the picture is traced
# once), which prints "(quantize X s)": histogram, median cut and mapping,
# with the driver fed row by row. Runs alternate thread counts (1 2 1 2 ...)
# so a change in the machine's load hits each alike; medians of --runs.
#
# Then, per size, from the whole process's median wall times T1 and TN:
#   speed-up   T1 / TN
#   serial     the Karp-Flatt serial fraction e = (TN/T1 - 1/N) / (1 - 1/N)
#              (Karp and Flatt, "Measuring parallel processor performance",
#              CACM 33(5), 1990): Amdahl's serial fraction that explains
#              the measured speed-up, the time lost to threads included
#   16x, 64x   Amdahl's law with it: 1 / (e + (1 - e) / P) at P = 16, 64
#   non-trace  (whole - trace) / whole at one thread, by the wall clock and
#              by CPU time: the serial fraction if nothing but the trace ran
#              in parallel (a bound: set-up and output run partly on every
#              thread), and the Amdahl speed-up it allows at 16 and 64
#   by phase   each phase's serial part s from its own T1 and TN (s + (T1 - s)
#              / N = TN): set-up, output and the rest of the process outside
#              the trace, their sum as a share of T1, and what that share
#              allows with the trace counted parallel (its own losses are in e)
# On a shared machine other work inflates TN more than T1 (it takes the
# second core), so e is an over-estimate there; the CPU shares are the
# figures that hold (the load average is printed).
#   bench/scaling.sh [--build DIR] [--scene FILE] [--sizes "512 1024 2048"]
#                    [--threads "1 2"] [--runs N] [--out FILE]
# Defaults: Plate 7 (scenes/fuzzy-sphere-5000.toml), threads 1 and every
# core, 3 runs. Needs python3 for the table.
set -euo pipefail

source "$(dirname "$0")/lib.sh"
build="$root/build"
scene="$root/scenes/fuzzy-sphere-5000.toml"
sizes="512 1024 2048"
threads_list="1 $(nproc)"
runs=3
out=""
bench_parse --build=build --scene=scene --sizes=sizes --threads=threads_list --runs=runs --out=out -- "$@"
bench_positive --runs "$runs"
for s in $sizes; do bench_positive --sizes "$s"; done
for t in $threads_list; do bench_positive --threads "$t"; done
[[ -f $scene ]] || bench_die "no scene file $scene (give --scene FILE)"
command -v python3 >/dev/null || bench_die "python3 is needed for the table"
bench_need_built "$build" lattice
lattice="$build/app/lattice"
bench_workdir work

# One line of phases: "size threads whole setup trace quantize output
# cpu_whole cpu_setup cpu_trace cpu_output cpu_quantize": wall seconds (the
# whole process by the clock around it), then CPU seconds from lattice
# render's report (the whole: the process's from its start to the report,
# all but its exit; quantize: the sixel render's).
measure() {
  local size=$1 threads=$2 start end whole line device
  start=$(date +%s.%N)
  line=$("$lattice" render "$scene" --width "$size" --height "$size" --threads "$threads" -q -o "$work/out.png" 2>&1)
  end=$(date +%s.%N)
  whole=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.4f", b - a }')
  device=$("$lattice" render "$scene" --device sixel --set width="$size" --set height="$size" --set registers=256 \
    --width "$size" --height "$size" --threads "$threads" --mode frame -q --stream "$work/out.six" 2>&1 \
    | grep '(quantize ' || true)
  phase() { grep -o "($1 [0-9.]* s)" <<<"$2" | grep -o '[0-9.]*' || echo 0; }
  cpuphase() { grep -o "(CPU .*)" <<<"$2" | grep -o "$1 [0-9.]* s" | grep -o '[0-9.]*' || echo 0; }
  echo "$size $threads $whole $(phase set-up "$line") $(phase trace "$line") $(phase quantize "$device")" \
    "$(phase output "$line") $(cpuphase process "$line") $(cpuphase set-up "$line") $(cpuphase trace "$line") $(cpuphase output "$line")" \
    "$(cpuphase quantize "$device")"
}

report() {
  echo "scene: ${scene#"$root"/}; sizes: $sizes; threads: $threads_list; runs: $runs; $(nproc) cores"
  echo "load average before: $(bench_loadavg)"
  local raw="$work/raw.txt"
  : >"$raw"
  for size in $sizes; do
    for ((r = 0; r < runs; r++)); do
      for t in $threads_list; do measure "$size" "$t" >>"$raw"; done
    done
  done
  echo "load average after: $(bench_loadavg)"
  python3 - "$raw" <<'PY'
import statistics, sys
rows = [line.split() for line in open(sys.argv[1]) if line.strip()]
data = {}
for size, threads, *values in rows:
    data.setdefault((int(size), int(threads)), []).append([float(v) for v in values])
def med(runs, i): return statistics.median(r[i] for r in runs)
def meddiff(runs, i, j): return statistics.median(r[i] - r[j] for r in runs)
print("\nWall seconds, medians (whole - trace: the median of each run's difference):\n")
print("| size | threads | whole | set-up | trace | quantize | output | whole - trace |")
print("|---:|---:|---:|---:|---:|---:|---:|---:|")
for (size, threads), runs in sorted(data.items()):
    w, s, t, q, o = (med(runs, i) for i in range(5))
    print(f"| {size} | {threads} | {w:.3f} | {s:.4f} | {t:.3f} | {q:.4f} | {o:.4f} | {meddiff(runs, 0, 2):.4f} |")
print("\nCPU seconds (every thread's), medians; at one thread what a quiet machine's wall clock shows:\n")
print("| size | threads | whole | set-up | trace | quantize | output | whole - trace |")
print("|---:|---:|---:|---:|---:|---:|---:|---:|")
for (size, threads), runs in sorted(data.items()):
    w, s, t, o, q = (med(runs, i) for i in (5, 6, 7, 8, 9))
    print(f"| {size} | {threads} | {w:.3f} | {s:.4f} | {t:.3f} | {q:.4f} | {o:.4f} | {meddiff(runs, 5, 7):.4f} |")
print("\nSerial fraction and the speed-up it allows (Amdahl):\n")
print("| size | threads N | speed-up T1/TN | e (Karp-Flatt) | at 16 | at 64 | non-trace share, wall | at 16 | at 64 "
      "| non-trace share, CPU | at 16 | at 64 |")
print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
amdahl = lambda e, p: 1 / (e + (1 - e) / p)
for size in sorted({k[0] for k in data}):
    counts = sorted(t for (s, t) in data if s == size)
    if 1 not in counts: continue
    one = data[(size, 1)]
    t1 = med(one, 0)
    wall_share = statistics.median((r[0] - r[2]) / r[0] for r in one)
    cpu_share = statistics.median((r[5] - r[7]) / r[5] if r[5] > 0 else 0.0 for r in one)  # 0: no CPU report
    for n in counts:
        if n == 1: continue
        tn = med(data[(size, n)], 0)
        e = max((tn / t1 - 1 / n) / (1 - 1 / n), 0.0)
        print(f"| {size} | {n} | {t1 / tn:.2f} | {e:.4f} | {amdahl(e, 16):.1f} | {amdahl(e, 64):.1f} | "
              f"{wall_share:.4f} | {amdahl(wall_share, 16):.1f} | {amdahl(wall_share, 64):.1f} | "
              f"{cpu_share:.4f} | {amdahl(cpu_share, 16):.1f} | {amdahl(cpu_share, 64):.1f} |")
# The shares above charge every non-trace second as serial, though the PNG's
# bands and parts of the set-up run on every thread. Phase by phase, a phase
# taking T1 at one thread and TN at N has the serial part s of s + (T1 - s) / N
# = TN; the process's rest (whole - set-up - trace - output) is counted the same way.
print("\nSerial seconds outside the trace, phase by phase from the wall medians (s = (N TN - T1) / (N - 1),\n"
      "within 0..T1), and the speed-up they allow with the trace itself counted parallel:\n")
print("| size | threads N | set-up serial | output serial | rest serial | serial, all | share of T1 | at 16 | at 64 |")
print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
def serial_part(t1, tn, n): return min(max((n * tn - t1) / (n - 1), 0.0), t1)
for size in sorted({k[0] for k in data}):
    counts = sorted(t for (s, t) in data if s == size)
    if 1 not in counts: continue
    one = data[(size, 1)]
    rest1 = statistics.median(r[0] - r[1] - r[2] - r[4] for r in one)
    for n in counts:
        if n == 1: continue
        many = data[(size, n)]
        restn = statistics.median(r[0] - r[1] - r[2] - r[4] for r in many)
        parts = [serial_part(med(one, i), med(many, i), n) for i in (1, 4)] + [serial_part(rest1, restn, n)]
        share = sum(parts) / med(one, 0)
        print(f"| {size} | {n} | {parts[0] * 1000:.1f} ms | {parts[1] * 1000:.1f} ms | {parts[2] * 1000:.1f} ms | "
              f"{sum(parts) * 1000:.1f} ms | {share:.4f} | {amdahl(share, 16):.1f} | {amdahl(share, 64):.1f} |")
PY
}
bench_write "$out" report
