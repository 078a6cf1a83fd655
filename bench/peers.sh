#!/usr/bin/env bash
# Lattice beside its peers, one command: ours in lattice mode and
# with --full (lattices replaced by their exact objects), POV-Ray 3.7 on the
# scene written by `lattice export pov`, and the Embree 3 program of
# bench/peers/, run alternately (one run of each, in turn, N times) on the
# example scenes at 1 and 2 threads. Writes a markdown table of medians,
# min-max and ratios to lattice mode, for the whole process and for the pure
# trace by each side's own timer, and each picture's PSNR against ours --full.
#
#   bench/peers.sh --build-dir DIR [--runs N] [--threads "1 2"] [--scenes "a b"]
#                  [--programs "lattice embree"] [--sphere-sweep] [--out FILE.md] [--images DIR]
#
# DIR: a Release build with the `lattice` target, and `embree_peer` when
# configured with -DLATTICE_EMBREE_PEER=ON (else the Embree rows say so).
# Timers: ours, `lattice render`'s "(trace S s)": renderImage alone, no scene
# set-up, no lattice rasterizing, no PNG; POV-Ray, its "Trace Time"
# statistic; Embree, embree_peer's trace_seconds (no load, no BVH build, no
# PNG). Whole process: wall time of the command, everything included (ours
# rasterizes the lattice table; POV-Ray parses the exported file), and its
# CPU time (user + system) when GNU time is installed.
# --sphere-sweep adds POV-Ray rows for the export with sphere_sweep hair.
# --programs keeps only the named contenders (of lattice, full, povray,
# povray-sweep, embree), so a pair can be timed without the slow ones; the
# PSNR column needs `full` among them.
# A scene a peer cannot trace (Embree: CSG, tori) gets a row saying why.
# Peers: povray, libembree-dev (scripts/setup.sh --bench); python3 for the table.
set -euo pipefail

source "$(dirname "$0")/lib.sh"
here="$root/bench"
build=""
runs=5
threads_list="1 2"
scenes="fuzzy-sphere-1000 fuzzy-sphere-5000 thistle torus-floor sphere-hole thesis-camera"
sweep=0
only=""
out=""
images=""
bench_parse --build-dir=build --runs=runs --threads=threads_list --scenes=scenes --sphere-sweep:sweep=1 --programs=only --out=out --images=images -- "$@"
[[ -n "$build" ]] || bench_die "give --build-dir DIR (a Release build with the lattice target)"
bench_positive --runs "$runs"
lattice="$build/app/lattice"
embree="$build/bench/peers/embree_peer"
[[ -x "$lattice" ]] || { echo "peers.sh: $lattice is not built (cmake --build $build --target lattice)" >&2; exit 1; }
command -v python3 >/dev/null || { echo "peers.sh: python3 is needed for the table" >&2; exit 1; }
have_povray=1
command -v povray >/dev/null || { have_povray=0; echo "peers.sh: povray not found (scripts/setup.sh --bench); no POV-Ray rows" >&2; }
have_embree=1
[[ -x "$embree" ]] || { have_embree=0; echo "peers.sh: $embree not built (configure with -DLATTICE_EMBREE_PEER=ON); no Embree rows" >&2; }
if [[ -z "$images" ]]; then
  bench_workdir images
fi
mkdir -p "$images"
gnutime=""
[[ -x /usr/bin/time ]] && /usr/bin/time -f %U true 2>/dev/null && gnutime=/usr/bin/time
raw="$images/raw.tsv"        # scene threads program run whole_s whole_cpu_s trace_s
notes="$images/notes.tsv"    # scene program note
: >"$raw"
: >"$notes"

# Runs "$@" with stdout and stderr to $images/log; prints "wall cpu": its wall
# seconds and, with GNU time, its CPU seconds (user + system, all threads;
# steadier than wall time while other jobs share the cores), else "-".
wall() {
  local t0=$EPOCHREALTIME status=0 cpu="-"
  if [[ -n "$gnutime" ]]; then
    "$gnutime" -f '%U %S' -o "$images/cpu" "$@" >"$images/log" 2>&1 || status=$?
  else
    "$@" >"$images/log" 2>&1 || status=$?
  fi
  local t1=$EPOCHREALTIME
  ((status == 0)) || return $status
  [[ -z "$gnutime" ]] || cpu=$(awk 'END { printf "%.4f", $1 + $2 }' "$images/cpu")
  awk -v a="$t0" -v b="$t1" -v c="$cpu" 'BEGIN { printf "%.4f %s\n", b - a, c }'
}

size_of() { grep -m1 -o '+W[0-9]* +H[0-9]*' "$1" | tr -d '+WH'; }

# Export each scene once (not timed), and note what a peer cannot trace.
for scene in $scenes; do
  file="$root/scenes/$scene.toml"
  [[ -f "$file" ]] || { echo "peers.sh: no scene $file" >&2; exit 1; }
  "$lattice" export pov "$file" -o "$images/$scene.pov" -q
  ((sweep == 0)) || "$lattice" export pov "$file" -o "$images/$scene-sweep.pov" -q --sphere-sweep
done

all_programs() {
  echo lattice full
  ((have_povray == 0)) || echo povray
  ((have_povray == 0 || sweep == 0)) || echo povray-sweep
  ((have_embree == 0)) || echo embree
}
programs() {
  local p
  for p in $(all_programs); do
    [[ -z "$only" || " $only " == *" $p "* ]] && echo "$p"
  done
  return 0
}

# One run of one program: appends "scene threads program run whole cpu trace" to raw.
run_one() {
  local scene=$1 threads=$2 program=$3 r=$4 file="$root/scenes/$1.toml" whole trace w h pov
  case "$program" in
    lattice | full)
      local flags=()
      [[ $program == full ]] && flags=(--full)
      whole=$(wall "$lattice" render "$file" "${flags[@]}" -o "$images/$scene-$program-$threads.png" \
        --threads "$threads" --quiet) || { cat "$images/log" >&2; exit 1; }
      trace=$(grep -o '(trace [0-9.]* s)' "$images/log" | grep -o '[0-9.]*') ;;
    povray | povray-sweep)
      pov="$images/$scene.pov"
      [[ $program == povray-sweep ]] && pov="$images/$scene-sweep.pov"
      read -r w h < <(size_of "$pov")
      whole=$(wall povray -D -A +Q4 +FN8 File_Gamma=1.0 "+W$w" "+H$h" "+WT$threads" "+I$pov" \
        "+O$images/$scene-$program-$threads.png") || { cat "$images/log" >&2; exit 1; }
      trace=$(sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$images/log" | head -n 1) ;;
    embree)
      if ! whole=$(wall "$embree" "$file" -o "$images/$scene-embree-$threads.png" --threads "$threads"); then
        grep -q "$scene	embree" "$notes" || printf '%s\tembree\t%s\n' "$scene" "$(head -n 1 "$images/log" | sed "s|^embree_peer: $root/||")" >>"$notes"
        return 0
      fi
      trace=$(awk '$1 == "trace_seconds" { print $2 }' "$images/log") ;;
  esac
  [[ -n "$trace" ]] || { echo "peers.sh: no trace time from $program on $scene:" >&2; cat "$images/log" >&2; exit 1; }
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$scene" "$threads" "$program" "$r" "${whole% *}" "${whole#* }" "$trace" \
    >>"$raw"
}

load_before=$(bench_loadavg)
started=$(date -u '+%Y-%m-%d %H:%M UTC')
for ((r = 1; r <= runs; r++)); do
  for scene in $scenes; do
    for threads in $threads_list; do
      for program in $(programs); do run_one "$scene" "$threads" "$program" "$r"; done
    done
  done
  echo "peers.sh: run $r of $runs done (load $(bench_loadavg))" >&2
done
load_after=$(bench_loadavg)

# PSNR of each picture (last run, each thread count gives the same picture) against ours --full.
psnr="$images/psnr.tsv"
: >"$psnr"
for scene in $scenes; do
  threads=${threads_list%% *}
  reference="$images/$scene-full-$threads.png"
  [[ -f "$reference" ]] || continue
  for program in $(programs); do
    picture="$images/$scene-$program-$threads.png"
    [[ $program != full && -f "$picture" ]] || continue
    value=$("$lattice" diff "$reference" "$picture" | awk '$1 == "PSNR" { print $2 == "inf" ? "inf" : $2 }')
    printf '%s\t%s\t%s\n' "$scene" "$program" "$value" >>"$psnr"
  done
done

report() {
  echo "Measured $started by \`bench/peers.sh --runs $runs\`: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//');"
  echo "load average before $load_before, after $load_after."
  echo "$(povray --version 2>&1 | grep -m1 'POV-Ray' || echo 'POV-Ray: not installed'); Embree $(dpkg-query -W -f='${Version}' libembree-dev 2>/dev/null || echo '(not installed)')."
  echo
  python3 "$here/peers_table.py" "$raw" "$psnr" "$notes"
}

bench_write "$out" report
