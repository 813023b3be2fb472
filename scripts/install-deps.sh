#!/usr/bin/env bash
# Installs the Debian 12 packages gdpn needs to build, test and run, then the npm packages
# of scripts/node (node-opcua, pinned by its package-lock.json) into scripts/node/node_modules.
# Idempotent: it asks apt only for the packages that are missing, and does
# nothing (not even `apt-get update`) when all of them are present; it runs `npm ci` only
# when scripts/node/node_modules was not installed from the lockfile as it is now.
set -euo pipefail

packages=(
  # toolchain; the Debian package (cpack: dpkg-shlibdeps needs file)
  build-essential cmake ninja-build pkg-config clang libclang-rt-14-dev git dpkg-dev file
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
  # virtual commissioning: OPC UA; node-opcua (npm, below) is the tests' real client and server
  # and the example's OPC UA controllers
  nodejs npm
)

missing=()
for p in "${packages[@]}"; do
  # NodeSource's nodejs package carries npm and conflicts with Debian's: its command will do
  if [ "$p" = npm ] && command -v npm >/dev/null; then continue; fi
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -o DPkg::Lock::Timeout=300 -qq
  $sudo apt-get install -y -qq --no-install-recommends -o DPkg::Lock::Timeout=300 "${missing[@]}"
fi

# the npm packages, exactly as the lockfile has them; the copy of the lockfile in node_modules
# says which lockfile they were installed from
node_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/node"
if cmp -s "$node_dir/package-lock.json" "$node_dir/node_modules/.gdpn-package-lock.json"; then
  echo "install-deps: scripts/node/node_modules is as its lockfile has it"
else
  echo "install-deps: npm ci in scripts/node"
  (cd "$node_dir" && npm ci --no-audit --no-fund --loglevel=error)
  cp "$node_dir/package-lock.json" "$node_dir/node_modules/.gdpn-package-lock.json"
fi
