#!/usr/bin/env bash
# Coverage-guided fuzzing of every surface that reads outside bytes
# (docs/testing.md, "Fuzzing").
#   scripts/fuzz.sh [SECONDS] [TARGET]
# Builds the libFuzzer harnesses with clang 14, AddressSanitizer and UBSan
# (-fno-sanitize-recover=all) in build-fuzz/, builds the seed corpora
# (scripts/fuzz-seeds.sh), then runs each harness (or only TARGET: scene,
# lht, tek4125, tek4027, tek4014, png, sixel, cli) for SECONDS (default 30).
#
# Method and tunables, per run:
# * Inputs the run finds go to build-fuzz/corpus/<target>/ (kept between
#   runs, so later runs start where earlier ones stopped); the seeds are read
#   from build-fuzz/seeds/<target>/.
# * A crash, leak, timeout, out-of-memory or sanitizer report stops the run
#   and its input is saved as build-fuzz/artifacts/<target>/<kind>-<sha1>;
#   the script exits 1 after the other targets have run. Once the defect is
#   fixed, copy the input to fuzz/regressions/<target>/ so the ordinary test
#   suite replays it (tests/fuzz/).
# * -timeout=10 s per input; -rss_limit_mb=2048 and -malloc_limit_mb=1024
#   (a single allocation past 1 GiB is a finding: no reader of ours needs
#   one for inputs of max_len bytes); max_len per target below, about the
#   size of the largest seed, so runs explore structure rather than bulk.
# * FUZZ_JOBS=N runs N targets at once (default 1; scripts/test.sh runs one
#   a core); FUZZ_NICE=N runs them under `nice -n N`.
# * LATTICE_SEED_LATTICE=PATH: the `lattice` that rasterizes the .lht seeds
#   (default build/app/lattice when it exists).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
seconds=${1:-30}
only=${2:-}
all=(scene lht tek4125 tek4027 tek4014 png sixel cli)
# The command line prints a line for every refusal: its output is closed
# (libFuzzer still reports findings on its own descriptor).
declare -A extra=([cli]="-close_fd_mask=3")
declare -A max_len=([scene]=8192 [lht]=65536 [tek4125]=16384 [tek4027]=16384 [tek4014]=16384 [png]=16384 [sixel]=16384 [cli]=512)
if [[ -n $only && -z ${max_len[$only]:-} ]]; then
  echo "fuzz.sh: unknown target '$only' (known: ${all[*]})" >&2
  exit 2
fi
if [[ -n $only ]]; then targets=("$only"); else targets=("${all[@]}"); fi

command -v clang++-14 >/dev/null || { echo "fuzz.sh: clang++-14 missing; run scripts/setup.sh --fuzz" >&2; exit 2; }
source scripts/cmake-args.sh
lattice_cmake_args build-fuzz
# -O2 with line tables only (LATTICE_SANITIZE adds -gline-tables-only): a
# finding's stack still names file and line, and the full debug information
# of RelWithDebInfo, which no report reads, is not compiled.
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -DNDEBUG" \
  -DCMAKE_CXX_COMPILER=clang++-14 \
  -DLATTICE_FUZZ=ON -DLATTICE_BUILD_TESTS=OFF -DLATTICE_BUILD_BENCH=OFF -DLATTICE_WITH_LIBUSB=OFF \
  "${cmake_args[@]}" >/dev/null
# The seeds are rasterized by any `lattice`: the ordinary build's when there
# is one (scripts/test.sh builds it first), else this folder's, so the
# command line is compiled a second time only when fuzz.sh runs alone.
seed_lattice=${LATTICE_SEED_LATTICE:-build/app/lattice}
fuzz_targets=($(printf 'fuzz_%s ' "${targets[@]}"))
[[ -x $seed_lattice ]] || { seed_lattice=build-fuzz/app/lattice; fuzz_targets+=(lattice); }
cmake --build build-fuzz -j "$(nproc)" --target "${fuzz_targets[@]}"
bash scripts/fuzz-seeds.sh build-fuzz/seeds "$seed_lattice"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:symbolize=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-$(command -v llvm-symbolizer-14 || true)}
mkdir -p build-fuzz/logs

run() {
  local t=$1
  mkdir -p "build-fuzz/corpus/$t" "build-fuzz/artifacts/$t"
  local log=build-fuzz/logs/$t.log
  local status=0
  nice -n "${FUZZ_NICE:-0}" "build-fuzz/fuzz/fuzz_$t" "build-fuzz/corpus/$t" "build-fuzz/seeds/$t" \
    -dict="fuzz/dict/$t.dict" -max_len="${max_len[$t]}" -timeout=10 ${extra[$t]:-} -rss_limit_mb=2048 -malloc_limit_mb=1024 \
    -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$t/" \
    >"$log" 2>&1 || status=$?
  local last
  last=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
  local execs rate
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  if ((status == 0)); then
    echo "fuzz.sh: $t: OK, ${seconds} s, execs $execs ($rate/s), $last"
  else
    echo "fuzz.sh: $t: FAILED (exit $status); input saved in build-fuzz/artifacts/$t/, log $log:" >&2
    grep -E 'ERROR|runtime error|SUMMARY|Test unit written|==[0-9]+==' "$log" | head -20 >&2 || true
  fi
  return $status
}

failed=()
jobs_max=${FUZZ_JOBS:-1}
declare -A pids=()
for t in "${targets[@]}"; do
  while ((${#pids[@]} >= jobs_max)); do
    for p in "${!pids[@]}"; do
      if ! kill -0 "$p" 2>/dev/null; then
        wait "$p" || failed+=("${pids[$p]}")
        unset "pids[$p]"
      fi
    done
    ((${#pids[@]} >= jobs_max)) && sleep 1
  done
  run "$t" &
  pids[$!]=$t
done
for p in "${!pids[@]}"; do wait "$p" || failed+=("${pids[$p]}"); done
if ((${#failed[@]})); then
  echo "fuzz.sh: findings in: ${failed[*]} (inputs under build-fuzz/artifacts/)" >&2
  exit 1
fi
echo "fuzz.sh: ${#targets[@]} target(s), ${seconds} s each, no findings"
