#!/usr/bin/env bash
# The compressed LHT against the hashed one (docs/lattices.md, "The compressed
# LHT"), one command:
#   bench/lht-compressed.sh [--build DIR] [--runs N (7)] [--table1] [--before BIN] [--out DIR (BUILD/lht-compressed)]
# 1. build/bench/lht_form_bench: bytes per entry all-in (index + payload, per
#    distinct entry and per N_iz) of the scene hair at f_lat 1 and 2 (and with
#    --table1 every Table 1 row), and the median ns per look-up of each form
#    over render-like pairs, the forms alternating.
# 2. Whole renders of Plates 6 and 7 (512x512, --threads 1, tables read from
#    caches made first, one per form and f_lat): median CPU seconds (user +
#    system, /usr/bin/time) and largest peak RSS of N runs, the forms
#    alternating run by run; then the same for `--lht-stats` on, and, with
#    --before BIN (a `lattice` built without look-up statistics), that
#    binary, to show that counting costs nothing while it is off.
# The load average is printed before and after each part: the machine may be
# shared; alternating keeps every variant under the same load.
set -euo pipefail

source "$(dirname "$0")/lib.sh"
build="$root/build"
runs=7
table1=""
before=""
out=""
bench_parse --build=build --runs=runs --table1:table1=--table1 --before=before --out=out -- "$@"
lattice="$build/app/lattice"
bench="$build/bench/lht_form_bench"
bench_need_built "$build" lattice lht_form_bench
bench_need_time
bench_positive --runs "$runs"
out=${out:-$build/lht-compressed}
mkdir -p "$out"

echo "## Bytes per entry and look-up speed (lht_form_bench)"
(cd "$root" && "$bench" --runs "$runs" $table1)

echo
echo "## Whole renders, --threads 1, $runs runs alternating (load average before: $(bench_loadavg))"
echo
echo "| scene | f_lat | variant | median CPU s | peak RSS KiB |"
echo "|---|---:|---|---:|---:|"
for scene in fuzzy-sphere-1000 fuzzy-sphere-5000; do
  for f in 1 2; do
    variants=(hashed compressed stats)
    [[ -n $before ]] && variants+=(before)
    for v in "${variants[@]}"; do
      form=$([[ $v == compressed ]] && echo compressed || echo hashed)
      sed -E "s/^oversample *= *[0-9.]+/oversample = $f\nform = \"$form\"\ncache = \"hair-f$f-$form.lht\"/" \
        "$root/scenes/$scene.toml" >"$out/$scene-f$f-$v.toml"
      [[ $v == before ]] && sed -i '/^form = /d' "$out/$scene-f$f-$v.toml"
      "$lattice" render "$out/$scene-f$f-$v.toml" --quiet --width 8 --height 8 -o "$out/warm.png" 2>/dev/null
      : >"$out/$scene-f$f-$v.times"
    done
    for ((r = 0; r < runs; r++)); do
      for v in "${variants[@]}"; do
        exe=$lattice extra=()
        [[ $v == before ]] && exe=$before
        [[ $v == stats ]] && extra=(--lht-stats)
        /usr/bin/time -f "%U %S %M" -a -o "$out/$scene-f$f-$v.times" \
          "$exe" render "$out/$scene-f$f-$v.toml" --quiet --threads 1 "${extra[@]}" -o "$out/$scene-f$f-$v.png" 2>/dev/null
      done
    done
    for v in "${variants[@]}"; do
      python3 - "$scene" "$f" "$v" "$out/$scene-f$f-$v.times" <<'PY'
import statistics, sys
scene, f, v, path = sys.argv[1:]
rows = [line.split() for line in open(path) if line.strip()]
cpu = statistics.median(float(u) + float(s) for u, s, m in rows)
peak = max(int(m) for u, s, m in rows)
print(f"| {scene} | {f} | {v} | {cpu:.3f} | {peak} |")
PY
    done
    # Byte-identical pictures, every variant.
    for v in "${variants[@]}"; do cmp -s "$out/$scene-f$f-hashed.png" "$out/$scene-f$f-$v.png" ||
      { echo "lht-compressed.sh: $scene f_lat $f: the $v picture differs from the hashed one" >&2; exit 1; }; done
  done
done
echo
echo "load average after: $(bench_loadavg)"
