"""One run and one analysis for every face: `gdpn run --report` and gdpn.load(...).run()
give the same report (circuits included), breakpoints read in the one syntax stop both at
the same step, and Model.analyze() runs under gdpn analyze's limits, its memory guard too."""

import json
import subprocess

import pytest

import gdpn

ALTERNATIVES = "tests/data/good/alternatives.gdpn.yaml"
PRODUCER_CONSUMER = "examples/basics/producer_consumer/producer_consumer.gdpn.yaml"


def gdpn_program():
    return gdpn.sweep.__globals__["find_gdpn"]()


def cli_report(tmp_path, model, *args):
    out = tmp_path / "report.json"
    done = subprocess.run([gdpn_program(), "run", model, "--report", str(out), "-q", *args],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return json.loads(out.read_text()), done.stderr


def circuits(report):
    return [c["circuits"] for c in report["cycles"] if c.get("circuits")]


@pytest.mark.parametrize("relative", [ALTERNATIVES, PRODUCER_CONSUMER])
def test_the_cli_and_python_give_the_same_report(source, tmp_path, relative):
    model = str(source / relative)
    cli, _ = cli_report(tmp_path, model, "--seed", "7")
    python = gdpn.load(model, seed=7).run()
    assert python == cli


def test_the_report_of_python_shows_each_circuit_as_the_cli_does(source, tmp_path):
    model = str(source / ALTERNATIVES)
    cli, _ = cli_report(tmp_path, model)
    m = gdpn.load(model)
    m.run()
    found = circuits(m.report())
    # the station's token works red parts and skips blue ones: two circuits
    assert len(found) == 1 and len(found[0]) == 2
    assert found == circuits(cli)
    # a reset keeps watching them
    m.reset()
    assert circuits(m.run()) == found


def test_a_breakpoint_written_alike_stops_both_at_the_same_step(source, tmp_path):
    model = str(source / PRODUCER_CONSUMER)
    cli, err = cli_report(tmp_path, model, "--break", "main/buffer>=3")
    assert "stopped at breakpoint 1: main/buffer >= 3" in err
    m = gdpn.load(model)
    assert m.add_breakpoint("main/buffer>=3") == 1
    python = m.run()
    assert m.hit == 1
    assert python == cli
    assert python["stopped"] == "breakpoint"


def test_a_mistake_in_a_written_breakpoint_is_located(source):
    m = gdpn.load(str(source / PRODUCER_CONSUMER))
    with pytest.raises(ValueError, match=r"column 12: expected start:TRANSITION"):
        m.add_breakpoint("main/buffer=>3")
    with pytest.raises(ValueError, match="no transition 'main/nope' in the net"):
        m.add_breakpoint("start:main/nope")
    with pytest.raises(ValueError, match="watches one thing"):
        m.add_breakpoint("start:main/consume", place="main/buffer")
    assert m.add_breakpoint("complete:main/consume") == 1
    assert m.breakpoints == [{"id": 1, "watches": "completes main/consume", "enabled": True}]


def test_a_witness_is_replayed_alike(source, tmp_path):
    model = str(source / "examples/basics/figure31/figure31.gdpn.yaml")
    witness = str(tmp_path / "w.json")
    done = subprocess.run([gdpn_program(), "analyze", model, "--query", "EF P4 = 1", "--witness", witness],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    cli, err = cli_report(tmp_path, model, "--replay", witness)
    m = gdpn.load(model)
    assert m.replay_verdict is None
    m.replay(witness)
    python = m.run()
    assert python == cli
    verdict = m.replay_verdict
    assert verdict["done"] is True
    assert verdict["message"] in err
    assert verdict["message"].startswith("replay: all 2 firings done by t = 2 s")
    with pytest.raises(gdpn.ModelError):
        m.replay(str(tmp_path / "none.json"))


def huge(write_model, n=40):
    """n independent switches: 2^n markings, far past any memory limit."""
    places = "".join(f"      p{i}: {{tokens: 1}}\n      q{i}: {{}}\n" for i in range(n))
    transitions = "".join(f"      on{i}: {{}}\n      off{i}: {{}}\n" for i in range(n))
    arcs = "".join(f"      - p{i} -> on{i}\n      - on{i} -> q{i}\n      - q{i} -> off{i}\n      - off{i} -> p{i}\n"
                   for i in range(n))
    return write_model("gdpn: 1\npages:\n  main:\n    places:\n" + places + "    transitions:\n" + transitions +
                       "    arcs:\n" + arcs)


def test_analyze_stops_at_a_memory_limit_with_a_partial_answer(write_model):
    m = gdpn.load(huge(write_model))
    result = m.analyze(max_memory_mib=1, time_limit=60)
    # the state space stops with what it found; the answer says it is partial and why
    assert result["complete"] is False
    assert result["stop"] == "partial: --max-memory reached"
    assert {"phase": "state space", "stop": result["stop"]} in result["partial"]
    assert 0 < result["states"] < 2**40


def test_analyze_runs_under_the_cli_s_memory_guard_by_default():
    # no limit given (0): the guard, 3/4 of the memory available at the start, as gdpn analyze
    limits = gdpn.analysis_limits()
    assert limits["guard"] is True
    assert limits["max_states"] == 20_000_000
    with open("/proc/meminfo") as f:
        total = next(int(line.split()[1]) * 1024 for line in f if line.startswith("MemTotal:"))
    assert 0 < limits["max_bytes"] <= total * 3 // 4
    assert "max_memory_mib: float = 0.0" in gdpn.Model.analyze.__doc__
    # a limit given is a limit, not a guard
    assert gdpn.analysis_limits(max_memory_mib=64) == {"max_states": 20_000_000, "max_bytes": 64 << 20, "guard": False}
    with pytest.raises(ValueError, match="max_memory_mib"):
        gdpn.analysis_limits(max_memory_mib=-1)
