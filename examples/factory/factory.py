# Helpers for the factory's scripts: names for what the transitions do, and the figures the
# run's summary shows. Every script sees these names (they are the model's globals).

painted = {}          # box name -> the station that painted it
painted_twice = 0     # paint() on a box already painted
strikes = []          # (time, station, box): a box the rod's guard met that it was not handling
handling = {}         # station -> the box its rod takes in and out
boxes_delivered = 0
drop_times = []       # when the arm let go of each box, seconds
cell_times = {}       # station -> when each of its cycles ended, seconds


def at(t, seconds):
    """True in the one step of transition t's occurrence at which `seconds` have passed."""
    return t.elapsed - sim.dt < seconds <= t.elapsed + 1e-9


def station(t):
    """The station instance a construct belongs to ("stationA")."""
    return t.name.split("/")[-2]


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
    ex, ey, _ = eye_position(t)
    bx, by, _ = box.position
    return abs(bx - ex) < 0.15 and abs(by - ey) < 0.15


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
    box.prev.diffuse = (0.95, 0.4, 0.05)


def rod(t):
    return t.b4.find("slide")


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


def done(t, box):
    handling.pop(station(t), None)
    cell_times.setdefault(station(t), []).append(sim.time)


def guard_touched(place, item):
    """The region at the rod's tip met something: a box other than the one it handles is a strike."""
    s = station(place)
    if item.name.startswith("boxes/") and item.name != handling.get(s):
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
        figures[f"{s} cycle, measured"] = f"{mean_interval(cell_times[s]):.2f} s over {len(cell_times[s])} boxes"
    figures["boxes delivered by the arm"] = boxes_delivered
    for s in ("stationA", "stationB"):
        figures[f"painted by {s}"] = sum(1 for v in painted.values() if v == s)
    figures["boxes at the end of the line"] = len(left)
    figures["share of those painted"] = f"{share:.0%}"
    figures["boxes painted twice"] = painted_twice
    figures["rod strikes"] = len(strikes)
    return figures


def no_box(sensor):
    """No box is in the region (the stops and doors it also sees do not count)."""
    return not any(item.name.startswith("boxes/") for item in sensor.items)
