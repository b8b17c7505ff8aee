#!/usr/bin/python3
"""revolve.RaycastingScene with many distinct objects: N 64-point polylines (vases of random waves,
on a grid) added one call each (add_revolution) or in one call (add_revolutions); the time to add
them, the time to the first ray (the scene is committed then), memory_bytes() and the peak resident
memory. One way and one N a process (its peak is its own).

    PYTHONPATH=BUILD/python bench/python/scale_python.py 100000 bulk
    PYTHONPATH=BUILD/python bench/python/scale_python.py 100000 each
"""
import json
import resource
import sys
import time

import numpy as np

import revolve


def profiles(count, seed=20011):
    rng = np.random.default_rng(seed)
    z = np.linspace(0.0, 1.0, 63)
    base, amplitude, frequency, phase = (rng.uniform(lo, hi, (count, 1)) for lo, hi in
                                         ((0.2, 0.35), (0.0, 0.35), (0.5, 2.5), (0.0, 1.0)))
    r = np.maximum(0.05, base * (1 + amplitude * np.sin(2 * np.pi * (frequency * z + phase))))
    points = np.zeros((count, 64, 2))
    points[:, 1:, 0] = r
    points[:, 1:, 1] = z
    return points


def main(count, way):
    points = profiles(count)
    side = int(np.ceil(np.sqrt(count)))
    transforms = np.tile(np.eye(4), (count, 1, 1))
    transforms[:, 0, 3] = 1.25 * (np.arange(count) % side)
    transforms[:, 1, 3] = 1.25 * (np.arange(count) // side)
    scene = revolve.RaycastingScene()
    start = time.perf_counter()
    if way == "bulk":
        scene.add_revolutions(points, transforms)
    else:
        for i in range(count):
            scene.add_revolution(points[i], transform=transforms[i])
    added = time.perf_counter() - start
    ray = np.array([[-1.0, 0.0, 0.5, 1, 0, 0]], np.float32)  # along the first row: object 0 first
    hit = scene.cast_rays(ray)
    first = time.perf_counter() - start
    record = dict(objects=count, way=way, add_seconds=added, first_ray_seconds=first,
                  memory_bytes=scene.memory_bytes(), memory_bytes_per_object=scene.memory_bytes() / count,
                  peak_resident_bytes=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024,
                  first_hit_id=int(hit["geometry_ids"][0]))
    print(json.dumps(record))


if __name__ == "__main__":
    main(int(sys.argv[1]), sys.argv[2])
