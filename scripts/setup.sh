#!/usr/bin/env bash
# Installs the Debian packages Lattice builds and tests with, only those
# missing, so it is safe to run again and again. gnuplot-nox: the Tek 4125
# emulator's tests decode the streams its tek410x and tek40xx terminals
# write. `--bench` adds the peers the benchmarks compare against (POV-Ray,
# Embree, pngquant, GNU time).
set -euo pipefail

packages=(cmake g++ make pkg-config git catch2 libglm-dev libpng-dev libusb-1.0-0-dev
          libtomlplusplus-dev libcli11-dev libfmt-dev gnuplot-nox)
if [[ "${1:-}" == "--bench" ]]; then
  packages+=(povray libembree-dev pngquant time python3)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
