"""examples/python/dask_lidar.py --scheduler ADDRESS against a scheduler with no workers:
it says on stderr that it waits for workers, gives up after --wait-for-workers SECONDS
(default 60) with a message and exit status 1, writing nothing; and a worker that joins while it
waits is used. The scheduler is a real distributed.LocalCluster started here with no workers."""

import subprocess
import sys

import pytest

from conftest import SOURCE_DIR, run_tool
from isolated import child_env
from robot_inputs import corridor_poses, write_poses, write_sensor

distributed = pytest.importorskip("distributed", reason="Dask distributed (Debian: python3-distributed) is not installed")

EXAMPLE = SOURCE_DIR / "examples" / "python" / "dask_lidar.py"
ROBOT_WORLD = SOURCE_DIR / "scenes" / "robot_world.json"
LIMIT = 240  # seconds: only for a run that never ends


@pytest.fixture
def empty_cluster():
    # Worker processes it is later scaled to inherit PYTHONPATH, and so find revolve.
    cluster = distributed.LocalCluster(n_workers=0, threads_per_worker=1, processes=True, dashboard_address=":0")
    yield cluster
    cluster.close()


@pytest.fixture
def job(tmp_path):
    return {"sensor": write_sensor(tmp_path / "sensor.json"), "poses": write_poses(tmp_path / "poses.csv", corridor_poses(12)),
            "out": tmp_path / "scan.pcd", "folder": tmp_path}


def _command(job, *options):
    return [sys.executable, str(EXAMPLE), str(ROBOT_WORLD), str(job["sensor"]), str(job["poses"]), "-o", str(job["out"]), *options]


def test_no_workers_is_said_and_given_up_on_after_the_wait(empty_cluster, job):
    """Rule: with no worker at the scheduler, dask_lidar.py says on stderr that it is waiting for
    workers (and for how long), and after --wait-for-workers SECONDS exits with status 1 and a
    message naming the scheduler and the option; no output, no temporary."""
    address = empty_cluster.scheduler_address
    done = subprocess.run(_command(job, "--scheduler", address, "--wait-for-workers", "2"), capture_output=True, text=True,
                          env=child_env(), timeout=LIMIT)
    assert done.returncode == 1, f"exit status {done.returncode}: {done.stderr[-3000:]}"
    assert "waiting" in done.stderr and "2 s" in done.stderr, done.stderr
    assert "no worker joined" in done.stderr and address in done.stderr and "--wait-for-workers" in done.stderr, done.stderr
    assert "Traceback" not in done.stderr, done.stderr
    assert sorted(p.name for p in job["folder"].iterdir()) == ["poses.csv", "sensor.json"]


def test_no_wait_at_all_fails_at_once(empty_cluster, job):
    """Rule: --wait-for-workers 0 does not wait: status 1 at once, saying the scheduler has no workers."""
    done = subprocess.run(_command(job, "--scheduler", empty_cluster.scheduler_address, "--wait-for-workers", "0"),
                          capture_output=True, text=True, env=child_env(), timeout=LIMIT)
    assert done.returncode == 1 and "no workers" in done.stderr and "Traceback" not in done.stderr, done.stderr
    assert not job["out"].exists()


@pytest.mark.parametrize("seconds", ["-1", "nan", "soon"])
def test_a_bad_wait_is_a_usage_error(job, seconds):
    """Rule: --wait-for-workers takes seconds >= 0 (or inf); anything else is a usage error (status 2)
    naming the option, before any cluster is contacted."""
    done = subprocess.run(_command(job, "--scheduler", "tcp://127.0.0.1:9", "--wait-for-workers", seconds), capture_output=True,
                          text=True, env=child_env(), timeout=LIMIT)
    assert done.returncode == 2 and "--wait-for-workers" in done.stderr, f"exit status {done.returncode}: {done.stderr}"
    assert "unrecognized arguments" not in done.stderr, done.stderr


def test_the_wait_is_documented_with_its_default():
    """Rule: --help names --wait-for-workers and its default, 60 seconds."""
    done = subprocess.run([sys.executable, str(EXAMPLE), "--help"], capture_output=True, text=True, env=child_env(), timeout=LIMIT)
    assert done.returncode == 0 and "--wait-for-workers" in done.stdout and "default 60" in done.stdout, done.stdout


def test_a_worker_that_joins_while_it_waits_does_the_scan(empty_cluster, job):
    """Rule: a worker joining during the wait is used: the scan is written, byte for byte
    revolve-lidar's, and the run ends with status 0."""
    expected = job["folder"] / "cli.pcd"
    run_tool("revolve-lidar", ROBOT_WORLD, "--sensor", job["sensor"], "--poses", job["poses"], "-o", expected)
    child = subprocess.Popen(_command(job, "--scheduler", empty_cluster.scheduler_address, "--wait-for-workers", str(LIMIT)),
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=child_env())
    try:
        said = child.stderr.readline()  # blocks until it says it waits (or ends)
        assert "waiting" in said, f"expected the waiting message first; got {said!r} {child.communicate(timeout=LIMIT)}"
        empty_cluster.scale(1)
        stdout, stderr = child.communicate(timeout=LIMIT)
    finally:
        if child.poll() is None:
            child.kill()
            child.communicate()
    assert child.returncode == 0, f"exit status {child.returncode}: {stderr[-3000:]}"
    assert job["out"].read_bytes() == expected.read_bytes()
    assert "wrote" in stdout
