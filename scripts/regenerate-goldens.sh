#!/usr/bin/env bash
# Rewrites the golden files under tests/golden/ from the current code: all of
# them, or one test area's (`scripts/regenerate-goldens.sh devices/tek4027`,
# `scripts/regenerate-goldens.sh devices/sixel` for tests/golden/sixel/).
# Review the result with `git diff --stat tests/golden` and look at changed
# PNGs before committing: a golden is only as good as the eyes that checked it.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ "${1:-}" == "--help" || "${1:-}" == "-h" ]]; then
  echo "usage: scripts/regenerate-goldens.sh [AREA]   (AREA as ctest names it, e.g. devices/tek4027 or devices/tek4014; default: all)"
  exit 0
fi
bash scripts/build.sh
cd build
if [[ $# -gt 0 ]]; then
  LATTICE_REGENERATE_GOLDENS=1 ctest -j "$(nproc)" --output-on-failure -R "^$1:"
else
  LATTICE_REGENERATE_GOLDENS=1 ctest -j "$(nproc)" --output-on-failure
fi
