#!/usr/bin/env bash
# Tek 4014 streams of long vectors (docs/limits.md, "Worst-case 1 MB emulator
# streams"): each generated stream is 1 MB (10^6 bytes) of graph-mode (GS)
# vectors in 12-bit addresses, decoded by `lattice emulate --device tek4014`
# with bits=12 (the 4096x3120 screen) and with bits=10 (the same stream on the
# 1024x780 screen, a quarter the pixels a vector). Prints, for each stream and
# screen, the median wall seconds of N runs, their range, the median CPU
# seconds (user + system), the peak resident memory and the exit code.
# Target: every 1 MB stream in under 5 s. A stream past the drawing budget
# (kPixelWorkBudget) exits 3; the others exit 0.
#   bench/tek4014-vectors.sh [--build DIR] [--lattice BINARY] [--bytes N] [--runs N]
# --lattice times another binary (an older build, for a before/after).
# Streams:
#   gs-2byte      vertical vectors at x = 0 between y = 0 and y = 3968, two
#                 bytes each (Hi Y, Lo X): at 12 bits, 3,120 pixels for two
#                 bytes, past the budget
#   vertical      five-byte addresses (Hi Y, extra, Lo Y, Hi X, Lo X):
#                 (x, 0) to (x, 3119) and back, x one unit further each time
#   horizontal    (0, y) to (4095, y) and back, y one unit further each time
#   diagonal      corner to corner, (0, 0) to (4095, 3119) and back
#   diagonal-45   (0, 0) to (3119, 3119) and back: all steps diagonal
#   slope-half    (0, 0) to (4095, 2047) and back: straight and diagonal steps
#                 alternate, the shortest runs (two pixels) the emulator draws
#   random        seeded random addresses over the 12-bit screen
set -euo pipefail

source "$(dirname "$0")/lib.sh"
build="$root/build"
lattice=""
bytes=1000000
runs=3
bench_parse --build=build --lattice=lattice --bytes=bytes --runs=runs -- "$@"
bench_positive --bytes "$bytes"
bench_positive --runs "$runs"
if [[ -z $lattice ]]; then
  bench_need_built "$build" lattice
  lattice="$build/app/lattice"
fi
[[ -x $lattice ]] || bench_die "$lattice is not an executable"
bench_need_time
bench_workdir work

python3 - "$work" "$bytes" <<'PY'
import random, sys
out, size = sys.argv[1], int(sys.argv[2])
GS = b"\x1d"

def xy(x, y):  # a 12-bit address, all five bytes
    return bytes([0x20 | (y >> 7), 0x60 | (y & 3) << 2 | (x & 3), 0x60 | ((y >> 2) & 31),
                  0x20 | (x >> 7), 0x40 | ((x >> 2) & 31)])

def write(name, body, units):
    body = bytearray(body)
    for unit in units:
        if len(body) + len(unit) > size: break
        body += unit
    open(f"{out}/{name}", "wb").write(body)

n = size // 5 + 1
write("gs-2byte", GS + xy(0, 0), (bytes([0x20 | (31 if i % 2 == 0 else 0), 0x40]) for i in range(size)))
write("vertical", GS, (xy((i // 2) % 4096, 3119 * (i % 2)) for i in range(n)))
write("horizontal", GS, (xy(4095 * (i % 2), (i // 2) % 3120) for i in range(n)))
write("diagonal", GS, (xy(4095, 3119) if i % 2 else xy(0, 0) for i in range(n)))
write("diagonal-45", GS, (xy(3119, 3119) if i % 2 else xy(0, 0) for i in range(n)))
write("slope-half", GS, (xy(4095, 2047) if i % 2 else xy(0, 0) for i in range(n)))
rng = random.Random(4014)
write("random", GS, (xy(rng.randrange(4096), rng.randrange(3120)) for i in range(n)))
PY

echo "# $lattice, $runs runs each, load average at the start: $(bench_loadavg)"
printf '%-12s %5s %10s %9s %11s %9s %10s %5s\n' stream bits bytes seconds range cpu_s peak_KiB exit
for f in gs-2byte vertical horizontal diagonal diagonal-45 slope-half random; do
  for bits in 12 10; do
    walls=() cpus=()
    for ((r = 0; r < runs; r++)); do
      set +e
      /usr/bin/time -f '%e %U %S %M' -o "$work/time" \
        "$lattice" emulate --device tek4014 "$work/$f" --set bits=$bits --raw -o "$work/out.png" >/dev/null 2>"$work/stderr"
      code=$?
      set -e
      read -r wall user sys peak < <(tail -n 1 "$work/time")
      walls+=("$wall")
      cpus+=("$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')")
    done
    printf '%-12s %5s %10s %9s %11s %9s %10s %5s\n' "$f" "$bits" "$(stat -c %s "$work/$f")" \
      "$(bench_median -f %.2f "${walls[@]}")" "$(bench_range "${walls[@]}")" "$(bench_median -f %.2f "${cpus[@]}")" \
      "$peak" "$code"
  done
done
echo "load average at the end: $(bench_loadavg)"
