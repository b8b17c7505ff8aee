"""revolve.RangeSensors against revolve-lidar run as a process on the same sonar ring, path and
scene (the same readings bit for bit), against the closed form on a one-pole scene, and its bad
inputs as one clear ValueError each."""

import csv
import math

import numpy as np
import pytest

import revolve
from conftest import SOURCE_DIR, run_tool
from robot_inputs import POLE_AT, POLE_RADIUS, write_pole_scene

RING = SOURCE_DIR / "examples" / "robot" / "sonar_ring.json"
WORLD = SOURCE_DIR / "scenes" / "robot_world.json"
PATH = SOURCE_DIR / "examples" / "robot" / "path.csv"


def sonar(**changes):
    sensor = {"type": "range", "pose": {"position": [0, 0, 0.5]}, "field_of_view": 0.4, "min_range": 0.1,
              "max_range": 20, "radiation_type": "ultrasound"}
    sensor.update(changes)
    return sensor


def test_the_ring_reads_as_revolve_lidar_does(tmp_path):
    table = tmp_path / "ranges.csv"
    run_tool("revolve-lidar", WORLD, "--sensor", RING, "--poses", PATH, "-o", table)
    with open(table, newline="") as f:
        rows = list(csv.DictReader(f))
    sensors = revolve.RangeSensors(RING)
    got = sensors.read(WORLD, PATH)
    poses = len(revolve.read_poses(PATH))
    assert got["range"].shape == (poses, sensors.count)
    assert got["point"].shape == (poses, sensors.count, 3)
    assert len(rows) == poses * sensors.count
    assert [(int(r["pose"]), int(r["sensor"])) for r in rows] == [(p, s) for p in range(poses) for s in range(8)]
    ranges = np.array([float(r["range"]) for r in rows]).reshape(poses, sensors.count)
    np.testing.assert_array_equal(got["range"], ranges)  # %.17g round-trips a double
    hit = np.isfinite(ranges)
    assert hit.sum() > poses, "the ring sees the world"
    points = np.array([[float(r[k]) if r[k] else math.nan for k in "xyz"] for r in rows]).reshape(poses, 8, 3)
    np.testing.assert_array_equal(got["point"], points)
    objects = np.array([int(r["object"]) if r["object"] else -1 for r in rows]).reshape(poses, 8)
    np.testing.assert_array_equal(got["object"], objects)
    assert np.all(np.isnan(got["point"][~hit]))
    assert sensors.names == [f"sonar_{i}" for i in range(8)]
    assert sensors.radiation_type == ["ultrasound"] * 8
    np.testing.assert_array_equal(sensors.field_of_view, np.full(8, 0.3))
    np.testing.assert_allclose(sensors.mounting[2], [0, 0.2, 0.5, math.pi / 2, 0, 0], atol=1e-6)


def test_a_dict_sensor_reads_the_pole_by_the_closed_form(tmp_path):
    scene = tmp_path / "pole.json"
    write_pole_scene(scene)
    sensors = revolve.RangeSensors(sonar())
    # Straight at the pole, and turned by 0.22 (the cone of half-angle 0.2 then meets it with its
    # boundary ray 0.02 off the pole's direction).
    px, py = POLE_AT
    poses = np.array([[px - 2, py, 0.0], [px - 2, py, 0.22]])
    got = sensors.read(scene, poses)
    assert got["range"][0, 0] == pytest.approx(2 - POLE_RADIUS, abs=1e-12)
    gamma = 0.02
    expected = 2 * math.cos(gamma) - math.sqrt(POLE_RADIUS ** 2 - (2 * math.sin(gamma)) ** 2)
    assert got["range"][1, 0] == pytest.approx(expected, abs=1e-12)
    assert list(got["object"][:, 0]) == [0, 0]


@pytest.mark.parametrize(
    "changes, message",
    [
        ({"field_of_view": 0}, r"sensor: field_of_view: 0 is out of range: the cone's full angle lies in \(0, pi\]"),
        ({"field_of_view": -1}, r"field_of_view: -1 is out of range"),
        ({"field_of_view": 3.5}, r"field_of_view: 3.5 is out of range"),
        ({"min_range": 30}, r"max_range: 20 is not above min_range = 30"),
        ({"radiation_type": "laser"}, r'radiation_type: "laser" is not a radiation type'),
        ({"fov": 1}, r"sensor: fov: unknown key"),
    ],
)
def test_bad_sensors_are_one_value_error(changes, message):
    with pytest.raises(ValueError, match=message):
        revolve.RangeSensors(sonar(**changes))


def test_bad_arguments_name_themselves(tmp_path):
    scene = tmp_path / "pole.json"
    write_pole_scene(scene)
    sensors = revolve.RangeSensors(sonar())
    with pytest.raises(ValueError, match=r"poses: shape \(2, 8\)"):
        sensors.read(scene, np.zeros((2, 8)))
    with pytest.raises(ValueError, match=r"threads"):
        sensors.read(scene, np.zeros((1, 3)), threads=100000)
    with pytest.raises(TypeError, match=r"expected a range sensor file's path or its JSON as a dict"):
        revolve.RangeSensors(42)
    with pytest.raises(ValueError, match=r'type: "range": a range sensor\'s file'):
        revolve.Lidar(sonar())
