"""One shard of a lidar scan, for a scan spread over processes or machines (Dask, multiprocessing):
the scene and sensor travel with the tasks as pickled objects (a Scene's pickle holds its file's text
and its CSVs', so a worker needs no file), or are files loaded once per process, which every shard it
traces after reuses."""

import os
import threading

import numpy as np

from ._revolve import Lidar, Scene, read_poses

_loaded = {}
_lock = threading.Lock()


def _path(value, name):
    if not isinstance(value, (str, bytes, os.PathLike)):
        raise TypeError(f"{name}: a {type(value).__name__}; expected a path (str or os.PathLike) or a revolve."
                        f"{'Scene' if name == 'scene' else 'Lidar'}")
    path = os.fsdecode(value)
    if not path or "\0" in path:
        raise ValueError(f"{name}: {path!r} is no file name")
    return path


def _modified(path, name):
    try:
        return os.stat(path).st_mtime_ns
    except OSError as error:
        raise ValueError(f"{name}: {path}: cannot open: {error.strerror}") from None


def _from_file(kind, value, name):
    # Keyed by path and modification time: a file changed on disk is read again.
    path = _path(value, name)
    key = (kind.__name__, os.path.abspath(path), _modified(path, name))
    with _lock:
        if key not in _loaded:
            if len(_loaded) >= 8:
                _loaded.clear()
            _loaded[key] = kind(path)
        return _loaded[key]


def scan_shard(scene, sensor, poses, first_pose=0, threads=0, sweeps=None):
    """Lidar(sensor).scan(Scene(scene), poses, threads, first_pose, sweeps): the arrays a ScanFile
    writes (ranges, points, ids, intensity, time) of poses first_pose, first_pose + 1, ... of a scan,
    each with its own noise. `scene` a revolve.Scene or a scene file's path, `sensor` a revolve.Lidar
    or a sensor file's path (files loaded once per process); `poses` as shard_poses gives them,
    `sweeps` the shard's count."""
    built = scene if isinstance(scene, Scene) else _from_file(Scene, scene, "scene")
    lidar = sensor if isinstance(sensor, Lidar) else _from_file(Lidar, sensor, "sensor")
    scan = lidar.scan(built, poses, threads=threads, first_pose=first_pose, sweeps=sweeps)
    return {key: scan[key] for key in ("ranges", "points", "ids", "intensity", "time")}


def shard_poses(poses, first, count, lidar):
    """The poses a shard of `count` sweeps from pose `first` needs: poses[first : first + count] and,
    for a sensor that moves during its sweeps (a rotation_rate or pattern times, and poses (N, 5) or (N, 7)
    carrying times),
    the poses after them up to the first after its last sweep's end, so that the shard's beams are
    traced from where the whole scan traces them (Lidar.scan's `sweeps` then counts the shard's own).
    `poses`: an (N, 3) to (N, 7) array as Lidar.scan takes, or a POSES.csv path (read_poses)."""
    if not isinstance(lidar, Lidar):
        raise TypeError(f"lidar: a {type(lidar).__name__}; expected a revolve.Lidar")
    if isinstance(poses, (str, bytes, os.PathLike)):
        poses = read_poses(poses)
    try:
        poses = np.asarray(poses, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError("poses: not an (N, 3) to (N, 7) array of numbers") from None
    if poses.ndim != 2 or poses.shape[1] not in (3, 4, 5, 6, 7):
        raise ValueError(f"poses: shape {poses.shape}; expected (N, 3) to (N, 7), as Lidar.scan takes")
    for name, value in (("first", first), ("count", count)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
            raise TypeError(f"{name}: a {type(value).__name__}; expected a whole number")
    if not 0 <= first < len(poses):
        raise ValueError(f"first = {first}: the poses are numbered 0 to {len(poses) - 1}")
    if not 1 <= count <= len(poses) - first:
        raise ValueError(f"count = {count}: a shard from pose {first} holds 1 to {len(poses) - first} poses")
    end = first + count
    timed = poses.shape[1] in (5, 7)  # the time is the last column (Lidar.scan's layouts)
    if timed and lidar.sweep_duration > 0 and end < len(poses):
        last_end = poses[end - 1, -1] + lidar.sweep_duration
        end = min(len(poses), int(np.searchsorted(poses[:, -1], last_end, side="right")) + 1)
    return poses[first:end]
