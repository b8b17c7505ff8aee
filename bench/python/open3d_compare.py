#!/usr/bin/python3
"""revolve's RaycastingScene beside Open3D's, from Python with numpy rays (docs/python.md).

    PYTHONPATH=build/python /usr/bin/python3 bench/python/open3d_compare.py [--rays N] [--repeats R]
        [--json OUT.json] [--shapes sphere,torus,...] [--tolerances 1e-3,1e-4,1e-5]
    bench/python/open3d_compare.py --markdown OUT.json    (docs/python.md's table of a results file)

For each of the benchmark's five test shapes (bench/test_shapes.cpp, lines and arcs) and each error
budget (a fraction of the object's size): Open3D traces the surface tessellated within the budget
(half of it to the profile's chords, half to the slices: the fewest triangles), revolve traces the
profile's polyline within the whole budget exactly. Both cast the same incoherent rays (origins on a
sphere three times the shape's bounding radius, aimed at uniform points of its box), Open3D's from a
tensor made beforehand, revolve's from the numpy array itself; each configuration is timed with one
thread and with all, the two libraries taking turns, and the median of the repeats is reported.
Beside each speed, its error: the largest distance of a hit point from the true curve in its
meridian plane (closed form), as a fraction of the size, and the rays on which it disagrees with
revolve's hit or miss. Memory, counted exactly by RaycastingScene.memory_bytes (the shapes' and the
meshes' arrays, and Embree's allocations by its memory monitor): revolve's scene, and the same mesh
as Open3D's in an Embree scene with Open3D's flags. Open3D's own, which Python cannot count, is
also estimated (JSON only) as a fresh process's resident growth while it builds the scene and first
casts, less that of a scene of one triangle; it resolves no less than a few MB.

Open3D must be able to cast rays: Debian 13's python3-open3d (0.19) can; Debian 12's (0.16.1) casts
none (every t_hit inf), and the script then stops, saying so.
"""

import argparse
import datetime
import gc
import json
import math
import os
import platform
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import smooth_shapes  # noqa: E402

import revolve  # noqa: E402

TOLERANCES = (1e-3, 1e-4, 1e-5)


def open3d():
    import open3d as o3d

    return o3d


def open3d_casts_rays(o3d):
    scene = o3d.t.geometry.RaycastingScene()
    scene.add_triangles(o3d.t.geometry.TriangleMesh.from_legacy(o3d.geometry.TriangleMesh.create_box()))
    t = scene.cast_rays(o3d.core.Tensor([[0.5, 0.5, 3, 0, 0, -1]], dtype=o3d.core.Dtype.Float32))["t_hit"].numpy()
    return bool(np.isfinite(t).all())


def incoherent_rays(shape, count, seed):
    r_max, low, high = shape.extent()
    lower, upper = np.array([-r_max, -r_max, low]), np.array([r_max, r_max, high])
    centre, radius = 0.5 * (lower + upper), 0.5 * np.linalg.norm(upper - lower)
    rng = np.random.default_rng(seed)
    u = rng.normal(size=(count, 3))
    u /= np.linalg.norm(u, axis=1)[:, None]
    origins = centre + 3 * radius * u
    d = rng.uniform(lower, upper, size=(count, 3)) - origins
    d /= np.linalg.norm(d, axis=1)[:, None]
    return np.ascontiguousarray(np.concatenate([origins, d], axis=1), dtype=np.float32)


def mesh_for(shape, tolerance):
    """Profile points and slices of the tessellation within tolerance x size: half the budget to
    the chords, half to the slices (r_max (1 - cos(pi / k)) <= budget / 2)."""
    budget = tolerance * shape.size()
    points, chord = shape.polyline(budget / 2)
    r_max = shape.extent()[0]
    slices = max(3, math.ceil(math.pi / math.acos(1 - budget / (2 * r_max)) - 1e-9))
    return points, slices, chord + r_max * (1 - math.cos(math.pi / slices))


def errors(shape, rays, t):
    """The largest meridian distance of the hits from the true curve, over the size; and the hit mask."""
    hit = np.isfinite(t)
    o, d = rays[hit, :3].astype(np.float64), rays[hit, 3:].astype(np.float64)
    p = o + t[hit, None].astype(np.float64) * d
    residual = shape.distance(np.hypot(p[:, 0], p[:, 1]), p[:, 2]) / shape.size()
    return float(residual.max()) if len(residual) else float("nan"), hit


def resident_bytes():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024
    raise RuntimeError("no VmRSS in /proc/self/status")


def measure_memory(shape_name, tolerance):
    """In a fresh process (--memory): the resident set's growth while Open3D builds the mesh's scene
    and first casts, less that of a scene of one triangle built before it (Open3D's Embree device and
    the one-time set-up of its first cast, about 2 MB)."""
    o3d = open3d()
    shape = next(make() for make in smooth_shapes.SHAPES if make().name == shape_name)
    tensor = o3d.core.Tensor(incoherent_rays(shape, 1000, 1))
    points, slices, _ = mesh_for(shape, tolerance)
    vertices, triangles = revolve.tessellate(points, slices)
    meshes = [(o3d.core.Tensor(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.float32)), o3d.core.Tensor(np.array([[0, 1, 2]], np.uint32))),
              (o3d.core.Tensor(vertices), o3d.core.Tensor(triangles))]
    growth, kept = [], []
    for v, t in meshes:
        gc.collect()
        before = resident_bytes()
        scene = o3d.t.geometry.RaycastingScene()
        scene.add_triangles(v, t)
        scene.cast_rays(tensor)
        kept.append(scene)  # alive while measured
        gc.collect()
        growth.append(resident_bytes() - before)
    print(json.dumps({"bytes": growth[1] - growth[0], "one_triangle_bytes": growth[0]}))


def open3d_memory(shape_name, tolerance):
    done = subprocess.run([sys.executable, __file__, "--memory", shape_name, repr(tolerance)], capture_output=True, text=True,
                          check=True)
    return json.loads(done.stdout.strip().splitlines()[-1])["bytes"]


def timed(cast, repeats):
    return [cast() for _ in range(repeats)]


def run(args):
    o3d = open3d()
    if not open3d_casts_rays(o3d):
        sys.exit(f"open3d_compare: Open3D {o3d.__version__} casts no rays here (every t_hit inf on a box; Debian 12's 0.16.1 "
                 "does this): nothing to compare with. Run it where Open3D casts rays (Debian 13's python3-open3d 0.19).")
    threads_all = os.cpu_count()
    load_before = os.getloadavg()
    results = []
    shapes = [make() for make in smooth_shapes.SHAPES if make().name in args.shapes]
    for shape in shapes:
        rays = incoherent_rays(shape, args.rays, args.seed)
        tensor = o3d.core.Tensor(rays)
        for tolerance in args.tolerances:
            points, slices, mesh_bound = mesh_for(shape, tolerance)
            vertices, triangles = revolve.tessellate(points, slices)
            theirs = o3d.t.geometry.RaycastingScene()
            theirs.add_triangles(o3d.core.Tensor(vertices), o3d.core.Tensor(triangles))
            profile, profile_bound = shape.polyline(tolerance * shape.size())
            ours = revolve.RaycastingScene()
            ours.add_revolution(profile)
            # First casts build the BVHs (untimed) and give the hits whose errors are reported.
            t_theirs = theirs.cast_rays(tensor)["t_hit"].numpy()
            t_ours = ours.cast_rays(rays)["t_hit"]
            error_theirs, hit_theirs = errors(shape, rays, t_theirs)
            error_ours, hit_ours = errors(shape, rays, t_ours)
            row = {
                "shape": shape.name, "size": shape.size(), "tolerance": tolerance,
                "open3d": {"profile_points": len(points), "slices": slices, "triangles": len(triangles),
                           "bound": mesh_bound / shape.size(), "max_error": error_theirs, "hits": int(hit_theirs.sum()),
                           "disagreements": int((hit_theirs != hit_ours).sum())},
                "revolve": {"profile_points": len(profile), "bound": profile_bound / shape.size(), "max_error": error_ours,
                            "hits": int(hit_ours.sum())},
            }
            for label, nthreads in (("1", 1), ("all", 0)):
                seconds = {"open3d": [], "revolve": []}
                for _ in range(args.repeats):  # in turns, so that drift in the machine's load falls on both
                    start = time.perf_counter()
                    theirs.cast_rays(tensor, nthreads=nthreads)
                    seconds["open3d"].append(time.perf_counter() - start)
                    start = time.perf_counter()
                    ours.cast_rays(rays, nthreads=nthreads)
                    seconds["revolve"].append(time.perf_counter() - start)
                for library in seconds:
                    median = float(np.median(seconds[library]))
                    row[library][f"seconds_{label}"] = seconds[library]
                    row[library][f"mrays_{label}"] = args.rays / median / 1e6
                row[f"speedup_{label}"] = row["revolve"][f"mrays_{label}"] / row["open3d"][f"mrays_{label}"]
            # The mesh's memory counted exactly in an Embree scene (revolve's, with Open3D's scene flags),
            # and Open3D's own as a process's resident growth, which cannot resolve less than a few MB.
            same = revolve.RaycastingScene()
            same.add_triangles(vertices, triangles)
            same.cast_rays(rays[:1000])
            row["open3d"]["memory_bytes"] = same.memory_bytes()
            row["open3d"]["resident_growth_bytes"] = open3d_memory(shape.name, tolerance)
            row["revolve"]["memory_bytes"] = ours.memory_bytes()
            results.append(row)
            print(line_of(row), flush=True)
            del theirs, ours
            gc.collect()
    return {
        "command": " ".join(["bench/python/open3d_compare.py", *sys.argv[1:]]),
        "date": datetime.date.today().isoformat(),
        "machine": f"{platform.processor() or platform.machine()}, {threads_all} threads",
        "cpu": cpu_name(),
        "os": os_name(),
        "open3d": o3d.__version__, "numpy": np.__version__, "python": platform.python_version(),
        "embree": revolve.embree_version, "rays": args.rays, "repeats": args.repeats, "seed": args.seed,
        "threads_all": threads_all,
        # The machine's load average (1, 5, 15 minutes) before and after: other work shares its cores.
        "load_average": {"before": load_before, "after": os.getloadavg()},
        "results": results,
    }


def cpu_name():
    try:
        with open("/proc/cpuinfo") as info:
            return next(line.split(":", 1)[1].strip() for line in info if line.startswith("model name"))
    except (OSError, StopIteration):
        return platform.machine()


def os_name():
    try:
        with open("/etc/os-release") as release:
            return next(line.split("=", 1)[1].strip().strip('"') for line in release if line.startswith("PRETTY_NAME"))
    except (OSError, StopIteration):
        return platform.platform()


HEADER = ("shape    budget | Open3D mesh              Mrays/s 1  all   max err | revolve   Mrays/s 1  all   max err | speed-up 1  all"
          " | memory Open3D revolve")


def line_of(r):
    o, v = r["open3d"], r["revolve"]
    mesh = f"{o['profile_points']}x{o['slices']} ({o['triangles'] / 1e3:.0f}k tri)"
    return (f"{r['shape']:8s} {r['tolerance']:.0e} | {mesh:22s} {o['mrays_1']:9.2f} {o['mrays_all']:5.2f} {o['max_error']:9.1e} | "
            f"{v['profile_points']:5d} pts {v['mrays_1']:9.2f} {v['mrays_all']:5.2f} {v['max_error']:9.1e} | "
            f"{r['speedup_1']:9.2f}x {r['speedup_all']:4.2f}x | {o['memory_bytes'] / 2**20:8.1f} MB {v['memory_bytes'] / 2**10:6.1f} KB")


def markdown(report):
    """docs/python.md's table of a results file."""
    lines = ["| shape | budget | Open3D: mesh | Mrays/s, 1 / all threads | max error | revolve: polyline | Mrays/s, 1 / all threads "
             "| max error | speed-up, 1 / all threads | memory, Open3D's mesh / revolve |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in report["results"]:
        o, v = r["open3d"], r["revolve"]
        lines.append(f"| {r['shape']} | {r['tolerance']:.0e} | {o['profile_points']} × {o['slices']} ({o['triangles'] / 1e3:.0f}k triangles) "
                     f"| {o['mrays_1']:.2f} / {o['mrays_all']:.2f} | {o['max_error']:.1e} | {v['profile_points']} points "
                     f"| {v['mrays_1']:.2f} / {v['mrays_all']:.2f} | {v['max_error']:.1e} | **{r['speedup_1']:.2f}×** / {r['speedup_all']:.2f}× "
                     f"| {o['memory_bytes'] / 2**20:.1f} MB / {v['memory_bytes'] / 2**10:.0f} KB |")
    return "\n".join(lines)


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--markdown":
        with open(sys.argv[2]) as f:
            print(markdown(json.load(f)))
        return
    if len(sys.argv) == 4 and sys.argv[1] == "--memory":
        measure_memory(sys.argv[2], float(sys.argv[3]))
        return
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rays", type=int, default=400_000, help="incoherent rays a shape (default 400000)")
    parser.add_argument("--repeats", type=int, default=5, help="timed casts a configuration and thread count (default 5)")
    parser.add_argument("--seed", type=int, default=2001, help="the rays' seed (default 2001)")
    parser.add_argument("--shapes", type=lambda s: s.split(","), default=[make().name for make in smooth_shapes.SHAPES])
    parser.add_argument("--tolerances", type=lambda s: [float(x) for x in s.split(",")], default=list(TOLERANCES))
    parser.add_argument("--json", help="write the results here")
    args = parser.parse_args()
    print(HEADER, flush=True)
    report = run(args)
    if args.json:
        with open(args.json, "w") as out:
            json.dump(report, out, indent=1)
            out.write("\n")


if __name__ == "__main__":
    main()
