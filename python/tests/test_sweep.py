"""Sweeps (gdpn.sweep and gdpn sweep): every combination and seed, the same table on any
number of workers, failed runs reported with their parameters, 95 % intervals, and a real
Dask scheduler with two workers as separate processes on 127.0.0.1."""

import csv
import io
import math
import os
import socket
import statistics
import subprocess
import sys

import pytest

import gdpn

QUEUE = "tests/data/sweep/queue.gdpn.yaml"


@pytest.fixture
def queue(source):
    return str(source / QUEUE)


def gdpn_program():
    return gdpn.sweep.__globals__["find_gdpn"]()


def test_serial_and_two_local_workers_give_the_same_table(queue):
    params = {"gap": [0.5, 1.0], "work": "0.2..0.4:0.2"}
    serial = gdpn.sweep(queue, params, seeds=3, until=20, workers=0)
    local = gdpn.sweep(queue, params, seeds=3, until=20, workers=2)
    assert serial.runs_csv() == local.runs_csv()
    assert serial.summary_csv() == local.summary_csv()
    runs = serial.runs
    # every combination, each with seeds 1, 2, 3, the first parameter varying slowest
    assert list(runs["gap"]) == [0.5] * 6 + [1.0] * 6
    assert list(runs["work"]) == [0.2, 0.2, 0.2, 0.4, 0.4, 0.4] * 2
    assert list(runs["seed"]) == [1, 2, 3] * 4
    assert runs["error"].isna().all()
    assert list(runs.columns) == ["gap", "work", "seed", "stopped", "time", "parts done", "parts waiting", "busy",
                                  "error"]
    # the seeds make the runs differ; a run's figure is its own (busy = done * work / 20 s)
    assert runs[(runs.gap == 1.0) & (runs.work == 0.2)]["parts done"].nunique() > 1
    for _, r in runs.iterrows():
        assert r["busy"] == pytest.approx(100 * r["parts done"] * r["work"] / 20)
    assert serial.units["busy"] == "%"


def test_the_summary_gives_each_combinations_mean_and_95_percent_interval(queue):
    s = gdpn.sweep(queue, {"gap": "0.5,1"}, seeds=4, until=20, workers=0)
    runs, summary = s.runs, s.summary
    assert list(summary["runs"]) == [4, 4]
    for gap in (0.5, 1.0):
        xs = list(runs[runs.gap == gap]["parts done"])
        row = summary[summary.gap == gap].iloc[0]
        half = 3.182446305284263 * statistics.stdev(xs) / math.sqrt(4)  # t(0.975, 3)
        assert row["parts done"] == pytest.approx(statistics.mean(xs))
        assert row["parts done low"] == pytest.approx(statistics.mean(xs) - half)
        assert row["parts done high"] == pytest.approx(statistics.mean(xs) + half)
    # more arrivals, more parts done
    assert summary["parts done"][0] > summary["parts done"][1]


def test_students_t_beyond_the_table():
    t975 = gdpn.sweep.__globals__["t975"]
    for df, t in ((1, 12.706204736), (30, 2.042272456), (40, 2.021075390), (100, 1.983971519),
                  (1000, 1.962339081)):
        assert t975(df) == pytest.approx(t, abs=2e-5), df


def test_a_failing_run_is_reported_with_its_parameters_and_the_others_are_kept(queue):
    s = gdpn.sweep(queue, {"gap": [-1.0, 1.0]}, seeds=2, until=5, workers=2)
    failed = s.failed
    assert [(r["gap"], r["seed"]) for r in failed] == [(-1.0, 1), (-1.0, 2)]
    assert "needs a positive mean" in failed[0]["error"], failed[0]["error"]
    assert "queue.gdpn.yaml:25:40" in failed[0]["error"]
    summary = s.summary
    assert list(summary["runs"]) == [0, 2] and list(summary["failed"]) == [2, 0]
    assert math.isnan(summary["parts done"][0]) and summary["parts done"][1] >= 0


def test_values_are_checked_before_any_run(queue):
    with pytest.raises(gdpn.SweepError, match=r"the range ends \(0\) before it starts \(1\)"):
        gdpn.sweep(queue, {"gap": "1..0"}, workers=0)
    with pytest.raises(gdpn.SweepError, match="expected a number, got 'fast'"):
        gdpn.sweep(queue, {"gap": "0.5,fast"}, workers=0)
    # a name the model does not declare, or a value its parameter refuses, before any run
    with pytest.raises(gdpn.SweepError, match=r"no parameter 'gapp' in .*queue.gdpn.yaml \(did you mean 'gap'\?\)"):
        gdpn.sweep(queue, {"gapp": [1, 2]}, workers=0)
    parse = gdpn.sweep.__globals__["parse_values"]
    assert parse("x", "0.1..0.5:0.1") == [0.1, 0.2, 0.3, 0.4, 0.5]
    assert parse("x", "1..3:0.5,10") == [1, 1.5, 2, 2.5, 3, 10]
    assert parse("x", "1..2:0.3") == [1, 1.3, 1.6, 1.9]
    # a value given twice runs once: its runs would count twice in its interval
    assert parse("x", "1,1,0.5..1:0.5") == [1, 0.5]
    with pytest.raises(gdpn.SweepError, match="more than 10000 values"):
        parse("x", "-1e308..1e308")


def test_a_figure_named_like_a_column_keeps_its_own_column(write_model):
    model = write_model("""gdpn: 1
settings: {dt: 0.1, until: 1}
params: {gap: 1}
scripts:
  globals: |
    def summary():
        return {"gap": 99, "seed": 7, "error": "none", "time": 5, "fine": sim.params.gap}
pages: {main: {places: {p: {tokens: 1}}}}
""")
    s = gdpn.sweep(model, {"gap": [1, 2]}, seeds=2, workers=0)
    assert not s.failed
    runs = s.runs
    assert list(runs["gap"]) == [1, 1, 2, 2] and list(runs["seed"]) == [1, 2, 1, 2]
    assert list(runs["summary.gap"]) == [99] * 4 and list(runs["summary.seed"]) == [7] * 4
    assert list(runs["fine"]) == [1, 1, 2, 2] and runs["error"].isna().all()


def test_the_command_line_writes_the_tables_and_the_plot(queue, tmp_path):
    out, summary, plot = tmp_path / "runs.csv", tmp_path / "summary.csv", tmp_path / "plot.svg"
    done = subprocess.run([gdpn_program(), "sweep", queue, "--param", "gap=0.5,1", "--param", "work=0.2,0.4",
                           "--seeds", "2", "--until", "10", "--workers", "2", "-o", str(out), "--summary",
                           str(summary), "--plot", str(plot), "--figure", "parts done"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    rows = list(csv.DictReader(io.StringIO(out.read_text())))
    assert len(rows) == 8 and rows[0]["gap"] == "0.5" and rows[0]["seed"] == "1"
    assert len(list(csv.DictReader(io.StringIO(summary.read_text())))) == 4
    assert plot.read_text().count("<svg") == 1
    # the terminal's table: a line per combination, each at most 100 columns
    lines = done.stdout.splitlines()
    assert len(lines) == 5 and all(len(line) <= 100 for line in lines), done.stdout
    assert "parts done" in lines[0]
    bad = subprocess.run([gdpn_program(), "sweep", queue, "--param", "gpa=1,2"], capture_output=True, text=True)
    assert bad.returncode == 2
    assert bad.stderr == f"--param: error: no parameter 'gpa' in {queue} (did you mean 'gap'?)\n"
    bad = subprocess.run([gdpn_program(), "sweep", queue, "--param", "gap=1", "--workers", "2", "--scheduler",
                          "tcp://127.0.0.1:1"], capture_output=True, text=True)
    assert bad.returncode == 2 and "does not go with --scheduler" in bad.stderr
    missing = tmp_path / "no" / "runs.csv"
    bad = subprocess.run([gdpn_program(), "sweep", queue, "--param", "gap=1", "-o", str(missing)],
                         capture_output=True, text=True)
    assert bad.returncode == 2
    assert bad.stderr == f"error: -o {missing}: the folder {missing.parent} is not there or not writable\n"
    bad = subprocess.run([gdpn_program(), "sweep", queue, "--param", "gap=1..1e9:1e-3"], capture_output=True,
                         text=True)
    assert bad.returncode == 2 and "more than 10000 values" in bad.stderr, bad.stderr
    # no output over the model, nor two outputs in one file
    bad = subprocess.run([gdpn_program(), "sweep", queue, "--param", "gap=1", "-o", queue], capture_output=True,
                         text=True)
    assert bad.returncode == 2 and "is the model file; gdpn writes no output over it" in bad.stderr, bad.stderr
    bad = subprocess.run([gdpn_program(), "sweep", queue, "--param", "gap=1", "-o", str(out), "--summary", str(out)],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and "-o and --summary name one file" in bad.stderr, bad.stderr
    for option, value in (("--seed", "-1"), ("--until", "nan"), ("--timeout", "nan"), ("--scheduler", "")):
        bad = subprocess.run([gdpn_program(), "sweep", queue, option, value], capture_output=True, text=True)
        assert bad.returncode == 2, (option, value, bad.stderr)
    bad = subprocess.run([gdpn_program(), "sweep", queue, "--param", "gap=1", "--scheduler", "foo"],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and "Traceback" not in bad.stderr, bad.stderr


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_a_real_scheduler_and_two_worker_processes_give_the_serial_table(queue, tmp_path):
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    env = dict(os.environ, DASK_DISTRIBUTED__WORKER__DAEMON="False")
    common = dict(stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env, cwd=tmp_path)
    procs = [subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1",
                               "--port", str(port), "--no-dashboard"], **common)]
    try:
        for _ in range(2):
            procs.append(subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker", address,
                                           "--nthreads", "1", "--no-dashboard", "--host", "127.0.0.1",
                                           "--nworkers", "1"], **common))
        from distributed import Client
        with Client(address, timeout="30s") as client:
            client.wait_for_workers(2, timeout=60)
        served = tmp_path / "served.csv"
        serial = tmp_path / "serial.csv"
        args = [gdpn_program(), "sweep", queue, "--param", "gap=0.5,1", "--seeds", "3", "--until", "10", "--quiet"]
        done = subprocess.run(args + ["--scheduler", address, "-o", str(served)], capture_output=True, text=True,
                              timeout=300)
        assert done.returncode == 0, done.stderr
        done = subprocess.run(args + ["--workers", "0", "-o", str(serial)], capture_output=True, text=True,
                              timeout=300)
        assert done.returncode == 0, done.stderr
        assert served.read_text() == serial.read_text()
        # the runs went through the scheduler, which has the two workers
        with Client(address, timeout="30s") as client:
            seen = client.run_on_scheduler(lambda dask_scheduler: sorted(dask_scheduler.task_prefixes))
            assert len(client.scheduler_info()["workers"]) == 2
        assert "gdpn-run" in seen, seen
    finally:
        for p in procs:
            p.terminate()
        for p in procs:
            try:
                p.wait(timeout=20)
            except subprocess.TimeoutExpired:
                p.kill()


def test_a_scheduler_that_is_not_there_is_an_error_not_a_hang(queue):
    port = free_port()
    done = subprocess.run([gdpn_program(), "sweep", queue, "--param", "gap=1", "--scheduler",
                           f"tcp://127.0.0.1:{port}", "--quiet"], capture_output=True, text=True, timeout=120)
    assert done.returncode == 2, done.stderr
    assert f"--scheduler tcp://127.0.0.1:{port}: no Dask scheduler answers there" in done.stderr
