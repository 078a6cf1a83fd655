#!/usr/bin/env bash
# The LHT built on demand against the precomputed one (thesis sec. 5.2.2;
# docs/lattices.md, "The LHT built on demand"), one command:
#   bench/lht-on-demand.sh [--build DIR] [--runs N (3)] [--flat "1 2 3 4"] [--threads T (2)] [--out DIR]
# For Plates 6 and 7 (scenes/fuzzy-sphere-1000 and -5000.toml) at each f_lat,
# with no cache (the precomputed table is rasterized in the process, as a
# first render would), N runs of each form alternating:
# - time to first pixel: a 1 x 1 render (load, table, one ray), wall seconds;
# - total: the 512 x 512 render, wall and CPU (user + system) seconds;
# - peak RSS (/usr/bin/time), largest of the runs;
# - entries: the precomputed table's entries against the hits the on-demand
#   table stored (and its misses), from `--lht-stats`.
# Medians; the load average is printed before and after (the machine may be
# shared; alternating keeps both forms under the same load). The pictures of
# the two forms are compared byte for byte.
set -euo pipefail

source "$(dirname "$0")/lib.sh"
build="$root/build"
runs=3
flats="1 2 3 4"
threads=2
out=""
bench_parse --build=build --runs=runs --flat=flats --threads=threads --out=out -- "$@"
lattice="$build/app/lattice"
bench_need_built "$build" lattice
bench_need_time
out=${out:-$build/lht-on-demand}
mkdir -p "$out"

echo "load average before: $(bench_loadavg); $runs runs alternating, --threads $threads"
echo
echo "| plate | f_lat | form | first pixel wall s | total wall s | total CPU s | peak RSS KiB | entries |"
echo "|---|---:|---|---:|---:|---:|---:|---|"
for plate in "6 fuzzy-sphere-1000" "7 fuzzy-sphere-5000"; do
  set -- $plate
  number=$1 scene=$2
  for f in $flats; do
    copy="$out/$scene-f$f.toml"
    sed -E "s/^oversample *= *[0-9.]+/oversample = $f/" "$root/scenes/$scene.toml" >"$copy"
    for form in hashed on-demand; do : >"$out/$scene-f$f-$form.first"; : >"$out/$scene-f$f-$form.total"; done
    for ((r = 0; r < runs; r++)); do
      for form in hashed on-demand; do
        /usr/bin/time -f "%e %U %S %M" -a -o "$out/$scene-f$f-$form.first" "$lattice" render "$copy" --quiet \
          --threads "$threads" --lht-form "$form" --width 1 --height 1 -o "$out/first.png" 2>/dev/null
        /usr/bin/time -f "%e %U %S %M" -a -o "$out/$scene-f$f-$form.total" "$lattice" render "$copy" --quiet \
          --threads "$threads" --lht-form "$form" -o "$out/$scene-f$f-$form.png" 2>/dev/null
      done
    done
    "$lattice" render "$copy" --quiet --threads "$threads" --lht-stats -o "$out/stats.png" 2>"$out/$scene-f$f-hashed.log"
    "$lattice" render "$copy" --quiet --threads "$threads" --lht-form on-demand --lht-stats -o "$out/stats.png" \
      2>"$out/$scene-f$f-on-demand.log"
    cmp -s "$out/$scene-f$f-hashed.png" "$out/$scene-f$f-on-demand.png" ||
      { echo "lht-on-demand.sh: $scene f_lat $f: the on-demand picture differs from the precomputed one" >&2; exit 1; }
    for form in hashed on-demand; do
      python3 - "$number" "$f" "$form" "$out/$scene-f$f-$form" <<'PY'
import re, statistics, sys
plate, flat, form, base = sys.argv[1:]
rows = lambda ext: [l.split() for l in open(f"{base}.{ext}") if l.strip()]
first = statistics.median(float(r[0]) for r in rows("first"))
total = rows("total")
wall = statistics.median(float(r[0]) for r in total)
cpu = statistics.median(float(r[1]) + float(r[2]) for r in total)
peak = max(int(r[3]) for r in total)
log = open(f"{base}.log").read()
if form == "hashed":
    entries = re.search(r"entries referenced: \d+ of (\d+)", log).group(1) + " precomputed"
else:
    hits, misses = re.search(r"built on demand: (\d+) hits and (\d+) misses", log).groups()
    entries = f"{hits} hits + {misses} misses built"
print(f"| {plate} | {flat} | {form} | {first:.2f} | {wall:.2f} | {cpu:.2f} | {peak} | {entries} |")
PY
    done
  done
done
echo
echo "load average after: $(bench_loadavg)"
