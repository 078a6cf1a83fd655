#!/usr/bin/env bash
# Our sixel encoder beside libsixel's, encoder only (docs/sixel.md, "Encoder
# only"): Plate 6 (scenes/fuzzy-sphere-1000.toml, 512x512) rendered once and
# median-cut by `lattice quantize --dither none` to 16 and 256 colours, then
# both pictures encoded in-process, alternated, by build/bench/
# sixel_encoder_bench (its opening comment gives the method).
#   bench/sixel-encoder.sh [RUNS]     (default 101)
# The program is built only where libsixel-dev is found (scripts/setup.sh
# --bench installs it); without it this script says so and exits 0.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-101}
lattice=build/app/lattice
bench=build/bench/sixel_encoder_bench
if [[ ! -x $bench ]]; then
  echo "sixel-encoder.sh: skipped: $bench is not built (it needs libsixel-dev: scripts/setup.sh --bench)"
  exit 0
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$lattice" render scenes/fuzzy-sphere-1000.toml -o "$work/plate6.png" -q 2>/dev/null
for k in 16 256; do
  "$lattice" quantize "$work/plate6.png" --colors "$k" --dither none -o "$work/q$k.png" -q
done
echo "load: $(uptime | sed 's/.*load average: //')"
"$bench" --runs "$runs" "$work/q16.png" "$work/q256.png"
echo "load: $(uptime | sed 's/.*load average: //')"
