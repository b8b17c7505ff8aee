#!/usr/bin/env python3
"""The lidar's intensity along one ring across a pole and a barrel of scenes/robot_world.json, traced
exactly and as 16-, 64- and 256-slice meshes (docs/robot.md): reflectivity |cos| / range^2 from the
exact normal falls smoothly towards each silhouette; a mesh's facets return it in steps.

    PYTHONPATH=build/python /usr/bin/python3 bench/python/plot_lidar_intensity.py docs/lidar_intensity.png
"""

import argparse
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import revolve  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
# From (1, 0.3), 0.5 m up, looking along +y (yaw pi/2) past pole 1 at (2, 1) and
# barrel 1 at (3, 2.45): both lie within the fan's 1.3 rad.
SENSOR = {"pose": {"position": [0, 0, 0.5]}, "horizontal": {"samples": 4001, "min_angle": -1.3, "max_angle": 0.0},
          "range": {"min": 0.05, "max": 20}}
POSE = np.array([[1.0, 0.3, np.pi / 2]])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("figure", help="PNG to write")
    args = parser.parse_args()
    lidar = revolve.Lidar(SENSOR)
    azimuths = np.degrees(lidar.azimuths)
    figure, axis = plt.subplots(figsize=(9, 4.2), dpi=110)
    geometries = [("exact", revolve.Scene(ROOT / "scenes" / "robot_world.json"), "black", 2.0)]
    for slices, colour in ((16, "tab:red"), (64, "tab:orange"), (256, "tab:blue")):
        geometries.append((f"{slices}-slice mesh", revolve.Scene(ROOT / "scenes" / "robot_world.json", geometry="mesh",
                                                                slices=slices), colour, 1.0))
    for label, scene, colour, width in geometries:
        scan = lidar.scan(scene, POSE, threads=1)
        intensity = scan["intensity"][0, 0].astype(np.float64)
        ids = scan["ids"][0, 0]
        on_round = np.isin(ids, [0, 4])  # pole 1 and barrel 1: walls and floor are not plotted
        axis.plot(azimuths, np.where(on_round, intensity, np.nan), color=colour, lw=width, label=label)
    axis.set_xlabel("beam azimuth in the sensor's frame (degrees)")
    axis.set_ylabel("intensity, reflectivity |cos θ| / range² (1/m²)")
    axis.set_title("One ring across a pole (left) and a barrel (right): exact normal against meshes")
    axis.legend(loc="upper right")
    axis.grid(alpha=0.3)
    figure.tight_layout()
    figure.savefig(args.figure)
    print(f"wrote {args.figure}", file=sys.stderr)


if __name__ == "__main__":
    main()
