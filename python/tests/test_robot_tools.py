"""revolve.Lidar, ScanFile and cylinder_clearance against revolve-lidar and revolve-clearance run as
processes on the same input: the same numbers bit for bit, the same files byte for byte; and
against closed forms on a one-pole scene."""

import math

import numpy as np
import pytest

import revolve
from conftest import run_tool
from robot_inputs import (
    MOVING_SENSOR,
    NOISY_SENSOR,
    POLE_AT,
    POLE_RADIUS,
    corridor_poses,
    read_binary_pcd,
    timed_corridor_poses,
    write_pole_scene,
    write_poses,
    write_sensor,
)


@pytest.fixture(scope="module")
def world(tmp_path_factory):
    from conftest import SOURCE_DIR

    folder = tmp_path_factory.mktemp("robot")
    return {
        "scene": SOURCE_DIR / "scenes" / "robot_world.json",
        "sensor": write_sensor(folder / "sensor.json"),
        "poses": write_poses(folder / "poses.csv", corridor_poses(12)),
        "folder": folder,
    }


def test_scan_is_revolve_lidars_bit_for_bit(world):
    run_tool("revolve-lidar", world["scene"], "--sensor", world["sensor"], "--poses", world["poses"], "-o", world["folder"] / "cli.pcd",
             "--pcd-data", "binary")
    expected, width = read_binary_pcd(world["folder"] / "cli.pcd")
    lidar = revolve.Lidar(world["sensor"])
    scan = lidar.scan(revolve.Scene(world["scene"]), world["poses"])
    poses, rings, azimuths = scan["ranges"].shape
    assert (poses, rings, azimuths) == (12, 8, 360) and width == azimuths
    assert scan["points"].shape == (12, 8, 360, 3) and scan["points"].dtype == np.float32
    assert scan["ranges"].dtype == np.float32 and scan["ids"].dtype == np.int32 and scan["rings"].dtype == np.uint16
    returns = np.isfinite(scan["ranges"]).ravel()
    assert 0.3 < returns.mean() < 1.0  # a mix of returns and none
    # The PCD writes nan for no return where the scan has inf (ROS) in ranges.
    assert np.array_equal(np.where(returns, scan["ranges"].ravel(), np.nan), expected["range"], equal_nan=True)
    for k, axis in enumerate("xyz"):
        assert np.array_equal(scan["points"][..., k].ravel(), expected[axis], equal_nan=True)
    assert np.array_equal(scan["rings"].ravel(), expected["ring"])
    assert np.array_equal(scan["ids"].ravel(), expected["object"])
    assert scan["intensity"].dtype == np.float32 and scan["intensity"].shape == scan["ranges"].shape
    assert np.array_equal(scan["intensity"].ravel(), expected["intensity"], equal_nan=True)
    assert np.all(np.isnan(scan["intensity"].ravel()[~returns])) and np.all(scan["intensity"].ravel()[returns] >= 0)
    assert scan["time"].dtype == np.float32 and not scan["time"].any()  # no rotation_rate: every beam at its pose's instant
    assert np.array_equal(scan["time"].ravel(), expected["time"])
    # The same from the poses as an array, on one thread, with the scene as a path.
    again = lidar.scan(str(world["scene"]), revolve.read_poses(world["poses"]), threads=1)
    for key in ("ranges", "points", "ids", "rings", "intensity", "time"):
        assert np.array_equal(again[key], scan[key], equal_nan=True), key


@pytest.fixture(scope="module")
def moving(tmp_path_factory):
    """The noisy sensor spinning at 10 Hz on a robot whose poses carry times, 0.04 s apart."""
    folder = tmp_path_factory.mktemp("moving")
    poses = timed_corridor_poses(12)
    return {"sensor": write_sensor(folder / "sensor.json", MOVING_SENSOR), "poses_array": poses,
            "poses": write_poses(folder / "poses.csv", poses), "folder": folder}


def test_a_moving_sensors_scan_is_revolve_lidars_bit_for_bit_whole_or_in_shards(world, moving):
    cli = moving["folder"] / "cli.pcd"
    run_tool("revolve-lidar", world["scene"], "--sensor", moving["sensor"], "--poses", moving["poses"], "-o", cli, "--pcd-data", "binary")
    expected, _ = read_binary_pcd(cli)
    lidar, scene = revolve.Lidar(moving["sensor"]), revolve.Scene(world["scene"])
    poses = revolve.read_poses(moving["poses"])
    assert poses.shape == (12, 5) and np.array_equal(poses, moving["poses_array"])
    assert lidar.rotation_rate == 10 and lidar.sweep_duration == pytest.approx(359 / 3600, rel=1e-15)
    scan = lidar.scan(scene, poses)
    # Column k fires k / (360 x 10 Hz) after its sweep starts, every ring of it at once.
    want = np.broadcast_to(np.float32(np.arange(360) / 3600.0), scan["time"].shape)
    assert np.array_equal(scan["time"], want)
    assert np.array_equal(scan["time"].ravel(), expected["time"])
    assert np.array_equal(np.where(np.isfinite(scan["ranges"]), scan["ranges"], np.nan).ravel(), expected["range"], equal_nan=True)
    assert np.array_equal(scan["points"][..., 0].ravel(), expected["x"], equal_nan=True)
    # At rest (the same sensor and poses without their times) the scan differs: the motion is in it.
    rest = lidar.scan(scene, poses[:, :4])
    assert not np.array_equal(rest["ranges"], scan["ranges"])
    assert np.array_equal(rest["time"], scan["time"])
    # In shards: each traces its sweeps from the poses shard_poses gives (past its last sweep's end).
    out = moving["folder"] / "shards.pcd"
    scan_file = revolve.ScanFile(out, lidar, len(poses), data="binary")
    for first, count in ((0, 5), (5, 1), (6, 6)):
        shard = revolve.shard_poses(poses, first, count, lidar)
        assert len(shard) > count or first + count == len(poses)
        scan_file.write(first, revolve.scan_shard(world["scene"], moving["sensor"], shard, first, 1, sweeps=count))
    scan_file.commit()
    assert out.read_bytes() == cli.read_bytes()


@pytest.mark.parametrize("data", ["ascii", "binary"])
def test_scan_files_written_in_shards_are_revolve_lidars_byte_for_byte(world, data):
    cli = world["folder"] / f"cli-{data}.pcd"
    run_tool("revolve-lidar", world["scene"], "--sensor", world["sensor"], "--poses", world["poses"], "-o", cli, "--pcd-data", data)
    lidar, scene = revolve.Lidar(world["sensor"]), revolve.Scene(world["scene"])
    poses = revolve.read_poses(world["poses"])
    out = world["folder"] / f"shards-{data}.pcd"
    scan_file = revolve.ScanFile(out, lidar, len(poses), data=data, inputs=[world["scene"], world["sensor"], world["poses"]])
    for first, count in ((0, 5), (5, 1), (6, 6)):  # uneven shards, each with its own first pose's noise
        scan_file.write(first, lidar.scan(scene, poses[first : first + count], first_pose=first))
    assert not out.exists()  # written to a temporary until committed
    scan_file.commit()
    assert out.read_bytes() == cli.read_bytes()


def test_scan_file_csv_is_revolve_lidars(world):
    cli = world["folder"] / "cli.csv"
    run_tool("revolve-lidar", world["scene"], "--sensor", world["sensor"], "--poses", world["poses"], "-o", cli)
    lidar = revolve.Lidar(world["sensor"])
    out = world["folder"] / "python.csv"
    scan_file = revolve.ScanFile(out, lidar, 12)
    scan_file.write(0, lidar.scan(world["scene"], world["poses"]))
    scan_file.commit()
    assert out.read_text() == cli.read_text()


def test_scan_files_refuse_out_of_order_or_partial_writes_and_inputs(world):
    lidar = revolve.Lidar(world["sensor"])
    poses = revolve.read_poses(world["poses"])
    out = world["folder"] / "partial.pcd"
    scan_file = revolve.ScanFile(out, lidar, len(poses))
    with pytest.raises(ValueError, match=r"poses are written in order: expected pose 0, got first_pose = 3"):
        scan_file.write(3, lidar.scan(world["scene"], poses[3:5], first_pose=3))
    scan_file.write(0, lidar.scan(world["scene"], poses[:2]))
    with pytest.raises(ValueError, match=r"2 of 12 poses written; a scan file is committed whole"):
        scan_file.commit()
    del scan_file
    assert not out.exists() and not list(world["folder"].glob("partial.pcd*"))  # the temporary is gone too
    with pytest.raises(ValueError, match=r"same file as .*input"):
        revolve.ScanFile(world["poses"].with_suffix(".csv"), lidar, 12, inputs=[world["poses"]])
    with pytest.raises(ValueError, match=r"data=\"binary\" applies to .pcd outputs"):
        revolve.ScanFile(out.with_suffix(".csv"), lidar, 12, data="binary")


def test_mesh_geometry_is_revolve_lidar_geometry_mesh(world):
    cli = world["folder"] / "mesh.pcd"
    run_tool("revolve-lidar", world["scene"], "--sensor", world["sensor"], "--poses", world["poses"], "-o", cli, "--pcd-data", "binary",
             "--geometry", "mesh", "--slices", "16")
    expected, _ = read_binary_pcd(cli)
    scan = revolve.Lidar(world["sensor"]).scan(revolve.Scene(world["scene"], geometry="mesh", slices=16), world["poses"])
    assert np.array_equal(scan["points"][..., 0].ravel(), expected["x"], equal_nan=True)
    assert np.array_equal(np.where(np.isfinite(scan["ranges"]), scan["ranges"], np.nan).ravel(), expected["range"], equal_nan=True)
    exact = revolve.Lidar(world["sensor"]).scan(world["scene"], world["poses"])
    assert not np.array_equal(exact["ranges"], scan["ranges"])  # the facets show


def test_a_beam_at_a_pole_returns_the_gap_to_its_surface(tmp_path):
    scene = write_pole_scene(tmp_path / "pole.json")
    sensor = {"pose": {"position": [0, 0, 1]}, "horizontal": {"samples": 1, "min_angle": 0, "max_angle": 0},
              "range": {"min": 0.1, "max": 10}}
    poses = np.array([[0, 0, 0], [0.5, 0, 0], [0, 0, math.pi / 2]])
    scan = revolve.Lidar(sensor).scan(scene, poses)
    ranges = scan["ranges"][:, 0, 0]
    # Straight at the pole: its near side, 2 - 0.1 and 1.5 - 0.1 away; turned 90 degrees: nothing.
    assert ranges[0] == pytest.approx(POLE_AT[0] - POLE_RADIUS, abs=1e-6)
    assert ranges[1] == pytest.approx(POLE_AT[0] - 0.5 - POLE_RADIUS, abs=1e-6)
    assert np.isinf(ranges[2]) and scan["ids"][2, 0, 0] == -1 and np.all(np.isnan(scan["points"][2, 0, 0]))
    assert np.allclose(scan["points"][0, 0, 0], [POLE_AT[0] - POLE_RADIUS, 0, 1], atol=1e-6)
    assert scan["ids"][0, 0, 0] == 0
    # Head-on (the pole's normal along the beam), reflectivity 1: intensity 1 / range^2.
    intensity = scan["intensity"][:, 0, 0]
    assert intensity[0] == pytest.approx(1 / (POLE_AT[0] - POLE_RADIUS) ** 2, rel=1e-6)
    assert intensity[1] == pytest.approx(1 / (POLE_AT[0] - 0.5 - POLE_RADIUS) ** 2, rel=1e-6)
    assert np.isnan(intensity[2])


def test_clearance_is_revolve_clearances(world):
    poses = world["folder"] / "clearance_poses.csv"
    write_poses(poses, corridor_poses(40))
    cli = world["folder"] / "clearance.csv"
    run_tool("revolve-clearance", world["scene"], "--robot", "0.3,0.05,1.2", "--ground", "0", "--poses", poses, "-o", cli)
    got = revolve.cylinder_clearance(revolve.Scene(world["scene"]), poses, 0.3, 0.05, 1.2, ground=0.0)
    rows = [line.split(",") for line in cli.read_text().splitlines()[1:]]
    assert len(rows) == 40 and got["clearance"].dtype == np.float64
    for i, row in enumerate(rows):
        # The tool prints %.9g: the same digits from the same double.
        assert row[1] == f"{got['clearance'][i]:.9g}"
        assert row[2] == str(int(got["collides"][i]))
        assert row[3] == str(got["object"][i])
        assert row[4:] == [f"{x:.9g}" for x in got["point"][i]]
    assert got["collides"].any() or (got["clearance"] > 0).all()


def test_clearance_beside_a_pole_is_the_gap_between_the_cylinders(tmp_path):
    scene = write_pole_scene(tmp_path / "pole.json")
    poses = np.array([[0, 0, 0, 0], [1.5, 0.2, 0, 0], [2, 0, 0, 0], [2, 0, 3, 0]])  # x, y, z, yaw
    got = revolve.cylinder_clearance(scene, poses, 0.3, 0.0, 1.0)
    # Apart: centre distance minus both radii; around the pole: minus the depth to the robot's
    # side (0.3 - 0.1); above it (from z = 3): the 1 m gap to the pole's top.
    expected = [2 - 0.1 - 0.3, math.hypot(0.5, 0.2) - 0.1 - 0.3, -(0.3 - 0.1), 1.0]
    assert np.allclose(got["clearance"], expected, atol=1e-12)
    assert got["collides"].tolist() == [False, False, True, False]
    assert np.all(got["object"] == 0) and np.all(got["exact"])
