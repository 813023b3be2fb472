#!/usr/bin/env python3
"""Writes the vehicles example: the terrain (terrain.png, a greyscale elevation image) and the
model (vehicles.gdpn.yaml) with its gradient field: at every grid point, a pull towards the
depot plus a push away from each rock, scaled to the driving speed. Run it again after
changing the numbers below; the files it writes are committed."""

import math
import struct
import zlib
from pathlib import Path

HERE = Path(__file__).resolve().parent
SIZE = 40.0              # the terrain and the field span SIZE x SIZE metres, centred on the origin
PIXELS = 65              # elevation image, PIXELS x PIXELS
HEIGHT = 2.0             # metres of the brightest pixel
GRID = 21                # field vectors, GRID x GRID
SPEED = 1.5              # m/s far from the depot
DEPOT = (12.0, 10.0)     # where every vehicle goes
ROCKS = [(-4.0, -2.0, 1.6), (4.0, 4.0, 1.4), (-8.0, 9.0, 1.2), (8.0, -7.0, 1.5)]  # x, y, radius
STARTS = {"car1": (-16.0, -15.0), "car2": (-16.0, 14.0), "car3": (14.0, -16.0), "car4": (-2.0, -17.0)}


def elevation(x, y):
    """Rolling hills, metres."""
    return 0.5 * HEIGHT * (1 + 0.6 * math.sin(x * 0.21) * math.cos(y * 0.17) + 0.4 * math.sin((x + y) * 0.09))


def write_png(path):
    rows = b""
    for j in range(PIXELS):              # row 0 is at +y
        y = SIZE / 2 - SIZE * j / (PIXELS - 1)
        row = bytes(max(0, min(255, round(255 * elevation(-SIZE / 2 + SIZE * i / (PIXELS - 1), y) / (1.5 * HEIGHT))))
                    for i in range(PIXELS))
        rows += b"\0" + row

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", PIXELS, PIXELS, 8, 0, 0, 0, 0)
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9)) +
                     chunk(b"IEND", b""))


def field(x, y):
    dx, dy = DEPOT[0] - x, DEPOT[1] - y
    d = max(1e-6, math.hypot(dx, dy))
    vx, vy = dx / d, dy / d                       # pull: unit vector to the depot
    for rx, ry, r in ROCKS:                       # push: grows fast near a rock, gone 3 radii away
        ex, ey = x - rx, y - ry
        e = max(1e-6, math.hypot(ex, ey))
        reach = 3 * r
        if e < reach:
            w = 2.5 * ((reach - e) / (reach - r if e > r else 1e-6)) ** 2 if e > r else 6.0
            vx, vy = vx + w * ex / e - 0.8 * w * ey / e, vy + w * ey / e + 0.8 * w * ex / e  # out and around
    n = max(1e-6, math.hypot(vx, vy))
    speed = SPEED * min(1.0, d / 2.0)             # slows down over the last 2 m
    return speed * vx / n, speed * vy / n


def num(v):
    return f"{v:.3f}".rstrip("0").rstrip(".") if abs(v) > 5e-4 else "0"


def write_model(path):
    vectors = []
    for j in range(GRID):                         # rows from -y, each from -x
        for i in range(GRID):
            x = -SIZE / 2 + SIZE * i / (GRID - 1)
            y = -SIZE / 2 + SIZE * j / (GRID - 1)
            vectors += field(x, y)
    rows = []
    for k in range(0, len(vectors), 2 * GRID):
        rows.append("        " + ", ".join(num(v) for v in vectors[k:k + 2 * GRID]))
    cars = list(STARTS)
    colours = {"car1": "[0.85, 0.2, 0.15]", "car2": "[0.2, 0.45, 0.85]", "car3": "[0.95, 0.75, 0.1]", "car4": "[0.3, 0.7, 0.3]"}
    text = f"""gdpn: 1
# Written by make.py (run it again after changing its numbers).
description: >-
  Autonomous vehicles cross a hilly terrain to a depot, each steered by the gradient field it
  stands in (sections 2.5 and 9.2.2 of the dissertation): the field pulls towards the depot and
  pushes away from the rocks. A vehicle's token leaves `driving` for `parked` when the depot's
  region holds it; the run stops when all {len(cars)} are parked.
settings: {{dt: 0.01, seed: 1, until: 60}}
scripts:
  globals: {{file: vehicles.py}}
scene:
  - World: {{substeps: 1}}
  - Light: {{kind: directional, direction: [-0.4, 0.6, -1]}}
  - Camera: {{name: overview, position: [0, -42, 34], target: [0, 0, 0], fov: 50}}
  - Camera: {{name: orbit, kind: orbit, position: [0, -45, 30], target: [0, 0, 0], speed: 4}}
  - Camera: {{name: close, position: [-1, -16, 12], target: [5, 3, 0], fov: 45}}
  - Material: {{diffuse: [0.45, 0.58, 0.32], friction: 0.6}}
  - Terrain: {{name: ground, file: terrain.png, width: {num(SIZE)}, depth: {num(SIZE)}, height_scale: {num(1.5 * HEIGHT / 255)}}}
  - GradientField:
      name: guide
      width: {num(SIZE)}
      depth: {num(SIZE)}
      nx: {GRID}
      ny: {GRID}
      vectors: [
{(','+chr(10)).join(rows)}
      ]
  - Material: {{diffuse: [0.5, 0.48, 0.45]}}
"""
    for k, (rx, ry, r) in enumerate(ROCKS):
        text += f"  - Transform: {{name: rock{k + 1}, translation: [{num(rx)}, {num(ry)}, {num(elevation(rx, ry))}], children: [{{Cylinder: {{radius: {num(r)}, height: 3}}}}]}}\n"
    text += f"""  - Material: {{diffuse: [0.9, 0.9, 0.9], transparency: 0.6}}
  - Transform: {{name: depot, translation: [{num(DEPOT[0])}, {num(DEPOT[1])}, {num(elevation(*DEPOT) + 1)}], children: [{{Region: {{name: zone, size: [3, 3, 4]}}}}]}}
"""
    for car in cars:
        x, y = STARTS[car]
        text += f"""  - Material: {{diffuse: {colours[car]}}}
  - Transform:
      name: {car}
      translation: [{num(x)}, {num(y)}, {num(elevation(x, y) + 0.6)}]
      children:
        - Body:
            name: body
            mass: 5
            children:
              - Cube: {{size: [0.8, 0.5, 0.4]}}
              - GradientSensor: {{name: compass}}
"""
    slots = {f"c{k}": f"{car}/body/compass" for k, car in enumerate(cars)}
    steering = ", ".join(f"{k}: 'drive(sim.node(\"{car}/body\"), value)'" for k, car in zip(slots, cars))
    text += f"""pages:
  main:
    places:
      driving: {{tokens: {{d0: [{', '.join(c + '/body' for c in cars)}]}}}}
      steer:
        sensors: {{{', '.join(f'{k}: {v}' for k, v in slots.items())}}}
        on_sample: {{{steering}}}
      depot:
        sensors: {{c0: depot/zone}}
      parked: {{}}
      home: {{}}
    transitions:
      park:
        pre_fire: 'park(self.d0[0])'
      all_parked:
        pre_fire: 'sim.stop(f"all {{len(arrivals)}} vehicles reached the depot")'
    arcs:
      - {{from: driving, to: park, weight: {{d0: 1}}, predicate: 'token in zone'}}
      - {{from: park, to: parked, weight: {{d0: 1}}}}
      - {{from: parked, to: all_parked, weight: {{d0: {len(cars)}}}}}
      - {{from: all_parked, to: home, weight: {{d0: {len(cars)}}}}}
"""
    path.write_text(text)


if __name__ == "__main__":
    write_png(HERE / "terrain.png")
    write_model(HERE / "vehicles.gdpn.yaml")
