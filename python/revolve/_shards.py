"""One shard of a lidar scan traced from files, for a scan spread over processes or machines (Dask,
multiprocessing): each process builds the scene and reads the sensor once, and every shard it traces
after reuses them."""

import os
import threading

from ._revolve import Lidar, Scene

_loaded = {}
_lock = threading.Lock()


def _path(value, name):
    if not isinstance(value, (str, bytes, os.PathLike)):
        raise TypeError(f"{name}: a {type(value).__name__}; expected a path (str or os.PathLike)")
    path = os.fsdecode(value)
    if not path or "\0" in path:
        raise ValueError(f"{name}: {path!r} is no file name")
    return path


def _modified(path, name):
    try:
        return os.stat(path).st_mtime_ns
    except OSError as error:
        raise ValueError(f"{name}: {path}: cannot open: {error.strerror}") from None


def _scene_and_lidar(scene, sensor):
    # Keyed by path and modification time: a file changed on disk is read again.
    key = tuple((os.path.abspath(path), _modified(path, name)) for path, name in ((scene, "scene"), (sensor, "sensor")))
    with _lock:
        if key not in _loaded:
            if len(_loaded) >= 4:
                _loaded.clear()
            _loaded[key] = (Scene(scene), Lidar(sensor))
        return _loaded[key]


def scan_shard(scene, sensor, poses, first_pose=0, threads=0):
    """Lidar(sensor).scan(Scene(scene), poses, threads, first_pose) with the scene and sensor files
    loaded once per process: the arrays a ScanFile writes (ranges, points, ids, intensity) of poses
    first_pose, first_pose + 1, ... of a scan, each with its own noise."""
    built, lidar = _scene_and_lidar(_path(scene, "scene"), _path(sensor, "sensor"))
    scan = lidar.scan(built, poses, threads=threads, first_pose=first_pose)
    return {key: scan[key] for key in ("ranges", "points", "ids", "intensity")}
