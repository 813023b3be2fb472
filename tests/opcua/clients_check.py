#!/usr/bin/python3
"""gdpn's OPC UA server and client, from outside: the station of examples/commissioning with
node-opcua (npm; scripts/install-deps.sh installs it), a real implementation no one here wrote.

  browse     node-opcua's client reads NamespaceArray and ServerStatus, browses the station's
             folders (BrowseNext 3 references a time), translates a browse path, registers nodes
  readwrite  io/height (Int16, 850 mm, unit mm), writes that move the pusher; BadNotWritable
             and BadTypeMismatch where they belong
  subscribe  io/eye's changes as the first box passes (lockstep, Step called in chunks) and an
             absolute deadband on io/height
  call       Step(10) advances the model by 10 x dt; in real time Step is BadInvalidState
  lockstep   the example's OPC UA soft PLC (plc_opcua.js) in lockstep, twice: the two traces
             are the same bytes, and every box is in its bin
  realtime   the same PLC scanning every 10 ms of wall clock: every box is in its bin
  client     the example's PLC that is a server (plc_server.js) and gdpn run --opcua-client:
             every box is in its bin

usage: clients_check.py GDPN REPOSITORY WORKDIR NODE_MODULES [PART...]
"""
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

GDPN, ROOT, WORK, NODE_MODULES = sys.argv[1:5]
PARTS = sys.argv[5:] or ["browse", "readwrite", "subscribe", "call", "lockstep", "realtime", "client"]
STATION = os.path.join(ROOT, "examples", "commissioning", "station.gdpn.yaml")
PLC = os.path.join(ROOT, "examples", "commissioning", "plc_opcua.js")
PLC_SERVER = os.path.join(ROOT, "examples", "commissioning", "plc_server.js")
CHECKS = os.path.join(ROOT, "tests", "opcua", "ua_checks.js")
NODE = shutil.which("node")
ENV = dict(os.environ, NODE_PATH=NODE_MODULES, NODEOPCUA_LOG_LEVEL="2")
failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what, flush=True)
    if not ok:
        failures.append(what)
    return ok


class PartFailed(Exception):
    """A part cannot go on (gdpn did not start, a program did not answer in time)."""


class Run:
    """gdpn run on the station, serving OPC UA on a free port (the one it prints), or its client."""

    def __init__(self, name, *args, serve=True):
        self.trace = os.path.join(WORK, name + ".jsonl")
        self.report = os.path.join(WORK, name + ".json")
        self.err = open(os.path.join(WORK, name + ".err"), "w+")
        cmd = [GDPN, "run", STATION, *(["--opcua", "0"] if serve else []),
               "--trace", self.trace, "--report", self.report, *args]
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=self.err, text=True)
        self.url = None
        if not serve:
            return
        deadline = time.monotonic() + 60
        while self.url is None and time.monotonic() < deadline and self.proc.poll() is None:
            time.sleep(0.05)
            self.err.seek(0)
            m = re.search(r"opcua: serving (opc\.tcp://127\.0\.0\.1:\d+)", self.err.read())
            self.url = m.group(1) if m else None
        if self.url is None:
            self.kill()
            self.err.seek(0)
            raise PartFailed(f"gdpn run --opcua did not start serving: {' '.join(cmd)}\n" + self.err.read().strip())

    def kill(self):
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.communicate()

    def finish(self, timeout=120):
        try:
            out, _ = self.proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.kill()
            raise PartFailed(f"gdpn run did not end in {timeout} s")
        self.err.seek(0)
        return self.proc.returncode, out, self.err.read()

    def figures(self):
        try:
            with open(self.report) as f:
                return json.load(f)["figures"]
        except (OSError, ValueError, KeyError):
            return {}


def node(*args, timeout=300):
    """node with node-opcua on its path; the finished process (a timeout is a failure)."""
    try:
        return subprocess.run([NODE, *args], capture_output=True, text=True, timeout=timeout, env=ENV)
    except subprocess.TimeoutExpired:
        raise PartFailed(f"node {' '.join(args)} did not end in {timeout} s")


def client_part(part, until, *run_args):
    """Runs the part of ua_checks.js against a lockstep run to `until`, its checks as ours."""
    run = Run(part, "--until", str(until), "-q", *run_args)
    p = node(CHECKS, part, run.url, str(until), timeout=150)
    lines = (p.stdout + p.stderr).strip().splitlines()
    for line in lines:
        if line.startswith(("ok    ", "FAIL  ")):
            check(line.startswith("ok"), line[6:])
        else:
            print("      " + line)
    check(p.returncode == 0 and any(l.startswith("ok") for l in lines), f"{part}: node-opcua's checks passed (rc {p.returncode})")
    if "--lockstep" in run_args:
        rc, _, err = run.finish(60)
        check(rc == 0, f"{part}: the run ended cleanly (rc {rc}) {err.strip()}")
    else:
        run.kill()


def part_browse():
    client_part("browse", 1, "--lockstep")


def part_readwrite():
    client_part("readwrite", 2, "--lockstep")


def part_subscribe():
    client_part("subscribe", 7, "--lockstep")


def part_call():
    client_part("call", 1, "--lockstep")
    client_part("call-realtime", 30)


def sorted_right(figures, boxes):
    return (figures.get("tall in the tall bin", 0) + figures.get("short in the short bin", 0) == boxes
            and figures.get("in the wrong bin") == 0 and figures.get("not in a bin") == 0)


def part_lockstep():
    traces = []
    for k in (1, 2):
        run = Run(f"lockstep{k}", "--lockstep", "-q")
        p = node(PLC, "--url", run.url, "--lockstep")
        rc, _, _ = run.finish()
        check(rc == 0 and p.returncode == 0, f"lockstep run {k}: gdpn and the PLC ended cleanly ({p.stdout.strip()} {p.stderr.strip()})")
        check(sorted_right(run.figures(), 8), f"lockstep run {k}: every box in its bin {run.figures()}")
        with open(run.trace, "rb") as f:
            traces.append(f.read())
    check(traces[0] == traces[1] and len(traces[0]) > 0, "lockstep: the two traces are the same, byte for byte")


def part_realtime():
    run = Run("realtime", "--param", "boxes=3", "--until", "16", "-q")
    p = node(PLC, "--url", run.url, timeout=120)
    rc, _, _ = run.finish()
    check(rc == 0 and p.returncode == 0, f"real time: gdpn and the PLC ended cleanly ({p.stdout.strip()} {p.stderr.strip()})")
    check(sorted_right(run.figures(), 3), f"real time: every box in its bin {run.figures()}")


def part_client():
    out = open(os.path.join(WORK, "plc_server.out"), "w+")
    plc = subprocess.Popen([NODE, PLC_SERVER, "--port", "0", "--pki", os.path.join(WORK, "pki")],
                           stdout=out, stderr=subprocess.STDOUT, text=True, env=ENV)
    try:
        url = None
        deadline = time.monotonic() + 60
        while url is None and time.monotonic() < deadline and plc.poll() is None:
            time.sleep(0.05)
            out.seek(0)
            m = re.search(r"plc: serving (opc\.tcp://127\.0\.0\.1:\d+)", out.read())
            url = m.group(1) if m else None
        if url is None:
            out.seek(0)
            raise PartFailed("plc_server.js did not start serving:\n" + out.read().strip())
        run = Run("client", "--opcua-client", url, "-q", serve=False)
        rc, _, err = run.finish(120)
        check(rc == 0, f"client: gdpn run --opcua-client {url} ended cleanly (rc {rc}) {err.strip()}")
        figures = run.figures()
        check(sorted_right(figures, 8), f"client: every box in its bin {figures}")
    finally:
        if plc.poll() is None:
            plc.send_signal(signal.SIGTERM)
        try:
            plc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            plc.kill()
            plc.wait()
    out.seek(0)
    text = out.read()
    m = re.search(r"sorted (\d+) tall and (\d+) short boxes", text)
    check(m is not None and plc.returncode == 0, f"client: the PLC stopped cleanly and says what it sorted: {text.strip()}")
    if m:
        # each box the photo-eye saw (its beam entered, in the plant's trace) sorted once: a box
        # that bounced back out of its bin onto the belt is seen, and sorted, a second time
        # (a clean-clone CI run: tall_4 left the tall bin, the belt carried it through the beam
        # again, lying, and the PLC counted 4 tall and 5 short of 8 boxes)
        with open(run.trace) as f:
            seen = sum(1 for line in f if '"ev":"enter","sensor":"station/eye/beam"' in line)
        check(int(m.group(1)) + int(m.group(2)) == seen and seen >= 8,
              f"client: the PLC sorted each box the eye saw once ({m.group(1)} tall, {m.group(2)} short; seen {seen} times)")


if __name__ == "__main__":
    if NODE is None:
        print("FAIL  node is missing (Debian's nodejs: scripts/install-deps.sh)")
        sys.exit(1)
    for package in ("node-opcua-client", "node-opcua-server"):
        if not os.path.isfile(os.path.join(NODE_MODULES, package, "package.json")):
            print(f"FAIL  {package} is missing from {NODE_MODULES} (scripts/install-deps.sh runs npm ci there)")
            sys.exit(1)
    os.makedirs(WORK, exist_ok=True)
    for part in PARTS:
        print(f"== {part}", flush=True)
        try:
            globals()["part_" + part.replace("-", "_")]()
        except PartFailed as e:
            check(False, f"{part}: {e}")
    if failures:
        print(f"{len(failures)} checks failed")
        sys.exit(1)
