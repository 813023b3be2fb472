#!/usr/bin/env bash
# The main job: build gdpn and run the flagship example headless, printing its summary: the
# production line of examples/factory (a robotic arm, two painting stations, three conveyors),
# with the cycle times measured beside their bounds and the line's own figures.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh >/dev/null
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" >/dev/null
exec build/release/apps/gdpn/gdpn run examples/factory "$@"
