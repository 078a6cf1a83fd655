#!/usr/bin/env bash
# The main job: install what is missing, build, and render the default scene
# (the thesis's Plate 6, a sphere with 1000 lattice hairs) through the
# Tektronix 4125 driver (its default, strict profile: docs/tek-sources.md) to a
# command stream file, plus the PNG the emulator draws from that very stream,
# and a truecolour PNG for comparison.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh --target lattice
mkdir -p out
scene=scenes/fuzzy-sphere-1000.toml
./build/app/lattice render "$scene" --device tek4125 --stream out/default.tek -o out/default-tek4125.png
./build/app/lattice render "$scene" -o out/default-truecolour.png
echo
echo "Tek 4125 command stream:        out/default.tek ($(stat -c %s out/default.tek) bytes)"
echo "what a 4125 shows (emulated):   out/default-tek4125.png"
echo "truecolour render:              out/default-truecolour.png"
echo "send it to a terminal with:     ./build/app/lattice send out/default.tek --port auto --baud 38400"
