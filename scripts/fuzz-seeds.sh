#!/usr/bin/env bash
# Builds the fuzzers' seed corpora from the project's own files, so no corpus
# binaries are committed: scenes/*.toml for the scene loader, the golden Tek
# streams for the Tek decoders, the golden sixel streams for the sixel one, the golden PNGs for the PNG reader, and small
# .lht files rasterized by the `lattice` binary given (a sphere and a
# capsule in each entry precision, and the sphere in the compressed form).
#   scripts/fuzz-seeds.sh OUT_DIR LATTICE_BINARY
# Writes OUT_DIR/<target>/ for scene, lht, tek4125, tek4027, tek4014, png, sixel, cli. The
# regression inputs (fuzz/regressions/<target>/) join each corpus too.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: fuzz-seeds.sh OUT_DIR LATTICE_BINARY}
lattice=${2:?usage: fuzz-seeds.sh OUT_DIR LATTICE_BINARY}
for t in scene lht tek4125 tek4027 tek4014 png sixel cli; do
  rm -rf "${out:?}/$t"
  mkdir -p "$out/$t"
  if [[ -d fuzz/regressions/$t ]]; then cp fuzz/regressions/$t/* "$out/$t/" 2>/dev/null || true; fi
done
cp scenes/*.toml "$out/scene/"
for f in tests/golden/tek4125/*.tek tests/golden/tek4125/scenes/*.tek; do cp "$f" "$out/tek4125/"; done
for f in tests/golden/tek4027/*.tek tests/golden/tek4027/scenes/*.tek; do cp "$f" "$out/tek4027/"; done
for f in tests/golden/tek4014/*.tek; do cp "$f" "$out/tek4014/"; done
for f in tests/golden/sixel/*.six tests/golden/sixel/scenes/*.six; do cp "$f" "$out/sixel/"; done
# PNGs: the golden pictures (the largest is about 12 KB), named by their path
# so equal base names in different folders stay apart.
while IFS= read -r f; do cp "$f" "$out/png/$(echo "${f#tests/golden/}" | tr / _)"; done \
  < <(find tests/golden -name '*.png' -size -16k)
for precision in thesis wide compact; do
  "$lattice" rasterize --shape sphere --radius 1.5 --precision "$precision" --threads 1 \
    -o "$out/lht/sphere-$precision.lht" >/dev/null
  "$lattice" rasterize --shape capsule --radius 0.6 --length 2 --precision "$precision" --threads 1 \
    -o "$out/lht/capsule-$precision.lht" >/dev/null
  # The compressed form: .lht version 3.
  "$lattice" rasterize --shape sphere --radius 1.5 --precision "$precision" --form compressed --threads 1 \
    -o "$out/lht/sphere-$precision-compressed.lht" >/dev/null
done
# The command line (fuzz/command_line.cpp): one program per command index,
# each naming a few flags, with a golden 4125 stream as the input file.
streams=(tests/golden/tek4125/*.tek)
stream=${streams[0]}
for i in $(seq 0 15); do
  { printf "$(printf '\\x%02x' "$i")\x01\x02\x03\x04\x05\x06\x07\x08\xff"; head -c 400 "$stream"; } >"$out/cli/cmd-$i"
done
for t in scene lht tek4125 tek4027 tek4014 png sixel cli; do
  echo "fuzz-seeds: $t: $(find "$out/$t" -type f | wc -l) files, $(du -sk "$out/$t" | cut -f1) KiB"
done
