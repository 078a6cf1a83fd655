#!/usr/bin/env bash
# How much of each lattice's table a render touches (thesis sec. 5.2.1-5.2.2;
# docs/lattices.md, "How much of the table a render touches"), one command:
#   bench/lht-stats.sh [--build DIR] [--flat "1 2 3 4"] [--out DIR (BUILD/lht-stats)]
# For Plates 4 (scenes/thistle.toml), 6 and 7 (scenes/fuzzy-sphere-1000 and
# -5000.toml) at each f_lat it renders a copy of the scene with `oversample`
# set and the table cached in OUT (Plates 6 and 7 share the hair's caches), with
# `lattice render --lht-stats`, and prints one markdown table row per render:
# look-ups, hits, misses, distinct (p_i, p_o) asked, entries, entries
# referenced (share of the entries and, weighted as eq. 1.3 counts, of N_iz),
# and look-ups per entry. The counts do not depend on the thread count
# (tests/lht/lookup_stats_test.cpp), so the renders use every core.
set -euo pipefail

source "$(dirname "$0")/lib.sh"
build="$root/build"
flats="1 2 3 4"
out=""
bench_parse --build=build --flat=flats --out=out -- "$@"
lattice="$build/app/lattice"
bench_need_built "$build" lattice
out=${out:-$build/lht-stats}
mkdir -p "$out"

echo "| plate | f_lat | look-ups | hits | misses | distinct pairs asked | entries | entries referenced | share of N_iz | look-ups per entry |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for plate in "4 thistle" "6 fuzzy-sphere-1000" "7 fuzzy-sphere-5000"; do
  set -- $plate
  number=$1 scene=$2
  cache=$([[ $scene == thistle ]] && echo thistle || echo hair)
  for f in $flats; do
    copy="$out/$scene-f$f.toml"
    sed -E "s/^oversample *= *[0-9.]+/oversample = $f\ncache = \"$cache-f$f.lht\"/" "$root/scenes/$scene.toml" >"$copy"
    grep -q "^oversample = $f" "$copy" || { echo "lht-stats.sh: scenes/$scene.toml has no 'oversample =' line" >&2; exit 3; }
    "$lattice" render "$copy" --quiet --lht-stats -o "$out/$scene-f$f.png" 2>"$out/$scene-f$f.log"
    python3 - "$number" "$f" "$out/$scene-f$f.log" <<'PY'
import re, sys
plate, flat, log = sys.argv[1], sys.argv[2], open(sys.argv[3]).read()
num = lambda pattern: re.search(pattern, log).group(1)
lookups, hits, misses = num(r"(\d+) look-ups,"), num(r"(\d+) hits,"), num(r"(\d+) misses")
distinct = num(r"distinct \(p_i, p_o\) asked: (\d+)")
ref, entries, refShare = re.search(r"entries referenced: (\d+) of (\d+) \(([\d.]+) %\)", log).groups()
nizShare, niz = re.search(r"([\d.]+) % of N_iz = (\d+)", log).groups()
perEntry = num(r"look-ups per entry: ([\d.]+)")
print(f"| {plate} | {flat} | {lookups} | {hits} | {misses} | {distinct} | {entries} | {ref} ({refShare} %) | {nizShare} % of {niz} | {perEntry} |")
PY
  done
done
