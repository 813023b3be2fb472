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
    assert "m.gdpn.yaml:10: error: pre_fire of transition 'main/t' at t = 0 s raised an exception" in str(info.value)
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


PRODUCER_CONSUMER = "examples/basics/producer_consumer"


def test_breakpoints_stop_runs_where_they_hold(source):
    model = gdpn.load(str(source / PRODUCER_CONSUMER))
    first = model.add_breakpoint(starts="main/consume")
    report = model.run()
    assert (report["stopped"], report["steps"], model.hit) == ("breakpoint", 100, first)
    model.remove_breakpoint(first)
    full = model.add_breakpoint(place="main/buffer", compare=">=", value=3)
    model.run()
    assert model.marking("main/buffer") == 3 and model.hit == full
    model.remove_breakpoint(full)
    late = model.add_breakpoint(predicate="sim.time >= 20")
    assert model.run()["steps"] == 2000 and model.hit == late
    assert model.breakpoints == [{"id": late, "watches": "sim.time >= 20", "enabled": True}]
    with pytest.raises(ValueError, match="no transition 'main/nope'"):
        model.add_breakpoint(completes="main/nope")
    with pytest.raises(ValueError, match="one thing"):
        model.add_breakpoint(starts="main/consume", place="main/buffer")
    with pytest.raises(KeyError):
        model.remove_breakpoint(first)


def test_reset_gives_the_same_run_again(source):
    model = gdpn.load(str(source / "tests/data/good/stochastic.gdpn.yaml"))
    model.run(until=20)
    first = model.trace()
    model.reset()
    assert (model.time, model.trace()) == (0.0, [])
    model.run(until=20)
    assert model.trace() == first


def test_fire_starts_a_transition_or_says_why_not(write_model):
    path = write_model("""gdpn: 1
settings: {dt: 0.5}
pages:
  main:
    places:
      ready: {tokens: 1}
      empty: {}
      done: {}
    transitions:
      rare: {duration: 1, probability: 0.000001}
      starved: {}
    arcs:
      - ready -> rare
      - rare -> done
      - empty -> starved
""")
    model = gdpn.load(str(path))
    with pytest.raises(gdpn.FireError, match="'main/empty' a0 holds 0 of the 1 it needs"):
        model.fire("main/starved")
    model.fire("main/rare")
    assert model.marking("main/ready") == 0
    model.step()
    model.step()
    assert model.marking("main/done") == 1


def test_step_plant_moves_the_plant_and_keeps_the_marking(write_model):
    path = write_model("""gdpn: 1
settings: {dt: 0.01}
scene:
  - Body: {name: ball, mass: 1, children: [{Sphere: {radius: 0.1}}]}
pages:
  main:
    places:
      a: {tokens: {d0: [ball]}}
      b: {}
    transitions:
      t: {duration: 1}
    arcs:
      - {from: a, to: t, weight: {d0: 1}}
      - {from: t, to: b, weight: {d0: 1}}
""")
    model = gdpn.load(str(path))
    model.step()
    for _ in range(100):
        model.step_plant()
    assert model.time == pytest.approx(1.01)
    assert model.marking("main/b") == {"d0": []}
    model.run(until=2.0)
    assert model.marking("main/b") == {"d0": ["ball"]}


def test_a_callable_predicate_and_live_input(source):
    model = gdpn.load(str(source / "tests/data/input/console.gdpn.yaml"))
    model.add_breakpoint(starts="main/go")
    assert model.run()["stopped"] == "dead"  # nobody at the console
    model.push(viewpoint=(0, 0, 0), at=1.0)
    model.push(key="g", at=1.5)
    report = model.run(until=5)
    assert (report["stopped"], report["steps"]) == ("breakpoint", 15)
    seen = []
    model.reset()
    late = model.add_breakpoint(predicate=lambda: seen.append(model.time) or model.time >= 0.3)
    model.enable_breakpoint(1, False)
    model.push(viewpoint=(0, 0, 0))
    model.push(key="x", at=1.0)  # pending input keeps the run going
    assert model.run(until=5)["steps"] == 3 and model.hit == late
    assert seen[-1] == pytest.approx(0.3)
    with pytest.raises(ValueError, match="one of key=, viewpoint= or click="):
        model.push()


def test_a_body_that_runs_away_raises_physics_error(write_model):
    path = write_model("""gdpn: 1
settings: {dt: 0.01}
scene:
  - Body: {name: box, mass: 1, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}
pages:
  main:
    places:
      a: {tokens: {d0: [box]}}
      b: {}
    transitions:
      push:
        duration: 1
        pre_fire: 'self.d0[0].set_force((1e17, 0, 0))'
    arcs:
      - {from: a, to: push, weight: {d0: 1}}
      - {from: push, to: b, weight: {d0: 1}}
""")
    model = gdpn.load(str(path))
    with pytest.raises(gdpn.PhysicsError, match="body 'box' ran away"):
        model.run(until=1)


def test_analyze_answers_queries_as_data_with_their_witnesses(source):
    model = gdpn.load(str(source / "examples/basics/figure31"))
    # figure 3.1: T1 then T2 end in a dead marking
    answer = model.analyze("EF deadlock")
    assert answer["answer"] == "true"
    assert answer["path"] == ["main/T1", "main/T2"]
    assert answer["marking"] == {"main/P2": 1, "main/P4": 1}
    answers = model.analyze(["AG P1 + P3 + P4 <= 1", "A (G F fireable(T1))", "bound(P3)"])
    assert [a["answer"] for a in answers] == ["true", "false", 1]
    assert answers[1]["cycle"] == []  # the counterexample stays in the dead marking
    assert "path" not in answers[0]  # an invariant rests on every marking: no path shows it
    # the whole analysis without a query
    whole = model.analyze()
    assert whole["states"] == 3 and whole["deadlock_path"] == ["main/T1", "main/T2"]
    # a mistake is located by its column
    with pytest.raises(gdpn.ModelError) as e:
        model.analyze(["EF deadlock", "EF (P1 >= 1"])
    assert e.value.file == "query 2" and e.value.line == 1 and e.value.column == 12
    # a limit leaves the answer unknown, and says why
    limited = model.analyze("EF P4 = 1", max_states=1)
    assert limited["answer"] == "unknown" and "--max-states" in limited["why"]


def test_params_set_at_load_reach_fields_and_scripts(source):
    path = str(source / "tests/data/good/params.gdpn.yaml")
    model = gdpn.load(path)
    assert model.params == {"wait": 0.5, "parts": 3, "spread": 0.25, "belt_speed": 0.4, "lane": 2, "chance": 0.5}
    assert model.marking("main/ready") == 3
    model = gdpn.load(path, params={"parts": 5, "wait": 1.0})
    assert model.params["parts"] == 5 and model.params["wait"] == 1.0
    assert model.marking("main/ready") == 5
    with pytest.raises(gdpn.ModelError) as info:
        gdpn.load(path, params={"wiat": 1})
    assert info.value.args[0].startswith("params=: error: no parameter 'wiat' in ")
    with pytest.raises(gdpn.ModelError) as info:
        gdpn.load(path, params={"parts": 2.5})
    assert "parameter 'parts' is a whole number (at most 2^53), got '2.5'" in info.value.args[0]
    with pytest.raises(TypeError):
        gdpn.load(path, params={"parts": "many"})


def test_signals_are_a_dataframe_of_the_falling_ball(source):
    pandas = pytest.importorskip("pandas")
    model = gdpn.load(str(source / "tests/data/good/falling_ball.gdpn.yaml"), signals=["place:main/clock"])
    model.run()
    frame = model.signals()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns) == ["ball.x", "ball.y", "ball.z", "speed.x", "speed.y", "speed.z", "ticks", "clock",
                                   "main/clock"]
    assert frame.index.name == "time"
    assert len(frame) == 101  # time 0 and each of 100 steps
    # the ball falls as the integrator has it: after n steps of h, g h^2 n (n + 1) / 2 below
    # its start, which is g t^2 / 2 and half a step's more
    h, g = 0.01, 9.81
    for n in (1, 50, 100):
        t = frame.index[n]
        assert t == pytest.approx(n * h)
        assert frame["ball.z"].iloc[n] == pytest.approx(20 - g * h * h * n * (n + 1) / 2, abs=1e-9)
        assert abs(frame["ball.z"].iloc[n] - (20 - g * t * t / 2)) <= g * h * t / 2 + 1e-9
    # each at its own period: NaN between
    assert frame["ticks"].dropna().tolist() == [float(k) for k in range(11)]
    assert frame["clock"].dropna().tolist() == [0.0, 1.0, 2.0]
    assert frame["speed.z"].dropna().iloc[-1] == pytest.approx(-g * 1.0)
    with pytest.raises(ValueError):
        gdpn.load(str(source / "tests/data/good/falling_ball.gdpn.yaml"), signals=["ball"])
    with pytest.raises(gdpn.ModelError) as info:
        gdpn.load(str(source / "tests/data/good/falling_ball.gdpn.yaml"), signals=["node:drop/ball.angle"])
    assert "'drop/ball' is no joint: it has no angle" in info.value.args[0]


def test_a_coloured_model_shows_its_values_and_is_analysed_unfolded(source):
    # value tokens (semantics.md, Value tokens): the marking is each value with its count, and
    # the analysis is gdpn analyze's, on the unfolded net, naming the places as written
    model = gdpn.load(str(source / "examples/coloured/job_shop"))
    assert model.marking("main/idle") == {"lathe": 1, "mill": 1, "drill": 1}
    assert model.marking("main/operators") == 2
    model.run(until=120)
    assert model.marking("main/waiting") == {}
    assert list(model.marking("main/shipped").values()) == [1, 1, 1, 1]
    answers = model.analyze(["AG operators + loaded <= 2", "bound(idle)", "EF shipped >= 4"])
    assert [a["answer"] for a in answers] == ["true", 3, "true"]
    assert answers[0]["formula"] == "AG main/operators + main/loaded <= 2"
    assert model.analyze()["states"] == 270


def test_a_continuous_place_reads_as_its_amount_and_breaks_on_it(source):
    # the pump fills at 0.3 L/s, dt 0.1: 0.5 L is first reached at the end of step 17 (0.51 L)
    model = gdpn.load(str(source / "tests/data/hybrid/fill.gdpn.yaml"))
    assert model.marking("main/tank") == 0.0
    assert model.add_breakpoint(place="main/tank", compare=">=", value=0.5) == 1
    report = model.run(until=5)
    assert report["steps"] == 17
    assert model.marking("main/tank") == pytest.approx(0.51, abs=1e-12)
    with pytest.raises(TypeError):
        model.add_breakpoint(place="main/tank", value="lots")
    model.reset()
    model.remove_breakpoint(1)
    report = model.run(until=5)
    assert report["amounts"] == [{"name": "main/tank", "unit": "L", "final": pytest.approx(1.02, abs=1e-12),
                                  "lowest": 0.0, "highest": pytest.approx(1.02, abs=1e-12),
                                  "mean": pytest.approx((0.3 * 3.4 * 3.4 / 2 + 1.02 * 0.1) / 3.5, abs=1e-12)}]
    assert report["flows"][0]["moved"] == pytest.approx(1.02, abs=1e-12)
