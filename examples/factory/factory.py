# Helpers for the factory's scripts: names for what the transitions do, and the figures the
# run's summary shows. Every script sees these names (they are the model's globals).

painted = {}          # box name -> the station that painted it
painted_twice = 0     # paint() on a box already painted
strikes = []          # (time, station, box): a box the rod's guard met that it was not handling
handling = {}         # station -> the box its rod takes in and out
boxes_delivered = 0
drop_times = []       # when the arm let go of each box, seconds
cell_times = {}       # station -> when each of its cycles ended, seconds
cell_starts = {}      # station -> when each of its cycles began (push_box), seconds
deck_waits = {}       # station -> per cycle, how long push_rod waited for the deck to clear, seconds
painted_at = {}       # station -> when it last painted a box (pull_rod's end), seconds


def at(t, seconds):
    """True in the one step of transition t's occurrence at which `seconds` have passed."""
    return t.elapsed - sim.dt < seconds <= t.elapsed + 1e-9


def station(t):
    """The station instance a construct belongs to ("stationA")."""
    return t.name.split("/")[-2]


def yard_eye(place):
    """The yard's belt runs while a box lies at the chute's foot, to make room for the next;
    stopped, the boxes on it come to rest (and sleep, costing the solver nothing)."""
    sim.node("line/yard/drive").speed = 0.0 if no_box(place.c0) else 0.6


def lane_drive():
    """The feed lane's belt: it runs only while a box moves up to the pickup place."""
    return sim.node("feed/lane/drive")


def gripper(t):
    return t.b2.find("gripper")


def delivered(t, box):
    global boxes_delivered
    gripper(t).detach(box)
    boxes_delivered += 1
    drop_times.append(sim.time)
    x, y, z = box.position
    sim.log(f"released {box.name} at ({x:.2f}, {y:.2f}, {z:.2f})")


def eye_position(t):
    return sim.node(station(t) + "/eye_at/eye").position


def at_eye(t, box):
    """The box stands still against the right stop, in front of the rod."""
    ex, ey, _ = eye_position(t)
    bx, by, _ = box.position
    return -0.12 < bx - ex < 0.1 and abs(by - ey) < 0.15 and abs(box.velocity[0]) < 0.05


def past(t, box):
    """The box has left the station's platform downstream."""
    return box.position[0] > eye_position(t)[0] + 1.0


def is_painted(box):
    return box.name in painted


def paint(t, box):
    global painted_twice
    if box.name in painted:
        painted_twice += 1
    painted[box.name] = station(t)
    painted_at[station(t)] = sim.time
    box.prev.diffuse = (0.95, 0.4, 0.05)


def rod(t):
    return t.b4.find("slide")


def begin(t):
    cell_starts.setdefault(station(t), []).append(sim.time)


def rod_out(t):
    """push_rod starts: the deck is clear at last."""
    s = station(t)
    deck_waits.setdefault(s, []).append(sim.time - painted_at.get(s, sim.time))


def take(t, box, speed=0.8):
    handling[station(t)] = box.name
    rod(t).attach(box)
    t.b4.vel1 = speed


def release(t, box):
    rod(t).detach(box)


def open_doors(t):
    t.b2.vel1 = -0.6
    t.b3.vel1 = 0.6


def close_doors(t):
    t.b2.vel1 = 0.6
    t.b3.vel1 = -0.6


# The stops never rise under a box: a stop asked to rise while a box is over it waits until
# the region's on_exit says the box has gone. The right stop waits for the whole deck to
# clear, so a train of boxes let go together passes whole instead of being split.
wanted_up = {}   # (station, "left" | "right") -> True while the stop should be up


def stop_region_clear(s, which):
    region = "over_left" if which == "left" else "deck"
    return no_box(sim.place(f"factory/{s}/{region}").c0)


def crowded(t):
    """A second box presses on the one in front of the rod: the left stop could not rise
    between them, so the station lets both pass."""
    return not stop_region_clear(station(t), "left")


def rise(t, which):
    s = station(t)
    wanted_up[(s, which)] = True
    if stop_region_clear(s, which):
        sim.node(f"{s}/{which}").vel1 = 1


def lower(t, which):
    s = station(t)
    wanted_up[(s, which)] = False
    sim.node(f"{s}/{which}").vel1 = -1


def stop_cleared(place, which):
    """on_exit of the region over a stop: raise the stop now if it was kept down."""
    s = station(place)
    if wanted_up.get((s, which)) and stop_region_clear(s, which):
        sim.node(f"{s}/{which}").vel1 = 1


def done(t, box):
    handling.pop(station(t), None)
    cell_times.setdefault(station(t), []).append(sim.time)


def guard_touched(place, item):
    """The region at the rod's tip met something while the rod was out: a box other than the
    one the rod handles is a strike. (At rest the tip lies at the platform's edge, where
    boxes going by brush the region.)"""
    s = station(place)
    out = sim.node(f"{s}/rod").angle > 0.02
    if out and item.name.startswith("boxes/") and item.name != handling.get(s):
        strikes.append((round(sim.time, 2), s, item.name))
        sim.log("the rod of", s, "struck", item.name, "at", round(sim.time, 2), "s")


def mean_interval(times):
    if len(times) < 2:
        return float("nan")
    return (times[-1] - times[0]) / (len(times) - 1)


def summary():
    piled = sim.place("factory/piled").d0
    left = [box.name for box in piled]
    share = sum(1 for name in left if name in painted) / len(left) if left else 0.0
    figures = {
        "arm cycle, measured": f"{mean_interval(drop_times):.2f} s over {len(drop_times)} boxes",
    }
    for s in sorted(cell_times):
        ends = cell_times[s]
        spans = [e - b for b, e in zip(cell_starts[s], ends)]
        waits = deck_waits[s][: len(spans)]
        mean_span = sum(spans) / len(spans)
        mean_wait = sum(waits) / len(waits)
        figures[f"{s} cycle, measured"] = (f"{mean_span:.2f} s over {len(spans)} boxes (push box to end of wait): "
                                            f"{mean_span - mean_wait:.2f} s working, {mean_wait:.2f} s waiting for the deck to clear")
        figures[f"{s} time between insertions"] = f"{mean_interval(cell_starts[s]):.2f} s"
    figures["boxes delivered by the arm"] = boxes_delivered
    for s in ("stationA", "stationB"):
        figures[f"painted by {s}"] = sum(1 for v in painted.values() if v == s)
    done_painted = sum(1 for name in left if name in painted)
    figures["boxes at the end of the line"] = len(left)
    figures["painted among them"] = done_painted
    figures["unpainted among them"] = len(left) - done_painted
    figures["share of those painted"] = f"{share:.0%}"
    figures["boxes painted twice"] = painted_twice
    figures["rod strikes"] = len(strikes)
    return figures


def no_box(sensor):
    """No box is in the region (the stops and doors it also sees do not count)."""
    return not any(item.name.startswith("boxes/") for item in sensor.items)
