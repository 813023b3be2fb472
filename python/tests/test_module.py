"""The gdpn Python module: loading, running, markings, trace, report and errors."""

import gdpn
import pytest


def test_load_and_run_reports_exact_cycle_times(source):
    model = gdpn.load(str(source / "tests/data/good/cycles.gdpn.yaml"))
    report = model.run()
    assert report["steps"] == 320
    assert report["stopped"] == "until"
    cycles = {t["name"]: t["mean_cycle"] for t in report["transitions"]}
    assert cycles["main/a1"] == 4.0
    assert cycles["main/b2"] == 1.0
    assert model.time == 40.0


def test_step_and_marking_follow_figure_3_1(source):
    model = gdpn.load(str(source / "examples/basics/figure31"))
    assert [model.marking(p) for p in ("main/P1", "main/P2", "main/P3", "main/P4")] == [1, 1, 0, 0]
    model.step()  # time 0's firing phase started T1; at 1 s it completes and T2 starts
    assert model.marking("main/P3") == 0
    model.step()
    assert [model.marking(p) for p in ("main/P1", "main/P2", "main/P3", "main/P4")] == [0, 1, 0, 1]
    with pytest.raises(KeyError):
        model.marking("main/nowhere")


def test_node_markings_list_node_names(write_model):
    path = write_model("""gdpn: 1
settings: {dt: 1, until: 5}
pages:
  main:
    places:
      a: {tokens: {d0: [box1, box2]}}
      b: {}
    transitions:
      move: {}
    arcs:
      - {from: a, to: move, weight: {d0: 1}}
      - {from: move, to: b, weight: {d0: 1}}
""")
    model = gdpn.load(path)
    assert model.marking("main/a") == {"d0": ["box1", "box2"]}
    model.run()
    assert model.marking("main/b") == {"d0": ["box1", "box2"]}


def test_trace_is_a_list_of_events(source):
    model = gdpn.load(str(source / "examples/basics/figure31"))
    model.run()
    events = model.trace()
    assert events[0] == {"step": 0, "t": 0, "ev": "start", "transition": "main/T1"}
    assert [e["ev"] for e in events].count("complete") == 2


def test_seed_makes_runs_repeatable_and_restarts(source):
    path = str(source / "tests/data/good/stochastic.gdpn.yaml")
    a = gdpn.load(path).run(seed=5)
    b = gdpn.load(path).run(seed=5)
    c = gdpn.load(path).run(seed=6)
    assert a == b
    assert a != c
    model = gdpn.load(path)
    model.run(steps=10)
    assert model.run(seed=5, steps=10)["steps"] == 10  # a seed restarts from the initial marking


def test_model_error_carries_the_location(source):
    bad = source / "tests/data/bad/unknown_key.gdpn.yaml"
    with pytest.raises(gdpn.ModelError) as info:
        gdpn.load(str(bad))
    err = info.value
    assert err.file == str(bad)
    assert (err.line, err.column) == (6, 23)
    assert "unknown key 'capacty'" in str(err)
    assert len(err.diagnostics) == 1


def test_semantic_errors_are_model_errors_too(source):
    with pytest.raises(gdpn.ModelError) as info:
        gdpn.load(str(source / "tests/data/bad/two_kinds.gdpn.yaml"))
    assert (info.value.line, info.value.column) == (7, 20)


def test_a_failing_script_raises_script_error(write_model):
    path = write_model("""gdpn: 1
settings: {dt: 1, until: 5}
pages:
  main:
    places:
      p: {tokens: 3}
    transitions:
      t:
        pre_fire: |
          raise ValueError("no good")
    arcs:
      - p -> t
""")
    model = gdpn.load(path)
    with pytest.raises(gdpn.ScriptError) as info:
        model.run()
    assert "m.gdpn.yaml:10: error: pre_fire of transition 'main/t' raised an exception" in str(info.value)
    assert "ValueError: no good" in str(info.value)


def test_script_timeout_stops_an_endless_script(write_model):
    path = write_model("""gdpn: 1
pages:
  main:
    places:
      p: {tokens: 1}
    transitions:
      t:
        pre_fire: |
          while True:
              pass
    arcs:
      - p -> t
""")
    model = gdpn.load(path, script_timeout=0.2)
    with pytest.raises(gdpn.ScriptError, match="ran longer than the script timeout of 0.2 s"):
        model.run()


def test_scripts_see_sim_and_self(write_model):
    path = write_model("""gdpn: 1
settings: {dt: 0.5, until: 2, seed: 3}
scripts:
  globals: |
    seen = []
pages:
  main:
    places:
      p: {tokens: 2}
    transitions:
      t:
        duration: 0.5
        pre_fire: |
          seen.append((sim.time, self.name, self.a0.get()))
          sim.log("seen", len(seen))
    arcs:
      - p -> t
""")
    model = gdpn.load(path)
    model.run()
    logs = [e["text"] for e in model.trace() if e["ev"] == "log"]
    assert logs == ["seen 1", "seen 2"]
