#!/usr/bin/env bash
# One command for the figures in docs/benchmarks.md: builds the `lattice` CLI,
# render_bench and embree_peer_bench (Release, warnings as errors) and runs
#   render_bench        every example scene, float/double, 1/2 threads, and
#                       lattice vs full ray trace of the fuzzy spheres at 512x512
#   embree_peer_bench   Lattice's CSG union + BVH against Embree 3's spheres
#   povray-peer.sh      POV-Ray 3.7 against `lattice render`, same scenes
#   peers.sh            ours (lattice mode, --full), POV-Ray and the Embree peer
#                       (bench/peers/) alternating on six scenes (peers.md)
# Each writes a small table to bench/results/<name>.txt (plain text; pictures
# stay in a temporary directory).
#
#   bench/run-all.sh [--build-dir DIR (default build-bench)] [--runs N] [--jobs J] [--quick]
#
# --quick: 3 runs, and the 5000-hair sphere is left out (a smoke run).
# Peers come from Debian packages: scripts/setup.sh --bench.
set -euo pipefail

source "$(dirname "$0")/lib.sh"
here="$root/bench"
build="$root/build-bench"
runs=5
jobs=2
quick=0
bench_parse --build-dir=build --runs=runs --jobs=jobs --quick:quick=1 -- "$@"
# --quick is 3 runs, whatever --runs says.
((quick)) && runs=3
results="$here/results"
mkdir -p "$results"

cmake -S "$root" -B "$build" -DLATTICE_WERROR=ON -DCMAKE_BUILD_TYPE=Release -DLATTICE_EMBREE_PEER=ON >/dev/null
targets=(lattice render_bench)
# bench/CMakeLists.txt defines embree_peer_bench only when Embree 3 is found.
available=$(cmake --build "$build" --target help)
if [[ "$available" == *embree_peer_bench* ]]; then
  targets+=(embree_peer_bench embree_peer)
else
  echo "run-all.sh: Embree 3 not found (scripts/setup.sh --bench installs libembree-dev); skipping its peer" >&2
fi
cmake --build "$build" --target "${targets[@]}" -j"$jobs"

machine() {
  echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')"
  echo "# load average before: $(bench_loadavg)"
}

# Writes stdin to bench/results/$1.txt atomically, echoing it as it comes.
keep() {
  local file="$results/$1.txt"
  tee "$file.tmp-$$"
  mv "$file.tmp-$$" "$file"
}

fuzzy=(--full-scene "$root/scenes/fuzzy-sphere-1000.toml")
[[ $quick == 1 ]] || fuzzy+=(--full-scene "$root/scenes/fuzzy-sphere-5000.toml")
scenes=()
for s in "$root"/scenes/*.toml; do
  [[ $quick == 1 && "$s" == *fuzzy-sphere-5000* ]] || scenes+=("$s")
done

{
  machine
  "$build/bench/render_bench" --runs "$runs" "${fuzzy[@]}" "${scenes[@]}"
  echo "# load average after: $(bench_loadavg)"
} | keep render

if [[ " ${targets[*]} " == *" embree_peer_bench "* ]]; then
  {
    machine
    "$build/bench/embree_peer_bench" --runs "$runs"
    echo "# load average after: $(bench_loadavg)"
  } | keep embree-peer
fi

if command -v povray >/dev/null; then
  { machine; "$here/povray-peer.sh" --build-dir "$build" --runs "$runs"; } | keep povray-peer
else
  echo "run-all.sh: povray not found (scripts/setup.sh --bench); skipping its peer" >&2
fi
peer_scenes="fuzzy-sphere-1000 fuzzy-sphere-5000 thistle torus-floor sphere-hole thesis-camera"
[[ $quick == 0 ]] || peer_scenes="${peer_scenes/fuzzy-sphere-5000 /}"
"$here/peers.sh" --build-dir "$build" --runs "$runs" --scenes "$peer_scenes" --sphere-sweep --out "$results/peers.md"
echo "run-all.sh: tables in $results/"
