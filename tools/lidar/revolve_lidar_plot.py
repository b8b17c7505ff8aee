#!/usr/bin/python3
"""Draws revolve-lidar's --plot: a top-down view of a scan over the scene's footprint.

    revolve-lidar-plot FOOTPRINT.json OUT.png     (OUT.png "-": standard output)

revolve-lidar runs this (the build copies it beside the tools, as build/bin/revolve-lidar-plot)
with a JSON file it writes itself: what the plot shows of the scene, already projected onto the
ground plane (platform/robot/scan_plot.cpp), and each pose's sensor and returns. revolve-lidar takes
the PNG from standard output into a temporary file that it renames into place, so a failed plot
leaves no partial image. Needs Debian's python3-matplotlib.
"""
import json
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
    from matplotlib.colors import LogNorm
    from matplotlib.patches import Circle, Polygon
except ImportError as error:
    sys.exit(f"needs matplotlib (Debian: apt-get install python3-matplotlib): {error}")

FLOOR = "#ede5d4"
WALL = "#4d4d52"
OBJECT, OBJECT_EDGE = "#c2d4ed", "#738cb8"
SECTION = "#1a338c"
BEAM, RETURN = "#f25933", "#cc0d0d"
MAX_BEAMS = 2000
SENSOR = "#0d8c26"


def extent(data):
    """The bounds of everything drawn, padded by 4%."""
    xs, ys = [], []
    for outline in data["surfaces"] + data["objects"] + data["walls"]:
        xs += [p[0] for p in outline]
        ys += [p[1] for p in outline]
    for pose in data["poses"]:
        xs.append(pose["origin"][0])
        ys.append(pose["origin"][1])
        xs += [p[0] for p in pose["returns"]]
        ys += [p[1] for p in pose["returns"]]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    if not x1 > x0:
        x0, x1 = x0 - 1, x1 + 1
    if not y1 > y0:
        y0, y1 = y0 - 1, y1 + 1
    pad_x, pad_y = 0.04 * (x1 - x0), 0.04 * (y1 - y0)
    return x0 - pad_x, x1 + pad_x, y0 - pad_y, y1 + pad_y


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: revolve-lidar-plot FOOTPRINT.json OUT.png")
    with open(sys.argv[1], encoding="utf-8") as file:
        data = json.load(file)
    x0, x1, y0, y1 = extent(data)

    # Equal scales on both axes, the plot area at most 11 x 7 inches.
    scale = min(11 / (x1 - x0), 7 / (y1 - y0))
    fig, ax = plt.subplots(figsize=(scale * (x1 - x0) + 1.6, scale * (y1 - y0) + 1.9))
    ax.set_aspect("equal")
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.grid(True, color="#dcdcdc", lw=0.8, zorder=0)
    ax.set_axisbelow(True)

    # The scene: floors (higher ones on top, as the JSON orders them), objects from above, their
    # sections at the sensor's height, walls edge-on.
    for outline in data["surfaces"]:
        ax.add_patch(Polygon(outline, closed=True, facecolor=FLOOR, edgecolor="none", zorder=1))
    for outline in data["objects"]:
        ax.add_patch(Polygon(outline, closed=True, facecolor=OBJECT, edgecolor=OBJECT_EDGE, lw=0.8, zorder=2))
    for section in data["sections"]:
        ax.add_patch(Circle(section["centre"], section["radius"], fill=False, edgecolor=SECTION, lw=1.4, zorder=3))
    if data["walls"]:
        ax.add_collection(LineCollection(data["walls"], colors=WALL, linewidths=3, zorder=3))

    # The scan: each pose's beams to its returns, the returns, the sensor and its heading.
    # Every step-th return's beam, at most MAX_BEAMS of them: the 230,000 beams of a 3-D scan's
    # eight poses would paint the whole footprint red. The title says when beams are thinned.
    total = sum(len(pose["returns"]) for pose in data["poses"])
    step, count = max(1, -(-total // MAX_BEAMS)), 0
    for pose in data["poses"]:
        origin = pose["origin"]
        beams = [[origin, point[:2]] for i, point in enumerate(pose["returns"], start=count) if i % step == 0]
        count += len(pose["returns"])
        if beams:
            ax.add_collection(LineCollection(beams, colors=BEAM, alpha=0.12, linewidths=0.6, zorder=4))
    returns = [point for pose in data["poses"] for point in pose["returns"]]
    if returns:
        # Dots shrink as returns multiply, so that a 3-D scan's rings stay apart. Coloured by
        # intensity (reflectivity |cos| / range^2), on a log scale: it spans decades with range.
        size = 4 if len(returns) <= 20000 else 1
        xs, ys, intensity = zip(*returns)
        positive = [i for i in intensity if i > 0]
        low, high = (min(positive), max(positive)) if positive else (1e-3, 1.0)
        dots = ax.scatter(xs, ys, s=size, c=[max(i, low) for i in intensity], cmap="inferno",
                          norm=LogNorm(vmin=low, vmax=max(high, low * 1.001)), zorder=5, linewidths=0)
        fig.colorbar(dots, ax=ax, shrink=0.7, pad=0.02, label="return intensity, reflectivity |cos θ| / range² (1/m²)")
    for pose in data["poses"]:
        (x, y), (hx, hy) = pose["origin"], pose["heading"]
        arrow = 0.05 * max(x1 - x0, y1 - y0)
        if hx or hy:
            ax.annotate("", xy=(x + arrow * hx, y + arrow * hy), xytext=(x, y), zorder=6,
                        arrowprops=dict(arrowstyle="-|>", color=SENSOR, lw=2, shrinkA=0, shrinkB=0))
        ax.plot(x, y, "o", ms=8, color=SENSOR, markeredgecolor="white", markeredgewidth=1.5, zorder=7)

    legend = [
        Polygon([[0, 0]], facecolor=FLOOR, label="floor"),
        plt.Line2D([], [], color=WALL, lw=3, label="wall"),
        Polygon([[0, 0]], facecolor=OBJECT, edgecolor=OBJECT_EDGE, label="object (top view)"),
        plt.Line2D([], [], color=SECTION, marker="o", ls="none", mfc="none", label="section at sensor height"),
        plt.Line2D([], [], color=BEAM, alpha=0.5, label="beam"),
        plt.Line2D([], [], color=RETURN, marker=".", ls="none", label="return (colour: intensity)"),
        plt.Line2D([], [], color=SENSOR, marker="o", ls="none", label="sensor"),
    ]
    ax.legend(handles=legend, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=7, fontsize=8, frameon=False)
    title = data["title"] + (f"; beams drawn for 1 return in {step}" if step > 1 else "")
    ax.set_title(title, pad=24, fontsize=10)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    fig.tight_layout()
    fig.savefig(sys.stdout.buffer if sys.argv[2] == "-" else sys.argv[2], dpi=100, format="png")


if __name__ == "__main__":
    main()
