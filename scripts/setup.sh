#!/usr/bin/env bash
# Installs the Debian packages Lattice builds and tests with, only those
# missing, so it is safe to run again and again. lld links the static build
# with its hot code side by side (docs/memory.md, "Code pages"). gnuplot-nox: the Tek 4125
# emulator's tests decode the streams its tek410x and tek40xx terminals
# write. `--terminals` adds the terminals people own and the programs that
# check our pictures of them: libsixel-bin (sixel2png, img2sixel), xterm, xvfb
# and x11-apps (xwd), for the sixel and Tek 4014 tests
# (tests/support/xterm_capture.hpp; scripts/test.sh asks for them), and
# plotutils, whose `graph -T tek` runs inside `lattice term --device tek4014`. `--bench`
# adds the peers the benchmarks compare against (POV-Ray,
# Embree, pngquant, GNU time, and libsixel-dev: libsixel's headers and library,
# for bench/sixel_encoder_bench, which times libsixel's sixel_encode beside our
# sixel encoder in one process; without it that benchmark is not built; and
# libspng-dev: libspng, a contender of bench/png_encoder_bench, which chose
# the PNG encoder io/png_encoder.hpp builds on zlib; without it that
# benchmark compares libpng and ours only);
# `--fuzz` adds clang 14, its runtime libraries
# (libFuzzer, ASan, UBSan: libclang-rt-14-dev) and llvm-14 (llvm-symbolizer),
# for scripts/fuzz.sh and the sanitizer build (scripts/test.sh asks for it);
# `--firmware` adds the ARM Cortex-M toolchain (gcc-arm-none-eabi, newlib and
# its libstdc++) and qemu-system-arm, for scripts/firmware.sh and the
# firmware tests (scripts/test.sh asks for them too; docs/firmware.md), and
# ccache: the two boards' images compile the same core with the same flags,
# so the second is served from the first even on a fresh machine (the
# firmware step of scripts/test.sh: 243 s with no ccache, 140 s with an
# empty cache; docs/testing.md).
set -euo pipefail

packages=(cmake ninja-build g++ make pkg-config git catch2 libglm-dev libpng-dev zlib1g-dev libusb-1.0-0-dev
          libtomlplusplus-dev libcli11-dev libfmt-dev gnuplot-nox lld)
for option in "$@"; do
  case $option in
    --terminals) packages+=(libsixel-bin xterm xvfb x11-apps plotutils) ;;
    --bench) packages+=(povray libembree-dev pngquant time python3 libsixel-dev libspng-dev) ;;
    --fuzz) packages+=(clang-14 libclang-rt-14-dev llvm-14) ;;
    --firmware) packages+=(gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib qemu-system-arm ccache) ;;
    *) echo "setup.sh: unknown option $option (known: --terminals, --bench, --fuzz, --firmware)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
