#!/usr/bin/env bash
# The 9600-baud user's path, measured (docs/wire.md): the wire budget's
# search time on one core, what the coarse-to-fine search gives up against
# searching every setting, and the picture a minute at 9600 baud brings.
#   bench/wire-search.sh [--build DIR] [--before LATTICE] [--runs N (5)] [--images DIR] [--out FILE]
# 1. build/bench/wire_search_bench on Plate 6 (scenes/fuzzy-sphere-1000.toml)
#    at 512x512, strict 4125, 57,600 B (60 s at 9600) and 76,800 B (20 s at
#    38400): the coarse-to-fine search's median wall and CPU seconds over N runs and
#    its choice, beside the exhaustive search's once (one core: the search
#    is single-threaded, the render --threads 1); then the same for the
#    compact form set, one run.
# 2. With --before: whole `lattice render ... --width 512 --height 512
#    --wire-bytes 57600 --threads 1` commands of that binary and of this
#    build, alternating, N each; median wall seconds of each (the render,
#    about 0.3 s, included in both).
# 3. The hobbyist's command without --width/--height: `lattice render
#    scenes/fuzzy-sphere-1000.toml --device tek4125 --baud 9600
#    --wire-seconds 60` (the size searched with the default 30 dB floor):
#    the size chosen, its PSNR and the command's wall seconds; with
#    --images DIR, the screen that arrives (DIR/wire-plate6-9600-60s.png)
#    and the screen after 25 % and 50 % of the bytes (-at25pct, -at50pct:
#    15 s and 30 s into the minute).
# 4. Sixel on Plate 6 at 512x512 (docs/sixel.md, docs/wire.md): bytes and
#    the PSNR of the emulated screen against the truecolour render (`lattice
#    diff`) at lambda (bench/rd_runs_bench) 0, 100, 400, 1600, 6400, 25600 with 256 and 16
#    registers, and the wire budget at 57,600 B and 76,800 B (256
#    registers, the size fixed at 512x512 as the figures before were).
# Medians are quoted with the load average (the machine is shared; the
# bytes and PSNRs are deterministic, the times are not).
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
build="$root/build"
before=""
runs=5
images=""
out=""
bench_parse --build=build --before=before --runs=runs --images=images --out=out -- "$@"
bench_positive --runs "$runs"
bench_need_built "$build" lattice wire_search_bench rd_runs_bench
L="$build/app/lattice"
plate6="$root/scenes/fuzzy-sphere-1000.toml"
bench_workdir work

measure() {
  echo "# wire-search.sh, $(date -u +%Y-%m-%dT%H:%MZ), load average before: $(bench_loadavg)"
  echo "## 1. The search on Plate 6, 512x512, strict (wire_search_bench, median of $runs coarse-to-fine runs)"
  "$build/bench/wire_search_bench" "$plate6" --size 512x512 --repeat "$runs"
  echo "compact:"
  "$build/bench/wire_search_bench" "$plate6" --size 512x512 --repeat 1 --profile compact | tail -n +2
  echo "load average after: $(bench_loadavg)"
  if [[ -n $before ]]; then
    [[ -x $before ]] || bench_die "--before $before is not an executable"
    echo "## 2. Whole commands, --wire-bytes 57600 at 512x512, --threads 1, alternating (wall s)"
    local -a old=() new=()
    local i start
    for ((i = 0; i < runs; i++)); do
      for which in old new; do
        local exe=$L
        [[ $which == old ]] && exe=$before
        start=$(date +%s.%N)
        "$exe" render "$plate6" --device tek4125 --set width=512 --set height=512 --width 512 --height 512 \
          --wire-bytes 57600 --threads 1 -q --stream "$work/$which.tek" 2>"$work/$which.err" ||
          bench_die "$exe failed: $(cat "$work/$which.err")"
        local took
        took=$(echo "$(date +%s.%N) - $start" | bc)
        if [[ $which == old ]]; then old+=("$took"); else new+=("$took"); fi
      done
    done
    echo "before: median $(bench_median -f '%.2f' "${old[@]}") s (range $(bench_range "${old[@]}")); $(grep -o 'wire budget: .*' "$work/old.err")"
    echo "after:  median $(bench_median -f '%.2f' "${new[@]}") s (range $(bench_range "${new[@]}")); $(grep -o 'wire budget: .*' "$work/new.err")"
    echo "load average: $(bench_loadavg)"
  fi
  echo "## 3. lattice render Plate 6 --device tek4125 --baud 9600 --wire-seconds 60 (size free, floor 30 dB)"
  local screen="$work/wire-plate6-9600-60s.png" start
  start=$(date +%s.%N)
  "$L" render "$plate6" --device tek4125 --baud 9600 --wire-seconds 60 -q --stream "$work/p6.tek" -o "$screen" \
    2>"$work/p6.err" || bench_die "the 9600-baud render failed: $(cat "$work/p6.err")"
  echo "wall $(echo "$(date +%s.%N) - $start" | bc) s (2 threads for the renders), load average $(bench_loadavg)"
  grep -o 'wire budget: .*\|tek4125 stream .*' "$work/p6.err"
  "$L" emulate --device tek4125 "$work/p6.tek" -o "$screen" --at 25%,50% 2>/dev/null
  echo "## 4. Sixel, Plate 6 512x512: rate-distortion lambda (rd_runs_bench; bytes, PSNR of the emulated screen) and the wire budget"
  "$L" render "$plate6" -q -o "$work/true.png" 2>/dev/null
  local registers lambda limit
  for registers in 256 16; do
    for lambda in 0 100 400 1600 6400 25600; do
      "$build/bench/rd_runs_bench" "$plate6" --device sixel --set registers=$registers --lambda $lambda \
        --stream "$work/s.six" -o "$work/s.png" >/dev/null
      echo "registers $registers lambda $lambda: $(stat -c %s "$work/s.six") B, $("$L" diff "$work/true.png" "$work/s.png" 2>&1 | awk '/^PSNR/ {print $2, $3}')"
    done
  done
  for limit in 57600 76800; do
    "$L" render "$plate6" --device sixel --set registers=256 --width 512 --height 512 --wire-bytes $limit -q \
      --stream "$work/s.six" -o "$work/s.png" 2>"$work/s.err"
    echo "registers 256 --wire-bytes $limit: $(grep -o 'wire budget: .*' "$work/s.err"); screen $("$L" diff "$work/true.png" "$work/s.png" 2>&1 | awk '/^PSNR/ {print $2, $3}')"
  done
  if [[ -n $images ]]; then
    mkdir -p "$images"
    cp "$work"/wire-plate6-9600-60s*.png "$images/"
    echo "pictures: $(cd "$work" && ls wire-plate6-9600-60s*.png | tr '\n' ' ')in $images"
  fi
}
bench_write "$out" measure
