#!/usr/bin/env bash
# How long a newcomer waits for the compiler (docs/benchmarks.md, "Build time").
#   bench/build-time.sh [--runs N] [--rev REV] [--jobs J]
# Method: for each run, a clean configure (scripts/build.sh's flags, the
# generator scripts/build.sh picks) and a clean build, first of `lattice`
# alone (what scripts/main-job.sh builds), then, in a second clean folder, of
# everything (what scripts/test.sh builds), on J parallel jobs (default: the
# cores, nproc). ccache is switched off (CCACHE_DISABLE=1), so every object is
# compiled: the figure a fresh machine sees. With --rev REV the same is done on
# a checkout of REV (a temporary git worktree) in turn with the working tree,
# A B A B ..., so a comparison holds when the machine's speed drifts. Prints
# each run's wall seconds, the median per contender, and the load average.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
runs=1 rev="" jobs=$(nproc)
while (($#)); do
  case $1 in
    --runs) runs=$2; shift 2 ;;
    --rev) rev=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    -h|--help) sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench/build-time.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "bench/build-time.sh: --runs takes a whole number >= 1" >&2; exit 2; }

work=$(mktemp -d)
cleanup() {
  [[ -n $rev ]] && git -C "$root" worktree remove --force "$work/rev" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT TERM
contenders=("$root")
if [[ -n $rev ]]; then
  git -C "$root" worktree add --detach -q "$work/rev" "$rev"
  contenders+=("$work/rev")
fi

generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
# One clean configure + build of TARGET from SOURCE; prints the wall seconds.
build_once() {
  local source=$1 target=$2 dir=$work/build start
  rm -rf "$dir"
  start=$(date +%s.%N)
  CCACHE_DISABLE=1 cmake -S "$source" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DLATTICE_WERROR=ON \
    "${generator[@]}" >/dev/null
  CCACHE_DISABLE=1 cmake --build "$dir" -j "$jobs" --target "$target" >"$work/log" 2>&1 ||
    { tail -20 "$work/log" >&2; echo "bench/build-time.sh: the build of $target in $source failed" >&2; exit 1; }
  echo "$(date +%s.%N) - $start" | bc
}
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

declare -A times
echo "bench/build-time.sh: $runs run(s), $jobs jobs, generator ${generator[*]:-Unix Makefiles}, load $(cut -d' ' -f1-3 /proc/loadavg)"
for ((run = 1; run <= runs; run++)); do
  for source in "${contenders[@]}"; do
    name=working-tree
    [[ $source == "$root" ]] || name=$rev
    for target in lattice all; do
      seconds=$(build_once "$source" "$target")
      times[$name/$target]+="$seconds "
      printf '  run %d  %-14s %-8s %7.1f s\n' "$run" "$name" "$target" "$seconds"
    done
  done
done
echo "medians (load now $(cut -d' ' -f1-3 /proc/loadavg)):"
for key in "${!times[@]}"; do
  printf '  %-24s %7.1f s\n' "$key" "$(tr ' ' '\n' <<<"${times[$key]}" | grep . | median)"
done | sort
