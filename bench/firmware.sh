#!/usr/bin/env bash
# Plate 6 (scenes/fuzzy-sphere-1000.toml, 1000 lattice hairs) at 512x512 on
# an emulated board (docs/firmware.md, "Measured"), beside the thesis's
# 12.1 hours on a Sun 3/60.
#   bench/firmware.sh [--board NAME] [--ram budget|board] [--size WxH] [--scene FILE] [--mode sample|passes]
#                     [--sample N] [--set key=value ...]
# --mode, --sample: the quantizer pipeline's (scripts/firmware.sh; the host's
# render takes the same): sample (the default) with the
# histogram from every Nth row and column (default 8: 1.125 renders a pixel;
# 0.9 dB below two passes' palette on Plate 6's emulated screen, 4 is 0.8 dB
# closer and 11 % more instructions, docs/firmware.md), or passes (every row
# rendered twice, the older default).
# --set: a Tek 4125 profile setting, given to the bake and to the host's
# render alike; on netduinoplus2 the default is strategy=runs, the strategy
# that streams rows with no frame (a 512x512 frame is 256 KiB, twice the
# part's RAM; docs/firmware.md, "The driver without a frame").
# --board: mps2-an385 (default; projected at 72 MHz, an STM32F103-class M3;
# linked with --ram board unless told) or netduinoplus2 (the STM32F405,
# projected at its 168 MHz; linked with the part's 128 KiB and 1 MiB, so a
# scene that does not fit fails the link or runs out of heap, and says so).
# Method: scripts/firmware.sh --icount --ram board runs the firmware under
# QEMU with -icount shift=0, where the firmware's SysTick clock reads one
# nanosecond per instruction executed (calibrated: a loop of 10^8 and 10^9
# known instructions reads 10^8 + 40 and 10^9 + 40 ns), so the report's
# virtual time is the instruction count. The board's 4 MiB of RAM are linked
# so a scene over the 256 KiB budget still runs; its peak RAM is reported
# against the board's budget. Time = instructions x CPI / clock, printed at
# CPI 1.0 (the floor: the M3 issues one instruction a cycle, LLVM's
# ARMScheduleM3.td IssueWidth = 1) and at FIRMWARE_CPI (default 1.5, an
# estimate: Arm's Cortex-M3 instruction timing table gives 1 cycle for ALU
# and multiply, 2 for a load, 1 + 1..3 for a taken branch, 3..5 for UMULL,
# at zero wait states; docs/firmware.md). Flash is .text + .ARM.extab +
# .ARM.exidx + .data (the image as stored). The stream is compared with the
# host's `lattice render --arith fixed --threads 1 --histogram small`
# (scripts/firmware.sh does, and fails on a difference).
# Tunables: FIRMWARE_CPI, FIRMWARE_TIMEOUT (QEMU seconds, default 7200).
set -euo pipefail
source "$(dirname "$0")/lib.sh"
cd "$root"
size=512x512 scene=scenes/fuzzy-sphere-1000.toml board=mps2-an385 ram="" mode=sample sample=8 sets=()
bench_parse --board=board --ram=ram --size=size --scene=scene --mode=mode --sample=sample --set+=sets -- "$@"
cpi=${FIRMWARE_CPI:-1.5}
case $board in
  mps2-an385) mhz=72 budget=262144 ram=${ram:-board} ;;
  netduinoplus2) mhz=168 budget=131072 ram=${ram:-budget}; ((${#sets[@]})) || sets=(strategy=runs) ;;
  *) echo "bench/firmware.sh: --board is mps2-an385 or netduinoplus2" >&2; exit 2 ;;
esac
out=out/bench-firmware/$board
name="$(basename "$scene" .toml)-$size"
set_args=()
for kv in "${sets[@]}"; do set_args+=(--set "$kv"); name+="-${kv//[^A-Za-z0-9]/}"; done
sampling=()
[[ $mode == passes ]] || { name+="-$mode$sample"; sampling=(--sample "$sample"); }
start=$SECONDS
export FIRMWARE_TIMEOUT=${FIRMWARE_TIMEOUT:-7200}  # exported: scripts/firmware.sh reads it
same=byte-identical
bash scripts/firmware.sh "$scene" --board "$board" --size "$size" --mode "$mode" "${sampling[@]}" --icount --ram "$ram" \
  "${set_args[@]}" \
  --out "$out" || { status=$?; grep -q DIFFERENT "$out/$name.compare" 2>/dev/null && same=DIFFERENT || exit $status; }
wall=$((SECONDS - start))
report="$out/$name.report"
instructions=$(sed -nE 's/.*virtual time ([0-9]+) ns.*/\1/p' "$report")
peak=$(sed -nE 's/.*RAM peak ([0-9]+) B.*/\1/p' "$report")
flash=$(awk '$1 ~ /^\.(text|ARM\.extab|ARM\.exidx|data)$/ {s += $2} END {print s}' "$out/$name.sizes")

python3 - "$instructions" "$cpi" "$peak" "$flash" "$size" "$same" "$wall" "$mhz" "$budget" "$board" "--mode $mode ${sampling[*]}" <<'PY'
import sys
ins, cpi, peak, flash, size, same, wall = int(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5], sys.argv[6], int(sys.argv[7])
mhz, budget, board = int(sys.argv[8]), int(sys.argv[9]), sys.argv[10]
t1 = ins / (mhz * 1e6)
tc = ins * cpi / (mhz * 1e6)
print(f"| board | size | instructions | {mhz} MHz, CPI 1.0 | {mhz} MHz, CPI {cpi:g} | peak RAM | flash | thesis (Sun 3/60) |")
print("|---|---|---|---|---|---|---|---|")
print(f"| {board} | {size} | {ins:,} | {t1/60:.1f} min | {tc/60:.1f} min | {peak:,} B | {flash:,} B | 12.1 h |")
print(f"targets: <= 3.0e10 instructions: {'met' if ins <= 3.0e10 else 'NOT met'}; "
      f"RAM within {budget // 1024} KiB: {'met' if peak <= budget else 'NOT met'} ({peak / budget:.2f} x); "
      f"flash within 1 MiB: {'met' if flash <= 1048576 else 'NOT met'}")
print(f"stream vs host (both {sys.argv[11]}): {same}; QEMU wall time {wall} s")
PY
