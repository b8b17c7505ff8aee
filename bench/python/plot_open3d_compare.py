#!/usr/bin/python3
"""Draws docs/python.md's figure of revolve against Open3D from bench/python/open3d_compare.py's JSON
(Debian's python3-matplotlib).

    bench/python/plot_open3d_compare.py bench/results/python/open3d_compare.json docs/open3d_comparison.png

One panel per shape: rays per second against the measured error (the largest distance of a hit from
the true surface, over the object's size), Open3D's meshes and revolve's polylines at each error
budget (1e-3, 1e-4, 1e-5: the measured errors lie just under them), one thread (solid) and all
threads (dashed).
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {
    "open3d": dict(color="tab:red", marker="s", label="Open3D RaycastingScene, tessellated"),
    "revolve": dict(color="tab:blue", marker="o", label="revolve RaycastingScene, exact (polyline)"),
}


def main(source, target):
    with open(source) as f:
        report = json.load(f)
    shapes = list(dict.fromkeys(r["shape"] for r in report["results"]))
    figure, axes = plt.subplots(1, len(shapes), figsize=(3.6 * len(shapes), 3.6), sharey=True, squeeze=False)
    for ax, shape in zip(axes[0], shapes):
        rows = [r for r in report["results"] if r["shape"] == shape]
        for library, style in STYLE.items():
            for threads, line in (("1", "-"), ("all", "--")):
                x = [r[library]["max_error"] for r in rows]
                y = [r[library][f"mrays_{threads}"] for r in rows]
                label = f"{style['label']}, {'1 thread' if threads == '1' else 'all threads'}"
                ax.plot(x, y, line, color=style["color"], marker=style["marker"], markersize=4, label=label)
        ax.set_xscale("log")
        ax.invert_xaxis()
        ax.set_ylim(0, 1.15 * max(max(r[lib][f"mrays_{t}"] for lib in STYLE for t in ("1", "all")) for r in report["results"]))
        ax.set_title(shape)
        ax.set_xlabel("max error / object size")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("Mrays/s (numpy rays in, arrays out)")
    handles, labels = axes[0][0].get_legend_handles_labels()
    figure.legend(handles, labels, loc="lower center", ncol=2, fontsize=8, frameon=False)
    load = report.get("load_average", {}).get("before", [None])[0]
    shared = f", load average {load:.0f} from other work" if load is not None and load >= 1 else ""
    figure.suptitle(f"revolve and Open3D {report['open3d']} from Python: {report['rays'] // 1000}k incoherent rays a shape, "
                    f"median of {report['repeats']} ({report['cpu']}, {report['threads_all']} threads{shared}, {report['date']})", fontsize=10)
    figure.tight_layout(rect=(0, 0.1, 1, 0.95))
    figure.savefig(target, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
