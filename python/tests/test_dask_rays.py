"""Rays beyond memory (docs/python.md, "Dask"): a Dask array of rays, chunks of (n, 6), cast through
map_blocks on a two-worker LocalCluster against a RaycastingScene scattered once to the workers,
equal bit for bit to one cast_rays call on the same rays; examples/python/dask_rays.py's depth
images equal to its cameras' rays cast in this process; and the client's memory flat while four
times as many chunks flow through it (only reductions come back)."""

import importlib.util
import json
import math
import sys

import numpy as np
import pytest

from closed_forms import SEED, incoherent_rays, semicircle
from conftest import SOURCE_DIR
from isolated import child_env, how_it_ended, run_python

distributed = pytest.importorskip("distributed", reason="Dask distributed (Debian: python3-distributed) is not installed")
da = pytest.importorskip("dask.array")

import revolve  # noqa: E402

EXAMPLE = SOURCE_DIR / "examples" / "python" / "dask_rays.py"


def cast(rays, scene, key):
    return scene.cast_rays(np.ascontiguousarray(rays, dtype=np.float32))[key]


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0")
    with distributed.Client(cluster) as c:
        yield c
    cluster.close()


def test_a_dask_array_of_rays_casts_as_one_call(client):
    scene = revolve.RaycastingScene()
    scene.add_revolution(semicircle(0.5, 48))
    scene.add_triangles(np.array([[-3, -3, -0.6], [3, -3, -0.6], [3, 3, -0.6], [-3, 3, -0.6]], np.float32),
                        np.array([[0, 1, 2], [0, 2, 3]], np.uint32))
    rays = incoherent_rays(np.random.default_rng(SEED), 50_000, (0, 0, 0), 1.0, (-1, -1, -1), (1, 1, 1))
    expected = scene.cast_rays(rays)
    on_workers = client.scatter(scene, broadcast=True, hash=False)
    lazy = da.from_array(rays, chunks=(7_000, 6))  # uneven: the last chunk is shorter
    for key in ("t_hit", "geometry_ids", "primitive_ids"):
        got = lazy.map_blocks(cast, on_workers, key, drop_axis=1, dtype=expected[key].dtype).compute()
        np.testing.assert_array_equal(got, expected[key], err_msg=key)
    for key in ("primitive_uvs", "primitive_normals"):
        got = lazy.map_blocks(cast, on_workers, key, dtype=expected[key].dtype,
                              chunks=(lazy.chunks[0], (expected[key].shape[1],))).compute()
        np.testing.assert_array_equal(got, expected[key], err_msg=key)
    assert np.isfinite(expected["t_hit"]).sum() > 10_000


def load_example():
    spec = importlib.util.spec_from_file_location("dask_rays", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_example_writes_each_cameras_depths(tmp_path):
    out = tmp_path / "depths"
    done = run_python(EXAMPLE, "--cameras", "3", "--width", "40", "--height", "30", "--workers", "2", "-o",
                      str(out), env=child_env())
    assert done.returncode == 0, how_it_ended(done)
    assert "3,600 rays (3 cameras of 40 x 30)" in done.stdout
    example = load_example()
    patio = SOURCE_DIR / "scenes" / "patio.json"
    camera = json.loads(patio.read_text())["camera"]
    target, eye = camera["to"], camera["from"]
    scene = revolve.RaycastingScene()
    scene.load(str(patio))
    for k in range(3):
        rays = example.camera_rays((k,), 3, 40, 30, target, math.hypot(eye[0] - target[0], eye[1] - target[1]),
                                   eye[2] - target[2])
        expected = scene.cast_rays(rays)["t_hit"].reshape(30, 40)
        np.testing.assert_array_equal(np.load(out / f"{k}.npy"), expected[None])  # a stack: (1, H, W) a camera
        # Upright: the ground near the camera in the bottom row, the top row farther (a wall) or sky.
        assert np.isfinite(expected[-1]).all() and np.all(expected[0] > expected[-1].max())


MEMORY_CHILD = r"""
import sys, numpy as np, distributed, dask.array as da, revolve
sys.path.insert(0, sys.argv[1])
from closed_forms import semicircle

def resident():
    with open("/proc/self/status") as status:
        return next(int(line.split()[1]) * 1024 for line in status if line.startswith("VmRSS:"))

def rays_block(block_id=None):
    rng = np.random.default_rng(block_id[0])
    o = rng.uniform(-2, 2, (100_000, 3))
    return np.concatenate([o, -o + rng.uniform(-0.3, 0.3, (100_000, 3))], 1).astype(np.float32)

def cast(rays, scene):
    return scene.cast_rays(rays)["t_hit"]

if __name__ == "__main__":
    scene = revolve.RaycastingScene()
    scene.add_revolution(semicircle(0.5, 48))
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster, \
            distributed.Client(cluster) as client:
        on_workers = client.scatter(scene, broadcast=True, hash=False)
        def hits(chunks):
            rays = da.map_blocks(rays_block, chunks=((100_000,) * chunks, (6,)), dtype=np.float32)
            t = rays.map_blocks(cast, on_workers, drop_axis=1, dtype=np.float32)
            return int(da.isfinite(t).sum().compute())
        hits(10)
        before = resident()
        a = hits(10)
        after_few = resident()
        b = hits(40)
        after_many = resident()
        print(a, b, before, after_few, after_many)
"""


def test_the_clients_memory_stays_flat_while_chunks_flow():
    # 40 chunks of 100,000 rays are 96 MB of rays and 16 MB of depths: held by the client, its resident
    # size would grow by that; 16 MiB is a sixth of it, above the scheduler's own bookkeeping of the
    # extra tasks (a few KB each).
    done = run_python(MEMORY_CHILD, str(SOURCE_DIR / "python" / "tests"), env=child_env())
    assert done.returncode == 0, how_it_ended(done)
    a, b, before, after_few, after_many = (int(v) for v in done.stdout.split()[-5:])
    assert a > 0 and b > 3 * a, "the rays hit the sphere"
    assert after_many - after_few < 16 * 2**20, f"the client grew by {(after_many - after_few) / 2**20:.1f} MiB"
