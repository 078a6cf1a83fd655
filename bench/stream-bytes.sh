#!/usr/bin/env bash
# Bytes on the wire for the Tek 4125 (docs/tek4125.md, "Stream size"): for
# every example scene at the size the main job renders it (the scene's own
# width and height, scripts/main-job.sh), every form set (strict, compact)
# and every driver strategy, the stream's bytes, its seconds at 9600 and
# 38400 baud (8N1: 10 bits a byte) and its ratio to the same picture as a
# 256-colour PNG. The reference PNG is our quantizer's indexed PNG
# (`lattice quantize -k 256` of the truecolour render, the one the issue's
# 59,194 bytes come from); pngquant's is shown beside it where installed.
# Targets: strict <= 2.0x, compact <= 1.5x that PNG.
#   bench/stream-bytes.sh [--build DIR] [--scenes "a.toml b.toml"] [--out FILE]
set -euo pipefail
source "$(dirname "$0")/lib.sh"
build="$root/build"
scenes=("$root"/scenes/*.toml)
out=""
sceneList=""
bench_parse --build=build --scenes=sceneList --out=out -- "$@"
[[ -z $sceneList ]] || read -r -a scenes <<<"$sceneList"
lattice="$build/app/lattice"
bench_need_built "$build" lattice
havePngquant=1
command -v pngquant >/dev/null 2>&1 ||
  { havePngquant=0; echo "stream-bytes.sh: pngquant is not installed: its column is left empty (scripts/setup.sh --bench)" >&2; }
strategies=(shortest plain skip rectangles spans runs)
bench_workdir work
size() { stat -c %s "$1"; }

{
  echo "| scene | size | form set | strategy | bytes | s at 9600 | s at 38400 | x our PNG | x pngquant PNG |"
  echo "|---|---|---|---|---|---|---|---|---|"
  for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .toml)
    echo "stream-bytes.sh: $name" >&2
    "$lattice" render "$scene" --mode frame --quiet -o "$work/tc.png" 2>/dev/null
    "$lattice" quantize "$work/tc.png" -k 256 --quiet -o "$work/q.png"
    png=$(size "$work/q.png")
    pq=""
    if ((havePngquant)); then
      pngquant --force --output "$work/pq.png" 256 "$work/tc.png"
      pq=$(size "$work/pq.png")
    fi
    for forms in strict compact; do
      for strategy in "${strategies[@]}"; do
        log=$("$lattice" render "$scene" --mode frame --device tek4125 --set "profile=$forms" \
          --set "strategy=$strategy" --stream "$work/s.tek" 2>&1 >/dev/null)
        dims=$(grep -o '[0-9]*x[0-9]*,' <<<"$log" | head -1 | tr -d ,)
        bytes=$(size "$work/s.tek")
        awk -v n="$name" -v d="$dims" -v f="$forms" -v s="$strategy" -v b="$bytes" -v p="$png" -v q="$pq" 'BEGIN {
          printf "| %s | %s | %s | %s | %d | %.1f | %.1f | %.2f | %s |\n", n, d, f, s, b, b * 10 / 9600, b * 10 / 38400,
            b / p, q == "" ? "" : sprintf("%.2f", b / q) }'
      done
    done
    echo "| $name | | our PNG | | $png | $(awk -v b="$png" 'BEGIN{printf "%.1f | %.1f", b*10/9600, b*10/38400}') | 1.00 | |"
  done
} | tee "$work/table.md"

# The targets, on the default ("shortest") strategy of each form set.
awk -F'|' '$5 ~ /shortest/ {
    gsub(/ /, "", $4); r = $9 + 0; n[$4]++; if (r > worst[$4]) worst[$4] = r; sum[$4] += r }
  END {
    target["strict"] = 2.0; target["compact"] = 1.5
    for (f in n) printf "%s: worst %.2fx, mean %.2fx of our PNG over %d scenes; target <= %.1fx %s\n",
      f, worst[f], sum[f] / n[f], n[f], target[f], worst[f] <= target[f] ? "met" : "NOT met"
  }' "$work/table.md" | tee "$work/summary.txt"
if [[ -n $out ]]; then cat "$work/table.md" "$work/summary.txt" >"$out"; fi
