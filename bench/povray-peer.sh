#!/usr/bin/env bash
# POV-Ray peer benchmark: the same scenes (scenes/*.toml, written for POV-Ray
# by `lattice export pov`) rendered by POV-Ray 3.7 and by Lattice at the same size,
# 1 and 2 threads, median of N runs each; the runs of the two programs
# alternate so that both see the same machine load. Then the two pictures of
# each scene are compared (PSNR, bench/povray/psnr.py).
#
#   bench/povray-peer.sh [--build-dir DIR] [--runs N] [--out FILE] [--images DIR]
#
# Two figures per program:
#  * render time, the comparison that counts: POV-Ray's own "Trace Time"
#    statistic against render_bench's in-process render of the same scene
#    (double); both leave out parsing, set-up and writing the picture.
#  * whole-process wall time (`povray` against `lattice render -o`): POV-Ray
#    3.7's front end spends about half a second starting and stopping its
#    render back end, which would swamp these small scenes.
# Needs povray (scripts/setup.sh --bench); GNU time, when present, adds each
# program's peak memory (max RSS). DIR is a configured build directory with
# the `lattice` and `render_bench` targets built (bench/run-all.sh does that).
set -euo pipefail

source "$(dirname "$0")/lib.sh"
here="$root/bench"
build="$root/build"
runs=5
out=""
images=""
bench_parse --build-dir=build --runs=runs --out=out --images=images -- "$@"
bench_positive --runs "$runs"
command -v povray >/dev/null || { echo "povray-peer.sh: povray not found; run scripts/setup.sh --bench" >&2; exit 1; }
lattice="$build/app/lattice"
render_bench="$build/bench/render_bench"
for program in "$lattice" "$render_bench"; do
  [[ -x "$program" ]] || { echo "povray-peer.sh: $program is not built; pass --build-dir DIR" >&2; exit 1; }
done
command -v python3 >/dev/null || { echo "povray-peer.sh: python3 is needed for the PSNR" >&2; exit 1; }
if [[ -z "$images" ]]; then
  bench_workdir images
fi
mkdir -p "$images"
gnutime=""
[[ -x /usr/bin/time ]] && /usr/bin/time -f %M true 2>/dev/null && gnutime=/usr/bin/time

# scene  width  height (as in scenes/<scene>.toml [options])
scenes=("sphere-hole 256 256" "torus-floor 320 240" "thesis-camera 256 256")

# Runs a command, prints "seconds max_rss_kib" (rss "-" without GNU time).
timed() {
  local t0 t1 rss="-"
  t0=$EPOCHREALTIME
  if [[ -n "$gnutime" ]]; then
    "$gnutime" -f %M -o "$images/rss" "$@" >/dev/null 2>"$images/stderr" || { cat "$images/stderr" >&2; return 1; }
    rss=$(tail -n 1 "$images/rss")
  else
    "$@" >/dev/null 2>"$images/stderr" || { cat "$images/stderr" >&2; return 1; }
  fi
  t1=$EPOCHREALTIME
  echo "$(python3 -c "print(f'{$t1 - $t0:.4f}')") $rss"
}


# "wall cpu": seconds of POV-Ray's "Trace Time" statistic in the log of its
# last run and the CPU-seconds its next line reports.
pov_trace_seconds() {
  awk '/Trace Time:/ { match($0, /\(([0-9.]+) seconds\)/); wall = substr($0, RSTART + 1, RLENGTH - 10); next }
       wall != "" && /CPU-seconds/ { for (i = 1; i < NF; ++i) if ($(i + 1) == "CPU-seconds") print wall, $i; exit }' \
    "$images/stderr"
}

report() {
  echo "# POV-Ray peer: $(povray --version 2>&1 | grep -m1 'POV-Ray' || echo povray) against Lattice"
  echo "# median of $runs runs, the two programs alternating; $(nproc) cores; load before: $(bench_loadavg)"
  echo "# povray -D -A +Q4 +FN8 File_Gamma=1.0 +WT<n> (no AA, shadows, no reflections); Lattice: double, --threads <n>"
  echo "# ms: render wall time (POV-Ray's Trace Time vs render_bench's render); cpu: the same renders' CPU time,"
  echo "# all threads (steadier on a loaded machine); wall: whole process (povray vs lattice render -o)"
  printf '%-14s %8s %3s %8s %8s %6s | %8s %8s %6s | %8s %8s %6s | %7s %7s\n' scene size thr pov_ms lat_ms ratio \
    pov_cpu lat_cpu ratio pov_wall lat_wall ratio pov_MiB lat_MiB
  local entry scene w h threads r
  for entry in "${scenes[@]}"; do
    read -r scene w h <<<"$entry"
    "$lattice" export pov "$root/scenes/$scene.toml" -o "$images/$scene.pov" -q
    for threads in 1 2; do
      local povr=() latr=() povc=() latc=() povw=() latw=() povrss="-" latrss="-" line trace ms
      for ((r = 0; r < runs; r++)); do
        line=$(timed povray -D -A +Q4 +FN8 File_Gamma=1.0 "+W$w" "+H$h" "+WT$threads" \
          "-I$images/$scene.pov" "+O$images/$scene-povray.png")
        povw+=("${line% *}"); povrss="${line#* }"
        trace=$(pov_trace_seconds)
        [[ -n "$trace" ]] || { echo "povray-peer.sh: no Trace Time in POV-Ray's statistics:" >&2; cat "$images/stderr" >&2; exit 1; }
        povr+=("${trace% *}"); povc+=("${trace#* }")
        line=$(timed "$lattice" render "$root/scenes/$scene.toml" -o "$images/$scene-lattice.png" \
          --threads "$threads" --quiet)
        latw+=("${line% *}"); latrss="${line#* }"
        ms=$("$render_bench" --runs 1 --threads-list "$threads" --arith double "$root/scenes/$scene.toml" |
          awk -v s="$scene" '$1 == s { print $5 / 1000, $6 / 1000 }')
        [[ -n "$ms" ]] || { echo "povray-peer.sh: render_bench gave no time for $scene" >&2; exit 1; }
        latr+=("${ms% *}"); latc+=("${ms#* }")
      done
      awk -v s="$scene" -v sz="${w}x${h}" -v t="$threads" -v pr="$(bench_median "${povr[@]}")" \
        -v lr="$(bench_median "${latr[@]}")" -v pc="$(bench_median "${povc[@]}")" -v lc="$(bench_median "${latc[@]}")" \
        -v pw="$(bench_median "${povw[@]}")" -v lw="$(bench_median "${latw[@]}")" -v pm="$povrss" -v lm="$latrss" \
        'function mib(k) { return k == "-" ? "-" : sprintf("%.1f", k / 1024) }
         function ratio(a, b) { return b > 0 ? sprintf("%.2f", a / b) : "-" }
         BEGIN { printf "%-14s %8s %3d %8.1f %8.1f %6s | %8.1f %8.1f %6s | %8.1f %8.1f %6s | %7s %7s\n",
                 s, sz, t, pr * 1e3, lr * 1e3, ratio(lr, pr), pc * 1e3, lc * 1e3, ratio(lc, pc),
                 pw * 1e3, lw * 1e3, ratio(lw, pw), mib(pm), mib(lm) }'
    done
  done
  echo
  echo "# ratio = Lattice / POV-Ray (below 1: Lattice is faster). Pictures: lattice render -o against POV-Ray's"
  printf '%-14s %8s %8s %9s %9s\n' scene psnr_dB maxdiff differ_% mean_abs
  for entry in "${scenes[@]}"; do
    read -r scene w h <<<"$entry"
    read -r psnr maxd differ mean < <(python3 "$here/povray/psnr.py" "$images/$scene-lattice.png" "$images/$scene-povray.png")
    printf '%-14s %8s %8s %9s %9s\n' "$scene" "$psnr" "$maxd" "$differ" "$mean"
  done
  echo "# load after: $(bench_loadavg)"
}

bench_write "$out" report
