"""RaycastingScene.add_revolutions: many revolutions in one call. Each object's hits against its
closed form where its matrix puts it, with its own geometry id (ids are consecutive, in the order
given); the same answers as adding them one by one; and a refused profile or matrix named by its
index, with nothing added."""

import numpy as np
import pytest

import revolve
from closed_forms import SEED, placement


def cylinders(rng, count):
    """Closed cylinders (a disc, the wall, a disc) of random radius and height, as (count, 4, 2)."""
    radius = rng.uniform(0.2, 0.9, count)
    height = rng.uniform(0.5, 2.0, count)
    zeros = np.zeros(count)
    return np.stack(
        [np.stack([zeros, zeros], 1), np.stack([radius, zeros], 1), np.stack([radius, height], 1), np.stack([zeros, height], 1)],
        axis=1,
    ), radius, height


def test_each_object_is_hit_where_its_matrix_puts_it_under_its_own_id():
    print(f"seed {SEED}")
    rng = np.random.default_rng(SEED + 40)
    count = 300
    profiles, radius, height = cylinders(rng, count)
    scale = rng.uniform(0.5, 1.5, count)
    matrices = np.stack([placement(scale[i], (0, 0, 1), 0, (3.0 * i, 0, 0)) for i in range(count)])
    scene = revolve.RaycastingScene()
    first = scene.add_revolution(np.array([[0.0, 0.0], [0.1, 0.0], [0.1, 0.1]]), transform=placement(1, (0, 0, 1), 0, (0, 50, 0)))
    ids = scene.add_revolutions(profiles, matrices)
    assert ids.dtype == np.uint32 and list(ids) == list(range(first + 1, first + 1 + count))
    # A ray along +y at mid-height towards each axis meets that cylinder's wall at y = -scale r.
    rays = np.zeros((count, 6), dtype=np.float32)
    rays[:, 0] = 3.0 * np.arange(count)
    rays[:, 1] = -10
    rays[:, 2] = 0.5 * scale * height
    rays[:, 4] = 1
    got = scene.cast_rays(rays)
    expected = 10 - scale * radius
    assert np.all(got["geometry_ids"] == ids)
    assert np.all(got["primitive_ids"] == 1)  # the wall
    assert np.allclose(got["t_hit"], expected, rtol=0, atol=1e-5)
    # The normal's azimuth comes from the hit point in float: x rounds by a float ulp of 3 i, a
    # fraction of the radius scale r; 2^-22 (3 i + 1) / (scale r) bounds the x component with room.
    tolerance = 2.0**-22 * (3.0 * np.arange(count) + 1) / (scale * radius)
    assert np.all(np.abs(got["primitive_normals"][:, 0]) <= tolerance)
    assert np.allclose(got["primitive_normals"][:, 1:], [[-1, 0]] * count, atol=1e-6)


def test_in_one_call_as_one_by_one():
    """Polylines of different lengths (a list) and splines: the same hits, ids and attributes, bit
    for bit, as add_revolution gives each."""
    rng = np.random.default_rng(SEED + 41)
    count = 40
    profiles = []
    for i in range(count):
        n = 5 + i % 7
        z = np.linspace(0, 1, n)
        profiles.append(np.stack([0.3 + 0.2 * rng.uniform(size=n), z], 1))
    matrices = np.stack([placement(1.0, (1, 0, 0), 10 * i, (2.0 * i, 1, 0)) for i in range(count)])
    rays = np.zeros((4000, 6), dtype=np.float32)
    rays[:, 0] = rng.uniform(-1, 2 * count, 4000)
    rays[:, 1] = -5
    rays[:, 2] = rng.uniform(-0.5, 1.5, 4000)
    rays[:, 3:] = [0, 1, 0]
    for spline in (None, "catmull-rom"):
        bulk, single = revolve.RaycastingScene(), revolve.RaycastingScene()
        bulk.add_revolutions(profiles, matrices, spline=spline)
        for points, matrix in zip(profiles, matrices):
            single.add_revolution(points, transform=matrix, spline=spline)
        a, b = bulk.cast_rays(rays), single.cast_rays(rays)
        assert np.isfinite(a["t_hit"]).sum() > 500  # not a comparison of misses alone
        for key in a:
            assert np.array_equal(a[key], b[key]), (spline, key)


def test_a_refused_object_is_named_by_its_index_and_nothing_is_added():
    rng = np.random.default_rng(SEED + 42)
    profiles, _, _ = cylinders(rng, 10)
    scene = revolve.RaycastingScene()
    bad = profiles.copy()
    bad[6, 2, 0] = -0.5
    with pytest.raises(revolve.ProfileError, match=r"points\[6\]: profile point 2 \(r = -0.5, z = .*\): r must be >= 0"):
        scene.add_revolutions(bad)
    assert scene.geometry_count() == 0
    matrices = np.stack([np.eye(4)] * 10)
    matrices[4, 3, 0] = 1  # not affine
    with pytest.raises(ValueError, match=r"transforms\[4\]"):
        scene.add_revolutions(profiles, matrices)
    with pytest.raises(ValueError, match=r"transforms: shape \(9, 4, 4\); expected \(10, 4, 4\)"):
        scene.add_revolutions(profiles, matrices[:9])
    with pytest.raises(ValueError, match=r"points: shape \(10, 4, 3\); expected \(N, P, 2\)"):
        scene.add_revolutions(np.zeros((10, 4, 3)))
    # Nothing was added: the next id is 0.
    assert list(scene.add_revolutions(profiles[:2])) == [0, 1]


def test_a_pickled_scene_keeps_its_bulk_added_objects_and_casts_while_others_add():
    """The bulk call's objects travel in a pickle (each keeps its recipe), and the call runs while
    other threads cast on another scene: same hits after the round trip, bit for bit."""
    import pickle
    import threading

    rng = np.random.default_rng(SEED + 42)
    count = 50
    profiles, radius, height = cylinders(rng, count)
    matrices = np.stack([placement(1.0, (0, 0, 1), 0, (3.0 * i, 0, 0)) for i in range(count)])
    rays = np.zeros((count, 6), dtype=np.float32)
    rays[:, 0] = 3.0 * np.arange(count)
    rays[:, 1] = -10
    rays[:, 2] = 0.5 * height
    rays[:, 4] = 1

    other = revolve.RaycastingScene()
    other.add_revolutions(profiles, matrices)
    before = other.cast_rays(rays)
    stop = threading.Event()
    faults = []

    def cast():
        while not stop.is_set():
            got = other.cast_rays(rays)
            if not np.array_equal(got["t_hit"], before["t_hit"]):
                faults.append("a cast during another scene's bulk add changed its answer")

    casters = [threading.Thread(target=cast) for _ in range(2)]
    for thread in casters:
        thread.start()
    try:
        scene = revolve.RaycastingScene()
        ids = scene.add_revolutions(profiles, matrices)
    finally:
        stop.set()
        for thread in casters:
            thread.join()
    assert faults == []
    first = scene.cast_rays(rays)
    assert np.all(first["geometry_ids"] == ids)
    assert np.allclose(first["t_hit"], 10 - radius, rtol=0, atol=1e-5)
    again = pickle.loads(pickle.dumps(scene)).cast_rays(rays)
    for key in ("t_hit", "geometry_ids", "primitive_ids", "primitive_uvs", "primitive_normals"):
        assert np.array_equal(again[key], first[key]), key
