#!/usr/bin/env bash
# Rewrites every golden file under tests/golden/ from the current code.
# Review the result with `git diff --stat tests/golden` and look at changed
# PNGs before committing: a golden is only as good as the eyes that checked it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
LATTICE_REGENERATE_GOLDENS=1 ctest -j "$(nproc)" --output-on-failure
