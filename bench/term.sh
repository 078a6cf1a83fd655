#!/usr/bin/env bash
# `lattice term`'s targets, measured (docs/term.md, "Speed"):
#   bench/term.sh [--runs N] [--out FILE]     (default 7 runs; build/app/lattice must exist, or LATTICE=path)
# 1. Plate 6's strict Tek 4125 stream (scenes/fuzzy-sphere-1000.toml at
#    512x512, the default profile: about 160 KB) fed with no pacing
#    (`--stream --unpaced`) to `lattice term` running in a sixel terminal,
#    played by bench/term_host.py (a pty whose text area is 100 x 40 cells of
#    1000 x 800 pixels, answering DA1 as xterm -ti vt340 with 256 registers):
#    wall seconds from the start until lattice exits, which it does once the
#    last redraw has been written to the terminal. Target: <= 1 s. Beside it,
#    `lattice emulate` of the same stream to a PNG, the decoding alone. Runs
#    alternate the two; medians, with the load average (the machine is shared).
# 2. Idle CPU: `lattice term -- sleep 60` in the same terminal, left alone
#    for 5 s after 2 s to settle: the CPU it used over those 5 s, per cent
#    of one core (from /proc/PID/stat, clock ticks of 10 ms). Target: near zero.
# 3. Bytes a redraw sends: the same stream played at 115200 baud (14 s), so
#    the screen arrives over many redraws (10 a second at most); from lattice's
#    closing summary: redraws, sixel bytes in all, the mean a redraw, and one
#    full frame of the final screen.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
runs=7
out=""
bench_parse --runs=runs --out=out -- "$@"
bench_positive --runs "$runs"
lattice=${LATTICE:-$root/build/app/lattice}
[[ -x $lattice ]] || bench_die "no $lattice: build it first (bash scripts/build.sh --target lattice)"
host=("python3" "$root/bench/term_host.py")
bench_workdir work
"$lattice" render "$root/scenes/fuzzy-sphere-1000.toml" --device tek4125 --width 512 --height 512 \
  --stream "$work/plate6.tek" -q

report() {
  local stream_bytes on_screen=() emulate=() i line t0 t1
  stream_bytes=$(stat -c %s "$work/plate6.tek")
  echo "# lattice term (bench/term.sh), $(date -u +%Y-%m-%d), $(nproc) cores, load before: $(bench_loadavg)"
  echo
  echo "Plate 6's strict stream: $stream_bytes bytes, fed unpaced; $runs runs, alternating"
  for ((i = 0; i < runs; i++)); do
    line=$("${host[@]}" -- "$lattice" term --stream "$work/plate6.tek" --unpaced)
    on_screen+=("$(sed -n 's/.*seconds=\([0-9.]*\).*/\1/p' <<<"$line")")
    t0=$(date +%s.%N)
    "$lattice" emulate --device tek4125 "$work/plate6.tek" -o "$work/e.png"
    t1=$(date +%s.%N)
    emulate+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.3f", b - a}')")
  done
  echo
  echo "| contender | median s | range s |"
  echo "|---|---|---|"
  echo "| lattice term --stream --unpaced, on screen in a sixel terminal | $(bench_median -f %.3f "${on_screen[@]}") | $(bench_range "${on_screen[@]}") |"
  echo "| lattice emulate to a PNG (decoding alone) | $(bench_median -f %.3f "${emulate[@]}") | $(bench_range "${emulate[@]}") |"
  echo
  echo "Idle: $("${host[@]}" --idle 5 --settle 2 -- "$lattice" term -- sleep 60) (per cent of one core over 5 s)"
  echo
  "${host[@]}" --keep "$work/drawn.txt" -- "$lattice" term --stream "$work/plate6.tek" --baud 115200 >/dev/null
  # The summary follows the display's last bytes (the cursor shown again, CSI ? 25 h).
  line=$(tr -d '\r\n' <"$work/drawn.txt")
  line=${line##*$'\e[?25h'}
  echo "At 115200 baud: ${line#lattice term: }"
  local redraws total full
  redraws=$(sed -n 's/.* \([0-9]*\) redraws.*/\1/p' <<<"$line")
  total=$(sed -n 's/.* \([0-9]*\) sixel bytes.*/\1/p' <<<"$line")
  full=$(sed -n 's/.*a full frame \([0-9]*\).*/\1/p' <<<"$line")
  awk -v n="$redraws" -v t="$total" -v f="$full" \
    'BEGIN { printf "Mean bytes a redraw: %d; one full frame: %d; the mean is %.1f %% of it\n", t / n, f, 100 * t / n / f }'
  echo
  echo "load after: $(bench_loadavg)"
}
bench_write "$out" report
