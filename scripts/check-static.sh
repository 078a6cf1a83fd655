#!/usr/bin/env bash
# The static "firmware" build (-DLATTICE_STATIC=ON, docs/memory.md) must work
# and draw exactly what the ordinary build draws. Builds `lattice` statically
# in build-static/, checks it has no shared-library dependencies, and compares
# its Tek 4125 stream and --memory-budget run against build/app/lattice.
#   scripts/check-static.sh        (after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
dynamic=build/app/lattice
[[ -x $dynamic ]] || { echo "check-static.sh: $dynamic is missing; run scripts/build.sh first" >&2; exit 2; }
source scripts/cmake-args.sh
lattice_cmake_args build-static
cmake -S . -B build-static "${cmake_args[@]}" -DCMAKE_BUILD_TYPE=Release -DLATTICE_WERROR=ON -DLATTICE_STATIC=ON \
  -DLATTICE_BUILD_TESTS=OFF -DLATTICE_BUILD_BENCH=OFF >/dev/null
cmake --build build-static -j "$(nproc)" --target lattice
static=build-static/app/lattice
if ldd "$static" >/dev/null 2>&1; then
  echo "check-static.sh: $static is dynamically linked:" >&2
  ldd "$static" >&2
  exit 1
fi
# The code a render runs sits together (app/CMakeLists.txt links with lld and
# app/hot-code.order; docs/memory.md, "Code pages"): the listed functions span
# at most 1.5 times their own bytes (1.2 linked so, 3.7 without the order).
if command -v ld.lld >/dev/null; then
  nm --defined-only -S -t d "$static" | awk -v bin="$static" 'NR == FNR { if ($0 !~ /^#/ && NF) want[$1] = 1; next }
    NF == 4 && ($4 in want) && !seen[$4]++ { a = $1 + 0; s = $2 + 0; sum += s; if (n++ == 0 || a < lo) lo = a; if (a + s > hi) hi = a + s }
    END { printf "check-static.sh: %d hot functions, %d bytes, spanning %d bytes of %s\n", n, sum, hi - lo, bin
          if (n == 0 || hi - lo > 1.5 * sum) { print "check-static.sh: the hot code is scattered; is app/hot-code.order passed to lld?"; exit 1 } }' \
    app/hot-code.order - || exit 1
else
  echo "check-static.sh: ld.lld is missing, so the hot code is not grouped and not checked (scripts/setup.sh installs lld)"
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(render "$root/scenes/hook.toml" --device tek4125 --width 256 --height 256 --quiet)
"$dynamic" "${args[@]}" --stream "$work/dynamic.tek" 2>/dev/null
"$static" "${args[@]}" --stream "$work/static.tek" --memory-budget 8MiB 2>"$work/log" ||
  { cat "$work/log" >&2; echo "check-static.sh: the static build failed within 8 MiB" >&2; exit 1; }
cmp "$work/dynamic.tek" "$work/static.tek" ||
  { echo "check-static.sh: the static and dynamic builds wrote different streams" >&2; exit 1; }
echo "check-static.sh: static lattice OK ($(grep -o 'peak resident memory .*' "$work/log"); stream identical)"
