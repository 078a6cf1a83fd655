#!/usr/bin/env bash
# The whole test suite: set-up, build, every test through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/check-layers.sh
bash scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)"
cd ..
bash scripts/check-static.sh
