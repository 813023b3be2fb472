"""Parts from Python: the library as `gdpn parts` lists it, a run's part I/O with their
values, and forces that apply at the next step, as the IDE's I/O list applies them."""

import subprocess

import gdpn

STATION = "examples/station/sorting_station.gdpn.yaml"


def test_the_library_lists_what_gdpn_parts_lists(source):
    parts = {p["name"]: p for p in gdpn.parts()}
    for name in ["emitter", "belt_conveyor", "pusher", "diffuse_sensor", "bin", "remover", "stack_light"]:
        assert name in parts
    assert parts["pusher_control"]["pattern"]
    pusher = parts["pusher"]
    assert {i["name"]: (i["direction"], i["signal"]) for i in pusher["io"]} == {
        "extend": ("output", "digital"), "front_limit": ("input", "digital"), "back_limit": ("input", "digital")}
    listed = subprocess.run([gdpn.sweep.__globals__["find_gdpn"](), "parts"], capture_output=True, text=True)
    assert listed.returncode == 0, listed.stderr
    for name, p in parts.items():
        if not p["pattern"]:
            assert f"  {name} " in listed.stdout


def test_a_forced_output_holds_and_is_released(source):
    m = gdpn.load(str(source / STATION))
    rows = {(r["part"], r["io"]): r for r in m.io()}
    assert rows[("main/belt_conveyor1", "run")]["signal"] == "digital"
    m.step()
    m.force("belt_conveyor1", "run", 0)
    rows = {(r["part"], r["io"]): r for r in m.io()}
    assert not rows[("main/belt_conveyor1", "run")]["forced"]  # at the next step, not now
    m.step()
    rows = {(r["part"], r["io"]): r for r in m.io()}
    assert rows[("main/belt_conveyor1", "run")]["forced"]
    assert rows[("main/belt_conveyor1", "run")]["value"] == 0
    events = [e for e in m.trace() if e.get("ev") == "force"]
    assert events == [{"step": 2, "t": events[0]["t"], "ev": "force", "part": "main/belt_conveyor1", "io": "run",
                       "value": 0}]
    m.release()
    m.step()
    rows = {(r["part"], r["io"]): r for r in m.io()}
    assert not rows[("main/belt_conveyor1", "run")]["forced"]
    assert rows[("main/belt_conveyor1", "run")]["value"] == 1
    try:
        m.force("belt", "run", 1)
    except KeyError as e:
        assert "no part 'belt'" in str(e)
    else:
        raise AssertionError("an unknown part is a KeyError")
