#!/usr/bin/env bash
# Peak resident memory of Plate 7 at f_lat 2 (docs/memory.md, "Plate 7"):
# scenes/fuzzy-sphere-5000.toml with `oversample = 2`, `form = "compressed"`
# and its table cached in a .lht file (written by a first run, then read),
# rendered at 512x512 on one thread through the Tek 4125 driver into a stream
# file, quantizer mode passes, no dither, the small histogram: the board's
# lowest-memory way to render it. The target is 8 MiB (8192 KiB).
#   bench/plate7-memory.sh [--lattice BIN] [--before BIN] [--runs N] [--mappings] [--out FILE]
# --lattice: the binary measured (default build-static/app/lattice, the static
# build bench/memory.sh configures; build it with that script or
# `cmake -S . -B build-static -DLATTICE_STATIC=ON ...`). --before: a second
# binary, measured alternately with the first (before, after, before, ...) so
# a change of the machine's state hits both alike. Prints each binary's
# "Maximum resident set size" (/usr/bin/time) for every run, the median and
# range, and whether every stream of both binaries is the same file (cmp).
# --mappings: then, for each binary, one more run sampled by
# bench/peak_mappings.py: its mappings at the sampled peak (the executable's
# code and read-only data apart from the heap and the other anonymous memory).
# The page cache's folio sizes make a binary's code pages count differently
# by a few hundred KiB from copy to copy, so both binaries are copied into
# the work folder the same way before they run.
set -euo pipefail

source "$(dirname "$0")/lib.sh"
lattice="$root/build-static/app/lattice"
before=""
runs=5
out=""
mappings=0
bench_parse --lattice=lattice --before=before --runs=runs --mappings:mappings=1 --out=out -- "$@"
bench_positive --runs "$runs"
bench_need_time
[[ -x $lattice ]] || bench_die "no lattice binary at $lattice (give --lattice BIN; bench/memory.sh builds build-static/)"
[[ -z $before || -x $before ]] || bench_die "no lattice binary at $before (--before)"
bench_workdir work

# The scene at f_lat 2, compressed, with its table cached beside it.
sed -E 's/^oversample *= *[0-9.]+/oversample = 2\nform = "compressed"\ncache = "hair.lht"/' \
  "$root/scenes/fuzzy-sphere-5000.toml" >"$work/plate7.toml"
grep -q '^cache = "hair.lht"' "$work/plate7.toml" || bench_die "the scene has no 'oversample =' line" 3
args=(--device tek4125 --width 512 --height 512 --threads 1 --mode passes --dither none --histogram small --quiet)

names=(after)
cp "$lattice" "$work/after"
if [[ -n $before ]]; then
  names=(before after)
  cp "$before" "$work/before"
fi
"$work/${names[0]}" render "$work/plate7.toml" "${args[@]}" --stream "$work/first.tek" 2>/dev/null  # writes the cache

measure() {  # name run -> max RSS in KiB; the stream must be the first one
  /usr/bin/time -f '%M' "$work/$1" render "$work/plate7.toml" "${args[@]}" --stream "$work/$1.tek" \
    2>"$work/time" >/dev/null || { cat "$work/time" >&2; bench_die "$1 failed" 4; }
  cmp -s "$work/first.tek" "$work/$1.tek" || bench_die "$1 wrote a different stream" 5
  tail -n 1 "$work/time"
}

run() {
  echo "plate7-memory.sh: Plate 7 at f_lat 2, compressed, cached, 512x512 -> Tek 4125 stream, passes, small histogram, 1 thread"
  echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), load $(bench_loadavg)"
  declare -A kib=()
  local r name
  for ((r = 1; r <= runs; ++r)); do
    for name in "${names[@]}"; do kib[$name]+="$(measure "$name") "; done
  done
  echo "| binary | runs (KiB) | median | range | against 8 MiB |"
  echo "|---|---|---:|---|---:|"
  local n median range
  for n in "${names[@]}"; do
    # shellcheck disable=SC2086 # the runs are words
    median=$(bench_median ${kib[$n]})
    # shellcheck disable=SC2086
    range=$(bench_range ${kib[$n]})
    printf '| %s | %s| %s | %s | %+d |\n' "$n" "${kib[$n]}" "$median" "$range" "$((${median%.*} - 8192))"
  done
  echo "every stream the same file: yes"
  if ((mappings)); then
    for n in "${names[@]}"; do
      echo "$n, mappings at the sampled peak:"
      python3 "$root/bench/peak_mappings.py" "$work/$n" render "$work/plate7.toml" "${args[@]}" --stream "$work/$n.tek"
    done
  fi
  echo "# load at the end $(bench_loadavg)"
}

bench_write "$out" run
