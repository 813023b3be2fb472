"""The script timeout from Python: a script that does not return is stopped, wherever it waits
and even when it catches the stop; the run ends with a located gdpn.ScriptError."""

import signal
import sys
import textwrap
import time

import gdpn
import pytest


def hooks(pre_fire, on_deposit="pass"):
    """A model whose transition t runs `pre_fire` (from line 9) and whose place q runs
    `on_deposit` (from line 14 when pre_fire is one line)."""
    def indent(code):
        return textwrap.indent(textwrap.dedent(code).strip() + "\n", " " * 10)
    return ("gdpn: 1\n"
            "settings: {dt: 1, until: 5}\n"
            "pages:\n"
            "  main:\n"
            "    arcs: [p -> t, t -> q]\n"
            "    transitions:\n"
            "      t:\n"
            "        pre_fire: |\n" + indent(pre_fire) +
            "    places:\n"
            "      p: {tokens: 3}\n"
            "      q:\n"
            "        on_deposit: |\n" + indent(on_deposit))


def run_stopped(path, timeout):
    """Runs the model at `path`; the ScriptError's text and the seconds it took."""
    model = gdpn.load(path, script_timeout=timeout)
    start = time.monotonic()
    with pytest.raises(gdpn.ScriptError) as info:
        model.run()
    seconds = time.monotonic() - start
    assert seconds < 4
    assert model.trace()[-1]["ev"] == "error"
    return str(info.value)


def test_a_sleeping_pre_fire_is_stopped_at_its_line(write_model):
    path = write_model(hooks("""
        import time
        time.sleep(100)
    """))
    assert run_stopped(path, 0.3) == (
        f"{path}:10: error: pre_fire of transition 'main/t' at t = 0 s ran longer than the script timeout of 0.3 s")


@pytest.mark.parametrize("call", [
    "import socket\na, b = socket.socketpair()\na.recv(1)",
    "import os\nr, w = os.pipe()\nos.read(r, 1)",
    "import os\nr, w = os.pipe()\nos.fdopen(r).read()",
], ids=["socket", "pipe", "file"])
def test_a_blocking_read_in_on_deposit_is_stopped(write_model, call):
    path = write_model(hooks("pass", call))
    line = 14 + call.count("\n")
    assert run_stopped(path, 0.3) == (
        f"{path}:{line}: error: on_deposit of place 'main/q' slot a0 at t = 1 s ran longer than the script timeout of 0.3 s")


def test_a_script_that_swallows_the_stop_is_stopped_all_the_same(write_model):
    path = write_model(hooks("""
        import time
        while True:
            try: time.sleep(1)
            except BaseException: pass
    """))
    # the stop is located where it came last: in the except clause
    assert run_stopped(path, 0.3) == (
        f"{path}:12: error: pre_fire of transition 'main/t' at t = 0 s ran longer than the script timeout of 0.3 s")


def test_a_sleeping_globals_script_fails_the_load_where_it_sleeps(write_model):
    path = write_model("gdpn: 1\nscripts:\n  globals: |\n    import time\n    time.sleep(100)\n"
                       "pages:\n  main:\n    places:\n      p: {tokens: 1}\n")
    start = time.monotonic()
    with pytest.raises(gdpn.ModelError) as info:
        gdpn.load(path, script_timeout=0.5)
    assert time.monotonic() - start < 4
    assert (info.value.file, info.value.line) == (path, 5)
    assert "the globals script ran longer than the script timeout of 0.5 s" in str(info.value)


def test_a_sleeping_predicate_breakpoint_ends_the_run_naming_it(source):
    model = gdpn.load(str(source / "examples/basics/producer_consumer"), script_timeout=0.3)
    model.add_breakpoint(predicate="__import__('time').sleep(100)")
    start = time.monotonic()
    with pytest.raises(gdpn.ScriptError, match=r"breakpoint 1 \(.*\) failed: it ran longer than the script timeout"):
        model.run(steps=100)
    assert time.monotonic() - start < 4


def test_runs_without_a_timeout_or_within_it_are_untouched(write_model):
    # a stopped run first: nothing of its stop may reach the runs after it
    tracer = sys.gettrace()
    stopped = write_model(hooks("import time\nwhile True:\n  try: time.sleep(1)\n  except BaseException: pass"),
                          "stopped.gdpn.yaml")
    run_stopped(stopped, 0.2)
    path = write_model(hooks("""
        import sys, time
        time.sleep(0.05)
        sim.log("start", sys.gettrace() is None)
    """, "import time\ntime.sleep(0.02)\nsim.log('deposit')"))
    for timeout in (0.0, 1.0):
        model = gdpn.load(path, script_timeout=timeout)
        assert model.run()["stopped"] == "dead"
        logs = [e["text"] for e in model.trace() if e["ev"] == "log"]
        assert logs == ["start True", "deposit"] * 3
    # the process's own signal handling is as it was: Ctrl-C is still Python's
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    assert sys.gettrace() is tracer
