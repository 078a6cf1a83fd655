#!/usr/bin/env bash
# Peak resident memory of the lowest-memory mode (docs/memory.md):
# the fuzzy sphere with 1000 hairs at 512x512, single thread, through the
# Tek 4125 driver into a stream file, quantizer mode "passes" (no frame
# buffer), no emulator. The target is the Sun 3/60's 8 MiB.
#   bench/memory.sh [--build DIR] [--static-build DIR] [--runs N] [--scene FILE]
# Measures the ordinary (dynamically linked) build in --build (default build/)
# and the static "firmware" build (-DLATTICE_STATIC=ON) in --static-build
# (default build-static/, configured and built here when missing).
# Prints, for each case, the largest "Maximum resident set size" that
# /usr/bin/time -v reports over N runs, and then where that memory is: the
# resident pages of each mapping, sampled from /proc/PID/smaps while the
# render runs (code = the executable and shared libraries; data = heap,
# anonymous mappings and stacks).
# Cases, for each build:
#   floor        `lattice --help`: the process with its libraries and nothing else
#   rasterize    the hair's lattice table built in the process (no cache)
#   cached       the table read from a .lht file made beforehand (the thesis's
#                precomputed table; the rasterizer's temporaries never exist)
#   budget 8MiB  the cached case with --memory-budget 8MiB instead of --mode:
#                the plan the renderer chooses, or its refusal (exit 8)
set -euo pipefail

source "$(dirname "$0")/lib.sh"
build="$root/build"
staticBuild="$root/build-static"
runs=3
scene="$root/scenes/fuzzy-sphere-1000.toml"
bench_parse --build=build --static-build=staticBuild --runs=runs --scene=scene -- "$@"
bench_need_built "$build" lattice
if [[ ! -x $staticBuild/app/lattice ]]; then
  echo "memory.sh: building the static lattice in $staticBuild (a few minutes)" >&2
  cmake -S "$root" -B "$staticBuild" -DCMAKE_BUILD_TYPE=Release -DLATTICE_STATIC=ON -DLATTICE_BUILD_TESTS=OFF \
    -DLATTICE_BUILD_BENCH=OFF >/dev/null
  cmake --build "$staticBuild" -j "$(nproc)" --target lattice >/dev/null
fi
bench_need_time
[[ -f $scene ]] || bench_die "$scene does not exist"
bench_positive --runs "$runs"
bench_workdir work

# The same scene with its lattice table cached in $work.
sed -E 's/^oversample *= *([0-9.]+)/oversample = \1\ncache = "hair.lht"/' "$scene" >"$work/cached.toml"
grep -q '^cache = "hair.lht"' "$work/cached.toml" || { echo "memory.sh: $scene has no 'oversample =' line" >&2; exit 3; }

lowest=(--device tek4125 --width 512 --height 512 --threads 1 --mode passes --dither none --quiet)

peak() {  # command... -> the largest max RSS (KiB) of $runs runs
  local best=0 kib
  for ((i = 0; i < runs; ++i)); do
    /usr/bin/time -v "$@" >/dev/null 2>"$work/time" || { echo "memory.sh: $* failed:" >&2; cat "$work/time" >&2; exit 4; }
    kib=$(awk -F': ' '/Maximum resident set size/ { print $2 }' "$work/time")
    ((kib > best)) && best=$kib
  done
  echo "$best"
}

# Where the peak is: resident KiB per mapping at the sampled maximum.
breakdown() {
  python3 "$root/bench/peak_mappings.py" "$@"
}

report() {  # label kib
  awk -v l="$1" -v k="$2" 'BEGIN { printf "%-10s %6d KiB = %5.2f MiB  (%+d KiB against 8 MiB)\n", l, k, k / 1024, k - 8192 }'
}

measure() {  # label lattice-binary
  local label=$1 lattice=$2
  echo "== $label: $lattice"
  report floor "$(peak "$lattice" --help)"
  report rasterize "$(peak "$lattice" render "$scene" "${lowest[@]}" --stream "$work/a.tek")"
  breakdown "$lattice" render "$scene" "${lowest[@]}" --stream "$work/a.tek"
  rm -f "$work/hair.lht"
  "$lattice" render "$work/cached.toml" "${lowest[@]}" --stream "$work/b.tek" 2>/dev/null  # writes the cache
  report cached "$(peak "$lattice" render "$work/cached.toml" "${lowest[@]}" --stream "$work/b.tek")"
  breakdown "$lattice" render "$work/cached.toml" "${lowest[@]}" --stream "$work/b.tek"
  cmp -s "$work/a.tek" "$work/b.tek" || { echo "memory.sh: the cached table gave a different stream" >&2; exit 5; }
  # The budget chooses the mode itself; exit 8 is its refusal, reported, not a failure of this script.
  local budgetArgs=(--device tek4125 --width 512 --height 512 --threads 1 --dither none --quiet --memory-budget 8MiB)
  local status=0
  /usr/bin/time -v "$lattice" render "$work/cached.toml" "${budgetArgs[@]}" --stream "$work/c.tek" \
    >/dev/null 2>"$work/budget" || status=$?
  grep -E "memory plan|peak resident|error" "$work/budget" | sed 's/^/    /'
  if ((status == 0)); then
    report "budget 8M" "$(awk -F': ' '/Maximum resident set size/ { print $2 }' "$work/budget")"
    cmp -s "$work/a.tek" "$work/c.tek" || { echo "memory.sh: the budgeted render gave a different stream" >&2; exit 5; }
  else
    echo "budget 8M  refused (exit $status)"
  fi
  echo "table: $("$lattice" lht-info "$work/hair.lht" | awk '/^table bytes:/ { print $3 }') bytes in the hash table"
}

echo "memory.sh: $(basename "$scene") at 512x512 -> Tek 4125 stream file, mode passes, 1 thread; max of $runs runs"
measure "dynamic build" "$build/app/lattice"
measure "static build" "$staticBuild/app/lattice"
