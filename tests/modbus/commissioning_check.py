#!/usr/bin/python3
"""gdpn run --modbus, from outside: the station of examples/commissioning served on a free
loopback port and driven by real clients.

  tables     mbpoll (Debian's) reads and writes every table; the values are checked against
             the plant (a coil moves the pusher, a register sets a place's tokens)
  errors     malformed frames and bad requests get their exception codes, a stream that is no
             Modbus TCP and an abrupt disconnect close that client only, too many clients are
             refused; the run goes on and ends with its trace whole
  read-only  --modbus-read-only answers every write with exception 01 and changes nothing
  lockstep   the example's soft PLC in lockstep, twice: the two traces are the same bytes,
             and every box is in its bin
  realtime   the soft PLC scanning every 10 ms of wall clock: every box is in its bin

usage: commissioning_check.py GDPN REPOSITORY WORKDIR [PART...]
"""
import json
import os
import re
import shutil
import socket
import struct
import subprocess
import sys
import time

GDPN, ROOT, WORK = sys.argv[1:4]
PARTS = sys.argv[4:] or ["tables", "errors", "read-only", "lockstep", "realtime"]
STATION = os.path.join(ROOT, "examples", "commissioning", "station.gdpn.yaml")
PLC = os.path.join(ROOT, "examples", "commissioning", "plc.py")
failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what, flush=True)
    if not ok:
        failures.append(what)


class Run:
    """gdpn run on the station, serving on a free port (the one it prints)."""

    def __init__(self, name, *args):
        self.trace = os.path.join(WORK, name + ".jsonl")
        self.report = os.path.join(WORK, name + ".json")
        self.err = open(os.path.join(WORK, name + ".err"), "w+")
        self.proc = subprocess.Popen(
            [GDPN, "run", STATION, "--modbus", "0", "--trace", self.trace, "--report", self.report, *args],
            stdout=subprocess.PIPE, stderr=self.err, text=True)
        deadline = time.monotonic() + 60
        self.port = None
        while self.port is None and time.monotonic() < deadline and self.proc.poll() is None:
            time.sleep(0.05)
            self.err.seek(0)
            m = re.search(r"modbus: serving 127\.0\.0\.1:(\d+)", self.err.read())
            self.port = int(m.group(1)) if m else None
        if self.port is None:
            self.err.seek(0)
            raise SystemExit("gdpn run did not start serving:\n" + self.err.read())

    def finish(self, timeout=120):
        out, _ = self.proc.communicate(timeout=timeout)
        self.err.seek(0)
        return self.proc.returncode, out, self.err.read()

    def figures(self):
        with open(self.report) as f:
            return json.load(f)["figures"]


def mbpoll(port, table, ref, count=1, values=()):
    """mbpoll once, 0-based; the values read, or the failure's text."""
    cmd = ["mbpoll", "-m", "tcp", "-0", "-1", "-o", "5", "-p", str(port), "-t", table, "-r", str(ref),
           *([] if values else ["-c", str(count)]), "127.0.0.1", *[str(v) for v in values]]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=30)
    if p.returncode != 0:
        return p.stderr.strip().splitlines()[-1] if p.stderr.strip() else f"rc {p.returncode}"
    if values:
        return "written" if "Written" in p.stdout else p.stdout
    return [float(v) if "." in v else int(v) for v in re.findall(r"^\[\d+\]:\s+(\S+)", p.stdout, re.M)]


def steps(port, n):
    """Asks the lockstep run for n steps (the station's lockstep register is 100)."""
    return mbpoll(port, "4", 100, values=[n])


def part_tables():
    run = Run("tables", "--lockstep", "--until", "2")
    p = run.port
    # at t = 0: nothing at the eye, the first box fed and 7 to come, the height sensor sees the
    # belt 850 mm down
    check(mbpoll(p, "1", 0, 2) == [0, 1], "discrete inputs 0-1: the eye is clear, boxes are to come")
    check(mbpoll(p, "3", 0, 4) == [850, 0, 0, 0], "input registers 0-3: 850 mm to the belt, pusher in, bins empty")
    check(mbpoll(p, "0", 0, 2) == [0, 0], "coils 0-1: belt stopped, pusher in")
    check(mbpoll(p, "4", 0, 2) == [800, 7], "holding registers 0-1: pusher 800 mm/s, 7 boxes to feed")
    # writes: the pusher goes out, at 500 mm/s; 2 boxes left to feed
    check(mbpoll(p, "0", 1, values=[1]) == "written", "coil 1 written (pusher out)")
    check(mbpoll(p, "4", 0, values=[500, 2]) == "written", "holding registers 0-1 written")
    check(mbpoll(p, "4", 0, 2) == [500, 2], "holding registers read back: 500 mm/s, 2 boxes")
    check(mbpoll(p, "0", 0, 2) == [0, 1], "coils read back: belt stopped, pusher out")
    # 1 s of model time: at 0.5 m/s the pusher has gone 500 mm or a little less (its servo)
    check(steps(p, 200) == "written", "200 steps asked for")
    stroke = mbpoll(p, "3", 1)
    check(isinstance(stroke, list) and 470 <= stroke[0] <= 510, f"input register 1: pusher out {stroke} mm, about 500")
    check(mbpoll(p, "4", 1) == [2], "holding register 1: 2 boxes, the feeder busy with the first for 3 s")
    check(mbpoll(p, "1", 1) == [1], "discrete input 1: a box is still to come")
    check(steps(p, 200) == "written", "the rest of the run asked for")
    rc, out, err = run.finish()
    check(rc == 0, f"the run ended cleanly (rc {rc})")
    with open(run.trace) as f:
        io = [json.loads(l) for l in f if '"io"' in l]
    check([(e["table"], e["address"], e["value"]) for e in io] ==
          [("coils", 1, 1), ("holding_registers", 0, 0.5), ("holding_registers", 1, 2)],
          "the trace has the three writes that changed something, in the model's units")
    check("station/pusher.target1" in out and "127.0.0.1:" in out, "the summary's table names the writer")


def raw(port):
    s = socket.create_connection(("127.0.0.1", port), timeout=5)
    s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    return s


def ask(s, pdu, tid=7, unit=1):
    """Sends one request; the reply's PDU."""
    s.sendall(struct.pack(">HHHB", tid, 0, len(pdu) + 1, unit) + pdu)
    head = b""
    while len(head) < 7:
        chunk = s.recv(7 - len(head))
        if not chunk:
            return None
        head += chunk
    t, proto, length, u = struct.unpack(">HHHB", head)
    body = b""
    while len(body) < length - 1:
        body += s.recv(length - 1 - len(body))
    assert t == tid and proto == 0 and u == unit, (t, proto, u)
    return body


def exception(body):
    return body[1] if body and body[0] & 0x80 else None


def closed(s):
    try:
        s.settimeout(5)
        return s.recv(1) == b""
    except ConnectionResetError:
        return True


def part_errors():
    run = Run("errors", "--until", "3")
    p = run.port
    s = raw(p)
    check(ask(s, struct.pack(">BHH", 4, 0, 1)) == bytes([4, 2, 0x03, 0x52]), "a good read: 850 mm")
    check(exception(ask(s, struct.pack(">BHH", 43, 0, 1))) == 1, "function 43: exception 01")
    check(exception(ask(s, struct.pack(">BHH", 1, 0, 0))) == 3, "read 0 coils: exception 03")
    check(exception(ask(s, struct.pack(">BHH", 3, 0, 126))) == 3, "read 126 registers: exception 03")
    check(exception(ask(s, struct.pack(">BHH", 1, 7, 1))) == 2, "read an unmapped coil: exception 02")
    check(exception(ask(s, struct.pack(">BHH", 2, 0, 3))) == 2, "read past the last discrete input: exception 02")
    check(exception(ask(s, struct.pack(">BHH", 3, 65535, 2))) == 2, "read past address 65535: exception 02")
    check(exception(ask(s, struct.pack(">BHH", 5, 0, 0x1234))) == 3, "a coil written 0x1234: exception 03")
    check(exception(ask(s, struct.pack(">BHHBBB", 15, 0, 2, 2, 3, 0))) == 3, "write coils with a wrong byte count: exception 03")
    check(exception(ask(s, struct.pack(">BH", 3, 0))) == 3, "a request cut short: exception 03")
    check(exception(ask(s, struct.pack(">BHH", 6, 2, 0xFFFF))) == 3, "pusher force -1 N (fmax1 is at least 0): exception 03")
    check(exception(ask(s, struct.pack(">BHH", 6, 1, 0x8000))) == 3, "a negative number of tokens: exception 03")
    check(exception(ask(s, struct.pack(">BHHBHH", 16, 1, 2, 4, 3, 0xFFFF))) == 3,
          "write 3 boxes and a force of -1 N at once: exception 03")
    check(exception(ask(s, struct.pack(">BHH", 6, 5, 1))) == 2, "write an unmapped holding register: exception 02")
    check(ask(s, struct.pack(">BHH", 3, 0, 3)) == bytes([3, 6, 0x03, 0x20, 0, 7, 0x01, 0x90]),
          "nothing refused was written: 800 mm/s, 7 boxes, 400 N")
    # a stream that is no Modbus TCP: that client is closed, the others go on
    bad = raw(p)
    bad.sendall(b"GET / HTTP/1.1\r\nHost: x\r\n\r\n")
    check(closed(bad), "an HTTP request: the connection is closed")
    half = raw(p)
    half.sendall(struct.pack(">HHHB", 1, 0, 6, 1) + b"\x03\x00")
    half.close()
    reset = raw(p)
    reset.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
    reset.sendall(struct.pack(">HHHB", 1, 0, 6, 1) + b"\x03")
    reset.close()  # a reset, mid-frame
    many = [raw(p) for _ in range(40)]
    time.sleep(0.3)
    served = 0
    for c in many:
        try:
            if ask(c, struct.pack(">BHH", 2, 0, 1)) is not None:
                served += 1
        except OSError:
            pass
    check(served == 31, f"40 more clients: 31 served beside the first, the rest refused ({served} served)")
    for c in many:
        c.close()
    check(ask(s, struct.pack(">BHH", 4, 0, 1)) == bytes([4, 2, 0x03, 0x52]), "the first client is still served")
    s.close()
    rc, out, err = run.finish()
    check(rc == 0, f"the run ended at its time (rc {rc})")
    with open(run.trace) as f:
        lines = f.read().splitlines()
    check(lines and json.loads(lines[-1])["t"] == 3, "its trace is whole, to t = 3 s")
    m = re.search(r"(\d+) requests \((\d+) writes, (\d+) answered with an exception\), (\d+) connections refused", out)
    check(m is not None and int(m.group(4)) == 9, "the summary counts 9 connections refused")
    check("closed for bytes that are no Modbus TCP" in out, "the summary counts the closed stream")


def part_read_only():
    run = Run("read_only", "--modbus-read-only", "--until", "1", "-q")
    s = raw(run.port)
    check(exception(ask(s, struct.pack(">BHH", 5, 0, 0xFF00))) == 1, "read-only: write a coil, exception 01")
    check(exception(ask(s, struct.pack(">BHHBHH", 16, 0, 2, 4, 1, 1))) == 1, "read-only: write registers, exception 01")
    check(ask(s, struct.pack(">BHH", 1, 0, 2)) == bytes([1, 1, 0]), "read-only: reads are served; the coils did not change")
    s.close()
    rc, _, _ = run.finish()
    check(rc == 0, "read-only: the run ended cleanly")


def plc(port, *args):
    return subprocess.run([sys.executable, PLC, "--port", str(port), *args], capture_output=True, text=True,
                          timeout=300)


def sorted_right(figures, boxes):
    return (figures.get("tall in the tall bin", 0) + figures.get("short in the short bin", 0) == boxes
            and figures.get("in the wrong bin") == 0 and figures.get("not in a bin") == 0)


def part_lockstep():
    traces = []
    for k in (1, 2):
        run = Run(f"lockstep{k}", "--lockstep", "-q")
        p = plc(run.port, "--lockstep")
        rc, _, _ = run.finish()
        check(rc == 0 and p.returncode == 0, f"lockstep run {k}: gdpn and the PLC ended cleanly")
        check(sorted_right(run.figures(), 8), f"lockstep run {k}: every box in its bin {run.figures()}")
        with open(run.trace, "rb") as f:
            traces.append(f.read())
    check(traces[0] == traces[1], "lockstep: the two traces are the same, byte for byte")


def part_realtime():
    run = Run("realtime", "--param", "boxes=3", "--until", "16", "-q")
    p = plc(run.port)
    rc, _, _ = run.finish()
    check(rc == 0 and p.returncode == 0, f"real time: gdpn and the PLC ended cleanly ({p.stderr.strip()})")
    check(sorted_right(run.figures(), 3), f"real time: every box in its bin {run.figures()}")


if __name__ == "__main__":
    if not shutil.which("mbpoll"):
        print("mbpoll is missing (Debian's mbpoll: scripts/install-deps.sh)")
        sys.exit(1)
    os.makedirs(WORK, exist_ok=True)
    for part in PARTS:
        print(f"== {part}", flush=True)
        globals()["part_" + part.replace("-", "_")]()
    if failures:
        print(f"{len(failures)} checks failed")
        sys.exit(1)
