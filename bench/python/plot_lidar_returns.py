#!/usr/bin/env python3
"""A dual-return scan of a pole in front of a wall (docs/robot.md): a pole of radius 0.1 m stands 3 m
from a 2-D lidar, a wall 6 m away behind it. Each beam is a cone of 10 mrad sampled by 16 sub-rays,
and every return is reported, up to 2 a beam. A beam near one of the pole's edges is cut in two: part
of it hits the pole and the rest goes on to the wall, so it has two returns; every other beam has
one. A thin beam (one ray, first return) jumps from the pole to the wall instead.

    PYTHONPATH=build/python /usr/bin/python3 bench/python/plot_lidar_returns.py docs/lidar_returns.png
"""

import argparse
import json
import pathlib
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import revolve  # noqa: E402

POLE_RADIUS, POLE_AT, WALL_X = 0.1, (3.0, 0.0), 6.0
SCENE = {"camera": {"from": [0, -5, 1], "to": [3, 0, 1], "up": [0, 0, 1], "fov": 40},
         "profiles": {"pole": {"points": [[0, 0], [POLE_RADIUS, 0], [POLE_RADIUS, 2], [0, 2]]}},
         "materials": {"grey": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
         "objects": [{"profile": "pole", "material": "grey", "translate": [POLE_AT[0], POLE_AT[1], 0]}],
         "quads": [{"corners": [[WALL_X, -3, 0], [WALL_X, 3, 0], [WALL_X, 3, 2], [WALL_X, -3, 2]],
                    "material": "grey"}]}
# A narrow fan across the pole, 1.3 mrad between beams: several beams straddle each of its edges.
SENSOR = {"pose": {"position": [0, 0, 1]}, "horizontal": {"samples": 121, "min_angle": -0.08, "max_angle": 0.08},
          "range": {"min": 0.1, "max": 20}, "divergence": 0.01, "subrays": 16, "returns": "all", "max_returns": 2}
# The same fan of thin beams (one ray each), first return only: a scan of one layer, (poses, rings, azimuths).
THIN = {"pose": SENSOR["pose"], "horizontal": SENSOR["horizontal"], "range": SENSOR["range"], "divergence": 0.0,
        "returns": "first"}
POSE = np.array([[0.0, 0.0, 0.0]])
FIRST, SECOND = dict(color="tab:blue", marker="o"), dict(color="tab:orange", marker="D")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("figure", help="PNG to write")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        path = pathlib.Path(folder) / "pole_and_wall.json"
        path.write_text(json.dumps(SCENE))
        scene = revolve.Scene(path)
        lidar = revolve.Lidar(SENSOR)
        scan = lidar.scan(scene, POSE)
        thin = revolve.Lidar(THIN).scan(scene, POSE)
    azimuths = np.degrees(lidar.azimuths)
    ranges, points = scan["ranges"][0, :, 0], scan["points"][0, :, 0]  # (returns, azimuths)
    hit = np.isfinite(ranges)
    doubles = int(hit[1].sum())
    by_edge = [int(hit[1, azimuths < 0].sum()), int(hit[1, azimuths > 0].sum())]
    edge = np.degrees(np.arcsin(POLE_RADIUS / np.hypot(*POLE_AT)))  # the pole's edges seen from the sensor

    figure, (top, side) = plt.subplots(1, 2, figsize=(11, 4.5), dpi=130, gridspec_kw={"width_ratios": [1.15, 1]})
    # Left: from above. The fan is 0.16 rad wide, so y is stretched to show it.
    for n, b in enumerate(np.flatnonzero(hit[1])):  # the beams with two returns, to their farther return
        top.plot([0, points[1, b, 0]], [0, points[1, b, 1]], color="0.75", lw=0.6, zorder=1,
                 label="beams with two returns" if n == 0 else None)
    angle = np.linspace(0, 2 * np.pi, 200)
    top.fill(POLE_AT[0] + POLE_RADIUS * np.cos(angle), POLE_AT[1] + POLE_RADIUS * np.sin(angle),
             facecolor="0.8", edgecolor="0.3", lw=1, zorder=2, label="pole (radius 0.1 m)")
    top.plot([WALL_X, WALL_X], [-3, 3], color="0.55", lw=4, solid_capstyle="butt", zorder=2, label="wall")
    top.scatter(points[0, hit[0], 0], points[0, hit[0], 1], s=8, zorder=3, label="first returns", **FIRST)
    top.scatter(points[1, hit[1], 0], points[1, hit[1], 1], s=30, facecolors="none", edgecolors=SECOND["color"],
                marker=SECOND["marker"], lw=1.3, zorder=4, label="second returns")
    top.plot(0, 0, "^", color="tab:red", ms=9, zorder=4, label="sensor")
    top.set_xlim(-0.3, 6.6)
    top.set_ylim(-0.62, 0.62)
    top.set_xlabel("x (m)")
    top.set_ylabel("y (m, stretched)")
    top.set_title("From above: returns where they lie", fontsize=10)
    top.legend(loc="upper left", fontsize=8, framealpha=0.95)
    top.grid(alpha=0.3)
    # Right: range against azimuth.
    for e in (-edge, edge):
        side.axvline(e, color="0.6", ls=":", lw=1)
    side.plot(azimuths, thin["ranges"][0, 0], color="0.5", lw=1, drawstyle="steps-mid",
              label="thin beams (divergence 0), first return")
    side.scatter(azimuths[hit[0]], ranges[0, hit[0]], s=10, zorder=3, label="first return", **FIRST)
    side.scatter(azimuths[hit[1]], ranges[1, hit[1]], s=30, facecolors="none", edgecolors=SECOND["color"],
                 marker=SECOND["marker"], lw=1.3, zorder=4,
                 label=f"second return ({doubles} beams: {by_edge[0]} + {by_edge[1]})")
    side.set_xlim(azimuths[0] - 0.2, azimuths[-1] + 0.2)
    side.set_ylim(1.5, 6.8)
    for sign in (-1, 1):  # the beams with two returns on each side
        at = hit[1] & (np.sign(azimuths) == sign)
        side.annotate("", xy=(azimuths[at].mean(), 5.85), xytext=(0.9 * sign, 4.75),
                      arrowprops=dict(arrowstyle="->", color="0.3", lw=0.8))
        side.annotate("", xy=(azimuths[at].mean(), 3.1), xytext=(0.9 * sign, 4.35),
                      arrowprops=dict(arrowstyle="->", color="0.3", lw=0.8))
    side.text(0, 4.55, "beams across an edge:\nfirst return on the pole,\nsecond on the wall", ha="center",
              va="center", fontsize=8.5)
    side.set_xlabel("beam azimuth (degrees)")
    side.set_ylabel("range (m)")
    side.set_title("Range by beam: two returns at each of the pole's edges (dotted)", fontsize=10)
    side.legend(loc="lower center", fontsize=8, framealpha=0.95)
    side.grid(alpha=0.3)
    figure.suptitle("A pole 3 m away in front of a wall at 6 m: divergence 10 mrad, 16 sub-rays, "
                    "returns \"all\" (up to 2 per beam)", fontsize=11)
    figure.tight_layout()
    figure.savefig(args.figure)
    print(f"wrote {args.figure} ({doubles} of {azimuths.size} beams with two returns, {by_edge[0]} + {by_edge[1]})",
          file=sys.stderr)


if __name__ == "__main__":
    main()
