"""RaycastingScene.list_intersections (Open3D 0.19's keys, dtypes and ray_splits) against every
crossing of the surface computed here in long double from the profile (numpy, nothing of revolve):
a cup's four walls, a polyline sphere's two crossings on random rays, a tangent ray touching a wall,
meshes (an edge shared by two triangles crossed once), and Open3D's own list_intersections on a mesh
where Open3D has it; its counts are always count_intersections'."""

import numpy as np
import pytest

import revolve
from closed_forms import SEED, incoherent_rays, semicircle

# A cup: outer wall r = 1 from z = 0 to 1, a rim to r = 0.9, the inner wall down to z = 0.1 and the
# inner floor to the axis (listed from the outside's bottom: outwards normals).
CUP = np.array([[0, 0], [1, 0], [1, 1], [0.9, 1], [0.9, 0.1], [0, 0.1]])
KEYS = {"ray_splits": np.uint32, "ray_ids": np.uint32, "geometry_ids": np.uint32, "primitive_ids": np.uint32,
        "t_hit": np.float32, "primitive_uvs": np.float32}


def crossings(rays, profile):
    """Every t >= 0 at which each ray crosses the surface swept by the polyline, in long double, with
    the segment crossed, nearest first; and how near each ray comes to a case the boundary rules
    decide (a vertex circle or a tangent touch: the smallest |discriminant| / b^2 or |z - vertex|)."""
    o = rays[:, :3].astype(np.longdouble)
    d = rays[:, 3:].astype(np.longdouble)
    found = [[] for _ in rays]
    margin = np.full(len(rays), np.inf, dtype=np.longdouble)
    for s, ((r0, z0), (r1, z1)) in enumerate(zip(profile[:-1], profile[1:])):
        r0, z0, r1, z1 = (np.longdouble(v) for v in (r0, z0, r1, z1))
        if z0 == z1:  # a disc or annulus in the plane z = z0
            with np.errstate(divide="ignore", invalid="ignore"):
                t = (z0 - o[:, 2]) / d[:, 2]
            r = np.hypot(o[:, 0] + t * d[:, 0], o[:, 1] + t * d[:, 1])
            lo, hi = min(r0, r1), max(r0, r1)
            hit = np.isfinite(t) & (t >= 0) & (r >= lo) & (r <= hi)
            margin = np.minimum(margin, np.where(np.isfinite(t) & (t >= 0), np.minimum(abs(r - lo), abs(r - hi)), np.inf))
            for i in np.flatnonzero(hit):
                found[i].append((t[i], s))
            continue
        k = (r1 - r0) / (z1 - z0)
        m = r0 - k * z0
        a = d[:, 0] ** 2 + d[:, 1] ** 2 - (k * d[:, 2]) ** 2
        b = 2 * (o[:, 0] * d[:, 0] + o[:, 1] * d[:, 1] - k * d[:, 2] * (m + k * o[:, 2]))
        c = o[:, 0] ** 2 + o[:, 1] ** 2 - (m + k * o[:, 2]) ** 2
        disc = b * b - 4 * a * c
        margin = np.minimum(margin, np.abs(disc) / (b * b + np.abs(4 * a * c)))
        root = np.sqrt(np.maximum(disc, 0))
        for sign in (-1, 1):
            with np.errstate(divide="ignore", invalid="ignore"):
                t = (-b + sign * root) / (2 * a)
            z = o[:, 2] + t * d[:, 2]
            lo, hi = min(z0, z1), max(z0, z1)
            margin = np.minimum(margin, np.where(np.isfinite(z), np.minimum(abs(z - lo), abs(z - hi)), np.inf))
            hit = (disc > 0) & np.isfinite(t) & (t >= 0) & (z >= lo) & (z <= hi) & (m + k * z >= 0)
            for i in np.flatnonzero(hit):
                found[i].append((t[i], s))
    return [sorted(f) for f in found], margin


def check_layout(got, rays_count):
    assert set(got) == set(KEYS)
    for key, dtype in KEYS.items():
        assert got[key].dtype == dtype, key
    n = int(got["ray_splits"][-1])
    assert got["ray_splits"].shape == (rays_count + 1,) and got["ray_splits"][0] == 0
    assert np.all(np.diff(got["ray_splits"].astype(np.int64)) >= 0)
    for key in ("ray_ids", "geometry_ids", "primitive_ids", "t_hit"):
        assert got[key].shape == (n,), key
    assert got["primitive_uvs"].shape == (n, 2)
    for i in range(rays_count):
        a, b = got["ray_splits"][i], got["ray_splits"][i + 1]
        assert np.all(got["ray_ids"][a:b] == i)
        assert np.all(np.diff(got["t_hit"][a:b]) >= 0), "each ray's crossings nearest first"


def test_a_cups_four_walls_and_its_floor():
    scene = revolve.RaycastingScene()
    scene.add_revolution(CUP)
    # Across the cup at half height: outer wall, inner wall, inner wall, outer wall. Straight down
    # into it: inner floor, outer floor. A miss.
    rays = np.array([[-3, 0, 0.5, 1, 0, 0], [0.2, 0.3, 2, 0, 0, -1], [5, 5, 5, 1, 0, 0]], np.float32)
    got = scene.list_intersections(rays)
    check_layout(got, 3)
    assert got["ray_splits"].tolist() == [0, 4, 6, 6]
    # Exact (3 - 0.9, ...) to within the float rounding of the result.
    np.testing.assert_array_max_ulp(got["t_hit"], np.array([2, 2.1, 3.9, 4, 1.9, 2], np.float32), maxulp=1)
    # Segments: 1 the outer wall, 3 the inner wall, 4 the inner floor, 0 the outer floor.
    assert got["primitive_ids"].tolist() == [1, 3, 3, 1, 4, 0]
    assert got["geometry_ids"].tolist() == [0] * 6
    assert got["ray_ids"].tolist() == [0, 0, 0, 0, 1, 1]
    np.testing.assert_array_equal(np.diff(got["ray_splits"]), scene.count_intersections(rays))
    # The first crossing of each ray is cast_rays' hit, with its u, v.
    cast = scene.cast_rays(rays)
    first = got["ray_splits"][:2]
    np.testing.assert_array_equal(got["t_hit"][first], cast["t_hit"][:2])
    np.testing.assert_array_equal(got["primitive_uvs"][first], cast["primitive_uvs"][:2])


def test_random_rays_through_a_sphere_and_a_cup_against_long_double_crossings():
    rng = np.random.default_rng(SEED)
    for profile in (semicircle(0.5, 48), CUP):
        scene = revolve.RaycastingScene()
        scene.add_revolution(profile)
        rays = incoherent_rays(rng, 4000, (0, 0, 0.5), 1.0, (-1, -1, -0.5), (1, 1, 1.2))
        got = scene.list_intersections(rays)
        check_layout(got, len(rays))
        expected, margin = crossings(rays, profile)
        clear = margin > 1e-6  # rays the boundary rules do not decide
        assert clear.sum() > 3500
        splits = got["ray_splits"]
        np.testing.assert_array_equal(np.diff(splits), scene.count_intersections(rays))
        several = 0
        for i in np.flatnonzero(clear):
            a, b = splits[i], splits[i + 1]
            want = expected[i]
            assert b - a == len(want), (i, rays[i], want, got["t_hit"][a:b])
            t = np.array([w[0] for w in want], dtype=np.float64)
            np.testing.assert_allclose(got["t_hit"][a:b], t, rtol=2e-6, atol=1e-7)
            assert got["primitive_ids"][a:b].tolist() == [w[1] for w in want]
            several += len(want) >= 4
        if profile is CUP:
            assert several > 100, "rays through both walls"


def test_a_tangent_ray_touches_the_wall_once():
    # A unit cylinder; a ray along y = 1 at half height touches its wall at x = 0 (a double root: the
    # boundary rules make it a touch, one crossing), then nothing.
    scene = revolve.RaycastingScene()
    scene.add_revolution([[0, 0], [1, 0], [1, 1], [0, 1]])
    rays = np.array([[-3, 1, 0.5, 1, 0, 0], [-3, 1.0001, 0.5, 1, 0, 0]], np.float32)
    got = scene.list_intersections(rays)
    check_layout(got, 2)
    assert got["ray_splits"].tolist() == [0, 1, 1]
    assert got["t_hit"].tolist() == [3.0] and got["primitive_ids"].tolist() == [1]
    np.testing.assert_array_equal(np.diff(got["ray_splits"]), scene.count_intersections(rays))


def unit_cube():
    vertices = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], np.float32)
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return vertices, np.array([t for a, b, c, d in faces for t in ((a, b, c), (a, c, d))], np.uint32)


def test_meshes_beside_revolutions_and_a_shared_edge_crossed_once():
    scene = revolve.RaycastingScene()
    cube = scene.add_triangles(*unit_cube())
    cup = scene.add_revolution(CUP, transform=np.array([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]))
    # Along x at y = z = 0.5: the cube's two faces, then the cup's four walls. Down the diagonal of
    # the cube's top face (the edge its two triangles share): crossed once on the way in and out.
    rays = np.array([[-1, 0, 0.5, 1, 0, 0], [0.3, 0.3, 2, 0, 0, -1]], np.float32)
    rays[0, 1] = 0.0
    got = scene.list_intersections(rays.reshape(1, 2, 6))  # any leading shape: rays in C order
    check_layout(got, 2)
    assert got["ray_splits"].tolist() == [0, 6, 8]
    assert got["geometry_ids"].tolist() == [cube, cube, cup, cup, cup, cup, cube, cube]
    np.testing.assert_allclose(got["t_hit"], [1, 2, 3, 3.1, 4.9, 5, 1, 2], rtol=1e-6)
    np.testing.assert_array_equal(np.diff(got["ray_splits"]), scene.count_intersections(rays).ravel())


def test_open3d_lists_the_same_crossings_on_meshes():
    o3d = pytest.importorskip("open3d")
    if not hasattr(o3d, "t") or not hasattr(o3d.t.geometry.RaycastingScene, "list_intersections"):
        pytest.skip(f"Open3D {o3d.__version__} has no list_intersections (0.19 has: Debian 13)")
    rng = np.random.default_rng(SEED)
    vertices, triangles = revolve.tessellate(CUP, 24)
    ours = revolve.RaycastingScene()
    ours.add_triangles(vertices, triangles)
    theirs = o3d.t.geometry.RaycastingScene()
    theirs.add_triangles(o3d.core.Tensor(vertices), o3d.core.Tensor(triangles))
    rays = incoherent_rays(rng, 3000, (0, 0, 0.5), 1.0, (-1, -1, -0.5), (1, 1, 1.2))
    got = ours.list_intersections(rays)
    want = {k: v.numpy() for k, v in theirs.list_intersections(o3d.core.Tensor(rays)).items()}
    assert set(got) == set(want)
    for key in want:
        assert got[key].dtype == want[key].dtype, key
    np.testing.assert_array_equal(got["ray_splits"], want["ray_splits"])
    np.testing.assert_array_equal(got["ray_ids"], want["ray_ids"])
    # Open3D leaves each ray's crossings in Embree's traversal order: sorted by t here. The values as
    # this suite compares cast_rays' with Open3D's: t to 1e-6, the same geometry, and away from
    # triangle edges (where either neighbour may answer) the same triangle and barycentrics.
    splits = want["ray_splits"]
    order = np.concatenate([np.argsort(want["t_hit"][a:b], kind="stable") + a for a, b in zip(splits[:-1], splits[1:])])
    want = {k: (v[order] if k not in ("ray_splits", "ray_ids") else v) for k, v in want.items()}
    assert len(want["t_hit"]) > 3000
    np.testing.assert_allclose(got["t_hit"], want["t_hit"], rtol=1e-6)
    np.testing.assert_array_equal(got["geometry_ids"], want["geometry_ids"])
    u, v = want["primitive_uvs"][:, 0], want["primitive_uvs"][:, 1]
    inside = (u > 1e-4) & (v > 1e-4) & (1 - u - v > 1e-4)
    assert inside.sum() > 0.9 * len(u)
    np.testing.assert_array_equal(got["primitive_ids"][inside], want["primitive_ids"][inside])
    np.testing.assert_allclose(got["primitive_uvs"][inside], want["primitive_uvs"][inside], atol=1e-5)


def test_bad_rays_name_themselves():
    scene = revolve.RaycastingScene()
    scene.add_revolution(CUP)
    with pytest.raises(ValueError, match=r"rays"):
        scene.list_intersections(np.zeros((3, 5), np.float32))
    with pytest.raises(ValueError, match=r"rays\[1\]"):
        scene.list_intersections(np.array([[0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 0, 0]], np.float32))
    with pytest.raises(ValueError, match=r"nthreads"):
        scene.list_intersections(np.zeros((1, 6), np.float32), nthreads=5000)
