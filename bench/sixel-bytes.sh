#!/usr/bin/env bash
# Sixel bytes and time beside libsixel's img2sixel, like for like: the same
# quantized picture, the same palette, the same input file, and the pixels
# checked equal on both sides (docs/sixel.md, "Bytes beside img2sixel").
#   bench/sixel-bytes.sh [RUNS]      (default 5; build/app/lattice must exist, or LATTICE=path)
# Method: Plate 6 (scenes/fuzzy-sphere-1000.toml, 512x512) is rendered once
# to a truecolour PNG and median-cut by `lattice quantize --dither none` to
# 16 and to 256 colours (qK.png). That picture is written once as a sixel
# stream, inK.six, which is the input of both contenders: a sixel stream is
# the one paletted format both read. img2sixel keeps a paletted input's
# palette and indices as they are (libsixel 1.10.3: loader.c load_sixel
# returns PAL8 when the colours fit, encoder.c sixel_encoder_prepare_palette
# takes a paletted frame's palette unchanged); from a PNG it cannot: Debian's
# build reads PNG through stb_image as RGB (img2sixel -V: "libpng: no"), and
# its median cut (-m or not) keeps 5 bits a gun (quant.c computeHistogram).
#   ours:   lattice show inK.six --set registers=K > ours.six
#   theirs: img2sixel -d none inK.six > theirs.six
# Both decode the same stream and encode it again, and both write to
# standard output redirected to a file (`--stream` would add our atomic
# file's fsync, which img2sixel -o does not do), so the times are whole
# commands on the same input: wall seconds and CPU (user + system) seconds
# from bash's `time` (milliseconds); runs alternate the two, medians are reported with the
# load average (the machine is shared: wall time waits for the CPU too).
# Where perf is installed each run is also counted by `perf stat -e
# task-clock` (the CPU milliseconds of the command, which a busy machine
# inflates least) and its median reported; without perf that column is "-".
# Pixels: sixel2png decodes both outputs, which must
# equal sixel2png's picture of the input (0 pixels differing), and `lattice
# diff` against qK.png shows the register percent rounding only.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
lattice=${LATTICE:-build/app/lattice}  # LATTICE=another/lattice: a before/after run
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$lattice" render scenes/fuzzy-sphere-1000.toml -o "$work/plate6.png" -q 2>/dev/null
median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
havePerf=0
if perf stat -x, -e task-clock -o /dev/null true 2>/dev/null; then havePerf=1; fi
# Runs "$@" with standard output to file $out; prints "wall cpu task-clock-ms".
timed() {
  local TIMEFORMAT='%3R %3U %3S' clock=-
  { time "$@" >"$out" 2>/dev/null; } 2>"$work/time"
  if ((havePerf)); then
    perf stat -x, -e task-clock -o "$work/perf" "$@" >"$out" 2>/dev/null
    clock=$(awk -F, '$3 == "task-clock" {print $1}' "$work/perf")
  fi
  awk -v c="$clock" '{print $1, $2 + $3, c}' "$work/time"
}
differing() { "$lattice" diff "$1" "$2" 2>&1 | awk '/^differing/ {print $2}'; }
maxError() { "$lattice" diff "$1" "$2" 2>&1 | awk '/^max error/ {print $3}'; }
echo "load: $(uptime | sed 's/.*load average: //')"
printf '%-8s %10s %10s %6s %8s %8s %6s %8s %8s %6s %8s %8s %6s  %s\n' colours "ours B" "img2sixel" ratio "ours s" \
  "theirs s" ratio "ours cpu" "their cpu" ratio "ours ms" "their ms" ratio \
  "pixels (differing from the input; max error against qK.png)"
for k in 16 256; do
  q="$work/q$k.png" in="$work/in$k.six"
  "$lattice" quantize "$work/plate6.png" --colors "$k" --dither none -o "$q" -q
  "$lattice" show "$q" --set registers="$k" --stream "$in" 2>/dev/null
  ours=() theirs=() oursCpu=() theirsCpu=() oursClock=() theirsClock=()
  for ((i = 0; i < runs; i++)); do
    read -r wall cpu clock < <(out="$work/ours.six" timed "$lattice" show "$in" --set registers="$k")
    ours+=("$wall") oursCpu+=("$cpu") oursClock+=("$clock")
    read -r wall cpu clock < <(out="$work/theirs.six" timed img2sixel -d none "$in")
    theirs+=("$wall") theirsCpu+=("$cpu") theirsClock+=("$clock")
  done
  sixel2png -i "$in" -o "$work/in.png"
  sixel2png -i "$work/ours.six" -o "$work/ours.png"
  sixel2png -i "$work/theirs.six" -o "$work/theirs.png"
  bo=$(stat -c %s "$work/ours.six") bt=$(stat -c %s "$work/theirs.six")
  mo=$(printf '%s\n' "${ours[@]}" | median) mt=$(printf '%s\n' "${theirs[@]}" | median)
  co=$(printf '%s\n' "${oursCpu[@]}" | median) ct=$(printf '%s\n' "${theirsCpu[@]}" | median)
  ko=- kt=- kr=-
  if ((havePerf)); then
    ko=$(printf '%s\n' "${oursClock[@]}" | median) kt=$(printf '%s\n' "${theirsClock[@]}" | median)
    kr=$(printf '%.2f' "$(echo "$ko / $kt" | bc -l)") ko=$(printf '%.1f' "$ko") kt=$(printf '%.1f' "$kt")
  fi
  printf '%-8s %10d %10d %6.3f %8.3f %8.3f %6.2f %8.3f %8.3f %6.2f %8s %8s %6s  ours %s, %s; img2sixel %s, %s\n' \
    "$k" "$bo" "$bt" "$(echo "$bo / $bt" | bc -l)" "$mo" "$mt" "$(echo "$mo / $mt" | bc -l)" "$co" "$ct" \
    "$(echo "$co / $ct" | bc -l)" "$ko" "$kt" "$kr" \
    "$(differing "$work/ours.png" "$work/in.png")" "$(maxError "$work/ours.png" "$q")" \
    "$(differing "$work/theirs.png" "$work/in.png")" "$(maxError "$work/theirs.png" "$q")"
done
echo "load: $(uptime | sed 's/.*load average: //')"
