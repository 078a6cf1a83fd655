#!/usr/bin/env bash
# The attack table of docs/limits.md, measured: the hostile inputs of the
# readers and of the command-line surfaces (--at, numbers, the memory budget
# over rasterizing, send and show, outputs as one transaction), run against the
# Release binary under /usr/bin/time -v. Prints one Markdown row per case:
# exit code, wall seconds, peak resident memory, and the start of the message.
#   bench/hostile-input.sh [--build DIR]
# Needs python3 and GNU time (scripts/setup.sh --bench). The full-disk case
# mounts a 16 KiB tmpfs and runs only as root; it is skipped otherwise.
set -euo pipefail

source "$(dirname "$0")/lib.sh"
build="$root/build"
bench_parse --build=build -- "$@"
L="$build/app/lattice"
bench_need_built "$build" lattice
bench_need_time
w=$(mktemp -d)
cleanup() { mountpoint -q "$w/full" 2>/dev/null && umount "$w/full"; rm -rf "$w"; }
trap cleanup EXIT

# Inputs, generated here (nothing large is committed).
python3 - "$w" <<'PY'
import os, random, struct, sys, zlib
w = sys.argv[1]
def chunk(t, d): return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
def liar(wd, ht):
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", wd, ht, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", bytes.fromhex("789c630000000100 01".replace(" ", ""))) + chunk(b"IEND", b""))
open(f"{w}/liar-65535.png", "wb").write(liar(65535, 65535))
open(f"{w}/liar-20000.png", "wb").write(liar(20000, 20000))
rng = random.Random(15)
for name in ("junk.lht", "junk.png"):
    with open(f"{w}/{name}", "wb") as f:
        f.write(bytes(rng.getrandbits(8) for _ in range(4096)))
        f.truncate(1 << 30)                      # 1 GiB, sparse
open(f"{w}/random-100M", "wb").write(os.urandom(100 * 1000 * 1000))
def tint(v):
    m = abs(v); b = b""
    if m >> 10: b += bytes([0x40 | m >> 10])
    if m >> 4: b += bytes([0x40 | (m >> 4) & 63])
    return b + bytes([0x20 | (m & 15) | (0x10 if v >= 0 else 0)])
def xy(x, y): return bytes([0x20 | y >> 7, 0x60 | (y & 3) << 2 | (x & 3), 0x60 | (y >> 2) & 31, 0x20 | x >> 7, 0x40 | (x >> 2) & 31])
rr = b"\x1bRR" + xy(0, 0) + xy(4095, 4095) + tint(1)
open(f"{w}/rr-200K.tek", "wb").write(rr * (200000 // len(rr)))
open(f"{w}/rr-1M.tek", "wb").write(rr * (1000000 // len(rr)))
open(f"{w}/pilcrow.toml", "wb").write(b"\xc2\xb6")
open(f"{w}/nested.toml", "w").write("a = " + "[" * 10000 + "]" * 10000 + "\n")
open(f"{w}/nan.toml", "w").write('[[objects]]\ntype = "sphere"\nradius = nan\n')
PY
scene="$root/scenes/torus-floor.toml"
"$L" render "$scene" --width 64 --height 48 -o "$w/good.png" >/dev/null 2>&1
"$L" rasterize --shape sphere -o "$w/good.lht" >/dev/null 2>&1
head -c 1000 "$w/good.lht" > "$w/truncated.lht"
python3 -c "import sys; b=bytearray(open(sys.argv[1],'rb').read()); b[len(b)//2]^=0x40; open(sys.argv[2],'wb').write(b)" \
  "$w/good.lht" "$w/flipped.lht"
for n in 5000 10000 20000 100000 100001; do
  sed "s/^count = 5000/count = $n/" "$root/scenes/fuzzy-sphere-5000.toml" > "$w/scatter-$n.toml"
done

row() {  # row LABEL COMMAND...
  local label=$1; shift
  set +e
  /usr/bin/time -v -o "$w/time" "$@" >/dev/null 2>"$w/err"
  local code=$?
  set -e
  local secs peak message
  secs=$(awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, p, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + p[i]; printf "%.2f", s }' "$w/time")
  peak=$(awk -F': ' '/Maximum resident set size/ { printf "%.1f", $2 / 1024 }' "$w/time")
  message=$(grep -v '^Command' "$w/err" | head -n 1 | sed "s|$w/||g; s|$root/||g" | cut -c 1-110)
  printf '| %s | %s | %s | %s | %s |\n' "$label" "$code" "$secs" "$peak" "${message:-}"
}

echo "| case | exit | seconds | peak MiB | message (start) |"
echo "|---|---|---|---|---|"
row "PNG claiming 65535x65535 (66 B), quantize" "$L" quantize "$w/liar-65535.png" -o "$w/q.png"
row "same, diff" "$L" diff "$w/liar-65535.png" "$w/good.png"
row "PNG claiming 20000x20000, quantize" "$L" quantize "$w/liar-20000.png" -o "$w/q.png"
row "1 GiB junk .png, quantize" "$L" quantize "$w/junk.png" -o "$w/q.png"
row "1 GiB junk .lht, lht-info" "$L" lht-info "$w/junk.lht"
row "Tek 4125 full-screen RR fills, 200 KB" "$L" emulate --device tek4125 "$w/rr-200K.tek" -o "$w/e.png"
row "Tek 4125 full-screen RR fills, 1 MB" "$L" emulate --device tek4125 "$w/rr-1M.tek" -o "$w/e.png"
row "emulate --device tek4125 --raw /dev/zero" "$L" emulate --device tek4125 --raw /dev/zero -o "$w/e.png"
row "emulate --device tek4027 --raw /dev/zero" "$L" emulate --device tek4027 --raw /dev/zero -o "$w/e.png"
row "100 MB random bytes, tek4125" "$L" emulate --device tek4125 --raw "$w/random-100M" -o "$w/e.png"
row "100 MB random bytes, tek4027" "$L" emulate --device tek4027 --raw "$w/random-100M" -o "$w/e.png"
for n in 5000 10000 20000 100000; do
  row "lattice_scatter $n, render 1x1" "$L" render "$w/scatter-$n.toml" --width 1 --height 1 --threads 1 -o "$w/s.png"
done
row "lattice_scatter 100001" "$L" render "$w/scatter-100001.toml" --width 1 --height 1 -o "$w/s.png"
row "scene C2 B6" "$L" render "$w/pilcrow.toml" -o "$w/p.png"
row "arrays nested 10,000 deep" "$L" render "$w/nested.toml" -o "$w/p.png"
row "radius = nan" "$L" render "$w/nan.toml" -o "$w/p.png"
row "--width 0" "$L" render "$scene" --width 0 -o "$w/p.png"
row "--width 100000" "$L" render "$scene" --width 100000 -o "$w/p.png"
row "truncated .lht" "$L" lht-info "$w/truncated.lht"
row "bit-flipped .lht" "$L" lht-info "$w/flipped.lht"
row "missing output directory" "$L" render "$scene" --width 32 --height 24 -o "$w/no/such/dir/p.png"
if [[ $(id -u) -eq 0 ]] && mkdir -p "$w/full" && mount -t tmpfs -o size=16k tmpfs "$w/full" 2>/dev/null; then
  row "full disk (16 KiB tmpfs), 256x192 PNG" "$L" render "$scene" --width 256 --height 192 -o "$w/full/p.png"
  echo "| (files left on the full disk: $(ls -A "$w/full" | wc -l)) | | | | |"
else
  echo "| full disk | skipped: needs root to mount a tmpfs | | | |"
fi

# The surfaces added after the readers: --at, numbers, the memory budget over
# rasterizing, send and show recognising their input, outputs as one transaction.
echo
echo "| case | exit | seconds | peak MiB | message (start) |"
echo "|---|---|---|---|---|"
cat > "$w/ball.toml" <<'TOML'
[options]
width = 64
height = 64
[camera]
type = "look_at"
eye = [0.0, 0.0, 4.0]
target = [0.0, 0.0, 0.0]
fov = 40
[[lights]]
position = [4.0, 6.0, 5.0]
intensity = 9.0
[[lattices]]
name = "ball"
spacing = 0.0079
object = { type = "sphere", radius = 0.999 }
[[objects]]
type = "lattice"
lattice = "ball"
TOML
"$L" render "$scene" --device tek4125 --width 128 --height 96 -q --stream "$w/t.tek" >/dev/null 2>&1
"$L" render "$root/scenes/sphere-hole.toml" --device tek4014 --stream "$w/hole.tek" -q >/dev/null 2>&1
files() { find "$w" -maxdepth 1 -name "$1" | wc -l; }
for device in tek4125 sixel tek4014; do
  row "emulate --device $device --at nan%" "$L" emulate --device "$device" --raw "$w/t.tek" -o "$w/a.png" --at nan%
done
row "emulate --at 1%,50% on a stream the drawing budget refuses" "$L" emulate --device tek4125 "$w/rr-200K.tek" -o "$w/b.png" --at 1%,50%
echo "| (snapshots left: $(files 'b-at*')) | | | | |"
"$L" emulate --device tek4125 "$w/t.tek" -o "$w/c.png" --at 50% >/dev/null 2>&1 && chmod 444 "$w/c-at50pct.png"
row "emulate --at 50% over a read-only snapshot" "$L" emulate --device tek4125 "$w/t.tek" -o "$w/c.png" --at 50%
row "emulate --at with 4,999 points" "$L" emulate --device tek4125 "$w/t.tek" -o "$w/d.png" --at "$(seq -s, 0 2 9998)"
echo "| (snapshots written: $(files 'd-at*')) | | | | |"
row "emulate --at inf" "$L" emulate --device tek4125 "$w/t.tek" -o "$w/e.png" --at inf
row "emulate --at 1e300" "$L" emulate --device tek4125 "$w/t.tek" -o "$w/e.png" --at 1e300
row "render --wire-seconds nan" "$L" render "$scene" --device tek4125 --stream "$w/f.tek" --wire-seconds nan
row "render --wire-bytes nan" "$L" render "$scene" --device tek4125 --stream "$w/f.tek" --wire-bytes nan
row "render --set width=nan" "$L" render "$scene" --device tek4125 --stream "$w/f.tek" --set width=nan
row "254-cell sphere lattice (401 B scene), --memory-budget 1G" "$L" render "$w/ball.toml" -o "$w/g.png" --memory-budget 1G
row "the same, the default budget" "$L" render "$w/ball.toml" -o "$w/g.png"
row "send a PNG to virtual:tek4125" "$L" send "$w/good.png" --port virtual:tek4125
row "send 100 MB of random bytes to virtual:tek4125" "$L" send "$w/random-100M" --port virtual:tek4125
row "show hole.tek (a Tek 4014 stream)" "$L" show "$w/hole.tek" --stream "$w/hole.six"
if [[ $(id -u) -eq 0 ]] && mkdir -p "$w/full2" && mount -t tmpfs -o size=4k tmpfs "$w/full2" 2>/dev/null; then
  row "render --stream OK/x.tek -o FULL/s.png" "$L" render "$scene" --device tek4125 --width 128 --height 96 -q --stream "$w/x.tek" -o "$w/full2/s.png"
  echo "| (x.tek left: $(files x.tek)) | | | | |"
  umount "$w/full2"
fi

# Killed writes: SIGTERM at random moments during emulate; leftovers counted.
python3 - "$w" "$L" <<'PY'
import os, random, signal, subprocess, sys, time
w, L = sys.argv[1], sys.argv[2]
rng = random.Random(15); left = 0; killed = 0
for i in range(40):
    p = subprocess.Popen([L, "emulate", "--device", "tek4125", f"{w}/rr-200K.tek", "-o", f"{w}/k.png"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(rng.uniform(0, 0.06)); p.send_signal(signal.SIGTERM)
    killed += p.wait() == -signal.SIGTERM
    left += sum(1 for f in os.listdir(w) if ".tmp-" in f)
print(f"| 40 SIGTERMs during emulate ({killed} landed) | | | | temporaries left: {left} |")
PY
echo
echo "load average: $(bench_loadavg)"
