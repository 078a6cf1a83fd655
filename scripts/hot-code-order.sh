#!/usr/bin/env bash
# Writes app/hot-code.order, the functions a low-memory render executes,
# which the static build's linker lays out side by side
# (app/CMakeLists.txt, lld's --symbol-ordering-file; docs/memory.md, "Code
# pages"). Why: a static executable's code pages count in its resident set,
# and the kernel maps 64 KiB of the file around each page a fault touches, so
# 860 KB of executed code scattered over 3.9 MB of text kept 3.7 MiB of it
# resident; laid out together it is about 1.3 MiB.
#   scripts/hot-code-order.sh [--lattice BIN] [--out FILE]
# --lattice: a static lattice (default build-static/app/lattice; its symbol
# table names what ran). Method: each command line below runs under
# valgrind's callgrind with --dump-instr=yes; every executed instruction's
# address is mapped to the function holding it (nm). The functions of the
# command line docs/memory.md measures come first (Plate 7 at f_lat 2, its
# table read from its cache, Tek 4125 stream, passes, small histogram), so
# that run's code is one block; then those only the run that rasterized the
# table executed, then those only a PNG render on two threads in frame mode
# did; within each group by the instructions they executed, most first. The
# pictures are 128x128: a smaller picture runs the same code.
# Re-run after changes to what a render calls; a name that no longer exists is
# skipped by the linker, and a new function left out only costs its pages.
# Needs valgrind and python3 (scripts/setup.sh --bench).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
lattice=build-static/app/lattice
out=app/hot-code.order
while (($#)); do
  case $1 in
    --lattice) lattice=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h | --help) sed -n '2,${/^#/!q;p}' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "hot-code-order.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done
for program in valgrind python3 nm; do
  command -v "$program" >/dev/null || { echo "hot-code-order.sh: $program is missing (scripts/setup.sh --bench)" >&2; exit 2; }
done
[[ -x $lattice ]] || { echo "hot-code-order.sh: no lattice at $lattice (give --lattice BIN)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

sed -E 's/^oversample *= *[0-9.]+/oversample = 2\nform = "compressed"\ncache = "hair.lht"/' \
  scenes/fuzzy-sphere-5000.toml >"$work/plate7.toml"
low=(--device tek4125 --width 128 --height 128 --threads 1 --mode passes --dither none --histogram small --quiet)
lattice=$(realpath "$lattice")
# Run in this order (the first writes the cache the second reads); ranked
# by the profile numbers: the cached run is 1. Run in $work, one with
# relative paths and one with absolute ones (a relative path asks for the
# current directory). The cached run's stream exists already, as in the
# benchmark's repeated runs (an existing output is checked for write access).
: >"$work/cached.tek"
runs=(
  "2:render $work/plate7.toml ${low[*]} --stream $work/raster.tek"
  "1:render plate7.toml ${low[*]} --stream cached.tek"
  "3:render $root/scenes/fuzzy-sphere-1000.toml --width 128 --height 128 --threads 2 --quiet -o $work/plate6.png"
)
for entry in "${runs[@]}"; do
  n=${entry%%:*}
  run=${entry#*:}
  echo "hot-code-order.sh: callgrind: lattice $run" >&2
  # shellcheck disable=SC2086 # a run is words
  (cd "$work" && valgrind -q --tool=callgrind --dump-instr=yes --compress-pos=no --compress-strings=no \
    --callgrind-out-file="$work/profile.$n" "$lattice" $run 2>/dev/null)
done

nm --defined-only -S "$lattice" >"$work/symbols"
python3 - "$work/symbols" "$work"/profile.1 "$work"/profile.2 "$work"/profile.3 >"$work/order" <<'EOF'
# Executed instructions (callgrind's "0xADDR LINE Ir" lines, not the call
# sites' inclusive costs) summed by the text symbol holding them; a function
# ranks by the first profile (in the order given) that executed it, then by
# that sum. glibc picks a string function's variant by the CPU (IFUNC), and
# valgrind's CPU is not the machine's: each variant that ran brings every
# variant of its function along, next to it.
import bisect, re, sys
symbols = []
for line in open(sys.argv[1]):
    fields = line.split()
    if len(fields) == 4 and fields[2] in "tTwW":
        symbols.append((int(fields[0], 16), int(fields[1], 16), fields[3]))
    elif len(fields) == 3 and fields[1] in "tT":  # no size (start-up code): up to the next symbol
        symbols.append((int(fields[0], 16), 0, fields[2]))
symbols.sort()
for i, (start, size, name) in enumerate(symbols):
    if size == 0 and i + 1 < len(symbols):
        symbols[i] = (start, symbols[i + 1][0] - start, name)
variant = re.compile(r"^(__\w+?)_(sse2|ssse3|sse4_1|sse4_2|sse42|avx|avx2|evex|evex512|avx512)")
variants = {}
for _, _, name in symbols:
    match = variant.match(name)
    if match:
        variants.setdefault(match.group(1), []).append(name)
starts = [s[0] for s in symbols]
cost = {}
first = {}
for rank, profile in enumerate(sys.argv[2:]):
    after_call = False
    for line in open(profile):
        if line.startswith("calls="):
            after_call = True  # the next line is the call site with the callee's inclusive cost
            continue
        if not line.startswith("0x") or after_call:
            after_call = False
            continue
        fields = line.split()
        address = int(fields[0], 16)
        i = bisect.bisect_right(starts, address) - 1
        if i >= 0 and address < symbols[i][0] + symbols[i][1]:
            name = symbols[i][2]
            cost[name] = cost.get(name, 0) + (int(fields[-1]) if len(fields) > 2 else 1)
            first.setdefault(name, rank)
printed = set()
for name, _ in sorted(cost.items(), key=lambda item: (first[item[0]], -item[1], item[0])):
    match = variant.match(name)
    for each in [name] + (sorted(variants[match.group(1)]) if match else []):
        if each not in printed:
            printed.add(each)
            print(each)
EOF
{
  echo "# The functions a low-memory render executes, its measured run's first: the static build's"
  echo "# linker lays them out side by side (lld --symbol-ordering-file, app/CMakeLists.txt)."
  echo "# Written by scripts/hot-code-order.sh from callgrind runs; docs/memory.md, \"Code pages\"."
  cat "$work/order"
} >"$work/hot-code.order"
mv "$work/hot-code.order" "$out"
echo "hot-code-order.sh: $(grep -vc '^#' "$out") functions -> $out" >&2
