#!/usr/bin/python3
"""Runs revolve-bench scale over a ladder of object counts, one process a run (so that each run's
peak resident memory is its own), and writes the runs as one JSON document. Three configurations:
revolve's exact surfaces built by the library alone (--build library), the same through the tools'
scene stack (--build scene), and Embree meshes at matched error.

    bench/python/scale_ladder.py BUILD/bench/revolve-bench out/scale/scale.json \
        [--counts 100,1000,10000,100000,1000000] [--runs 3] [--mesh-limit-gb 12] [--scene-max 300000]

Each configuration runs --runs times; the document keeps every run, and plot_scale.py draws the
median of each. A mesh run whose triangles would need more than --mesh-limit-gb (at 128 bytes a
triangle, platform/embree/memory_check.h's figure) is not started, and recorded as not fitting.
The scene stack, which also holds the scene's description, runs up to --scene-max objects.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("bench")
    parser.add_argument("output")
    parser.add_argument("--counts", default="100,1000,10000,100000,1000000")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--mesh-limit-gb", type=float, default=12.0)
    parser.add_argument("--scene-max", type=int, default=300000)
    args = parser.parse_args()
    counts = [int(c) for c in args.counts.split(",")]
    document = {"command": " ".join(sys.argv), "runs": [], "not_fitting": []}
    triangles_per_mesh = None
    for count in counts:
        for geometry, build in (("revolve", "library"), ("revolve", "scene"), ("mesh", "scene")):
            if geometry == "mesh" and triangles_per_mesh is not None:
                need = triangles_per_mesh * count * 128 / 1e9
                if need > args.mesh_limit_gb:
                    document["not_fitting"].append({"objects": count, "geometry": geometry, "estimated_gb": need})
                    print(f"mesh, {count} objects: about {need:.0f} GB of triangles, not run", flush=True)
                    continue
            if build == "scene" and count > args.scene_max:
                continue
            for run in range(args.runs):
                with tempfile.TemporaryDirectory() as folder:
                    path = os.path.join(folder, "run.json")
                    command = [args.bench, "scale", "--objects", str(count), "--geometry", geometry,
                               "--build", build, "--json", path]
                    subprocess.run(command, check=True)
                    with open(path) as f:
                        record = json.load(f)
                document["runs"].append(record)
                if geometry == "mesh":
                    # 2 triangles a segment a slice; the splines' polylines are near 64 points too.
                    triangles_per_mesh = 2 * (record["points_per_profile"] - 1) * record["mesh_slices"]
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    temporary = args.output + ".tmp"
    with open(temporary, "w") as f:
        json.dump(document, f, indent=1)
        f.write("\n")
    os.replace(temporary, args.output)


if __name__ == "__main__":
    main()
