#!/usr/bin/env bash
# The main job: build gdpn and run the best example headless, printing its summary.
# Until the flagship factory example exists, that is the feeder of examples/plant: a net
# driving a hinged arm and spawning boxes onto a conveyor.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh >/dev/null
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" >/dev/null
exec build/release/apps/gdpn/gdpn run examples/plant/feeder "$@"
