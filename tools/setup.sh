#!/usr/bin/env bash
# Installs every Debian package Baize needs to build, test and benchmark.
# Idempotent: when everything is already installed it does nothing and prints nothing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  python3                # the command-line tests read JSON and CSV with it
  libeigen3-dev          # small fixed-size linear algebra in the physics
  nlohmann-json3-dev     # scene, result and output JSON
  libcli11-dev           # the baize command line
  libgtest-dev libgmock-dev  # unit tests
  libbenchmark-dev       # micro benchmarks
  libcairo2-dev          # charts (render/line_chart): drawing and PNG output
  libbox2d-dev           # the Box2D 2.4.1 baseline of baize bench accuracy
  libosmesa6-dev         # off-screen OpenGL (llvmpipe) for baize render
  libpng-dev             # PNG pictures
  libgif-dev             # animated GIFs of shots (render/gif_writer)
  libsdl2-dev            # the baize-view window
  libgl1-mesa-dri        # Mesa's software rasteriser behind EGL: baize-view with no display (tests)
  libfreetype-dev fonts-dejavu-core  # legend text and the charts' font (DejaVu Sans)
  libfontconfig-dev      # finding that font at run time
  python3-dev python3-pybind11 python3-numpy  # the Python package baize
  python3-pytest         # its tests
  python3-distributed    # spreading batches over a Dask cluster (baize.dask) and its test
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

if [[ $(id -u) -ne 0 ]]; then
  echo "setup.sh: missing packages: ${missing[*]}; run as root (or with sudo) to install them" >&2
  exit 1
fi
echo "setup.sh: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
