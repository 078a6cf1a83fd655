#!/usr/bin/env bash
# Rebuilds every picture and figure in docs/images/ from the scenes, with one
# command:
#   scripts/make-gallery.sh            # renders once each
#   RUNS=3 scripts/make-gallery.sh     # median of 3 timed runs (docs/gallery.md)
# Uses build/app/lattice (built with scripts/build.sh --target lattice when
# missing); LATTICE=/path/to/lattice picks another binary.
# Writes docs/images/*.png, timings.txt (wall and CPU seconds, peak RSS of each
# render), lattice-vs-full.txt (`lattice diff` of lattice vs --full) and
# table1.txt (`lattice table1`).
set -euo pipefail
cd "$(dirname "$0")/.."

LATTICE=${LATTICE:-build/app/lattice}
RUNS=${RUNS:-1}
OUT=docs/images
if [[ ! -x "$LATTICE" ]]; then
  if [[ "$LATTICE" == build/app/lattice ]]; then
    scripts/build.sh --target lattice
  else
    echo "make-gallery: $LATTICE is not an executable; build it or unset LATTICE" >&2
    exit 2
  fi
fi
if [[ ! -x /usr/bin/time ]]; then
  echo "make-gallery: /usr/bin/time is needed for the timings (apt-get install time)" >&2
  exit 2
fi
mkdir -p "$OUT"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

timings="$work/timings.txt"
{
  echo "# lattice render timings: median of $RUNS run(s); wall and CPU (user+sys) seconds, peak RSS"
  echo "# $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(date -u +%Y-%m-%d)"
  printf '%-28s %9s %9s %10s\n' picture wall_s cpu_s peak_MiB
} >"$timings"

median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# render NAME ARGS...: renders RUNS times into $OUT/NAME.png, records the medians.
render() {
  local name=$1
  shift
  local walls=() cpus=() rss=()
  for ((i = 0; i < RUNS; i++)); do
    /usr/bin/time -o "$work/time" -f '%e %U %S %M' "$LATTICE" render "$@" -q -o "$OUT/$name.png"
    read -r wall user sys kb <"$work/time"
    walls+=("$wall")
    cpus+=("$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')")
    rss+=("$kb")
  done
  printf '%-28s %9s %9s %10s\n' "$name" \
    "$(printf '%s\n' "${walls[@]}" | median)" \
    "$(printf '%s\n' "${cpus[@]}" | median)" \
    "$(printf '%s\n' "${rss[@]}" | median | awk '{ printf "%.1f", $1 / 1024 }')" >>"$timings"
  echo "make-gallery: $OUT/$name.png" >&2
}

# The thesis's pictures (512x512 is the scenes' default size).
render hook-lattice scenes/hook.toml
render hook-full scenes/hook.toml --full
render thistle-plate3 scenes/thistle.toml --no-lattice-shadows
render thistle-plate4 scenes/thistle.toml
render fuzzy-1000 scenes/fuzzy-sphere-1000.toml
render fuzzy-1000-full scenes/fuzzy-sphere-1000.toml --full
render fuzzy-5000 scenes/fuzzy-sphere-5000.toml

# The output chain: the same scene through the Tek command streams, as the
# emulators decode them.
render fuzzy-1000-tek4125 scenes/fuzzy-sphere-1000.toml --device tek4125 --stream "$work/fuzzy.tek4125"
render fuzzy-1000-tek4027 scenes/fuzzy-sphere-1000.toml --device tek4027 --stream "$work/fuzzy.tek4027"

# The example scenes at their own sizes.
render torus-floor scenes/torus-floor.toml
render sphere-hole scenes/sphere-hole.toml
render thesis-camera scenes/thesis-camera.toml

# Lattice vs full ray trace (thesis Table 2's fidelity column, measured).
"$LATTICE" diff "$OUT/fuzzy-1000.png" "$OUT/fuzzy-1000-full.png" --block 8 --gain 4 \
  -o "$OUT/fuzzy-1000-diff.png" >"$work/diff.txt"
"$LATTICE" diff "$OUT/hook-lattice.png" "$OUT/hook-full.png" --block 8 --gain 4 \
  -o "$OUT/hook-diff.png" >>"$work/diff.txt"
sed "s|$OUT/||g" "$work/diff.txt" >"$OUT/lattice-vs-full.txt"

"$LATTICE" table1 >"$OUT/table1.txt"
cp "$timings" "$OUT/timings.txt"
cat "$OUT/timings.txt" "$OUT/lattice-vs-full.txt"
