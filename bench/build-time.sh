#!/usr/bin/env bash
# How long a newcomer waits for the compiler (docs/developing.md, "Build time"; figures from bench/build-time.sh).
#   bench/build-time.sh [--runs N] [--rev REV] [--jobs J] [--targets 'lattice all']
# Method: for each run and each target, a clean configure (scripts/build.sh's
# flags and generator: Ninja where installed) and a clean build in a new
# folder, on J parallel jobs (default: the cores). `lattice` is what
# scripts/main-job.sh builds, `all` what scripts/test.sh builds. ccache is
# switched off (CCACHE_DISABLE=1), so every object is compiled: the figure a
# fresh machine sees. With --rev REV the same is done on a checkout of REV (a
# temporary git worktree) in turn with the working tree, A B A B ..., so a
# comparison holds when the machine's speed drifts. Prints each build's wall
# and CPU seconds (user + system of the configure and the build, from GNU
# time: on a shared machine the CPU figure moves far less with the load than
# the wall one), the medians per contender and target, and the load average.
source "$(dirname "$0")/lib.sh"
cd "$root"
runs=1 rev="" jobs=$(nproc) targets="lattice all"
bench_parse --runs=runs --rev=rev --jobs=jobs --targets=targets -- "$@"
bench_positive --runs "$runs"
bench_positive --jobs "$jobs"
bench_workdir work
if [[ -n $rev ]]; then
  git -C "$root" worktree add --detach -q "$work/rev" "$rev" || bench_die "cannot check out $rev"
  # shellcheck disable=SC2064 # the folder's name is fixed now, on purpose
  trap "git -C '$root' worktree remove --force '$work/rev'; rm -rf '$work'" EXIT
fi
trap 'exit 130' INT TERM
contenders=("$root")
[[ -n $rev ]] && contenders+=("$work/rev")
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)

# One clean configure + build of TARGET from SOURCE; prints "WALL CPU" seconds.
build_once() {
  local source=$1 target=$2 dir=$work/build
  rm -rf "$dir"
  /usr/bin/time -f '%e %U %S' -o "$work/time" bash -c '
    CCACHE_DISABLE=1 cmake -S "$1" -B "$2" -DCMAKE_BUILD_TYPE=Release -DLATTICE_WERROR=ON "${@:5}" >/dev/null &&
    CCACHE_DISABLE=1 cmake --build "$2" -j "$3" --target "$4"' _ "$source" "$dir" "$jobs" "$target" \
    "${generator[@]}" >"$work/log" 2>&1 ||
    { tail -20 "$work/log" >&2; bench_die "the build of $target in $source failed" 1; }
  awk '{ printf "%.1f %.1f", $1, $2 + $3 }' "$work/time"
}

bench_need_time
declare -A times cpus
echo "$bench_name: $runs run(s), $jobs jobs, generator ${generator[*]:-Unix Makefiles}, load $(bench_loadavg)"
for ((run = 1; run <= runs; run++)); do
  for source in "${contenders[@]}"; do
    name=working-tree
    [[ $source == "$root" ]] || name=$rev
    for target in $targets; do
      result=$(build_once "$source" "$target") || exit 1
      read -r seconds cpu <<<"$result"
      times[$name/$target]+="$seconds "
      cpus[$name/$target]+="$cpu "
      printf '  run %d  %-14s %-8s %7.1f s wall %7.1f s CPU\n' "$run" "$name" "$target" "$seconds" "$cpu"
    done
  done
done
echo "medians (load now $(bench_loadavg)):"
for key in "${!times[@]}"; do
  # shellcheck disable=SC2086 # the list is whitespace-separated numbers
  printf '  %-24s %7s s wall %7s s CPU\n' "$key" "$(bench_median -f '%.1f' ${times[$key]})" \
    "$(bench_median -f '%.1f' ${cpus[$key]})"
done | sort
