#!/usr/bin/env bash
# Configures and builds into build/ (Release, warnings as errors).
# Extra arguments go to `cmake --build` (e.g. --target lattice).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/cmake-args.sh
lattice_cmake_args build
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DLATTICE_WERROR=ON "${cmake_args[@]}" >/dev/null
cmake --build build -j "$(nproc)" "$@"
