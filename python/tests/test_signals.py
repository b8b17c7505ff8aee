"""A scan file being written when the process is told to stop: SIGTERM leaves no
temporary (`scan.pcd.tmp-XXXX`) behind and the file already at the path untouched, as revolve-lidar
does; SIGINT stays a KeyboardInterrupt the program can catch; a program's own SIGTERM handler still
runs. The same for examples/python/dask_lidar.py stopped by SIGTERM in the middle of a scan.

Each writer is a child process (this file run as a script) that says on its stdout when its scan
file is open; the test then signals it and waits for it to end. Nothing is timed (the waits have
generous limits only so that a child that never ends fails the test instead of hanging it)."""

import os
import signal
import subprocess
import sys
import time

if __name__ != "__main__":
    import pytest

    from conftest import SOURCE_DIR
    from isolated import child_env
    from robot_inputs import corridor_poses, write_poses, write_sensor

OLD = b"the scan of an earlier run\n"
LIMIT = 120  # seconds: only for a child that never ends or never gets going


def _writer(mode, out, scene, sensor):
    """Opens ScanFile(s) at `out`, writes shards in a loop, and says 'writing' once the first is in."""
    import numpy as np

    import revolve

    lidar = revolve.Lidar(sensor)
    # Busy writers have more poses than they could write before the test's signal arrives (and few
    # enough that one which ignored it would end within a minute); SIGINT's wait after pose 2.
    count = 50 if mode.startswith("SIGINT") else 100_000
    poses = np.array([[1 + (i % 50) * 0.1, 1.5, 0.01 * i] for i in range(count)])
    files = [revolve.ScanFile(out, lidar, len(poses))]
    if mode == "two files":
        files.append(revolve.ScanFile(out + ".second.csv", lidar, len(poses)))
    if mode == "own handler":
        def handler(number, frame):
            # os.write, not print: the signal may come while print("writing") holds stdout's buffer,
            # and a second print there raises "reentrant call".
            os.write(1, b"my handler ran\n")
            sys.exit(3)

        signal.signal(signal.SIGTERM, handler)
    first = 0
    shard = lidar.scan(scene, poses[:1], threads=1)
    for f in files:
        f.write(first, shard)
    first += 1
    try:
        print("writing", flush=True)  # inside the try: the signal may come at once
        while first < len(poses):
            shard = lidar.scan(scene, poses[first : first + 1], threads=1, first_pose=first)
            for f in files:
                f.write(first, shard)
            first += 1
            if mode in ("SIGINT caught", "SIGINT uncaught", "idle") and first == 2:
                while True:
                    time.sleep(3600)  # until the signal
    except KeyboardInterrupt:
        if mode != "SIGINT caught":
            raise
        print("caught KeyboardInterrupt", flush=True)
        while first < len(poses):
            for f in files:
                f.write(first, lidar.scan(scene, poses[first : first + 1], threads=1, first_pose=first))
            first += 1
        for f in files:
            f.commit()
        print("committed", flush=True)


if __name__ == "__main__":
    _writer(*sys.argv[1:5])
    sys.exit(0)


@pytest.fixture(scope="module")
def inputs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("signals")
    sensor = write_sensor(folder / "sensor.json", {"pose": {"position": [0, 0, 0.5]},
                                                   "horizontal": {"samples": 64, "min_angle": -3, "max_angle": 3},
                                                   "range": {"min": 0.1, "max": 10}})
    return {"scene": str(SOURCE_DIR / "scenes" / "robot_world.json"), "sensor": str(sensor)}


def _start_writer(mode, out, inputs):
    out.write_bytes(OLD)
    child = subprocess.Popen([sys.executable, "-X", "faulthandler", __file__, mode, str(out), inputs["scene"], inputs["sensor"]],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=child_env(), cwd=out.parent)
    line = child.stdout.readline()  # blocks until the scan file is open and a shard is in it
    if line.strip() != "writing":
        child.kill()
        _, stderr = child.communicate()
        pytest.fail(f"the writer did not get going: {line!r}, exit status {child.returncode}: {stderr}")
    return child


def _temporaries(folder):
    return sorted(p.name for p in folder.iterdir() if ".tmp" in p.name)


@pytest.mark.parametrize("out_name, idle", [("scan.pcd", False), ("scan.csv", False), ("scan.pcd", True)])
def test_sigterm_leaves_no_temporary_and_the_old_file_untouched(tmp_path, inputs, out_name, idle):
    """Rule: a process killed by SIGTERM while a ScanFile is open (busy writing shards, or idle in a
    sleep) removes the ScanFile's temporary (as revolve-lidar does) and ends (not exit status 0: it
    did not finish); the file that was at the path is as it was."""
    out = tmp_path / out_name
    child = _start_writer("idle" if idle else "one file", out, inputs)
    assert _temporaries(tmp_path), "the scan file's temporary should exist while it is written"
    child.send_signal(signal.SIGTERM)
    _, stderr = child.communicate(timeout=LIMIT)
    assert child.returncode != 0, f"exit status 0 after SIGTERM: {stderr}"
    assert _temporaries(tmp_path) == [], f"left behind: {_temporaries(tmp_path)} (exit status {child.returncode}) {stderr}"
    assert out.read_bytes() == OLD


def test_sigterm_removes_every_open_scan_files_temporary(tmp_path, inputs):
    """Rule: two ScanFiles open at once: SIGTERM removes both temporaries."""
    out = tmp_path / "scan.pcd"
    child = _start_writer("two files", out, inputs)
    assert len(_temporaries(tmp_path)) == 2
    child.send_signal(signal.SIGTERM)
    _, stderr = child.communicate(timeout=LIMIT)
    assert _temporaries(tmp_path) == [], f"left behind: {_temporaries(tmp_path)} (exit status {child.returncode}) {stderr}"
    assert out.read_bytes() == OLD


def test_a_programs_own_sigterm_handler_still_runs(tmp_path, inputs):
    """Rule: a handler the program installed for SIGTERM after opening the ScanFile is the one that
    runs (its exit status is the process's), and the temporary goes all the same."""
    out = tmp_path / "scan.pcd"
    child = _start_writer("own handler", out, inputs)
    child.send_signal(signal.SIGTERM)
    stdout, stderr = child.communicate(timeout=LIMIT)
    assert "my handler ran" in stdout and child.returncode == 3, f"exit status {child.returncode}: {stdout} {stderr}"
    assert _temporaries(tmp_path) == [] and out.read_bytes() == OLD


def test_sigint_is_still_a_keyboard_interrupt_that_can_be_caught(tmp_path, inputs):
    """Rule: SIGINT raises KeyboardInterrupt as ever; a program that catches it can go on writing its
    ScanFile and commit it (the old file is then replaced, and no temporary is left)."""
    out = tmp_path / "scan.pcd"
    child = _start_writer("SIGINT caught", out, inputs)
    child.send_signal(signal.SIGINT)
    stdout, stderr = child.communicate(timeout=LIMIT)
    assert child.returncode == 0 and "caught KeyboardInterrupt" in stdout and "committed" in stdout, (
        f"exit status {child.returncode}: {stdout} {stderr}")
    assert _temporaries(tmp_path) == [] and out.read_bytes() != OLD and out.read_bytes().startswith(b"# .PCD")


def test_an_uncaught_keyboard_interrupt_ends_the_program_and_removes_the_temporary(tmp_path, inputs):
    """Rule: an uncaught KeyboardInterrupt ends the program as Python does (traceback, killed by
    SIGINT), the temporary is removed and the old file kept."""
    out = tmp_path / "scan.pcd"
    child = _start_writer("SIGINT uncaught", out, inputs)
    child.send_signal(signal.SIGINT)
    _, stderr = child.communicate(timeout=LIMIT)
    assert "KeyboardInterrupt" in stderr and child.returncode in (-signal.SIGINT, 128 + signal.SIGINT, 1), (
        f"exit status {child.returncode}: {stderr}")
    assert _temporaries(tmp_path) == [] and out.read_bytes() == OLD


def test_dask_lidar_stopped_by_sigterm_mid_scan_leaves_no_temporary(tmp_path):
    """Rule: examples/python/dask_lidar.py (a one-worker LocalCluster here) stopped by SIGTERM while
    its scan file is being written leaves no temporary, keeps the old file, and ends."""
    pytest.importorskip("distributed", reason="Dask distributed (Debian: python3-distributed) is not installed")
    sensor = write_sensor(tmp_path / "sensor.json")
    poses = write_poses(tmp_path / "poses.csv", corridor_poses(3000))  # minutes of work: it is stopped long before
    out = tmp_path / "scan.pcd"
    out.write_bytes(OLD)
    child = subprocess.Popen([sys.executable, str(SOURCE_DIR / "examples" / "python" / "dask_lidar.py"), str(SOURCE_DIR / "scenes" / "robot_world.json"),
                              str(sensor), str(poses), "-o", str(out), "--workers", "1", "--shard-size", "5"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=child_env(), cwd=tmp_path,
                             start_new_session=True)
    try:
        deadline = time.monotonic() + LIMIT
        while not _temporaries(tmp_path):  # the scan file is open once its temporary exists
            assert child.poll() is None, f"dask_lidar.py ended before writing: {child.communicate()}"
            assert time.monotonic() < deadline, "dask_lidar.py never opened its scan file"
            time.sleep(0.05)
        child.send_signal(signal.SIGTERM)
        _, stderr = child.communicate(timeout=LIMIT)
    finally:
        try:
            os.killpg(child.pid, signal.SIGKILL)  # the cluster's processes too, should any outlive it
        except ProcessLookupError:
            pass
        if child.poll() is None:
            child.communicate()
    assert child.returncode != 0, f"exit status 0 after SIGTERM: {stderr[-2000:]}"
    assert _temporaries(tmp_path) == [], f"left behind: {_temporaries(tmp_path)} (exit status {child.returncode}) {stderr[-2000:]}"
    assert out.read_bytes() == OLD
