#!/usr/bin/python3
"""Draws the README's POV-Ray scaling plot from a revolve-bench pov-scaling JSON file (Debian's
python3-matplotlib).

    bench/plot_pov_scaling.py bench/results/pov-scaling.json docs/pov_scaling.png

Left axis: each renderer's time for the image (revolve's render time, POV-Ray's Trace Time
statistic) against the lathe's profile points; right axis: their ratio. The vase as a spline
(traced exactly by revolve, a bezier_spline lathe for POV-Ray) is drawn as two stars at its number
of Bézier pieces. Every point is a figure of the JSON.
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        results = json.load(f)
    settings = results["settings"]
    rows = sorted(results["points"], key=lambda p: p["points"])
    points = [p["points"] for p in rows]
    revolve = [p["revolve_render_seconds"]["median"] for p in rows]
    povray = [p["povray_trace_seconds"]["median"] for p in rows]
    ratio = [p["povray_over_revolve"] for p in rows]

    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.plot(points, revolve, color="tab:blue", marker="o", ms=4, label="revolve (MIBIT, wide tree): render time")
    ax.plot(points, povray, color="tab:red", marker="s", ms=4, label="POV-Ray 3.7 linear_spline lathe: Trace Time")
    spline = results.get("spline")
    if spline:
        pieces = spline["bezier_pieces"]
        ax.scatter([pieces], [spline["revolve_render_seconds"]["median"]], s=110, marker="*", color="tab:blue", zorder=5,
                   label=f"revolve, the vase as {pieces} cubic Bézier pieces, exact")
        ax.scatter([pieces], [spline["povray_trace_seconds"]["median"]], s=110, marker="*", color="tab:red", zorder=5,
                   label="POV-Ray bezier_spline lathe of the same pieces")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("profile points of the lathe")
    ax.set_ylabel("seconds for the image")
    ax.grid(True, which="both", lw=0.3)
    right = ax.twinx()
    right.plot(points, ratio, color="gray", ls="--", lw=1, label="POV-Ray / revolve (right axis)")
    right.set_yscale("log")
    right.set_ylabel("POV-Ray / revolve")
    handles = ax.get_legend_handles_labels()[0] + right.get_legend_handles_labels()[0]
    labels = ax.get_legend_handles_labels()[1] + right.get_legend_handles_labels()[1]
    ax.legend(handles, labels, fontsize=8, loc="upper left")
    ax.set_title(f"One lathe, {settings['width']} x {settings['height']}, whitted depth 1 with shadows, "
                 f"{settings['threads']} threads\n{results['machine']['cpu']}, {results['date']}", fontsize=9)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    main()
