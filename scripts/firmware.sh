#!/usr/bin/env bash
# The firmware end to end (docs/firmware.md): bake a scene with the host
# `lattice`, build the image for a board of firmware/boards/, run it under
# that board's QEMU machine with its serial port to a file, compare the
# stream with the host's `lattice render --arith fixed` (it prints
# "identical" or the first differing byte, and fails on a difference), and
# decode it with our Tek 4125 emulator to a PNG.
#   scripts/firmware.sh SCENE [--board NAME] [--size WxH] [--set key=value ...] [--mode MODE] [--sample N] [--out DIR] [--icount] [--ram board]
# --board: mps2-an385 (the default; Cortex-M3) or netduinoplus2 (STM32F405).
# --mode: the quantizer pipeline's mode, given to the bake and the host render
# alike: passes (the default: every row rendered twice) or sample (the
# histogram from every 4th row, then one full pass: 1.25 renders a pixel);
# --sample N: sample mode's step (the pipeline's --sample, default 4).
# Writes DIR/NAME.tek (the UART bytes), DIR/NAME.png, DIR/NAME.report (the
# firmware's own report: stream bytes, palette, RAM high-water marks) and,
# with --icount, the report's virtual time is the instruction count (QEMU
# -icount shift=0; bench/firmware.sh). --ram board links with all the RAM
# QEMU maps instead of the part's, to measure what does not fit.
# DIR defaults to out/firmware.
# Tunables (environment): LATTICE_EXE (host binary, default build/app/lattice),
# FIRMWARE_BUILD (default build-firmware), FIRMWARE_TIMEOUT (seconds of QEMU,
# default 900). Exit 77 when the ARM toolchain or QEMU is missing
# (scripts/setup.sh --firmware installs them).
set -euo pipefail
cd "$(dirname "$0")/.."

usage() { sed -n '2,23p' "$0" | sed 's/^# \{0,1\}//'; exit "${1:-0}"; }
scene="" board=mps2-an385 size="64x64" out="out/firmware" icount=0 ram=budget sets=() mode=passes sample=
while (($#)); do
  case $1 in
    --size) size=$2; shift 2 ;;
    --board) board=$2; shift 2 ;;
    --set) sets+=(--set "$2"); shift 2 ;;
    --mode) mode=$2; shift 2 ;;
    --sample) sample=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --icount) icount=1; shift ;;
    --ram) ram=$2; shift 2 ;;
    -h|--help) usage ;;
    -*) echo "firmware.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) [[ -z $scene ]] || { echo "firmware.sh: one scene only" >&2; exit 2; }; scene=$1; shift ;;
  esac
done
[[ -n $scene ]] || { echo "firmware.sh: give a scene file (see --help)" >&2; exit 2; }
[[ -f $scene ]] || { echo "firmware.sh: $scene: no such scene file" >&2; exit 2; }

# The board's row (firmware/boards/BOARD/board.tsv): name, QEMU machine, CPU, ...
[[ $board != */* && -f firmware/boards/$board/board.tsv ]] ||
  { echo "firmware.sh: --board $board is not a folder of firmware/boards/ ($(ls firmware/boards | tr '\n' ' '))" >&2; exit 2; }
row=$(awk '$1 !~ /^#/' "firmware/boards/$board/board.tsv")
read -r _ machine cpu _ <<<"$row"

for tool in arm-none-eabi-g++ qemu-system-arm; do
  if ! command -v "$tool" >/dev/null; then
    echo "firmware.sh: $tool is not installed: run scripts/setup.sh --firmware" >&2
    exit 77
  fi
done
lattice=${LATTICE_EXE:-build/app/lattice}
[[ -x $lattice ]] || { echo "firmware.sh: $lattice missing: build the host first (scripts/build.sh)" >&2; exit 2; }

name="$(basename "$scene" .toml)-$size"
for kv in "${sets[@]}"; do [[ $kv == --set ]] || name+="-${kv//[^A-Za-z0-9]/}"; done
[[ $mode == passes ]] || name+="-$mode"
pipeline=(--mode "$mode")
[[ -z $sample ]] || { pipeline+=(--sample "$sample"); name+="$sample"; }
build=${FIRMWARE_BUILD:-build-firmware}
[[ $board == mps2-an385 ]] || build+="-$board"
[[ $ram == budget || $ram == board ]] || { echo "firmware.sh: --ram is budget or board" >&2; exit 2; }
[[ $ram == budget ]] || build+="-$ram"
build=$(realpath -m "$build")
mkdir -p "$build/scenes" "$out"
"$lattice" bake "$scene" --size "$size" "${sets[@]}" "${pipeline[@]}" -q -o "$build/scenes/$name.cpp.new"
# Only a changed scene relinks (cmp keeps the old file's time stamp).
if cmp -s "$build/scenes/$name.cpp.new" "$build/scenes/$name.cpp"; then rm "$build/scenes/$name.cpp.new"
else mv "$build/scenes/$name.cpp.new" "$build/scenes/$name.cpp"; fi

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
# One build folder for every scene (the core compiles once); a lock keeps
# two runs (ctest -j) from building in it at the same time.
exec 9>"$build/.lock"
flock 9
cmake -S firmware -B "$build" -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/arm-cortex-m3.cmake" \
  -DLATTICE_SCENES_DIR="$build/scenes" -DLATTICE_BOARD="$board" -DLATTICE_FIRMWARE_CPU="$cpu" -DLATTICE_FIRMWARE_RAM="$ram" -DLATTICE_WERROR=ON "${launcher[@]}" >/dev/null
if ! cmake --build "$build" --target "firmware-$name" -j "$(nproc)" >"$build/$name.log" 2>&1; then
  cat "$build/$name.log" >&2
  if grep -qE "will not fit|overflowed|exceeded" "$build/$name.log" && [[ -f $build/firmware-$name.map ]]; then
    # What does not fit: the largest input sections of the failed link.
    echo "firmware.sh: the image does not fit $board; its largest input sections:" >&2
    # hex() instead of gawk's strtonum: Debian's default awk is mawk.
    awk 'function hex(s,   n, i, c) { n = 0; s = tolower(substr(s, 3))
           for (i = 1; i <= length(s); i++) { c = index("0123456789abcdef", substr(s, i, 1)); n = n * 16 + c - 1 }
           return n }
         NF >= 3 && $1 ~ /^\./ && $2 ~ /^0x/ && $3 ~ /^0x/ {print hex($3), $1, $4}
         NF == 3 && $1 ~ /^0x/ && $2 ~ /^0x/ && prev ~ /^ \./ {split(prev, p, " "); print hex($2), p[1], $3}
         {prev = $0}' "$build/firmware-$name.map" | sort -rn | head -12 >&2
  fi
  exit 1
fi
flock -u 9
elf="$build/firmware-$name.elf"
arm-none-eabi-size -A "$elf" | awk '$1 ~ /^\.(text|ARM\.extab|ARM\.exidx|eh_frame|data|bss)$/ {print}' >"$out/$name.sizes"

qemu=(qemu-system-arm -M "$machine" -nographic -monitor none -semihosting-config enable=on,target=native
      -serial "file:$out/$name.tek" -kernel "$elf")
status=0
if ((icount)); then
  # -icount shift=0: the virtual clock advances 1 ns per instruction, so the
  # virtual time the firmware reports is its instruction count.
  timeout "${FIRMWARE_TIMEOUT:-900}" "${qemu[@]}" -icount shift=0 2>"$out/$name.report" || status=$?
else
  timeout "${FIRMWARE_TIMEOUT:-900}" "${qemu[@]}" 2>"$out/$name.report" || status=$?
fi
cat "$out/$name.report" >&2
if ((status != 0)); then
  echo "firmware.sh: the firmware exited with status $status (124: QEMU timed out)" >&2
  exit 1
fi
"$lattice" emulate "$out/$name.tek" --device tek4125 "${sets[@]}" -o "$out/$name.png"
echo "firmware.sh: $out/$name.tek ($(stat -c %s "$out/$name.tek") bytes), $out/$name.png"
# The host's stream with the same flags: the firmware's must be the same bytes.
w=${size%x*} h=${size#*x}
"$lattice" render "$scene" --arith fixed --device tek4125 --width "$w" --height "$h" --histogram small --threads 1 \
  "${sets[@]}" "${pipeline[@]}" -q --stream "$out/$name.host.tek"
if cmp -s "$out/$name.tek" "$out/$name.host.tek"; then
  echo "firmware.sh: identical: the $board stream equals the host's ($(stat -c %s "$out/$name.tek") bytes)" |
    tee "$out/$name.compare"
else
  first=$(cmp "$out/$name.tek" "$out/$name.host.tek" 2>&1 | head -1 || true)
  byte=$(cmp -l "$out/$name.tek" "$out/$name.host.tek" 2>/dev/null | head -1 || true)
  echo "firmware.sh: DIFFERENT: the $board stream is not the host's: $first${byte:+ (offset, firmware, host in octal: $byte)}" |
    tee "$out/$name.compare" >&2
  exit 1
fi
