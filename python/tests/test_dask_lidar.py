"""examples/python/dask_lidar.py on a two-worker LocalCluster: the PCD it writes is revolve-lidar's
byte for byte, also when the worker tracing a shard is killed in the middle of it. The sensor spins
and the poses carry times, so every shard also needs the poses past its own (revolve.shard_poses)."""

import importlib.util
import os
import shutil
import signal
import threading
import time

import numpy as np
import pytest

import revolve
from conftest import SOURCE_DIR, run_tool
from robot_inputs import MULTI_RETURN_SENSOR, timed_corridor_poses, write_poses, write_sensor

distributed = pytest.importorskip("distributed", reason="Dask distributed (Debian: python3-distributed) is not installed")


def load_example():
    spec = importlib.util.spec_from_file_location("dask_lidar", SOURCE_DIR / "examples" / "python" / "dask_lidar.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def client():
    # Worker processes inherit PYTHONPATH, and so find revolve where this process did.
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0")
    with distributed.Client(cluster) as c:
        yield c
    cluster.close()


@pytest.fixture(scope="module")
def job(tmp_path_factory):
    folder = tmp_path_factory.mktemp("dask")
    job = {
        "scene": str(SOURCE_DIR / "scenes" / "robot_world.json"),
        "sensor": str(write_sensor(folder / "sensor.json", MULTI_RETURN_SENSOR)),
        "poses_file": write_poses(folder / "poses.csv", timed_corridor_poses(48)),
        "folder": folder,
    }
    job["poses"] = revolve.read_poses(job["poses_file"])
    run_tool("revolve-lidar", job["scene"], "--sensor", job["sensor"], "--poses", job["poses_file"], "-o", folder / "cli.pcd")
    return job


def test_sharded_scan_is_revolve_lidars_byte_for_byte(client, job):
    example = load_example()
    out = job["folder"] / "dask.pcd"
    example.scan_to_file(client, job["scene"], job["sensor"], job["poses"], out, shard_size=5)
    assert out.read_bytes() == (job["folder"] / "cli.pcd").read_bytes()


def test_a_worker_killed_mid_shard_loses_nothing_and_writes_nothing_twice(client, job):
    example = load_example()
    marker = job["folder"] / "started"
    scan_shard = revolve.scan_shard

    # Shard 20 (poses 20 to 24), on its first attempt, says which process runs it and then takes
    # its time; the test kills that process meanwhile. Any later attempt traces normally.
    def trace(scene, sensor, poses, first_pose, threads, sweeps=None):
        if first_pose == 20 and not os.path.exists(str(marker)):
            with open(str(marker) + ".part", "w") as note:
                note.write(str(os.getpid()))
            os.rename(str(marker) + ".part", str(marker))
            time.sleep(120)
        return scan_shard(scene, sensor, poses, first_pose, threads, sweeps)

    killed = []

    def kill_when_started():
        deadline = time.monotonic() + 60
        while not marker.exists() and time.monotonic() < deadline:
            time.sleep(0.05)
        pid = int(marker.read_text())
        os.kill(pid, signal.SIGKILL)
        killed.append(pid)

    killer = threading.Thread(target=kill_when_started)
    killer.start()
    out = job["folder"] / "killed.pcd"
    started = time.monotonic()
    example.scan_to_file(client, job["scene"], job["sensor"], job["poses"], out, shard_size=5, trace=trace)
    killer.join()
    assert killed and killed[0] != os.getpid()
    with pytest.raises(ProcessLookupError):
        os.kill(killed[0], 0)  # that worker process is gone
    assert time.monotonic() - started < 100  # the shard was traced again, not waited out
    assert out.read_bytes() == (job["folder"] / "cli.pcd").read_bytes()
    assert sorted(p.name for p in job["folder"].iterdir() if p.name.startswith("killed")) == ["killed.pcd"]  # no temporary left


def test_the_command_line_writes_the_same_file(job):
    out = job["folder"] / "command.pcd"
    example = load_example()
    example.main([job["scene"], job["sensor"], str(job["poses_file"]), "-o", str(out), "--workers", "2", "--shard-size", "7"])
    assert out.read_bytes() == (job["folder"] / "cli.pcd").read_bytes()


def test_workers_without_the_files_write_the_same_file(client, job, tmp_path):
    # The scene (with its profile CSVs) and the sensor are copied to a folder, built here from the
    # copy, and the folder is moved away before any shard runs; the workers run elsewhere too. They
    # can read no file: the scene and sensor reach them as pickles holding the files' texts.
    folder = tmp_path / "inputs"
    shutil.copytree(SOURCE_DIR / "scenes", folder / "scenes")
    shutil.copy(job["sensor"], folder / "sensor.json")
    scene = revolve.Scene(folder / "scenes" / "robot_world.json")
    lidar = revolve.Lidar(folder / "sensor.json")
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    before = client.run(os.getcwd)
    client.run(os.chdir, str(elsewhere))
    moved = folder.rename(tmp_path / "moved")
    try:
        out = job["folder"] / "no_files.pcd"
        load_example().scan_to_file(client, scene, lidar, job["poses"], out, shard_size=6)
        assert set(client.run(os.getcwd).values()) == {str(elsewhere)}
        assert not folder.exists()
        assert out.read_bytes() == (job["folder"] / "cli.pcd").read_bytes()
    finally:
        for worker, cwd in before.items():
            client.run(os.chdir, cwd, workers=[worker])
        moved.rename(folder)
