# Steering and bookkeeping for the vehicles: every script sees these names.

arrivals = {}     # vehicle -> seconds when it reached the depot
travelled = {}    # vehicle -> metres driven (in the plane)
last = {}         # vehicle -> its last (x, y)
clearance = {}    # vehicle -> its smallest distance to a rock's side, metres (the car's half-diagonal is 0.47 m)


def vehicle(body):
    return body.name.split("/")[0]


def drive(body, compass):
    """Set the vehicle's velocity in the plane to the field's vector where it stands; gravity
    keeps it on the ground. A parked vehicle stands still."""
    name = vehicle(body)
    x, y, _ = body.position
    # the distance counts while the vehicle drives: once parked, its log line and the
    # summary say the same metres
    if name in last and name not in arrivals:
        px, py = last[name]
        travelled[name] = travelled.get(name, 0.0) + ((x - px) ** 2 + (y - py) ** 2) ** 0.5
    last[name] = (x, y)
    for rock in rocks():
        rx, ry, _ = rock.position
        gap = ((x - rx) ** 2 + (y - ry) ** 2) ** 0.5 - rock.children[0].radius
        clearance[name] = min(clearance.get(name, gap), gap)
    _, _, vz = body.velocity
    if name in arrivals:
        body.set_velocity((0.0, 0.0, vz))
        return
    vx, vy = compass.vector[0], compass.vector[1]
    body.set_velocity((vx, vy, vz))


_rocks = []


def rocks():
    if not _rocks:
        k = 1
        while True:
            try:
                _rocks.append(sim.node(f"rock{k}"))
            except Exception:
                break
            k += 1
    return _rocks


def park(body):
    name = vehicle(body)
    arrivals[name] = sim.time
    sim.log(f"{name} reached the depot at {sim.time:.2f} s after {travelled.get(name, 0.0):.1f} m")


def summary():
    figures = {}
    for name in sorted(last):
        if name in arrivals:
            figures[name] = f"reached the depot at {arrivals[name]:.2f} s after {travelled[name]:.1f} m"
        else:
            figures[name] = "still driving"
    figures["vehicles at the depot"] = f"{len(arrivals)} of {len(last)}"
    figures["closest approach to a rock"] = f"{min(clearance.values()):.2f} m" if clearance else "-"
    return figures
