#!/usr/bin/python3
"""Draws docs/performance.md's figure of scenes of many distinct objects from scale_ladder.py's JSON
(Debian's python3-matplotlib): memory, build time and throughput against the number of objects,
revolve's exact surfaces (built by the library alone, and through the tools' scene stack) beside
Embree meshes at matched error, the median of each configuration's runs; and prints the table the
docs quote.

    bench/python/plot_scale.py out/scale/scale.json docs/scale_objects.png
"""
import json
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {
    "revolve, library": dict(color="tab:green", marker="^", label="revolve, exact, the library alone"),
    "revolve, scene": dict(color="tab:blue", marker="o", label="revolve, exact, the scene stack"),
    "mesh, scene": dict(color="tab:red", marker="s", label="Embree meshes, matched error"),
}


def configuration(run):
    """The run's geometry and how it was built (runs from before --build were the scene stack's)."""
    return run["geometry"] + ", " + run.get("build", "scene")


def medians(runs):
    """One row a (geometry, objects): the median of each figure over the runs."""
    groups = {}
    for run in runs:
        groups.setdefault((configuration(run), run["objects"]), []).append(run)
    rows = []
    for (geometry, objects), group in sorted(groups.items()):
        median = lambda f: statistics.median(f(r) for r in group)  # noqa: E731
        rows.append(
            dict(
                geometry=geometry,
                objects=objects,
                runs=len(group),
                build=median(lambda r: r["build_seconds"]),
                first_ray=median(lambda r: r["first_ray_seconds"]),
                counted=median(lambda r: r["memory"]["counted_bytes_per_object"]),
                peak=median(lambda r: r["memory"]["peak_resident_bytes"]),
                camera=median(lambda r: r["camera"]["mrays_per_second"]),
                lidar=median(lambda r: r["lidar"]["mrays_per_second"]),
                load=max(max(r["machine"]["load_before"], r["machine"]["load_after"]) for r in group),
            )
        )
    return rows


def main(source, target):
    with open(source) as f:
        document = json.load(f)
    rows = medians(document["runs"])
    print("| built | objects | build s | first ray s | bytes/object (counted) | peak RSS MB | camera Mrays/s | lidar Mrays/s | load |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print(
            f"| {r['geometry']} | {r['objects']:,} | {r['build']:.2f} | {r['first_ray']:.2f} | {r['counted']:,.0f} | "
            f"{r['peak'] / 1e6:,.0f} | {r['camera']:.2f} | {r['lidar']:.2f} | {r['load']:.1f} |"
        )
    for item in document.get("not_fitting", []):
        print(f"| {item['geometry']} | {item['objects']:,} | does not fit: about {item['estimated_gb']:.0f} GB of triangles |")

    figure, axes = plt.subplots(1, 3, figsize=(12, 3.6))
    panels = [
        (axes[0], "peak resident memory (MB)", lambda r: r["peak"] / 1e6),
        (axes[1], "build time (s)", lambda r: r["build"]),
        (axes[2], "throughput (Mrays/s)", None),
    ]
    for ax, title, value in panels:
        for geometry, style in STYLE.items():
            mine = [r for r in rows if r["geometry"] == geometry]
            if not mine:
                continue
            x = [r["objects"] for r in mine]
            if value is None:
                ax.plot(x, [r["camera"] for r in mine], "-", color=style["color"], marker=style["marker"],
                        label=style["label"] + ", camera")
                ax.plot(x, [r["lidar"] for r in mine], "--", color=style["color"], marker=style["marker"],
                        label=style["label"] + ", lidar")
            else:
                ax.plot(x, [value(r) for r in mine], "-", color=style["color"], marker=style["marker"],
                        label=style["label"])
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("distinct objects (64-point profiles)")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=8)
    axes[2].legend(fontsize=6, loc="lower left")
    figure.tight_layout()
    figure.savefig(target, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
