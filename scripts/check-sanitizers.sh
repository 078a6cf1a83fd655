#!/usr/bin/env bash
# The whole test suite built with clang 14, AddressSanitizer and UBSan
# (-fno-sanitize-recover=all: the first report fails the test), in
# build-asan/, every CTest test run. Tests whose figure the sanitizers make
# meaningless (measured resident memory) are compiled with LATTICE_SANITIZED
# and say so as they skip (docs/testing.md lists them). Warnings are not
# errors here: clang warns where g++ does not, and the g++ build
# (scripts/build.sh) is the one that keeps -Werror.
#   scripts/check-sanitizers.sh        (scripts/setup.sh --fuzz installs clang)
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang++-14 >/dev/null ||
  { echo "check-sanitizers.sh: clang++-14 missing; run scripts/setup.sh --fuzz" >&2; exit 2; }
source scripts/cmake-args.sh
lattice_cmake_args build-asan
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-14 -DLATTICE_SANITIZE=ON \
  -DLATTICE_WERROR=OFF -DLATTICE_BUILD_BENCH=OFF "${cmake_args[@]}" >/dev/null
cmake --build build-asan -j "$(nproc)"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1:check_initialization_order=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-$(command -v llvm-symbolizer-14 || true)}
cd build-asan
ctest --output-on-failure -j "$(nproc)"
