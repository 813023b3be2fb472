#!/usr/bin/env bash
# Installs the Debian 12 packages gdpn needs to build, test and run.
# Idempotent: it asks apt only for the packages that are missing, and does
# nothing (not even `apt-get update`) when all of them are present.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config clang libclang-rt-14-dev git
  # physics and scripting
  libode-dev pybind11-dev python3-dev python3-pytest python3-numpy
  # experiments: signals as DataFrames (pandas), the HTML report's plots (matplotlib) and its
  # check in a real browser (chromium), sweeps on a Dask cluster (distributed)
  python3-pandas python3-matplotlib chromium python3-distributed
  # graphics and GUI
  libglfw3-dev libimgui-dev libepoxy-dev libegl-dev libgl-dev libgl1-mesa-dri xvfb xauth fonts-dejavu-core
  # the IDE's window driven as a user's hands drive it (tests/ide/window_keys.sh)
  xdotool
  # file formats
  libassimp-dev libcoin-dev libgdal-dev libstb-dev libtinygltf-dev
  libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libeigen3-dev libglm-dev
  # tests, benchmarks, movies
  libgtest-dev libgmock-dev libbenchmark-dev ffmpeg
  # net pictures: Graphviz lays out nets without positions; DejaVu Sans draws their text
  libgraphviz-dev fonts-dejavu-core
  # linear programs: bounds from the state equation
  libglpk-dev
  libsundials-dev
  # virtual commissioning: Modbus TCP (the server), mbpoll and pymodbus (the tests' clients and
  # the example's soft PLC; Debian's pymodbus 3.0 imports serial_asyncio, only recommended)
  libmodbus-dev mbpoll python3-pymodbus python3-serial-asyncio
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -o DPkg::Lock::Timeout=300 -qq
$sudo apt-get install -y -qq --no-install-recommends -o DPkg::Lock::Timeout=300 "${missing[@]}"
