#!/usr/bin/env python3
"""A ring of 8 sonars driving through scenes/robot_world.json (docs/robot.md): each sonar is a cone of
0.3 rad reporting the nearest surface inside it (ROS Range), read exactly by revolve.RangeSensors
along examples/robot/path.csv. Left: the world from above with the path and every pose's readings;
right: one pose close up, each cone drawn to its reading with the nearest point it found.

    PYTHONPATH=build/python /usr/bin/python3 bench/python/plot_sonar_ring.py docs/sonar_ring.png
"""

import argparse
import json
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.patches import Wedge  # noqa: E402

import revolve  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "robot_world.json"
RING = ROOT / "examples" / "robot" / "sonar_ring.json"
PATH = ROOT / "examples" / "robot" / "path.csv"
CLOSE_UP = 2  # the pose drawn close up


def rotation(axis, degrees):
    """Rodrigues' rotation about `axis` (normalised) by `degrees`, as the scene file's "rotate"."""
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    a = math.radians(degrees)
    cross = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(a) * cross + (1 - math.cos(a)) * cross @ cross


def footprints(scene):
    """Each object's tessellated surface projected on the ground (triangles), and the quads that
    stand up from it (the floor left out) as segments."""
    profiles = {}
    for name, profile in scene["profiles"].items():
        profiles[name] = np.array(profile["points"], float)
    triangles = []
    for obj in scene["objects"]:
        vertices, faces = revolve.tessellate(profiles[obj["profile"]], 48)
        turn = obj.get("rotate", [0, 0, 1, 0])
        world = (rotation(turn[:3], turn[3]) @ (vertices * obj.get("scale", [1, 1, 1])).T).T + obj["translate"]
        triangles.extend(world[faces][:, :, :2])
    walls = []
    for quad in scene["quads"]:
        corners = np.array(quad["corners"], float)
        if np.ptp(corners[:, 2]) > 0:  # standing: its trace on the ground
            low = corners[np.argsort(corners[:, 2])[:2]]
            walls.append(low[:, :2])
    return np.array(triangles), walls


def cone_apexes(sensors, pose):
    """Each sonar's apex and heading in the world for a robot pose (x, y, z, yaw: read_poses's
    columns for a level path without times)."""
    x, y, _, yaw = pose
    mount = sensors.mounting
    c, s = math.cos(yaw), math.sin(yaw)
    apex = np.stack([x + c * mount[:, 0] - s * mount[:, 1], y + s * mount[:, 0] + c * mount[:, 1]], axis=1)
    return apex, yaw + mount[:, 3]


def draw_cones(axes, sensors, pose, ranges, points, alpha):
    apex, heading = cone_apexes(sensors, pose)
    half = np.degrees(sensors.field_of_view / 2)
    for i in range(sensors.count):
        seen = np.isfinite(ranges[i])
        reach = ranges[i] if seen else sensors.max_range[i]
        centre = math.degrees(heading[i])
        axes.add_patch(Wedge(apex[i], reach, centre - half[i], centre + half[i], alpha=alpha,
                             facecolor="tab:orange" if seen else "none", edgecolor="tab:orange",
                             linestyle="-" if seen else ":", linewidth=0.8))
        if seen:
            axes.plot(*points[i, :2], "o", color="tab:red", markersize=3.5)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("figure", help="PNG to write")
    args = parser.parse_args()
    scene = json.loads(SCENE.read_text())
    sensors = revolve.RangeSensors(RING)
    poses = revolve.read_poses(PATH)
    readings = sensors.read(str(SCENE), poses)
    triangles, walls = footprints(scene)

    figure, (world, close) = plt.subplots(1, 2, figsize=(13, 5.2), dpi=130, gridspec_kw={"width_ratios": [1.6, 1]})
    for axes in (world, close):
        axes.add_collection(PolyCollection(triangles, facecolor="0.55", edgecolor="none"))
        for wall in walls:
            axes.plot(wall[:, 0], wall[:, 1], color="0.25", linewidth=2)
        axes.set_aspect("equal")
        axes.set_xlabel("x (m)")
    world.set_ylabel("y (m)")
    world.plot(poses[:, 0], poses[:, 1], "-", color="tab:blue", linewidth=1)
    for p in range(len(poses)):
        draw_cones(world, sensors, poses[p], readings["range"][p], readings["point"][p], 0.18)
        world.plot(*poses[p, :2], "o", color="tab:blue", markersize=4)
    world.set_xlim(-0.5, 15)
    world.set_ylim(-0.5, 8.5)
    seen = np.isfinite(readings["range"])
    world.set_title(f"{len(poses)} poses x {sensors.count} sonars: {int(seen.sum())} readings "
                    f"(range {sensors.min_range[0]:g} to {sensors.max_range[0]:g} m)")

    pose = poses[CLOSE_UP]
    draw_cones(close, sensors, pose, readings["range"][CLOSE_UP], readings["point"][CLOSE_UP], 0.3)
    close.plot(*pose[:2], "o", color="tab:blue", markersize=5)
    for i in range(sensors.count):
        r = readings["range"][CLOSE_UP, i]
        if np.isfinite(r):
            x, y = readings["point"][CLOSE_UP, i, :2]
            close.annotate(f"{r:.2f} m", (x, y), textcoords="offset points", xytext=(4, 4), fontsize=8)
    close.set_xlim(pose[0] - 2.2, pose[0] + 2.2)
    close.set_ylim(pose[1] - 1.8, pose[1] + 1.8)
    close.set_title(f"pose {CLOSE_UP} close up: each cone drawn to its reading")
    world.legend(handles=[
        plt.Line2D([], [], color="tab:blue", marker="o", markersize=4, label="robot path (poses)"),
        plt.Rectangle((0, 0), 1, 1, facecolor="tab:orange", alpha=0.35, label="sonar cone, to its reading"),
        plt.Rectangle((0, 0), 1, 1, facecolor="none", edgecolor="tab:orange", linestyle=":",
                      label="no reading within max_range"),
        plt.Line2D([], [], color="tab:red", marker="o", linestyle="none", markersize=4, label="nearest point"),
        plt.Rectangle((0, 0), 1, 1, facecolor="0.55", label="objects from above (exact surfaces)"),
    ], loc="upper left", fontsize=8)
    figure.tight_layout()
    figure.savefig(args.figure)
    print(f"{args.figure}: {int(seen.sum())} of {seen.size} readings")


if __name__ == "__main__":
    main()
