#!/usr/bin/python3
"""Draws the README's plots from a revolve-bench JSON file (Debian's python3-matplotlib).

    bench/plot_results.py bench/results/revolve-bench.json OUTDIR [FIGURE...]

writes OUTDIR/speed_vs_error.png (incoherent rays, rtcIntersect1), OUTDIR/speed_vs_error_camera.png
(camera rays, rtcIntersect8), OUTDIR/speed_vs_error_shadow.png (shadow rays, rtcOccluded1),
OUTDIR/memory_vs_error.png, OUTDIR/scaling.png and
OUTDIR/embree_curves.png (MIBIT, the best mesh and Embree's own curves per shape, and their scaling).
Every point is a figure of the JSON; meshes are drawn as their whole grid with the best of them per
error joined; the spline traced exactly is a star, its polylines (adaptive, evenly spaced) and the
adaptive polylines' meshes are lines. Configurations a method cannot trace (their "limitation") have
no figures to draw.
Naming FIGUREs (speed_vs_error, speed_vs_error_camera, speed_vs_error_shadow, memory_vs_error,
scaling, embree_curves) draws only those.
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
    "embree_cone": dict(color="tab:orange", marker="P", label="Embree linear cone curve"),
    "embree_round_curve": dict(color="tab:olive", marker="*", label="Embree round Bézier curve (+ discs)"),
    "spline": dict(color="black", marker="*", label="spline, traced exactly"),
    "adaptive": dict(color="darkgoldenrod", marker="X", label="adaptive polyline of the spline (MIBIT)"),
    "uniform": dict(color="tab:pink", marker="+", label="evenly spaced polyline (MIBIT)"),
    "mesh_adaptive": dict(color="darkred", marker="d", label="mesh of the adaptive polyline"),
}


def error_of(config, mode):
    camera = mode.startswith("camera") or mode == "occluded_8"  # occluded_8 shadows along the camera rays
    error = config["error_camera"] if camera else config["error_incoherent"]
    return error["residual_max"] if error else None


def frontier(points, better):
    """The points not beaten by one with a smaller (or equal) error: the best per error level."""
    best = []
    for x, y in sorted(points):
        if not best or better(y, best[-1][1]):
            best.append((x, y))
    return best


def speed_panel(ax, shape, mode, methods=None):
    by_method = {}
    floor = None
    for config in shape["configs"]:
        if methods is not None and config["method"] not in methods:
            continue
        speed = config["mrays_per_second"].get(mode)
        if speed is None:
            continue
        if config["method"] == "sphere":
            floor = speed["median"]
            continue
        error = error_of(config, mode)
        by_method.setdefault(config["method"], []).append((config["points"], error, speed["median"]))
    for method, configs in by_method.items():
        style = STYLE[method]
        points = [(error, speed) for _, error, speed in configs]
        if method == "mesh":
            ax.scatter(*zip(*points), s=8, color=style["color"], alpha=0.35)
            best = frontier(points, lambda y, previous: y > previous)
            ax.plot(*zip(*best), color=style["color"], label=style["label"] + " (best of grid)")
        elif method == "spline":
            ax.scatter(*zip(*points), s=90, color=style["color"], marker=style["marker"], zorder=5, label=style["label"])
        else:
            # Joined in order of resolution: a round curve's error does not fall all the way.
            ordered = [(error, speed) for _, error, speed in sorted(configs)]
            ax.plot(*zip(*ordered), color=style["color"], marker=style["marker"], ms=3, label=style["label"])
    if floor is not None:
        ax.axhline(floor, color="black", ls="--", lw=0.8, label="one-quadratic user primitive")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.invert_xaxis()
    ax.set_title(shape["shape"])
    ax.set_xlabel("max error / object size")
    ax.grid(True, which="both", lw=0.3)


def memory_panel(ax, shape):
    lines = {"mibit": [], "embree_cone": [], "embree_round_curve": [], "adaptive": []}
    mesh, spline = [], []
    for config in shape["configs"]:
        if config.get("limitation"):
            continue
        error = error_of(config, "incoherent_1")
        if config["method"] in lines:
            lines[config["method"]].append((error, config["total_bytes"]))
        elif config["method"] == "mesh":
            mesh.append((error, config["total_bytes"]))
        elif config["method"] == "spline":
            spline.append((error, config["total_bytes"]))
    for method, points in lines.items():
        if points:
            style = STYLE[method]
            ax.plot(*zip(*sorted(points)), color=style["color"], marker=style["marker"], ms=3, label=style["label"])
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


def scaling_panel(ax, shape, methods=None):
    by_method = {}
    for config in shape["configs"]:
        if config.get("limitation") or (methods is not None and config["method"] not in methods):
            continue
        by_method.setdefault(config["method"], []).append((config["points"], config["mrays_per_second"]["incoherent_1"]["median"]))
    for method, points in by_method.items():
        style = STYLE[method]
        label = style["label"] + (" (slices balancing its error)" if method == "mesh" else "")
        ax.plot(*zip(*sorted(points)), color=style["color"], marker=style["marker"], ms=4, label=label)
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("profile points (round curve: segments)")
    ax.set_ylabel("Mrays/s (1 thread, rtcIntersect1)")
    ax.grid(True, which="both", lw=0.3)


def scaling_figure(shape, path):
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    scaling_panel(ax, shape)
    ax.set_title(f"Scaling with profile points: {shape['shape']}, {shape['incoherent_rays']} incoherent rays")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


EMBREE_CURVES = ("mibit", "mesh", "embree_cone", "embree_round_curve")


def curves_speed_panel(ax, shape):
    speed_panel(ax, shape, "incoherent_1", EMBREE_CURVES)
    # A method that traces none of the shape's configurations says so where its line would be.
    refused = []
    for method in ("embree_cone", "embree_round_curve"):
        configs = [c for c in shape["configs"] if c["method"] == method]
        if configs and all(c.get("limitation") for c in configs):
            refused.append(STYLE[method]["label"].split(" (")[0] + ": cannot trace it")
    if refused:
        ax.text(0.03, 0.03, "\n".join(refused), transform=ax.transAxes, fontsize=8, va="bottom")


def embree_curves_figure(shapes, scaling, machine, path):
    panels = len(shapes) + (1 if scaling else 0)
    fig, axes = plt.subplots(1, panels, figsize=(3.6 * panels, 4.4), squeeze=False)
    for ax, shape in zip(axes[0], shapes):
        curves_speed_panel(ax, shape)
    axes[0][0].set_ylabel("Mrays/s (1 thread, incoherent rays)")
    if scaling:
        ax = axes[0][-1]
        scaling_panel(ax, scaling, EMBREE_CURVES)
        ax.set_title(f"scaling: {scaling['shape']}")
    handles, labels = {}, {}
    for ax in axes[0]:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(label, handle)
    fig.legend(list(handles.values()), list(handles.keys()), loc="lower center", ncol=3, fontsize=9, frameon=False)
    fig.suptitle(f"MIBIT, meshes and Embree's own curves: speed against error, and against profile points ({machine})")
    fig.tight_layout(rect=(0, 0.1, 1, 0.95))
    fig.savefig(path, dpi=90)
    plt.close(fig)


FIGURES = ("speed_vs_error", "speed_vs_error_camera", "speed_vs_error_shadow", "memory_vs_error", "scaling", "embree_curves")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    for name in sys.argv[3:]:
        if name not in FIGURES:
            sys.exit(f"plot_results.py: unknown figure \"{name}\"; expected one of: {', '.join(FIGURES)}")
    with open(sys.argv[1]) as f:
        results = json.load(f)
    out = sys.argv[2]
    wanted = set(sys.argv[3:]) or set(FIGURES)
    os.makedirs(out, exist_ok=True)
    shapes = results["speed_error"]
    scaling = results["scaling"][0] if results["scaling"] else None
    machine = f"{results['machine']['cpu']}, {results['date']}"
    if shapes and "speed_vs_error" in wanted:
        grid_figure(shapes, lambda ax, s: speed_panel(ax, s, "incoherent_1"), "Mrays/s (1 thread)",
                    f"Speed against error: incoherent rays, rtcIntersect1 ({machine})", os.path.join(out, "speed_vs_error.png"))
    if shapes and "speed_vs_error_camera" in wanted:
        grid_figure(shapes, lambda ax, s: speed_panel(ax, s, "camera_8"), "Mrays/s (1 thread)",
                    f"Speed against error: camera rays, rtcIntersect8 ({machine})", os.path.join(out, "speed_vs_error_camera.png"))
    if shapes and "speed_vs_error_shadow" in wanted:
        grid_figure(shapes, lambda ax, s: speed_panel(ax, s, "occluded_1"), "Mrays/s (1 thread)",
                    f"Speed against error: shadow rays, rtcOccluded1 ({machine})", os.path.join(out, "speed_vs_error_shadow.png"))
    if shapes and "memory_vs_error" in wanted:
        grid_figure(shapes, memory_panel, "bytes (revolve + Embree)", f"Memory against error ({machine})",
                    os.path.join(out, "memory_vs_error.png"))
    if scaling and "scaling" in wanted:
        scaling_figure(scaling, os.path.join(out, "scaling.png"))
    if (shapes or scaling) and "embree_curves" in wanted:
        embree_curves_figure(shapes, scaling, machine, os.path.join(out, "embree_curves.png"))


if __name__ == "__main__":
    main()
