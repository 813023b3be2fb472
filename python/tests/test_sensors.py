"""The sensors of issue 23 as a model's scripts see them through the module: NumPy pictures
and ranges, and the IMU's tuples. The scripts hand what they read to this test through a
module of its own (`probe`), since they run in this interpreter."""

import sys
import types

import numpy as np
import pytest

import gdpn

SCENE = """gdpn: 1
settings: {dt: 0.01, until: 0.05, seed: 3}
scene:
  - World: {}
  # a red cube 2 m ahead of the colour camera, a wall 2 m ahead of the depth camera
  - Material: {diffuse: [1, 0, 0], emissive: [1, 0, 0]}
  - Transform: {translation: [2.5, 0, 5], children: [{Cube: {size: [1, 1, 1]}}]}
  - Transform: {translation: [2.5, 0, -5], children: [{Cube: {size: [1, 20, 20]}}]}
  - Transform: {name: a, translation: [0, 0, 5], children: [{ColorCamera: {name: cam, width: 32, height: 24, fov: 40, rate: 10}}]}
  - Transform: {name: b, translation: [0, 0, -5], children: [{DepthCamera: {name: depth, width: 16, height: 12, rate: 10}}]}
  # a laser in a room with one wall 3 m along +x, and a box resting on the ground with an IMU
  - Transform: {name: c, translation: [0, 0, 20], children: [
      {LaserScan: {name: lidar, count: 8, min_angle: -45, max_angle: 45, length: 10, rate: 10}},
      {Transform: {translation: [3.5, 0, 0], children: [{Cube: {size: [1, 40, 2]}}]}}]}
  - Plane: {}
  - Transform: {name: d, translation: [20, 0, 0.1], children: [{Body: {name: box, mass: 1, children: [
      {Cube: {size: [0.2, 0.2, 0.2]}}, {Imu: {name: imu, rate: 100}}]}}]}
pages:
  main:
    places:
      P:
        sensors: {c0: a/cam, c1: b/depth, c2: c/lidar, c3: d/box/imu}
        on_sample: |
          import probe
          probe.samples += 1
          probe.image = c0.image
          probe.depth = c1.image
          probe.ranges = c2.ranges
          probe.acceleration = c3.acceleration
          probe.nearest = (c2.nearest, c2.value)
          probe.imu_value = c3.value
          try:
              c2.image
          except AttributeError as e:
              probe.wrong = str(e)
          try:
              c3.ranges
          except AttributeError as e:
              probe.no_channel = str(e)
          try:
              sim.node("b/depth").far = 0.01
          except ValueError as e:
              probe.refused = str(e)
      clock: {tokens: 1}
    transitions:
      tick: {duration: 0.1}
    arcs: [clock -> tick, tick -> clock]
"""


@pytest.fixture
def probe():
    module = types.ModuleType("probe")
    module.samples = 0
    sys.modules["probe"] = module
    yield module
    del sys.modules["probe"]


def test_pictures_ranges_and_imu_reach_numpy(write_model, probe):
    model = gdpn.load(write_model(SCENE))
    model.run()
    assert probe.samples > 0

    image = probe.image
    assert isinstance(image, np.ndarray)
    assert image.shape == (24, 32, 3) and image.dtype == np.uint8
    assert not image.flags.writeable
    with pytest.raises(ValueError):
        image[0, 0, 0] = 1
    r, g, b = (int(c) for c in image[12, 16])  # the centre sees the cube: red
    assert r > 200 and g < 40 and b < 40
    r, g, b = (int(c) for c in image[0, 0])  # a corner sees the sky: not red
    assert not (r > 200 and g < 40)

    depth = probe.depth
    assert depth.shape == (12, 16) and depth.dtype == np.float32
    assert abs(float(depth[6, 8]) - 2.0) < 1e-3

    ranges = probe.ranges
    assert isinstance(ranges, np.ndarray) and ranges.shape == (8,)
    angles = np.radians(np.linspace(-45, 45, 8))
    np.testing.assert_allclose(ranges, 3.0 / np.cos(angles), atol=1e-6)

    ax, ay, az = probe.acceleration
    assert abs(ax) < 1e-3 and abs(ay) < 1e-3 and abs(az - 9.81) < 1e-2

    assert "sensor 'c/lidar' is a LaserScan: it has no 'image'" in probe.wrong
    # a channel of another kind's: the error lists what this one has
    assert probe.no_channel == (
        "sensor 'd/box/imu' is an Imu: it has no 'ranges' "
        "(it has: active, value, acceleration, angular_velocity, samples)")
    # the main number: a LaserScan's nearest distance, the samples an Imu has taken
    nearest, value = probe.nearest
    assert nearest == value and abs(nearest - 3.0 / np.cos(np.radians(45 / 7))) < 1e-6
    assert probe.imu_value >= 1
    # the rules between a camera's fields hold for a script as for the model file
    assert "far (0.01 m) must lie beyond near (0.05 m)" in probe.refused


def test_a_picture_kept_by_a_script_outlives_the_next(write_model, probe):
    # the array holds its picture: a later sample renders a new one, the kept one stays
    model = gdpn.load(write_model(SCENE))
    model.run(steps=2)
    first = probe.image
    kept = first.copy()
    model.run(until=0.5)
    assert probe.samples >= 5
    assert probe.image is not first
    np.testing.assert_array_equal(first, kept)
