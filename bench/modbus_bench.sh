#!/usr/bin/env bash
# Modbus TCP while the factory runs in real time (gdpn run --modbus, examples/factory with an
# io section added in a scratch copy: a region, a joint's angle, a belt's speed; a coil on a
# camera's field of view, which changes nothing the run does):
#   1. the round trip of one read of 4 input registers on loopback, a read every 2 ms as a
#      PLC polls (READS of them, default 5000): median and 99th percentile;
#   2. the highest scan rate one client sustains: scans (read the discrete input, read the 4
#      input registers, write the coil: 3 requests) back to back for 5 s, and the run's
#      real-time factor meanwhile.
# The client is Python on raw sockets (the PLC's side of the wire, no library in between).
# Needs a Release build (cmake --preset ci && cmake --build build/ci).
# Usage: bench/modbus_bench.sh [BUILD_DIR] [READS]
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh "${1:-build/ci}"
reads=${2:-5000}

cp examples/factory/factory.gdpn.yaml examples/factory/factory.py "$work/"
cat >>"$work/factory.gdpn.yaml" <<'YAML'
io:
  discrete_inputs: {0: {node: line/landing_at/landing, of: active}}
  input_registers:
    0: {node: line/landing_at/landing, of: reading}
    1: {node: arm/turn, of: angle, scale: 10, unit: 0.1 deg}
    2: {node: feed/lane/drive, of: speed, scale: 1000, unit: mm/s}
    3: {node: line/landing_at/landing, of: active}
  coils: {0: {node: overview, field: fov, on: 50, off: 50}}
YAML
"$gdpn" run "$work/factory.gdpn.yaml" --modbus 0 --until 60 >"$work/out" 2>"$work/err" &
run=$!
for _ in $(seq 100); do grep -q "modbus: serving" "$work/err" && break; sleep 0.1; done
port=$(grep -o "modbus: serving 127.0.0.1:[0-9]*" "$work/err" | cut -d: -f3)
/usr/bin/python3 - "$port" "$reads" <<'PY'
import socket, struct, sys, time
port, reads = int(sys.argv[1]), int(sys.argv[2])
s = socket.create_connection(("127.0.0.1", port))
s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
tid = 0
def ask(pdu):
    global tid
    tid = (tid + 1) & 0xFFFF
    s.sendall(struct.pack(">HHHB", tid, 0, len(pdu) + 1, 1) + pdu)
    head = s.recv(7, socket.MSG_WAITALL)
    n = struct.unpack(">H", head[4:6])[0] - 1
    body = s.recv(n, socket.MSG_WAITALL)
    if body[0] & 0x80:
        raise SystemExit(f"exception {body[1]} for function {pdu[0]}")
    return body
read_ir = struct.pack(">BHH", 4, 0, 4)
times = []
next_at = time.perf_counter()
for _ in range(reads):
    next_at += 0.002
    t0 = time.perf_counter_ns()
    ask(read_ir)
    times.append(time.perf_counter_ns() - t0)
    time.sleep(max(0.0, next_at - time.perf_counter()))
times.sort()
print(f"read of 4 input registers, round trip: median {times[len(times) // 2] / 1000:.0f} us, "
      f"99th percentile {times[len(times) * 99 // 100] / 1000:.0f} us ({reads} reads, one every 2 ms)")
scans, end = 0, time.perf_counter() + 5.0
while time.perf_counter() < end:
    ask(struct.pack(">BHH", 2, 0, 1))
    ask(read_ir)
    ask(struct.pack(">BHH", 5, 0, 0xFF00 if scans & 1 else 0))
    scans += 1
print(f"scans back to back (3 requests each): {scans / 5.0:.0f} scans/s, {3 * scans / 5.0:.0f} requests/s")
PY
wait "$run" || true
grep -E "^real time:|^Modbus TCP" "$work/out"
