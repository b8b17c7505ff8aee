"""Multiple returns and beam patterns everywhere a scan goes: revolve.Lidar's arrays, ScanFile and the
Dask shards against revolve-lidar run as a process (bit for bit, byte for byte), and the PCD files
read by PCL (pcl_convert_pcd_ascii_binary, Debian: pcl-tools) and by Open3D (o3d.t.io), both
readers independent of revolve."""

import json
import shutil
import subprocess

import numpy as np
import pytest

import revolve
from conftest import run_tool
from robot_inputs import MULTI_RETURN_SENSOR, read_binary_pcd, timed_corridor_poses, write_poses, write_sensor


@pytest.fixture(scope="module")
def dual(tmp_path_factory):
    from conftest import SOURCE_DIR

    folder = tmp_path_factory.mktemp("returns")
    poses = timed_corridor_poses(6)
    sensor = write_sensor(folder / "sensor.json", MULTI_RETURN_SENSOR)
    scene = SOURCE_DIR / "scenes" / "robot_world.json"
    cli = folder / "cli.pcd"
    run_tool("revolve-lidar", scene, "--sensor", sensor, "--poses", write_poses(folder / "poses.csv", poses), "-o", cli,
             "--pcd-data", "binary")
    return {"scene": scene, "sensor": sensor, "poses": poses, "folder": folder, "cli": cli}


def test_a_multi_return_scan_is_revolve_lidars_bit_for_bit(dual):
    expected, width = read_binary_pcd(dual["cli"])
    lidar = revolve.Lidar(dual["sensor"])
    assert lidar.returns_per_beam == 2
    scan = lidar.scan(revolve.Scene(dual["scene"]), dual["poses"])
    # One layer per return: (poses, returns, rings, azimuths), as the PCD's rows.
    assert scan["ranges"].shape == (6, 2, 8, 360) and width == 360
    assert scan["return"].dtype == np.uint8
    assert np.array_equal(scan["return"], np.broadcast_to(np.arange(2, dtype=np.uint8)[None, :, None, None], (6, 2, 8, 360)))
    assert np.array_equal(scan["return"].ravel(), expected["return"])
    assert np.array_equal(scan["rings"].ravel(), expected["ring"])
    for key, field in (("ranges", "range"), ("intensity", "intensity")):
        got = np.where(np.isfinite(scan["ranges"]), scan[key], np.nan).ravel()
        assert np.array_equal(got, expected[field], equal_nan=True), key
    for k, axis in enumerate("xyz"):
        assert np.array_equal(scan["points"][..., k].ravel(), expected[axis], equal_nan=True)
    assert np.array_equal(scan["ids"].ravel(), expected["object"])
    assert np.array_equal(scan["time"].ravel(), expected["time"])
    # Second returns exist (beams across the edges of poles and posts) and lie beyond the first.
    first, second = scan["ranges"][:, 0], scan["ranges"][:, 1]
    both = np.isfinite(second)
    assert both.sum() > 10 and np.all(np.isfinite(first[both])) and np.all(second[both] > first[both])
    # A beam without a first return has no second one.
    assert not np.any(np.isfinite(second) & ~np.isfinite(first))
    again = lidar.scan(str(dual["scene"]), dual["poses"], threads=1)
    for key in ("ranges", "points", "ids", "rings", "return", "intensity", "time"):
        assert np.array_equal(again[key], scan[key], equal_nan=True), key


def test_multi_return_shards_make_revolve_lidars_file(dual):
    lidar = revolve.Lidar(dual["sensor"])
    poses = dual["poses"]
    out = dual["folder"] / "shards.pcd"
    scan_file = revolve.ScanFile(out, lidar, len(poses), data="binary")
    for first, count in ((0, 2), (2, 1), (3, 3)):
        shard = revolve.shard_poses(poses, first, count, lidar)
        scan_file.write(first, revolve.scan_shard(dual["scene"], dual["sensor"], shard, first, 1, sweeps=count))
    scan_file.commit()
    assert out.read_bytes() == dual["cli"].read_bytes()


def test_a_pattern_scan_is_revolve_lidars_byte_for_byte(tmp_path):
    from conftest import SOURCE_DIR

    scene = SOURCE_DIR / "scenes" / "robot_world.json"
    sensor = SOURCE_DIR / "examples" / "robot" / "lidar_vlp16_pattern.json"
    poses = write_poses(tmp_path / "poses.csv", timed_corridor_poses(3))
    cli = tmp_path / "cli.csv"
    run_tool("revolve-lidar", scene, "--sensor", sensor, "--poses", poses, "-o", cli)
    lidar = revolve.Lidar(sensor)
    assert lidar.beams_per_pose == 14464 and lidar.azimuths.shape == lidar.elevations.shape == (14464,)
    scan = lidar.scan(scene, poses)
    assert scan["ranges"].shape == (3, 1, 14464)  # one ring of the pattern's beams
    out = tmp_path / "python.csv"
    scan_file = revolve.ScanFile(out, lidar, 3)
    scan_file.write(0, scan)
    scan_file.commit()
    assert out.read_text() == cli.read_text()
    header = cli.read_text().splitlines()[0]
    assert header == "pose,ring,return,azimuth,elevation,range,x,y,z,object,intensity,time"


def pcl_ascii(path, tmp_path):
    """The cloud as PCL reads it (pcl::PCDReader) and writes it back as ASCII: header and points."""
    tool = shutil.which("pcl_convert_pcd_ascii_binary")
    if tool is None:
        pytest.skip("PCL's tools (Debian: pcl-tools) are not installed")
    out = tmp_path / ("pcl-" + path.name)
    subprocess.run([tool, str(path), str(out), "0"], check=True, capture_output=True, timeout=120)
    lines = out.read_text().splitlines()
    data = lines.index("DATA ascii") + 1
    header = dict(line.split(" ", 1) for line in lines[:data] if not line.startswith("#"))
    return header, np.array([[float(v) for v in line.split()] for line in lines[data:]])


def test_pcl_reads_every_field_and_the_return_layers(dual, tmp_path):
    header, points = pcl_ascii(dual["cli"], tmp_path)
    assert header["FIELDS"] == "x y z range ring return object intensity time"
    assert header["TYPE"] == "F F F F U U I F F" and header["SIZE"] == "4 4 4 4 2 1 4 4 4"
    # Organised as written: WIDTH azimuths, HEIGHT poses x returns x rings.
    assert (int(header["WIDTH"]), int(header["HEIGHT"])) == (360, 6 * 2 * 8)
    expected, _ = read_binary_pcd(dual["cli"])
    assert points.shape == (len(expected), 9)
    for k, field in enumerate(expected.dtype.names):
        want = expected[field].astype(np.float64)
        # PCL writes floats with 7 significant digits (relative 5e-7), integers exactly.
        assert np.allclose(points[:, k], want, rtol=1e-6, atol=0, equal_nan=True), field


def test_pcl_reads_a_pattern_scan_as_an_unorganised_cloud(tmp_path):
    from conftest import SOURCE_DIR

    cli = tmp_path / "rosette.pcd"
    run_tool("revolve-lidar", SOURCE_DIR / "scenes" / "robot_world.json", "--sensor",
             SOURCE_DIR / "examples" / "robot" / "lidar_rosette.json", "-o", cli, "--pcd-data", "binary")
    header, points = pcl_ascii(cli, tmp_path)
    assert (int(header["WIDTH"]), int(header["HEIGHT"])) == (10000, 1)
    expected, _ = read_binary_pcd(cli)
    assert np.allclose(points[:, 8], expected["time"], rtol=1e-6, atol=0)
    assert np.isfinite(points[:, 3]).sum() > 1000  # the rosette sees the world


def test_open3d_reads_a_pattern_scan_as_an_unorganised_cloud(tmp_path):
    o3d = pytest.importorskip("open3d", reason="Open3D (Debian: python3-open3d) is not installed")
    from conftest import SOURCE_DIR

    cli = tmp_path / "vlp16.pcd"
    run_tool("revolve-lidar", SOURCE_DIR / "scenes" / "robot_world.json", "--sensor",
             SOURCE_DIR / "examples" / "robot" / "lidar_vlp16_pattern.json", "-o", cli, "--pcd-data", "binary")
    cloud = o3d.t.io.read_point_cloud(str(cli))
    expected, width = read_binary_pcd(cli)
    assert width == len(expected) == 14464  # HEIGHT 1: one row of the pattern's beams
    assert np.array_equal(cloud.point["positions"].numpy()[:, 0], expected["x"], equal_nan=True)
    assert np.array_equal(cloud.point["time"].numpy().ravel(), expected["time"])
    assert np.array_equal(cloud.point["return"].numpy().ravel(), expected["return"])


def test_open3d_reads_every_field(dual):
    o3d = pytest.importorskip("open3d", reason="Open3D (Debian: python3-open3d) is not installed")
    cloud = o3d.t.io.read_point_cloud(str(dual["cli"]))
    expected, _ = read_binary_pcd(dual["cli"])
    positions = cloud.point["positions"].numpy()
    assert positions.shape == (len(expected), 3)
    for k, axis in enumerate("xyz"):
        assert np.array_equal(positions[:, k], expected[axis], equal_nan=True)
    for field, dtype in (("range", np.float32), ("ring", np.uint16), ("return", np.uint8), ("object", np.int32),
                         ("intensity", np.float32), ("time", np.float32)):
        got = cloud.point[field].numpy().ravel()
        assert got.dtype == dtype, field
        assert np.array_equal(got, expected[field], equal_nan=True), field


def test_tilted_poses_are_revolve_lidars_bit_for_bit(tmp_path):
    """Roll and pitch columns (a robot on a ramp, a drone): POSES.csv and (N, 7) arrays give the same scan."""
    from conftest import SOURCE_DIR

    scene = SOURCE_DIR / "scenes" / "robot_world.json"
    sensor = write_sensor(tmp_path / "sensor.json", MULTI_RETURN_SENSOR)
    timed = timed_corridor_poses(4)  # x, y, z, yaw, time
    tilted = np.column_stack([timed[:, :3], [0.0, 0.05, -0.1, 0.02], [0.1, -0.05, 0.0, 0.2], timed[:, 3:]])
    path = write_poses(tmp_path / "tilted.csv", tilted)
    cli = tmp_path / "cli.pcd"
    run_tool("revolve-lidar", scene, "--sensor", sensor, "--poses", path, "-o", cli, "--pcd-data", "binary")
    poses = revolve.read_poses(path)
    assert poses.shape == (4, 7) and np.array_equal(poses, tilted)
    lidar = revolve.Lidar(sensor)
    scan = lidar.scan(scene, poses)
    expected, _ = read_binary_pcd(cli)
    for k, axis in enumerate("xyz"):
        assert np.array_equal(scan["points"][..., k].ravel(), expected[axis], equal_nan=True)
    level = lidar.scan(scene, timed)
    assert not np.array_equal(level["ranges"], scan["ranges"], equal_nan=True)  # the tilt is in the scan
    with pytest.raises(ValueError, match=r"pose 0 \(counting from 0\) has roll = 0, pitch = 0.1: the clearance robot is an upright cylinder"):
        revolve.cylinder_clearance(scene, poses, 0.3, 0, 1)


def test_a_scan_file_refuses_a_scan_of_another_shape(dual, tmp_path):
    """A ScanFile for the two-layer sensor takes (P, 2, 8, 360) scans only: a one-layer scan of the same
    beams is refused naming the shape expected, and nothing is written."""
    lidar = revolve.Lidar(dual["sensor"])
    single = revolve.Lidar({k: v for k, v in MULTI_RETURN_SENSOR.items() if k not in ("returns", "max_returns")})
    out = tmp_path / "scan.pcd"
    scan_file = revolve.ScanFile(out, lidar, 1)
    with pytest.raises(ValueError, match=r"ranges \(P, 2, 8, 360\)"):
        scan_file.write(0, single.scan(dual["scene"], dual["poses"][:1]))
    del scan_file
    assert not list(tmp_path.iterdir())
