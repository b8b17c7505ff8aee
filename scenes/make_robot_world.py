#!/usr/bin/env python3
"""Writes robot_world.json, the robot range-finding scene, and the sensor and pose examples that go
with it (examples/robot/): an L-shaped corridor of quads (a corridor along x opening into a hall)
with poles, barrels (one tipped over on its side), bins, traffic cones and a pedestal table with
bottles on it, all surfaces of revolution.

Run from anywhere: python3 scenes/make_robot_world.py. The committed files are this script's output;
edit the script, not them. Units are metres, z is up, scene angles in degrees (README, "Scene
format"); sensor angles in radians (README, "Robot range-finding").
"""
import json
import math
import os

from make_scenes import GAP, barrel, beer_bottle, pedestal_table, pts, r6, traffic_cone, wine_bottle

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.path.join(HERE, "..", "examples", "robot")

WALL_HEIGHT = 2.5


def pole(radius, height):
    return [(0, 0), (radius, 0), (radius, height), (0, height)]


def waste_bin():
    # Tapering up to a rim, with a domed lid.
    return [(0, 0), (0.21, 0), (0.215, 0.01), (0.25, 0.8), (0.27, 0.81), (0.27, 0.86), (0.2, 0.89), (0.1, 0.91), (0, 0.915)]


def floor(x0, y0, x1, y1):
    return {"corners": [[x0, y0, 0], [x1, y0, 0], [x1, y1, 0], [x0, y1, 0]], "material": "floor"}


def wall(x0, y0, x1, y1):
    return {"corners": [[x0, y0, 0], [x1, y1, 0], [x1, y1, WALL_HEIGHT], [x0, y0, WALL_HEIGHT]], "material": "wall"}


def robot_world():
    profiles = {
        "pole": {"points": pts(pole(0.1, 2.2))},
        "barrel": {"points": pts(barrel())},
        "bin": {"points": pts(waste_bin())},
        "cone": {"points": pts(traffic_cone())},
        "table": {"points": pts(pedestal_table(0.45, 0.75, 0.3))},
        "wine_bottle": {"points": pts(wine_bottle())},
        "beer_bottle": {"points": pts(beer_bottle())},
    }
    materials = {
        "floor": {"type": "diffuse", "color": [0.55, 0.53, 0.5]},
        "wall": {"type": "diffuse", "color": [0.8, 0.78, 0.72]},
        "steel": {"type": "metal", "color": [0.75, 0.75, 0.77], "roughness": 0.3},
        "blue_paint": {"type": "diffuse", "color": [0.1, 0.25, 0.6]},
        "green_plastic": {"type": "diffuse", "color": [0.15, 0.45, 0.2]},
        "orange": {"type": "diffuse", "color": [0.9, 0.35, 0.05]},
        "wood": {"type": "diffuse", "color": [0.45, 0.28, 0.15]},
        "green_glass": {"type": "glass", "ior": 1.5, "tint": [0.35, 0.7, 0.4]},
        "amber_glass": {"type": "glass", "ior": 1.5, "tint": [0.8, 0.5, 0.15]},
    }
    objects = []

    def add(profile, material, name, x, y, z=GAP, rotate=None):
        o = {"profile": profile, "material": material, "translate": [r6(x), r6(y), r6(z)], "name": name}
        if rotate:
            o["rotate"] = rotate
        objects.append(o)

    for i, (x, y) in enumerate([(2.0, 1.0), (4.0, 2.2), (6.0, 0.8), (11.5, 5.5)]):
        add("pole", "steel", f"pole {i + 1}", x, y)
    for i, (x, y) in enumerate([(3.0, 2.45), (7.5, 2.35), (12.9, 4.0), (10.2, 7.3)]):
        add("barrel", "blue_paint", f"barrel {i + 1}", x, y)
    # On its side: a quarter turn about x lays the axis along -y; the bulge (r = 0.33) rests on the floor.
    add("barrel", "blue_paint", "tipped barrel", 10.6, 1.9, 0.33 + GAP, [1, 0, 0, 90])
    for i, (x, y) in enumerate([(0.6, 2.5), (8.6, 0.4), (13.5, 7.5)]):
        add("bin", "green_plastic", f"bin {i + 1}", x, y)
    for i, (x, y) in enumerate([(5.0, 1.6), (5.6, 1.25)]):
        add("cone", "orange", f"cone {i + 1}", x, y)
    add("table", "wood", "table", 11.2, 6.4)
    top = 0.75 + 2 * GAP  # the table's top face, the table standing GAP above the floor
    add("wine_bottle", "green_glass", "bottle 1", 11.05, 6.5, top)
    add("wine_bottle", "green_glass", "bottle 2", 11.3, 6.55, top)
    add("beer_bottle", "amber_glass", "bottle 3", 11.25, 6.25, top)

    quads = [
        floor(0, 0, 14, 3), floor(9, 3, 14, 8),
        wall(0, 0, 14, 0), wall(14, 0, 14, 8), wall(14, 8, 9, 8), wall(9, 8, 9, 3), wall(9, 3, 0, 3), wall(0, 3, 0, 0),
    ]
    scene = {
        "description": "Robot range-finding world: an L-shaped corridor of quads (14 m along x, 3 m wide, opening "
                       "into a 5 m x 5 m hall) with poles, barrels (one tipped over), bins, traffic cones and a "
                       "pedestal table with bottles, all surfaces of revolution. Written by make_robot_world.py.",
        "camera": {"from": [0.8, 1.5, 1.6], "to": [8.0, 1.5, 0.5], "up": [0, 0, 1], "fov": 60,
                   "width": 640, "height": 400, "spp": 16},
        "profiles": profiles,
        "materials": materials,
        "objects": objects,
        "quads": quads,
        "lights": [{"type": "sun", "direction": [0.3, 0.5, -0.8], "irradiance": [2.5, 2.4, 2.2], "angle": 1.0}],
        "environment": {"sky": {"zenith": [0.3, 0.42, 0.7], "horizon": [0.75, 0.78, 0.85]}},
    }
    with open(os.path.join(HERE, "robot_world.json"), "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")


def sensors_and_poses():
    os.makedirs(EXAMPLES, exist_ok=True)

    def dump(name, value):
        with open(os.path.join(EXAMPLES, name), "w") as f:
            json.dump(value, f, indent=1)
            f.write("\n")

    # A planar scanner like a Hokuyo UTM-30LX: 1,080 steps over 270 degrees, 0.1 to 30 m, 1 cm noise.
    dump("lidar_2d.json", {
        "pose": {"position": [0.2, 0.0, 0.3], "yaw": 0.0},
        "horizontal": {"samples": 1080, "min_angle": r6(-0.75 * math.pi), "max_angle": r6(0.75 * math.pi)},
        "range": {"min": 0.1, "max": 30.0},
        "noise": {"mean": 0.0, "stddev": 0.01, "seed": 1},
    })
    # A 16-channel spinning lidar like a Velodyne VLP-16: 1,800 azimuths a turn, +-15 degrees.
    dump("lidar_3d.json", {
        "pose": {"position": [0.0, 0.0, 0.7], "yaw": 0.0},
        "horizontal": {"samples": 1800, "min_angle": r6(-math.pi), "max_angle": r6(math.pi * (1 - 2 / 1800))},
        "vertical": {"samples": 16, "min_angle": r6(math.radians(-15)), "max_angle": r6(math.radians(15))},
        "range": {"min": 0.4, "max": 100.0, "resolution": 0.002},
    })
    # A drive along the corridor and round the corner into the hall.
    path = [(1.0, 1.5, 0.0), (2.5, 1.6, 0.0), (4.5, 1.2, 0.0), (6.5, 1.6, 0.0), (8.0, 1.5, 0.0), (9.8, 1.6, 0.8),
            (10.2, 3.2, 1.57), (10.3, 5.0, 1.57)]
    with open(os.path.join(EXAMPLES, "path.csv"), "w") as f:
        f.write("x,y,yaw\n")
        for x, y, yaw in path:
            f.write(f"{x},{y},{yaw}\n")
    # One pose at the corner, facing into the hall: the README's plot.
    with open(os.path.join(EXAMPLES, "corner.csv"), "w") as f:
        f.write("x,y,yaw\n9.6,1.8,1.0\n")


if __name__ == "__main__":
    robot_world()
    sensors_and_poses()
