#!/usr/bin/env bash
# The test suite in two tiers (docs/testing.md, "Two tiers"):
#   scripts/test.sh        set-up, the layer check, the build, and every CTest
#                          suite, the firmware's under QEMU among them: what a
#                          contributor runs before asking for a review.
#   scripts/test.sh --all  all of that, then the static build, the sanitizer
#                          build of every test (clang, ASan + UBSan) and a short
#                          run of each fuzzer (scripts/fuzz.sh, 30 s a harness):
#                          what CI runs (.ci/run).
# Each step prints its wall time and the last line sums them, so the budget of
# each tier can be watched (targets: 10 and 30 minutes on 2 cores).
# Tunables (environment): LATTICE_FUZZ_SECONDS (default 30).
set -euo pipefail
cd "$(dirname "$0")/.."

usage() { sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; }
all=0
for arg in "$@"; do
  case $arg in
    --all) all=1 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "test.sh: unknown option '$arg' (known: --all, --help)" >&2; exit 2 ;;
  esac
done

summary=()
step() {
  local name=$1 start=$SECONDS
  shift
  "$@"
  summary+=("$name $((SECONDS - start)) s")
  echo "test.sh: step '$name' took $((SECONDS - start)) s"
}

started=$SECONDS
if ((all)); then
  step setup bash scripts/setup.sh --terminals --fuzz --firmware
else
  step setup bash scripts/setup.sh --terminals --firmware
fi
step layers bash scripts/check-layers.sh
step build bash scripts/build.sh
step ctest bash -c 'cd build && ctest --output-on-failure -j "$(nproc)" -E "^firmware:"'
step firmware bash -c 'cd build && ctest --output-on-failure -j "$(nproc)" -R "^firmware:"'
if ((all)); then
  step static bash scripts/check-static.sh
  step sanitizers bash scripts/check-sanitizers.sh
  # One fuzzer a core: the seven 30 s runs take half the wall time, each run as long.
  step fuzz env FUZZ_JOBS="${FUZZ_JOBS:-$(nproc)}" bash scripts/fuzz.sh "${LATTICE_FUZZ_SECONDS:-30}"
fi
tier=contributor
((all)) && tier="--all (CI)"
echo "test.sh: $tier tier passed in $((SECONDS - started)) s (${summary[*]/%/;})"
