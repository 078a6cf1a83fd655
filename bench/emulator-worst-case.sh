#!/usr/bin/env bash
# Worst-case streams for the emulators (docs/limits.md): each generated
# stream is 1 MB (10^6 bytes) of the command that asks for the most drawing
# per byte, decoded by `lattice emulate`; prints wall seconds, peak resident
# memory (/usr/bin/time) and the exit code. Target: every 1 MB stream in
# under 5 s. Streams past the drawing budget (kPixelWorkBudget) exit 3;
# the others exit 0.
#   bench/emulator-worst-case.sh [--build DIR] [--bytes N]
# Cases (Tek 4125 unless named 4027):
#   rr-fill        ESC RR full-screen rectangle fills, 14 bytes each
#   page-clear     ESC FF, 2 bytes each
#   gs-vectors     GS mode, 2-byte moves between y=0 and y=3968: 1240-pixel vectors
#   lg-vectors     ESC LG corner to corner
#   panel-fill     LP + 3 LG + LE full-screen panels
#   panel-points   panels of 65,536 points (the decoder's cap) over the whole screen
#   raster         RU 1 bit per pixel + one RP of 65,535 pixels after another
#   random         10^6 random bytes (seeded)
#   4027-erase     !ERA G, 7 bytes each
#   4027-vectors   !RVE with 4096 arguments of full-screen diagonals
#   4027-random    10^6 random bytes (seeded)
set -euo pipefail

source "$(dirname "$0")/lib.sh"
build="$root/build"
bytes=1000000
bench_parse --build=build --bytes=bytes -- "$@"
lattice="$build/app/lattice"
bench_need_built "$build" lattice
bench_need_time
bench_workdir work

python3 - "$work" "$bytes" <<'PY'
import random, sys
out, size = sys.argv[1], int(sys.argv[2])
ESC, GS = b"\x1b", b"\x1d"

def tint(v):  # Tek 4100 integer parameter
    m = abs(v); b = b""
    hi1, hi2 = m >> 10, (m >> 4) & 63
    if hi1: b += bytes([0x40 | hi1])
    if hi1 or hi2: b += bytes([0x40 | hi2])
    return b + bytes([0x20 | (m & 15) | (0x10 if v >= 0 else 0)])

def xy(x, y):  # full five-byte form
    return bytes([0x20 | (y >> 7), 0x60 | (y & 3) << 2 | (x & 3), 0x60 | ((y >> 2) & 31), 0x20 | (x >> 7), 0x40 | ((x >> 2) & 31)])

def fill(name, head, unit, tail=b""):
    body = head
    while len(body) + len(unit) + len(tail) <= size: body += unit
    open(f"{out}/{name}", "wb").write(body + tail)

fill("rr-fill", b"", ESC + b"RR" + xy(0, 0) + xy(4095, 4095) + tint(1))
fill("page-clear", b"", ESC + b"\x0c")
fill("gs-vectors", GS + xy(0, 0), bytes([0x20 | 31, 0x40]) + bytes([0x20, 0x40]))
fill("lg-vectors", b"", ESC + b"LG" + xy(0, 0) + ESC + b"LG" + xy(4095, 3276))
fill("panel-fill", b"", ESC + b"LP" + xy(0, 0) + tint(0) + ESC + b"LG" + xy(4095, 0) + ESC + b"LG" + xy(4095, 3276)
     + ESC + b"LG" + xy(0, 3276) + ESC + b"LE")
points = b"".join(ESC + b"LG" + xy((i * 37) % 4096, 0 if i % 2 else 3276) for i in range(65535))
fill("panel-points", b"", ESC + b"LP" + xy(0, 0) + tint(0) + points + ESC + b"LE")
fill("raster", ESC + b"RU" + tint(0) + tint(11) + tint(1), ESC + b"RP" + tint(65535) + tint(10923) + b"\x5f" * 10923)
rng = random.Random(1988)
open(f"{out}/random", "wb").write(bytes(rng.getrandbits(8) for _ in range(size)))
fill("4027-erase", b"", b"!ERA G\r")
fill("4027-vectors", b"!VEC 0 0\r", b"!RVE " + b" ".join([b"639 479 -639 -479"] * 1024) + b"\r")
open(f"{out}/4027-random", "wb").write(bytes(rng.getrandbits(8) for _ in range(size)))
PY

printf '%-14s %10s %9s %11s %5s\n' case bytes seconds peak_KiB exit
for f in rr-fill page-clear gs-vectors lg-vectors panel-fill panel-points raster random 4027-erase 4027-vectors 4027-random; do
  device=tek4125
  [[ $f == 4027-* ]] && device=tek4027
  set +e
  /usr/bin/time -f '%e %M' -o "$work/time" "$lattice" emulate --device $device "$work/$f" -o "$work/out.png" \
    >/dev/null 2>"$work/stderr"
  code=$?
  set -e
  read -r seconds peak < <(tail -n 1 "$work/time")
  printf '%-14s %10s %9s %11s %5s\n' "$f" "$(stat -c %s "$work/$f")" "$seconds" "$peak" "$code"
done
echo "load average: $(bench_loadavg)"
