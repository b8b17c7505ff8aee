#!/usr/bin/python3
"""How long a RaycastingScene holding one grid mesh takes to pickle and unpickle, at 10^4, 10^5 and
10^6 vertices (docs/python.md, "Pickling and copies"): the best of 5 of pickle.dumps at protocol 5
(in band, and with a buffer_callback: the arrays out of band) and of pickle.loads.

    PYTHONPATH=build/python /usr/bin/python3 bench/python/pickle_mesh.py
"""

import os
import pickle
import time

import numpy as np

import revolve


def grid_mesh(side):
    """A side x side grid of vertices over [-10, 10]^2, gently curved: 2 (side - 1)^2 triangles."""
    x, y = np.meshgrid(np.linspace(-10, 10, side), np.linspace(-10, 10, side))
    vertices = np.stack([x.ravel(), y.ravel(), 0.1 * np.sin(x.ravel()) * np.cos(y.ravel())], 1).astype(np.float32)
    index = np.arange(side * side, dtype=np.uint32).reshape(side, side)
    a, b, c, d = index[:-1, :-1].ravel(), index[:-1, 1:].ravel(), index[1:, 1:].ravel(), index[1:, :-1].ravel()
    return vertices, np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])


def main():
    print(f"load average {os.getloadavg()[0]:.1f}")
    for side in (100, 316, 1000):
        vertices, triangles = grid_mesh(side)
        scene = revolve.RaycastingScene()
        scene.add_triangles(vertices, triangles)
        best = {"dumps": np.inf, "dumps, out of band": np.inf, "loads": np.inf}
        for _ in range(5):
            start = time.perf_counter()
            payload = pickle.dumps(scene, protocol=5)
            middle = time.perf_counter()
            buffers = []
            pickle.dumps(scene, protocol=5, buffer_callback=buffers.append)
            dumped = time.perf_counter()
            pickle.loads(payload)
            loaded = time.perf_counter()
            for key, seconds in (("dumps", middle - start), ("dumps, out of band", dumped - middle), ("loads", loaded - dumped)):
                best[key] = min(best[key], seconds)
        sizes = f"{len(vertices):,} vertices, {len(triangles):,} triangles ({(vertices.nbytes + triangles.nbytes) / 1e6:.1f} MB)"
        print(sizes + ": " + ", ".join(f"{key} {seconds * 1e3:.1f} ms" for key, seconds in best.items()))


if __name__ == "__main__":
    main()
