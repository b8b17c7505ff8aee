#!/usr/bin/python3
"""Draws the README's plots from a revolve-bench JSON file (Debian's python3-matplotlib).

    bench/plot_results.py bench/results/revolve-bench.json OUTDIR

writes OUTDIR/speed_vs_error.png (incoherent rays, rtcIntersect1), OUTDIR/speed_vs_error_camera.png
(camera rays, rtcIntersect8), OUTDIR/memory_vs_error.png and OUTDIR/scaling.png. Every point is a
figure of the JSON; meshes are drawn as their whole grid with the best of them per error joined;
the spline traced exactly is a star, its polylines (adaptive, evenly spaced) and the adaptive
polylines' meshes are lines.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {
    "mibit": dict(color="tab:blue", marker="o", label="MIBIT (cylinder shells)"),
    "mibit_binary": dict(color="tab:green", marker="x", label="MIBIT (cylinder shells, the paper's binary tree)"),
    "mibit_cone": dict(color="tab:cyan", marker="v", label="MIBIT (cone shells)"),
    "mibit_hybrid": dict(color="tab:purple", marker="^", label="MIBIT (hybrid shells)"),
    "linear": dict(color="tab:gray", marker="s", label="Wang's linear scan"),
    "kajiya": dict(color="tab:brown", marker="D", label="Kajiya's strip tree"),
    "mesh": dict(color="tab:red", marker=".", label="Embree triangle mesh"),
    "spline": dict(color="black", marker="*", label="spline, traced exactly"),
    "adaptive": dict(color="tab:olive", marker="P", label="adaptive polyline of the spline (MIBIT)"),
    "uniform": dict(color="tab:pink", marker="+", label="evenly spaced polyline (MIBIT)"),
    "mesh_adaptive": dict(color="tab:orange", marker="d", label="mesh of the adaptive polyline"),
}


def error_of(config, mode):
    error = config["error_camera"] if mode.startswith("camera") else config["error_incoherent"]
    return error["residual_max"] if error else None


def frontier(points, better):
    """The points not beaten by one with a smaller (or equal) error: the best per error level."""
    best = []
    for x, y in sorted(points):
        if not best or better(y, best[-1][1]):
            best.append((x, y))
    return best


def speed_panel(ax, shape, mode):
    by_method = {}
    floor = None
    for config in shape["configs"]:
        speed = config["mrays_per_second"].get(mode)
        if speed is None:
            continue
        if config["method"] == "sphere":
            floor = speed["median"]
            continue
        error = error_of(config, mode)
        by_method.setdefault(config["method"], []).append((error, speed["median"]))
    for method, points in by_method.items():
        style = STYLE[method]
        if method == "mesh":
            ax.scatter(*zip(*points), s=8, color=style["color"], alpha=0.35)
            best = frontier(points, lambda y, previous: y > previous)
            ax.plot(*zip(*best), color=style["color"], label=style["label"] + " (best of grid)")
        elif method == "spline":
            ax.scatter(*zip(*points), s=90, color=style["color"], marker=style["marker"], zorder=5, label=style["label"])
        else:
            ax.plot(*zip(*sorted(points)), color=style["color"], marker=style["marker"], ms=3, label=style["label"])
    if floor is not None:
        ax.axhline(floor, color="black", ls="--", lw=0.8, label="one-quadratic user primitive")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.invert_xaxis()
    ax.set_title(shape["shape"])
    ax.set_xlabel("max error / object size")
    ax.grid(True, which="both", lw=0.3)


def memory_panel(ax, shape):
    mibit, mesh, adaptive, spline = [], [], [], []
    for config in shape["configs"]:
        error = error_of(config, "incoherent_1")
        if config["method"] == "mibit":
            mibit.append((error, config["total_bytes"]))
        elif config["method"] == "mesh":
            mesh.append((error, config["total_bytes"]))
        elif config["method"] == "adaptive":
            adaptive.append((error, config["total_bytes"]))
        elif config["method"] == "spline":
            spline.append((error, config["total_bytes"]))
    ax.plot(*zip(*sorted(mibit)), color=STYLE["mibit"]["color"], marker="o", ms=3, label=STYLE["mibit"]["label"])
    if adaptive:
        ax.plot(*zip(*sorted(adaptive)), color=STYLE["adaptive"]["color"], marker="P", ms=3, label=STYLE["adaptive"]["label"])
    if spline:
        ax.scatter(*zip(*spline), s=90, color="black", marker="*", zorder=5, label=STYLE["spline"]["label"])
    ax.scatter(*zip(*mesh), s=8, color=STYLE["mesh"]["color"], alpha=0.35)
    leanest = frontier(mesh, lambda y, previous: y < previous)
    ax.plot(*zip(*leanest), color=STYLE["mesh"]["color"], label="Embree triangle mesh (leanest of grid)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.invert_xaxis()
    ax.set_title(shape["shape"])
    ax.set_xlabel("max error / object size")
    ax.grid(True, which="both", lw=0.3)


def grid_figure(shapes, draw, ylabel, title, path):
    fig, axes = plt.subplots(1, len(shapes), figsize=(max(4 * len(shapes), 12), 4.8), squeeze=False)
    for ax, shape in zip(axes[0], shapes):
        draw(ax, shape)
    axes[0][0].set_ylabel(ylabel)
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=8, frameon=False)
    fig.suptitle(title)
    fig.tight_layout(rect=(0, 0.14, 1, 0.95))
    fig.savefig(path, dpi=90)
    plt.close(fig)


def scaling_figure(shape, path):
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    by_method = {}
    for config in shape["configs"]:
        by_method.setdefault(config["method"], []).append((config["points"], config["mrays_per_second"]["incoherent_1"]["median"]))
    for method, points in by_method.items():
        style = STYLE[method]
        label = style["label"] + (" (slices balancing its error)" if method == "mesh" else "")
        ax.plot(*zip(*sorted(points)), color=style["color"], marker=style["marker"], ms=4, label=label)
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("profile points")
    ax.set_ylabel("Mrays/s (1 thread, rtcIntersect1)")
    ax.set_title(f"Scaling with profile points: {shape['shape']}, {shape['incoherent_rays']} incoherent rays")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        results = json.load(f)
    out = sys.argv[2]
    os.makedirs(out, exist_ok=True)
    shapes = results["speed_error"]
    machine = f"{results['machine']['cpu']}, {results['date']}"
    if shapes:
        grid_figure(shapes, lambda ax, s: speed_panel(ax, s, "incoherent_1"), "Mrays/s (1 thread)",
                    f"Speed against error: incoherent rays, rtcIntersect1 ({machine})", os.path.join(out, "speed_vs_error.png"))
        grid_figure(shapes, lambda ax, s: speed_panel(ax, s, "camera_8"), "Mrays/s (1 thread)",
                    f"Speed against error: camera rays, rtcIntersect8 ({machine})", os.path.join(out, "speed_vs_error_camera.png"))
        grid_figure(shapes, memory_panel, "bytes (revolve + Embree)", f"Memory against error ({machine})",
                    os.path.join(out, "memory_vs_error.png"))
    if results["scaling"]:
        scaling_figure(results["scaling"][0], os.path.join(out, "scaling.png"))


if __name__ == "__main__":
    main()
