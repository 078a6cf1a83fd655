#!/usr/bin/env bash
# Sixel bytes and time beside libsixel's img2sixel, on the same quantized
# picture and palette (docs/sixel.md, "Bytes beside img2sixel").
#   bench/sixel-bytes.sh [RUNS]      (default 5; build/app/lattice must exist)
# Method: Plate 6 (scenes/fuzzy-sphere-1000.toml, 512x512) is rendered once
# to a truecolour PNG, then median-cut by `lattice quantize --dither none` to
# 16 and to 256 colours: Q16.png, Q256.png. Each contender encodes that
# picture with that palette:
#   ours:   lattice show QK.png --set registers=K --stream ours.six
#           (reads the PNG, its median cut finds the picture's own K colours
#           again, encodes; checked: same pixels as QK.png via sixel2png)
#   theirs: img2sixel -m QK.png -d none -o theirs.six QK.png
#           (its palette is the map file's colours, no diffusion)
# Both commands read a PNG, map it to the palette and encode, so the times
# are whole commands; runs alternate the two, and the medians are reported
# with the load average.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
lattice=build/app/lattice
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$lattice" render scenes/fuzzy-sphere-1000.toml -o "$work/plate6.png" -q 2>/dev/null
median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
seconds() { local s e; s=$(date +%s.%N); "$@" >/dev/null 2>&1; e=$(date +%s.%N); echo "$e - $s" | bc -l; }
echo "load: $(uptime | sed 's/.*load average: //')"
printf '%-8s %12s %12s %8s %10s %10s %8s %s\n' colours "ours bytes" "img2sixel" ratio "ours s" "img2sixel s" ratio "pixels equal"
for k in 16 256; do
  q="$work/q$k.png"
  "$lattice" quantize "$work/plate6.png" --colors "$k" --dither none -o "$q" -q
  ours=() theirs=()
  for ((i = 0; i < runs; i++)); do
    ours+=("$(seconds "$lattice" show "$q" --set registers="$k" --stream "$work/ours.six")")
    theirs+=("$(seconds img2sixel -m "$q" -d none -o "$work/theirs.six" "$q")")
  done
  sixel2png -i "$work/ours.six" -o "$work/ours.png"
  sixel2png -i "$work/theirs.six" -o "$work/theirs.png"
  same=$("$lattice" diff "$work/ours.png" "$q" 2>&1 | grep -o 'max error *[0-9]*' || true)
  theirsSame=$("$lattice" diff "$work/theirs.png" "$q" 2>&1 | grep -oE 'max error *[0-9]*|differing *[0-9]*' | tr '\n' ' ' || true)
  bo=$(stat -c %s "$work/ours.six") bt=$(stat -c %s "$work/theirs.six")
  mo=$(printf '%s\n' "${ours[@]}" | median) mt=$(printf '%s\n' "${theirs[@]}" | median)
  printf '%-8s %12d %12d %8.3f %10.4f %10.4f %8.3f %s\n' "$k" "$bo" "$bt" "$(echo "$bo / $bt" | bc -l)" "$mo" "$mt" \
    "$(echo "$mo / $mt" | bc -l)" "ours vs quantized: ${same:-?}; img2sixel vs quantized: ${theirsSame:-?}"
done
echo "load: $(uptime | sed 's/.*load average: //')"
