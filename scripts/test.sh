#!/usr/bin/env bash
# The whole test suite: set-up, the layer check, build, every test through
# CTest (the firmware's under QEMU as a step of its own), the static build, the sanitizer build of every test (clang, ASan +
# UBSan), and a short run of each fuzzer (scripts/fuzz.sh, 30 s a harness).
# Each step prints its wall time, so CI's budget can be watched
# (docs/testing.md).
set -euo pipefail
cd "$(dirname "$0")/.."
step() {
  local name=$1 start=$SECONDS
  shift
  "$@"
  echo "test.sh: step '$name' took $((SECONDS - start)) s"
}
bash scripts/setup.sh --fuzz --firmware
step layers bash scripts/check-layers.sh
step build bash scripts/build.sh
step ctest bash -c 'cd build && ctest --output-on-failure -j "$(nproc)" -E "^firmware:"'
step firmware bash -c 'cd build && ctest --output-on-failure -j "$(nproc)" -R "^firmware:"'
step static bash scripts/check-static.sh
step sanitizers bash scripts/check-sanitizers.sh
step fuzz bash scripts/fuzz.sh "${LATTICE_FUZZ_SECONDS:-30}"
