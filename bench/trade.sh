#!/usr/bin/env bash
# The speed-for-accuracy trade (docs/trade.md), one command:
#   bench/trade.sh [--build DIR] [--runs N (3)] [--size WxH (512x512)]
#                  [--scenes "fuzzy-sphere-1000 thistle"] [--out DIR (BUILD/trade)] [--no-docs]
# For each scene it renders every knob setting with `lattice render`, times it
# (median CPU seconds of N runs, as a ratio to the double-precision full ray
# trace of the same run), takes the peak resident memory (/usr/bin/time), the
# lattice table's bytes (`lattice lht-info` on the cache) and the error
# against the double full ray trace (bench/trade_bench.cpp: PSNR, max error,
# SSIM). Results: OUT/<scene>.tsv; then bench/plot_trade.py rewrites the
# tables and plots in docs/trade.md and docs/images/trade-*.svg (--no-docs: not).
#
# Knobs: arithmetic (float, double, and fixed once `lattice render --arith
# fixed` works), lattice oversampling f_lat 1..4 or the full ray trace,
# palette size and dithering, and the quantizer's memory mode (these two
# through the Tek 4125 driver and its emulator with the screen set to the
# picture size, ray tracing in full so the error is the quantizer's), and the
# LHT entry precision (`lattice render --lht-precision`: the thesis's 14-byte
# entry in the lattice rows, the wide 16-byte and compact 13-byte entries at
# f_lat 1 and 2 in the "lht precision" rows; docs/lattices.md, "Entry precision"),
# the LHT form (`--lht-form compressed` and `on-demand` at f_lat 1..4, the
# "lht form" rows; docs/lattices.md), and the look-up (`--lattice-lookup blend`
# at f_lat 1..4 in the "lattice lookup" rows, the thesis's in the lattice rows;
# docs/lattices.md, "Look-ups").
#
# Timing is CPU time (user + system) with --threads 1: the machine may be
# shared, and CPU time is what other processes disturb least. The lattice is
# rasterized once per setting into a cache (its CPU time is the "raster s"
# column, the thesis's precomputation); the timed runs read it.
set -euo pipefail

source "$(dirname "$0")/lib.sh"
build="$root/build"
runs=3
size="512x512"
scenes="fuzzy-sphere-1000 thistle"
docs=1
out=""
bench_parse --build=build --runs=runs --size=size --scenes=scenes --out=out --no-docs:docs=0 -- "$@"
lattice="$build/app/lattice"
metric="$build/bench/trade_bench"
bench_need_built "$build" lattice trade_bench
bench_need_time
bench_positive --runs "$runs"
bench_size "$size"
# The Tek 4125's screen shrunk to the picture, so its emulated picture lines up with the reference.
tekScreen=(--set "width=$bench_width" --set "height=$bench_height")
out=${out:-$build/trade}
mkdir -p "$out"
bench_workdir work

arithmetics="double float"
# Fixed point counts once `lattice render --arith fixed` renders (a 1x1 picture decides).
if "$lattice" render "$root/scenes/$(set -- $scenes; echo "$1").toml" --arith fixed --full --width 1 --height 1 \
  --quiet -o "$work/probe.png" >/dev/null 2>&1; then
  arithmetics="double float fixed"
fi

# A copy of the scene with oversample = f and the table cached next to it as
# $work/<tag>.lht; tag is SCENE-fF, plus -PRECISION for a non-thesis entry
# (a cache is only valid for the precision it was rasterized at).
variant() {  # scene f tag -> path
  local scene=$1 f=$2 tag=$3 dst="$work/$3.toml"
  sed -E "s/^oversample *= *[0-9.]+/oversample = $f\ncache = \"$tag.lht\"/" "$root/scenes/$scene.toml" >"$dst"
  grep -q "^oversample = $f" "$dst" || { echo "trade.sh: scenes/$scene.toml has no 'oversample =' line" >&2; exit 3; }
  echo "$dst"
}

# One timed run: prints "cpu_seconds peak_kib"; the render's own output goes to $work/log.
timed() {
  /usr/bin/time -f "%U %S %M" -o "$work/time" "$lattice" render "$@" --threads 1 --quiet "${bench_size_args[@]}" \
    >"$work/log" 2>&1 || { echo "trade.sh: lattice render $* failed:" >&2; cat "$work/log" >&2; exit 4; }
  awk '{ printf "%.3f %d\n", $1 + $2, $3 }' "$work/time"
}

# Median CPU seconds and the largest peak RSS of $runs runs.
measure() {
  local times=() peak=0 t m
  for ((i = 0; i < runs; ++i)); do
    read -r t m < <(timed "$@")
    times+=("$t")
    ((m > peak)) && peak=$m
  done
  printf '%s %d\n' "$(bench_median -f %.3f "${times[@]}")" "$peak"
}

tableBytes() {  # lht file -> bytes
  "$lattice" lht-info "$1" | awk '/^table bytes:/ { print $3 }'
}

# One lattice setting: the first render of a new variant rasterizes and
# writes its cache (rasterizing = that run's time less a cached run's; a
# variant already cached by an earlier arithmetic keeps its first figure).
declare -A rasterSeconds
latticeRow() {  # group setting scene f tag render-args...
  local group=$1 setting=$2 scene=$3 f=$4 tag=$5 v first="" t m
  shift 5
  v=$(variant "$scene" "$f" "$tag")
  if [[ ! -f $work/$tag.lht ]]; then
    read -r first _ < <(timed "$v" "$@" -o "$work/img.png")
  fi
  read -r t m < <(measure "$v" "$@" -o "$work/img.png")
  # A difference of two 10 ms-resolution timings: a small table can come out negative; say 0.
  [[ -n $first ]] && rasterSeconds[$tag]=$(awk -v a="$first" -v b="$t" 'BEGIN { d = a - b; printf "%.3f", (d > 0) ? d : 0 }')
  row "$group" "$setting" "$t" "$m" "$(tableBytes "$work/$tag.lht")" "${rasterSeconds[$tag]:-0}" "$work/img.png"
}

for scene in $scenes; do
  [[ -f $root/scenes/$scene.toml ]] || bench_die "scenes/$scene.toml does not exist"
  tsv="$out/$scene.tsv"
  printf 'group\tsetting\tcpu_s\tratio\tpeak_kib\ttable_bytes\traster_s\tpsnr_db\tmax_err\tssim\n' >"$tsv.tmp"
  base=$(variant "$scene" 1 "$scene-f1")
  ref="$work/ref.png"
  echo "trade.sh: $scene: reference (double, full ray trace)" >&2
  read -r refTime refPeak < <(measure "$base" --full --arith double -o "$ref")
  # The palette and memory-mode rows compare the emulator's picture to the truecolour reference.
  row() {  # group setting cpu peak table raster png
    local err ratio
    err=$("$metric" "$ref" "$7")
    ratio=$(awk -v a="$3" -v b="$refTime" 'BEGIN { printf "%.3f", (b > 0) ? a / b : 0 }')
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$ratio" "$4" "$5" "$6" "$(tr ' ' '\t' <<<"$err")" >>"$tsv.tmp"
  }
  row reference "double full" "$refTime" "$refPeak" 0 0 "$ref"

  for arith in $arithmetics; do
    if [[ $arith != double ]]; then
      echo "trade.sh: $scene: $arith full" >&2
      read -r t m < <(measure "$base" --full --arith "$arith" -o "$work/img.png")
      row arithmetic "$arith full" "$t" "$m" 0 0 "$work/img.png"
    fi
    for f in 1 2 3 4; do
      echo "trade.sh: $scene: $arith f_lat=$f" >&2
      latticeRow lattice "$arith f_lat=$f" "$scene" "$f" "$scene-f$f" --arith "$arith"
    done
  done

  # LHT entry precision (double): the thesis's entry is the lattice rows above.
  for precision in wide compact; do
    for f in 1 2; do
      echo "trade.sh: $scene: $precision entries, f_lat=$f" >&2
      latticeRow "lht precision" "$precision f_lat=$f" "$scene" "$f" "$scene-f$f-$precision" --arith double \
        --lht-precision "$precision"
    done
  done

  # LHT form (double, thesis entries): the compressed table (rasterized once
  # into a version-3 cache, as the hashed rows above) and the table built on
  # demand during the render (no cache can hold it: every timed run traces
  # the pairs it asks, so its time includes that work; table bytes 0, the
  # entries it built are in docs/lattices.md, "The LHT built on demand").
  for f in 1 2 3 4; do
    echo "trade.sh: $scene: compressed table, f_lat=$f" >&2
    latticeRow "lht form" "compressed f_lat=$f" "$scene" "$f" "$scene-f$f-compressed" --arith double --lht-form compressed
    echo "trade.sh: $scene: on-demand table, f_lat=$f" >&2
    sed -E "s/^oversample *= *[0-9.]+/oversample = $f/" "$root/scenes/$scene.toml" >"$work/$scene-f$f-on-demand.toml"
    read -r t m < <(measure "$work/$scene-f$f-on-demand.toml" --arith double --lht-form on-demand -o "$work/img.png")
    row "lht form" "on-demand f_lat=$f" "$t" "$m" 0 0 "$work/img.png"
  done

  # The blended look-up (double) on the same tables; the thesis's look-up is the lattice rows.
  for f in 1 2 3 4; do
    echo "trade.sh: $scene: blend look-up, f_lat=$f" >&2
    latticeRow "lattice lookup" "blend f_lat=$f" "$scene" "$f" "$scene-f$f" --arith double --lattice-lookup blend
  done

  # Palette and dithering: the Tek 4125 driver's stream, decoded by its emulator.
  # These rows ray trace in full (double), so their error is the quantizer's alone.
  for colors in 256 16 4; do
    for dither in none fs bayer; do
      echo "trade.sh: $scene: tek4125 $colors colours, dither $dither" >&2
      read -r t m < <(measure "$base" --full --device tek4125 --stream "$work/s.tek" -o "$work/img.png" "${tekScreen[@]}" \
        --colors "$colors" --dither "$dither" --mode passes)
      row palette "$colors colours, $dither" "$t" "$m" 0 0 "$work/img.png"
    done
  done

  # Quantizer memory mode (256 colours, no dither, full ray trace). The emulator
  # holds the screen, so the peak RSS of these rows is not the driver's alone
  # (bench/memory.sh measures the mode without it).
  for mode in passes frame sample; do
    echo "trade.sh: $scene: tek4125 mode $mode" >&2
    read -r t m < <(measure "$base" --full --device tek4125 --stream "$work/s.tek" -o "$work/img.png" "${tekScreen[@]}" --mode "$mode")
    row "quantizer mode" "$mode" "$t" "$m" 0 0 "$work/img.png"
  done
  mv "$tsv.tmp" "$tsv"
  echo "trade.sh: wrote $tsv" >&2
done

if ((docs)); then
  python3 "$root/bench/plot_trade.py" --results "$out" --docs "$root/docs" --runs "$runs" \
    --size "$size" $scenes
fi
