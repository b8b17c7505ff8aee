#!/usr/bin/env python3
"""Rays beyond memory: the depth images of many cameras around a scene, cast on a Dask cluster as a
Dask array of rays, chunk by chunk, against the scene sent once to every worker.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/dask_rays.py [SCENE] [--cameras K]
        [--width W] [--height H] [--workers N | --scheduler ADDRESS] [-o out/depths]

K pinhole cameras stand on a circle about the scene's camera target, each a chunk of W x H rays (a
(W H, 6) block of float32 origins and directions, made on the worker that casts it, never on the
client). `rays.map_blocks(cast, scene)` turns the Dask array of rays into a Dask array of depths
(t_hit) against the revolve.RaycastingScene the script loads from SCENE and scatters once to every
worker (a scene pickles as what builds it, so no worker reads a file). Then either a summary (the
fraction of rays that hit, the mean depth of the hits) computed as reductions, so that only numbers
come back, or with -o the depth images written chunk by chunk as a stack of .npy files
(dask.array.to_npy_stack: OUT/0.npy is camera 0, W x H float32, inf where nothing is hit). Memory,
on the client and on each worker, is a few chunks at a time whatever K is.
"""

import argparse
import math
import pathlib
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]


def camera_rays(block_id, cameras, width, height, target, radius, height_above):
    """The rays of camera block_id[0] (one chunk: width x height rows of ox, oy, oz, dx, dy, dz),
    a pinhole on a circle of `radius` about `target`, `height_above` it, looking at it."""
    import revolve

    k = block_id[0]
    angle = 2 * math.pi * k / cameras
    eye = [target[0] + radius * math.cos(angle), target[1] + radius * math.sin(angle), target[2] + height_above]
    # Open3D's pinhole takes `up` as the direction image rows run in (row 0 first): -z, so that row
    # 0 is the top of an upright image.
    rays = revolve.RaycastingScene.create_rays_pinhole(fov_deg=60, center=target, eye=eye, up=[0, 0, -1],
                                                       width_px=width, height_px=height)
    return np.asarray(rays, np.float32).reshape(-1, 6)


def cast(rays, scene):
    """The depths of one chunk of rays: t_hit, inf where nothing is hit."""
    return scene.cast_rays(np.ascontiguousarray(rays, dtype=np.float32))["t_hit"]


def depth_array(scene_on_workers, cameras, width, height, target, radius, height_above):
    """The Dask array of depths (cameras x width x height,), one chunk a camera, from rays made on
    the workers."""
    import dask.array as da

    per_camera = width * height
    rays = da.map_blocks(lambda block_id=None: camera_rays(block_id, cameras, width, height, target, radius,
                                                           height_above),
                         chunks=((per_camera,) * cameras, (6,)), dtype=np.float32)
    return rays.map_blocks(cast, scene_on_workers, drop_axis=1, dtype=np.float32)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", nargs="?", default=ROOT / "scenes" / "patio.json", help="a scene file (default the patio)")
    parser.add_argument("--cameras", type=int, default=64, help="cameras on the circle, one chunk each (default 64)")
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=480)
    parser.add_argument("--workers", type=int, default=2, help="worker processes of a LocalCluster (default 2)")
    parser.add_argument("--scheduler", help="a running Dask scheduler's address instead of a LocalCluster")
    parser.add_argument("-o", "--output", help="a folder for the depth images (an .npy stack); default: a summary only")
    args = parser.parse_args()
    for name in ("cameras", "width", "height", "workers"):
        if getattr(args, name) < 1:
            parser.error(f"--{name} {getattr(args, name)}: must be at least 1")

    try:
        import dask.array as da
        from distributed import Client, LocalCluster
    except ImportError as error:
        print(f"{sys.argv[0]}: needs Dask distributed (Debian: python3-distributed): {error}", file=sys.stderr)
        return 1
    import json

    import revolve

    scene = revolve.RaycastingScene()
    scene.load(str(args.scene))
    camera = json.loads(pathlib.Path(args.scene).read_text())["camera"]
    target = [float(v) for v in camera["to"]]
    eye = [float(v) for v in camera["from"]]
    radius = math.hypot(eye[0] - target[0], eye[1] - target[1])
    height_above = eye[2] - target[2]

    cluster = None if args.scheduler else LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True)
    with Client(args.scheduler or cluster) as client:
        start = time.perf_counter()
        scene_on_workers = client.scatter(scene, broadcast=True, hash=False)
        depths = depth_array(scene_on_workers, args.cameras, args.width, args.height, target, radius, height_above)
        if args.output:
            out = pathlib.Path(args.output)
            out.mkdir(parents=True, exist_ok=True)
            da.to_npy_stack(out, depths.reshape(args.cameras, args.height, args.width), axis=0)
            summary = f"{out}/0.npy ... {args.cameras - 1}.npy"
        else:
            hit = da.isfinite(depths)
            fraction, mean = da.compute(hit.mean(), da.where(hit, depths, 0).sum() / hit.sum())
            summary = f"{fraction:.1%} of the rays hit, mean depth {mean:.3f}"
        seconds = time.perf_counter() - start
        rays = args.cameras * args.width * args.height
        print(f"{rays:,} rays ({args.cameras} cameras of {args.width} x {args.height}) in {seconds:.2f} s, "
              f"{rays / seconds / 1e6:.2f} Mrays/s on {len(client.scheduler_info()['workers'])} workers: {summary}")
    if cluster is not None:
        cluster.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
