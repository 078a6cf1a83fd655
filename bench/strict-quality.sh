#!/usr/bin/env bash
# The strict Tek 4125 stream's quality on a wire budget, and the progressive
# stream part-way (docs/tek4125.md "Quality in strict on a wire budget, measured";
# docs/wire.md "A progressive stream"):
#   bench/strict-quality.sh [--lattice BIN] [--before BIN] [--runs N (3)] [--out FILE]
# BIN defaults to build/app/lattice; --before names a second binary (a build
# of the code before a change) measured the same way, the two alternating.
# Method, Plate 6 (scenes/fuzzy-sphere-1000.toml) at 512x512 with the
# terminal's screen set to the picture (--set width=512 --set height=512):
#   budget       `lattice render --wire-bytes N` (the default render, strict),
#                N = 57,600 (60 s at 9600 baud) and 76,800 (20 s at 38400):
#                the settings and bytes the search chose, PSNR of the picture
#                sent as the search scores it, and of the emulated screen
#                (the -o picture) against the truecolour render (`lattice diff`).
#   progressive  the full ray trace at 256 colours, no dither, strict, with
#                --set progressive=on: its bytes; PSNR against its own final
#                screen after 10, 25 and 50 % of its bytes (`lattice emulate
#                --at`), and after the byte counts that are 10, 25 and 50 % of
#                the ordinary (row order) stream of the same picture, so a
#                longer stream gains nothing by being longer; whether its final
#                screen is the ordinary stream's (cmp of the two PNGs).
#   time         wall seconds of the progressive `lattice render` (render,
#                quantize and the driver's encodings), median of --runs runs,
#                the binaries alternating, with the load average.
# Bytes and PSNRs are deterministic; only the times vary. Writes a Markdown
# report to standard output, and to FILE with --out.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
lattice="$root/build/app/lattice"
before=""
runs=3
out=""
bench_parse --lattice=lattice --before=before --runs=runs --out=out -- "$@"
bench_positive --runs "$runs"
[[ -x $lattice ]] || bench_die "$lattice is missing; build it: bash scripts/build.sh --target lattice"
[[ -z $before || -x $before ]] || bench_die "--before $before is not an executable"
bench_workdir work
scene="$root/scenes/fuzzy-sphere-1000.toml"
screen=(--set width=512 --set height=512)
size=(--width 512 --height 512)
declare -A label=([after]="$lattice")
contenders=(after)
[[ -n $before ]] && label[before]="$before" && contenders=(before after)

psnr() { "$lattice" diff "$1" "$2" | awk '/^PSNR/ {print $2}'; }

budget() {  # contender bytes
  local bin=${label[$1]} dir="$work/$1-$2" line
  mkdir -p "$dir"
  line=$("$bin" render "$scene" --device tek4125 "${screen[@]}" "${size[@]}" --wire-bytes "$2" \
    --stream "$dir/s.tek" -o "$dir/s.png" 2>&1 | sed -n 's/.*wire budget: //p')
  printf '| %s | %s | %s | %s |\n' "$1" "$2" "$line" "$(psnr "$work/truecolour.png" "$dir/s.png")"
}

progressive() {  # contender
  local bin=${label[$1]} dir="$work/$1-progressive" bytes ordinary at=() p
  mkdir -p "$dir"
  "$bin" render "$scene" --full "${size[@]}" --device tek4125 "${screen[@]}" --stream "$dir/rows.tek" \
    -o "$dir/rows.png" -q 2>/dev/null
  "$bin" render "$scene" --full "${size[@]}" --device tek4125 "${screen[@]}" --set progressive=on \
    --stream "$dir/p.tek" -o "$dir/p.png" -q 2>/dev/null
  bytes=$(stat -c %s "$dir/p.tek") ordinary=$(stat -c %s "$dir/rows.tek")
  "$lattice" emulate --device tek4125 "${screen[@]}" "$dir/p.tek" -o "$dir/final.png" \
    --at "10%,25%,50%,$((ordinary / 10)),$((ordinary / 4)),$((ordinary / 2))" >/dev/null 2>&1
  for p in 10pct 25pct 50pct $((ordinary / 10))B $((ordinary / 4))B $((ordinary / 2))B; do
    at+=("$(psnr "$dir/final.png" "$dir/final-at$p.png")")
  done
  local same=no
  cmp -s "$dir/rows.png" "$dir/p.png" && same=yes
  printf '| %s | %s | %s | %s / %s / %s | %s / %s / %s | %s |\n' "$1" "$bytes" "$ordinary" "${at[0]}" "${at[1]}" \
    "${at[2]}" "${at[3]}" "${at[4]}" "${at[5]}" "$same"
}

report() {
  echo "# Strict 4125 quality: Plate 6, 512x512 (bench/strict-quality.sh)"
  echo
  echo "Binaries: after = $lattice${before:+, before = $before}. Load average at the start: $(bench_loadavg)."
  echo
  "$lattice" render "$scene" "${size[@]}" -o "$work/truecolour.png" -q 2>/dev/null
  echo "## Wire budget, strict (PSNR against the truecolour render)"
  echo
  echo "| binary | bytes allowed | the search's choice (PSNR of the picture sent) | PSNR on the emulated screen |"
  echo "|---|---|---|---|"
  for b in 57600 76800; do for c in "${contenders[@]}"; do budget "$c" "$b"; done; done
  echo
  echo "## Progressive stream, strict, 256 colours, full ray trace (PSNR against its final screen)"
  echo
  echo "| binary | bytes | ordinary stream's bytes | after 10 / 25 / 50 % of its bytes, dB | after 10 / 25 / 50 % of the ordinary stream's bytes, dB | final screen = ordinary's |"
  echo "|---|---|---|---|---|---|"
  for c in "${contenders[@]}"; do progressive "$c"; done
  echo
  echo "## Time of the progressive render (wall s, median of $runs, alternating)"
  echo
  local -A times=()
  local i c
  for ((i = 0; i < runs; i++)); do
    for c in "${contenders[@]}"; do
      /usr/bin/time -f %e -o "$work/time" "${label[$c]}" render "$scene" --full "${size[@]}" --device tek4125 \
        "${screen[@]}" --set progressive=on --stream "$work/t.tek" -q >/dev/null 2>&1
      times[$c]+="$(cat "$work/time") "
    done
  done
  echo "| binary | median s | range s |"
  echo "|---|---|---|"
  for c in "${contenders[@]}"; do
    # shellcheck disable=SC2086 # the list of times, split on purpose
    printf '| %s | %s | %s |\n' "$c" "$(bench_median ${times[$c]})" "$(bench_range ${times[$c]})"
  done
  echo
  echo "Load average at the end: $(bench_loadavg)."
}

bench_need_time
bench_write "$out" report
