#!/usr/bin/env python3
"""Simulated lidar scans of many robot poses, sharded over a Dask distributed cluster and written as
one PCD (or CSV) byte for byte what revolve-lidar writes on the same input.

    PYTHONPATH=build/python python3 examples/python/dask_lidar.py SCENE SENSOR POSES -o OUT.pcd \\
        [--scheduler ADDRESS [--wait-for-workers SECONDS]] [--workers N] [--shard-size K] [--pcd-data ascii|binary]

The poses are split into shards of K; each shard is traced on a worker (revolve.Lidar, the code
revolve-lidar runs, with the shard's first pose number so that every beam draws its own noise) and
the shards come back in pose order into a revolve.ScanFile, which writes a temporary beside OUT and
renames it into place when every pose is in: the output is whole or absent. At most two shards a
worker are in flight, so memory does not grow with the number of poses. A worker that dies takes its
shard with it; Dask's scheduler gives the shard to another worker (and `retries` covers a shard that
raises), and since a shard is written only once it is back, in order, nothing is lost or written twice.

The scene and sensor are built here and sent once to every worker (client.scatter with broadcast: a
revolve.Scene pickles as its file's text and its profile CSVs' texts, a Lidar as its JSON and beam
pattern), so a worker reads no file: it needs only to import revolve (built for its Python and
machine). The poses travel with the shards. Without --scheduler a LocalCluster of N worker processes
runs here; with one, a scheduler started by `dask scheduler` and workers by `dask worker ADDRESS`. A
scheduler with no worker yet is
waited on for --wait-for-workers seconds (default 60; 0: not at all; inf: for ever), saying so on
stderr; if none has joined by then, the script says so and exits with status 1, writing nothing.
"""

import argparse
import math
import os
import sys
import time
from collections import deque

import revolve


def scan_to_file(client, scene, sensor, poses, output, shard_size, data="ascii", threads=1, retries=3, inputs=(), trace=revolve.scan_shard):
    """Traces `poses` (an (N, 4) array, or (N, 5) with times, as Lidar.scan takes them) shard by shard on `client`'s workers and writes `output`,
    which may not be the scene, the sensor or one of `inputs`. `scene` and `sensor` are files' paths
    (or a revolve.Scene and a revolve.Lidar), built here and sent once to every worker, which then
    needs no file. `trace(scene, lidar, poses, first_pose, threads, sweeps=...)` runs a shard on a
    worker (revolve.scan_shard)."""
    files = [os.path.abspath(path) for path in (scene, sensor) if not isinstance(path, (revolve.Scene, revolve.Lidar))]
    built = scene if isinstance(scene, revolve.Scene) else revolve.Scene(scene)  # a bad input fails before any work
    lidar = sensor if isinstance(sensor, revolve.Lidar) else revolve.Lidar(sensor)
    output = os.path.abspath(output)
    scan_file = revolve.ScanFile(output, lidar, len(poses), data=data, inputs=[*files, *inputs])
    # Once to every worker, as pickles holding the files' texts; a worker that joins later, or
    # replaces a dead one, fetches them from another.
    scene_on_workers, lidar_on_workers = client.scatter([built, lidar], broadcast=True, hash=False)
    shards = deque((first, min(shard_size, len(poses) - first)) for first in range(0, len(poses), shard_size))
    in_flight = deque()
    window = 2 * max(1, len(client.scheduler_info()["workers"]))

    def submit():
        first, count = shards.popleft()
        shard = revolve.shard_poses(poses, first, count, lidar)
        future = client.submit(trace, scene_on_workers, lidar_on_workers, shard, first, threads, sweeps=count,
                               retries=retries, pure=False)
        in_flight.append((first, future))

    while shards and len(in_flight) < window:
        submit()
    while in_flight:
        first, future = in_flight.popleft()
        scan_file.write(first, future.result())
        del future  # its result leaves the cluster's memory
        if shards:
            submit()
    scan_file.commit()


def wait_for_a_worker(client, address, seconds):
    """Returns once the scheduler at `address` has a worker; says on stderr that it waits when it has
    none, and exits (status 1, with a message) if none joins within `seconds` (inf: for ever)."""
    if client.scheduler_info()["workers"]:
        return
    if seconds == 0:
        sys.exit(f"dask_lidar: the scheduler at {address} has no workers (--wait-for-workers 0: not waiting); "
                 f"start some with `dask worker {address}`")
    limit = "" if math.isinf(seconds) else f" for up to {seconds:g} s"
    print(f"dask_lidar: the scheduler at {address} has no workers yet; waiting for one{limit} (--wait-for-workers)",
          file=sys.stderr, flush=True)
    try:
        client.wait_for_workers(1, timeout=None if math.isinf(seconds) else seconds)
    except TimeoutError:
        sys.exit(f"dask_lidar: no worker joined the scheduler at {address} within {seconds:g} s; start some with "
                 f"`dask worker {address}`, or wait longer with --wait-for-workers SECONDS")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene", help="scene file (JSON, revolve-render's format)")
    parser.add_argument("sensor", help="sensor file (JSON, revolve-lidar's --sensor)")
    parser.add_argument("poses", help="robot poses (CSV, revolve-lidar's --poses)")
    parser.add_argument("-o", "--output", required=True, help="scan to write: .pcd or .csv")
    parser.add_argument("--scheduler", help="address of a running Dask scheduler (default: a LocalCluster here)")
    parser.add_argument("--wait-for-workers", type=float, default=60, metavar="SECONDS",
                        help="with --scheduler: how long to wait for a first worker when it has none (default 60; "
                             "0: not at all; inf: for ever); then exit 1")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (default 2)")
    parser.add_argument("--shard-size", type=int, default=64, help="poses a shard (default 64)")
    parser.add_argument("--threads-per-worker", type=int, default=1, help="tracing threads a worker (default 1)")
    parser.add_argument("--pcd-data", choices=("ascii", "binary"), default="ascii", help="a .pcd output's DATA")
    args = parser.parse_args(argv)
    if args.workers < 1 or args.shard_size < 1 or args.threads_per_worker < 1:
        parser.error("--workers, --shard-size and --threads-per-worker take whole numbers >= 1")
    if args.threads_per_worker > 1024:
        parser.error(f"--threads-per-worker {args.threads_per_worker}: at most 1024, as every tool's --threads")
    if not args.wait_for_workers >= 0:
        parser.error(f"--wait-for-workers {args.wait_for_workers:g}: takes seconds >= 0 (inf: wait for ever)")

    from distributed import Client, LocalCluster

    poses = revolve.read_poses(args.poses)
    start = time.perf_counter()
    if args.scheduler:
        client, cluster = Client(args.scheduler), None
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=":0")
        client = Client(cluster)
    try:
        if args.scheduler:
            wait_for_a_worker(client, args.scheduler, args.wait_for_workers)
        ready = time.perf_counter()
        scan_to_file(client, args.scene, args.sensor, poses, args.output, args.shard_size, args.pcd_data, args.threads_per_worker,
                     inputs=[args.poses])
        done = time.perf_counter()
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    workers = "the scheduler's workers" if args.scheduler else f"{args.workers} worker{'s' if args.workers > 1 else ''}"
    print(f"dask_lidar: {len(poses)} poses in shards of {args.shard_size} on {workers}: {done - ready:.3g} s tracing and writing "
          f"({len(poses) / (done - ready):.4g} scans/s), {ready - start:.3g} s starting the cluster; wrote {args.output}")


if __name__ == "__main__":
    main()
