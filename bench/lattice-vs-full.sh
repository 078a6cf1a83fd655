#!/usr/bin/env bash
# Where lattices still win: every example scene with lattices rendered in
# lattice mode and with --full (each lattice replaced by its exact CSG
# object), whole process, side by side (docs/gallery.md, "Where the lattice
# wins").
#   bench/lattice-vs-full.sh [--runs N] [--threads T] [--size WxH] [--out FILE]
# Method: each case is a scene (and flags); a case is timed as `lattice render
# SCENE -o x.png -q` three ways, in turn within each round so drift hits all
# alike: lattice mode with its table built in the run (what a first render
# costs), lattice mode with its table read from a .lht cache (a copy of the
# scene with `cache = ...` added to each [[lattices]]: what every later render
# costs), and --full. Reported: the median CPU seconds (user + sys, the
# work done, which a loaded machine disturbs less than the wall clock) of
# each over RUNS rounds, the ratios cached/full and built/full (below 1: the
# lattice is faster), and the median wall seconds of the cached and full runs. The hair variants swap the Plate 6 hair's object (a polyline: CSG
# of 10 spheres and 9 cylinders) for a capsule (one closed-form leaf, the
# thistle's), so the CSG and the closed-form hair are both measured.
# A second table times the trace alone (bench/render_bench's lattice-vs-full
# part: scene set-up apart, median of RUNS renders, ratio = full / lattice, so
# above 1 the lattice is faster), where start-up and quantizing, the same for
# both, do not dilute the ratio.
# Options: --runs N (default 3), --threads T (default 1), --size WxH (default:
# the scenes' own), --out FILE (also write the table there).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
runs=3 threads=1 size="" out=""
bench_parse --runs=runs --threads=threads --size=size --out=out -- "$@"
bench_positive --runs "$runs"
bench_positive --threads "$threads"
size_args=()
if [[ -n $size ]]; then bench_size "$size"; size_args=("${bench_size_args[@]}"); fi
cd "$root"
bench_need_built build lattice render_bench
lattice=$root/build/app/lattice
bench_workdir work

# A copy of scene $1 with a cache file for every [[lattices]] entry, in $2.
cached_copy() {
  awk -v dir="$work" '{ print } /^\[\[lattices\]\]/ { n++; print "cache = \"" dir "/" FILENAME_BASE "-" n ".lht\"" }' \
    FILENAME_BASE="$(basename "$1" .toml)" "$1" >"$2"
}
# Plate 6 with capsule hairs of the polyline's length and radius.
capsule_hair() {
  sed -E 's|^object = \{ type = "polyline", radius = 0.006, points = .*$|object = { type = "capsule", radius = 0.006, length = 0.2 }|' \
    scenes/fuzzy-sphere-1000.toml >"$1"
}

# case name | scene | extra flags
capsule_hair "$work/fuzzy-1000-capsule.toml"
sed 's/^shadows = true .*/shadows = false/' scenes/thistle.toml >"$work/thistle-plate3.toml"
cases=(
  "hook (Figure 2)|scenes/hook.toml|"
  "thistle, Plate 4|scenes/thistle.toml|"
  "thistle, Plate 3|scenes/thistle.toml|--no-lattice-shadows"
  "Plate 6, CSG hair|scenes/fuzzy-sphere-1000.toml|"
  "Plate 6, capsule hair|$work/fuzzy-1000-capsule.toml|"
  "Plate 7, CSG hair|scenes/fuzzy-sphere-5000.toml|"
)

seconds() { # "cpu wall" seconds of one render
  /usr/bin/time -f '%U %S %e' -o "$work/t" "$lattice" render "$@" "${size_args[@]}" --threads "$threads" -q \
    -o "$work/x.png" >/dev/null 2>&1 || bench_die "render failed: $*" 1
  awk '{ printf "%.2f %.2f\n", $1 + $2, $3 }' "$work/t"
}

report() {
  echo "# lattice mode against --full, whole process, CPU s (user+sys) and wall s, median of $runs; $threads thread(s)"
  echo "# $(nproc) cores, load average $(bench_loadavg) at start, $(date -u +%Y-%m-%dT%H:%MZ)"
  printf '%-24s %9s %9s %9s %12s %11s %12s %10s\n' case built_cpu cached_cpu full_cpu cached/full built/full cached_wall full_wall
  local entry name scene flags
  for entry in "${cases[@]}"; do
    IFS='|' read -r name scene flags <<<"$entry"
    local -a extra=()
    [[ -n $flags ]] && read -r -a extra <<<"$flags"
    local copy="$work/cached-$(basename "$scene")"
    cached_copy "$scene" "$copy"
    rm -f "$work"/*.lht
    seconds "$copy" "${extra[@]}" >/dev/null  # writes the cache
    local -a built=() cached=() full=() cachedWall=() fullWall=()
    local cpu wall
    for ((r = 0; r < runs; r++)); do
      read -r cpu wall <<<"$(seconds "$scene" "${extra[@]}")"
      built+=("$cpu")
      read -r cpu wall <<<"$(seconds "$copy" "${extra[@]}")"
      cached+=("$cpu") cachedWall+=("$wall")
      read -r cpu wall <<<"$(seconds "$scene" "${extra[@]}" --full)"
      full+=("$cpu") fullWall+=("$wall")
    done
    local b c f
    b=$(bench_median "${built[@]}") c=$(bench_median "${cached[@]}") f=$(bench_median "${full[@]}")
    printf '%-24s %9s %9s %9s %12s %11s %12s %10s\n' "$name" "$b" "$c" "$f" \
      "$(awk -v a="$c" -v b="$f" 'BEGIN { printf "%.2f", a / b }')" \
      "$(awk -v a="$b" -v b="$f" 'BEGIN { printf "%.2f", a / b }')" \
      "$(bench_median "${cachedWall[@]}")" "$(bench_median "${fullWall[@]}")"
  done
  echo
  echo "# the trace alone: render_bench, $threads thread(s)"
  "$root/build/bench/render_bench" --runs "$runs" --threads-list "$threads" --arith double --full-size "${bench_width:-512}" \
    --full-threads "$threads" --full-scene scenes/hook.toml --full-scene scenes/thistle.toml \
    --full-scene "$work/thistle-plate3.toml" --full-scene scenes/fuzzy-sphere-1000.toml \
    --full-scene "$work/fuzzy-1000-capsule.toml" --full-scene scenes/fuzzy-sphere-5000.toml scenes/hook.toml |
    sed -n '/^# lattice vs full/,$p'
  echo "# load average $(bench_loadavg) at end"
}
bench_write "$out" report
