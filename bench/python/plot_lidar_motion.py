#!/usr/bin/env python3
"""A moving sensor's sweep of the corridor of scenes/robot_world.json beside the same sweep at rest
(docs/robot.md, "Time and motion"): a 2-D lidar spinning at 10 Hz on a robot driving at 4 m/s and
turning at 2 rad/s. Each beam is traced from where the sensor is when it fires; drawn as a driver
without deskewing draws a sweep (each range along its beam's angle from the sweep's first pose),
the moving sweep's walls come out bent and its seam shows a step. The scan's x, y, z, where each
return truly lies, stay on the walls (the right-hand panel's grey dots).

    PYTHONPATH=build/python /usr/bin/python3 bench/python/plot_lidar_motion.py docs/lidar_motion.png
"""

import argparse
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import revolve  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "robot_world.json"
RATE = 10.0  # Hz: a sweep lasts 0.1 s
SENSOR = {"pose": {"position": [0, 0, 0.5]},
          "horizontal": {"samples": 1800, "min_angle": -np.pi, "max_angle": np.pi * (1 - 2 / 1800)},
          "range": {"min": 0.1, "max": 30}, "rotation_rate": RATE}
# x, y, z, yaw, time: 4 m/s along +x while turning at 2 rad/s, a pose every 0.05 s.
TIMES = np.arange(0, 0.2001, 0.05)
PATH = np.stack([2.0 + 4 * TIMES, 1.4 + 0 * TIMES, 0 * TIMES, 2 * TIMES, TIMES], axis=1)


def walls(axis):
    """The scene's upright quads seen from above, as lines."""
    for quad in json.loads(SCENE.read_text())["quads"]:
        corners = np.array(quad["corners"])
        if np.ptp(corners[:, 2]) > 0:
            axis.plot(corners[:2, 0], corners[:2, 1], color="0.6", lw=3, solid_capstyle="butt", zorder=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("figure", help="PNG to write")
    args = parser.parse_args()
    lidar, scene = revolve.Lidar(SENSOR), revolve.Scene(SCENE)
    moving = lidar.scan(scene, PATH, sweeps=1)  # the first sweep, traced along the path
    rest = lidar.scan(scene, PATH[:1, :4])      # the same sweep from the first pose, without times
    figure, axes = plt.subplots(1, 2, figsize=(12, 2.6), dpi=110, sharey=True)
    x0, y0, yaw0 = PATH[0, 0], PATH[0, 1], PATH[0, 3]
    for axis, scan, title in ((axes[0], rest, "at rest"),
                              (axes[1], moving, "moving at 4 m/s, turning at 2 rad/s")):
        walls(axis)
        ranges, time = scan["ranges"][0, 0].astype(np.float64), scan["time"][0, 0]
        hit = np.isfinite(ranges)
        if scan is moving:  # where the returns truly lie: the scan's own points
            axis.scatter(scan["points"][0, 0, hit, 0], scan["points"][0, 0, hit, 1], s=1, color="0.35", zorder=2)
        # As the sensor reports the sweep: each range along its beam from the first pose.
        x = x0 + ranges[hit] * np.cos(yaw0 + lidar.azimuths[hit])
        y = y0 + ranges[hit] * np.sin(yaw0 + lidar.azimuths[hit])
        shown = axis.scatter(x, y, c=time[hit] * 1000, s=2, cmap="viridis", vmin=0, vmax=100, zorder=3)
        if scan is moving:
            axis.plot(PATH[:3, 0], PATH[:3, 1], color="tab:red", lw=1.5, zorder=4)
        axis.plot(x0, y0, "o", color="tab:red", ms=5, zorder=4)
        axis.set_title(title, fontsize=10)
        axis.set_aspect("equal")
        axis.set_xlim(-0.3, 14.3)
        axis.set_ylim(-0.3, 3.3)
        axis.set_xlabel("x (m)")
    axes[0].set_ylabel("y (m)")
    figure.suptitle("One 10 Hz sweep drawn from its first pose (coloured by beam time); grey: the scan's x, y", fontsize=10)
    figure.colorbar(shown, ax=axes, label="beam time in the sweep (ms)", fraction=0.03, pad=0.01)
    figure.savefig(args.figure, bbox_inches="tight")
    print(f"wrote {args.figure}", file=sys.stderr)


if __name__ == "__main__":
    main()
