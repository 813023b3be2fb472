#!/usr/bin/env python3
"""OPC UA while the factory runs (gdpn run examples/factory/factory.gdpn.yaml --opcua 0), measured
with node-opcua-client (bench/opcua_bench.mjs), a real client no one here wrote:

  1. in real time (--realtime), RUNS runs: the round trip of READS sequential Reads of one
     variable, and of 10 variables a request, on loopback: median and 99th percentile; then a
     subscription of 100 variables (places, transitions, sensor readings, time, steps; sampling
     interval 0, every step; publishing interval 50 ms) for SECONDS: data changes received per
     second and their latency (server sampling to client arrival); the run's real-time factor;
  2. in lockstep (--lockstep), ROUNDS rounds taken in turns: A the same steps run headless
     (wall clock of `gdpn run --until 60 --quiet` less that of `--steps 0`, the start-up), B a
     client calling Step(PER_CALL) back to back, C the same with the 100 items monitored: the
     wall clock per step (the client's, for B and C) and gdpn's own CPU time per step (its
     start-up, the CPU time of `--steps 0`, taken off), medians, and the ratios C/B and B/A.

Prints a table and writes every figure to OUT.json. Needs a Release build (cmake --preset ci &&
cmake --build build/ci) and node-opcua (scripts/install-deps.sh, or npm ci in scripts/node).
Not a test: nothing here is checked against a bound.

usage: bench/opcua_bench.py OUT.json [--build DIR] [--runs N] [--rounds N] [--reads N]
                            [--seconds S] [--per-call N]
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FACTORY = os.path.join(ROOT, "examples", "factory", "factory.gdpn.yaml")
CLIENT = os.path.join(ROOT, "bench", "opcua_bench.mjs")
DT = 0.01          # s, the factory's step
LOCKSTEP_S = 60.0  # s of model time per lockstep run
RATIOS = "C / B, median of the rounds' ratios"
CPU_HEAD = "lockstep, gdpn's CPU time per step"


def gdpn_run(gdpn, work, name, *args):
    """Starts gdpn run on the factory serving OPC UA on a free port; returns (process, url)."""
    err = open(os.path.join(work, name + ".err"), "w+")
    proc = subprocess.Popen([gdpn, "run", FACTORY, "--opcua", "0", *args], stdout=subprocess.PIPE,
                            stderr=err, text=True)
    end = time.monotonic() + 60
    while time.monotonic() < end:
        err.seek(0)
        found = re.search(r"opcua: serving (opc\.tcp://\S+?),", err.read())
        if found:
            return proc, found.group(1)
        if proc.poll() is not None:
            break
        time.sleep(0.05)
    proc.kill()
    err.seek(0)
    sys.exit(f"gdpn run did not serve OPC UA: {err.read()}")


def client(*args):
    """Runs opcua_bench.mjs; its last line is a JSON object."""
    out = subprocess.run([shutil.which("node") or "node", CLIENT, *map(str, args)], capture_output=True,
                         text=True, timeout=300, env=dict(os.environ, NODEOPCUA_LOG_LEVEL="2"))
    if out.returncode != 0:
        sys.exit(f"opcua_bench.mjs {args[0]} failed: {out.stderr.strip()}")
    figures = json.loads(out.stdout.strip().splitlines()[-1])
    figures.pop("watched", None)
    return figures


def finish(proc):
    """Waits for the run's end; returns its stdout and the CPU time it took (user + system, s)."""
    out = proc.stdout.read()
    _, _, usage = os.wait4(proc.pid, 0)
    proc.returncode = 0
    return out, usage.ru_utime + usage.ru_stime


def realtime(gdpn, work, reads, seconds):
    until = 20 + seconds + reads * 0.002  # s: long enough for the client's work (about 3 ms a Read pair)
    proc, url = gdpn_run(gdpn, work, "realtime", "--realtime", "--until", f"{until:g}")
    try:
        figures = client("realtime", url, reads, seconds)
    except BaseException:
        proc.kill()
        raise
    out, _ = finish(proc)
    found = re.search(r"real time: ([\d.]+) s simulated in ([\d.]+) s of wall clock, ([\d.]+) x real time", out)
    figures["real_time_factor"] = float(found.group(3)) if found else None
    figures["until"] = until
    return figures


def headless(gdpn, *args):
    """gdpn run --quiet: its wall clock and CPU time (s)."""
    t0 = time.perf_counter()
    proc = subprocess.Popen([gdpn, "run", FACTORY, "--quiet", *args], stdout=subprocess.PIPE, text=True)
    _, cpu = finish(proc)
    return time.perf_counter() - t0, cpu


def lockstep(gdpn, work, per_call, items):
    calls = round(LOCKSTEP_S / DT / per_call)
    proc, url = gdpn_run(gdpn, work, "lockstep", "--lockstep", "--quiet", "--until", f"{LOCKSTEP_S:g}")
    try:
        figures = client("lockstep", url, per_call, calls - 1, items)  # the last call ends the run
    except BaseException:
        proc.kill()  # a run in lockstep would wait for its Step calls for ever
        raise
    figures["cpu_s"] = finish(proc)[1]
    return figures


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", help="the JSON file to write")
    parser.add_argument("--build", default="build/ci")
    parser.add_argument("--runs", type=int, default=3, help="runs in real time")
    parser.add_argument("--rounds", type=int, default=5, help="rounds of A, B, C in lockstep")
    parser.add_argument("--reads", type=int, default=2000)
    parser.add_argument("--seconds", type=float, default=10.0, help="of the subscription in real time")
    parser.add_argument("--per-call", type=int, default=10, help="steps per Step call in lockstep")
    a = parser.parse_args()
    gdpn = os.path.join(ROOT, a.build, "apps", "gdpn", "gdpn")
    work = tempfile.mkdtemp(prefix="opcua_bench.")
    try:
        runs = [realtime(gdpn, work, a.reads, a.seconds) for _ in range(a.runs)]
        rounds = []
        steps = round(LOCKSTEP_S / DT)
        for _ in range(a.rounds):
            start, start_cpu = headless(gdpn, "--steps", "0")
            whole, whole_cpu = headless(gdpn, "--until", f"{LOCKSTEP_S:g}")
            b = lockstep(gdpn, work, a.per_call, 0)
            c = lockstep(gdpn, work, a.per_call, 100)
            rounds.append({"headless_us": (whole - start) / steps * 1e6, "start_s": start,
                           "step_us": b["seconds"] / b["steps"] * 1e6,
                           "step_monitored_us": c["seconds"] / c["steps"] * 1e6,
                           "headless_cpu_us": (whole_cpu - start_cpu) / steps * 1e6,
                           "step_cpu_us": (b["cpu_s"] - start_cpu) / steps * 1e6,
                           "step_monitored_cpu_us": (c["cpu_s"] - start_cpu) / steps * 1e6,
                           "changes_per_step": c["changes"] / c["steps"]})
    finally:
        shutil.rmtree(work, ignore_errors=True)

    med = lambda xs: statistics.median(xs)
    rt = {key: med([r[group][stat] for r in runs]) for group in ("read1", "read10", "latency")
          for stat in ("median", "p99") for key in [f"{group}_{stat}_ms"]}
    rt["changes_per_s"] = med([r["rate"] for r in runs])
    rt["real_time_factor"] = med([r["real_time_factor"] for r in runs])
    ls = {key: med([r[key] for r in rounds]) for key in rounds[0]}
    ls["monitored_over_plain"] = med([r["step_monitored_us"] / r["step_us"] for r in rounds])
    ls["plain_over_headless"] = med([r["step_us"] / r["headless_us"] for r in rounds])
    ls["per_item_per_step_ns"] = med([(r["step_monitored_us"] - r["step_us"]) * 10 for r in rounds])
    ls["cpu_monitored_over_plain"] = med([r["step_monitored_cpu_us"] / r["step_cpu_us"] for r in rounds])
    ls["cpu_plain_over_headless"] = med([r["step_cpu_us"] / r["headless_cpu_us"] for r in rounds])
    ls["cpu_per_item_per_step_ns"] = med([(r["step_monitored_cpu_us"] - r["step_cpu_us"]) * 10 for r in rounds])
    each = lambda key, fmt: ", ".join(fmt.format(r[key]) for r in rounds)

    print(f"{'OPC UA, the factory, node-opcua-client on loopback':<58}{'median':>10}  each run")
    rows = [("Read of 1 variable, round trip, median", rt["read1_median_ms"], "ms", [r["read1"]["median"] for r in runs]),
            ("  99th percentile", rt["read1_p99_ms"], "ms", [r["read1"]["p99"] for r in runs]),
            ("Read of 10 variables, round trip, median", rt["read10_median_ms"], "ms", [r["read10"]["median"] for r in runs]),
            ("  99th percentile", rt["read10_p99_ms"], "ms", [r["read10"]["p99"] for r in runs]),
            ("100 items, data changes received per second", rt["changes_per_s"], "/s", [r["rate"] for r in runs]),
            ("  latency, sampled to received, median", rt["latency_median_ms"], "ms", [r["latency"]["median"] for r in runs]),
            ("  99th percentile", rt["latency_p99_ms"], "ms", [r["latency"]["p99"] for r in runs]),
            ("real-time factor with the client", rt["real_time_factor"], "x", [r["real_time_factor"] for r in runs])]
    for what, value, unit, values in rows:
        print(f"{what:<48}{value:>10.3f} {unit:<3} " + ", ".join(f"{v:.3g}" for v in values))
    print(f"{'lockstep, wall clock per step':<48}{'median':>10}      each round")
    for what, key in (("A headless", "headless_us"), (f"B Step({a.per_call}) back to back", "step_us"),
                      ("C the same, 100 items monitored", "step_monitored_us")):
        print(f"{what:<48}{ls[key]:>10.1f} us  " + each(key, "{:.1f}"))
    print(f"{RATIOS:<48}{ls['monitored_over_plain']:>10.3f}")
    print(f"{'B / A (Step calls over the wire)':<48}{ls['plain_over_headless']:>10.3f}")
    print(f"{'(C - B) per monitored item per step':<48}{ls['per_item_per_step_ns']:>10.0f} ns")
    print(f"{CPU_HEAD:<48}{'median':>10}      each round")
    for what, key in (("A headless", "headless_cpu_us"), (f"B Step({a.per_call}) back to back", "step_cpu_us"),
                      ("C the same, 100 items monitored", "step_monitored_cpu_us")):
        print(f"{what:<48}{ls[key]:>10.1f} us  " + each(key, "{:.1f}"))
    print(f"{RATIOS:<48}{ls['cpu_monitored_over_plain']:>10.3f}")
    print(f"{'B / A':<48}{ls['cpu_plain_over_headless']:>10.3f}")
    print(f"{'(C - B) per monitored item per step':<48}{ls['cpu_per_item_per_step_ns']:>10.0f} ns")
    print(f"{'data changes received per step in C':<48}{ls['changes_per_step']:>10.2f}")
    with open(a.out, "w", encoding="utf-8") as f:
        json.dump({"model": "examples/factory/factory.gdpn.yaml", "dt_s": DT, "reads": a.reads,
                   "subscription_s": a.seconds, "publishing_interval_ms": 50, "sampling_interval_ms": 0,
                   "items": 100, "steps_per_call": a.per_call, "lockstep_steps": round(LOCKSTEP_S / DT),
                   "realtime": rt, "lockstep": ls, "runs": runs, "rounds": rounds}, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
