"""Inputs the robot tests share: a noisy 3-D sensor (noise, resolution and a tilted mounting make
every beam's number depend on the whole pipeline), poses along the corridor of
scenes/robot_world.json, and a one-pole scene whose answers are closed forms."""

import json
import math

import numpy as np

NOISY_SENSOR = {
    "pose": {"position": [0.1, 0.0, 0.7], "yaw": 0.05, "pitch": 0.02, "roll": -0.01},
    "horizontal": {"samples": 360, "min_angle": -math.pi, "max_angle": math.pi * (1 - 2 / 360)},
    "vertical": {"samples": 8, "min_angle": -0.25, "max_angle": 0.2},
    "range": {"min": 0.3, "max": 12.0, "resolution": 0.002},
    "noise": {"mean": 0.001, "stddev": 0.01, "seed": 12345},
}


# The noisy sensor spinning at 10 Hz: a sweep lasts 0.1 s (column k fires k / 3600 s after its start).
MOVING_SENSOR = {**NOISY_SENSOR, "rotation_rate": 10.0}


# The moving sensor's beams as cones of 4 mrad sampled by 8 sub-rays, every return reported (up to
# 2 a beam: the scan's second axis), with intensity noise: every new field depends on the pipeline.
MULTI_RETURN_SENSOR = {**MOVING_SENSOR, "divergence": 0.004, "subrays": 8, "returns": "all", "max_returns": 2,
                       "intensity_noise": {"stddev": 0.05, "seed": 3}}


def write_sensor(path, sensor=NOISY_SENSOR):
    path.write_text(json.dumps(sensor))
    return path


def corridor_poses(count):
    """`count` poses along the corridor (x from 1 to 9 m, weaving in y, turning)."""
    s = np.linspace(0, 1, count)
    return np.stack([1 + 8 * s, 1.5 + 0.3 * np.sin(7 * s), 0.02 * np.cos(5 * s), 0.6 * np.sin(3 * s)], axis=1)


def timed_corridor_poses(count, interval=0.04):
    """corridor_poses with a time column: one pose every `interval` seconds from t = 1000 s, more often
    than MOVING_SENSOR's sweeps, so that a sweep spans several segments of the path."""
    return np.concatenate([corridor_poses(count), (1000 + interval * np.arange(count))[:, None]], axis=1)


def write_poses(path, poses):
    """(N, 4) poses, (N, 5) with times, (N, 6) with roll and pitch or (N, 7) with both, as POSES.csv."""
    header = {4: "x,y,z,yaw", 5: "x,y,z,yaw,time", 6: "x,y,z,roll,pitch,yaw", 7: "x,y,z,roll,pitch,yaw,time"}
    with open(path, "w") as out:
        out.write(header[poses.shape[1]] + "\n")
        for pose in poses:
            out.write(",".join(repr(float(v)) for v in pose) + "\n")  # repr: exact, shortest
    return path


POLE_RADIUS, POLE_AT = 0.1, (2.0, 0.0)


def write_pole_scene(path):
    """One pole of radius 0.1 m and height 2 m standing at (2, 0)."""
    path.write_text(
        json.dumps(
            {
                "camera": {"from": [0, -5, 1], "to": [2, 0, 1], "up": [0, 0, 1], "fov": 40},
                "profiles": {"pole": {"points": [[0, 0], [POLE_RADIUS, 0], [POLE_RADIUS, 2], [0, 2]]}},
                "materials": {"grey": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
                "objects": [{"profile": "pole", "material": "grey", "translate": [POLE_AT[0], POLE_AT[1], 0]}],
            }
        )
    )
    return path


def read_binary_pcd(path):
    """A binary PCD of revolve-lidar's fields (x y z range: float32, ring: uint16, return: uint8, object: int32,
    intensity and time: float32, packed)."""
    data = path.read_bytes()
    header_end = data.index(b"DATA binary\n") + len(b"DATA binary\n")
    header = data[:header_end].decode()
    assert "FIELDS x y z range ring return object intensity time\nSIZE 4 4 4 4 2 1 4 4 4\nTYPE F F F F U U I F F\n" in header
    points = np.frombuffer(
        data[header_end:], dtype=np.dtype([("x", "<f4"), ("y", "<f4"), ("z", "<f4"), ("range", "<f4"), ("ring", "<u2"), ("return", "u1"),
                                     ("object", "<i4"), ("intensity", "<f4"), ("time", "<f4")])
    )
    width = int(next(line.split()[1] for line in header.splitlines() if line.startswith("WIDTH")))
    return points, width
