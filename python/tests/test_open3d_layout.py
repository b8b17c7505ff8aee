"""revolve.RaycastingScene beside Open3D's own RaycastingScene (python3-open3d) on the same mesh and
rays: the same result keys, shapes and dtypes, and, where Open3D can cast rays, the same values;
pinhole rays and closest points compared likewise. Debian 12's Open3D 0.16.1 casts no rays at all
(every t_hit is inf, even on a box), so the comparisons of ray-cast values skip there, saying so."""

import math

import numpy as np
import pytest

import revolve
from closed_forms import semicircle

o3d = pytest.importorskip("open3d", reason="Open3D (Debian: python3-open3d) is not installed")
Open3DScene = o3d.t.geometry.RaycastingScene


def open3d_casts_rays():
    scene = Open3DScene()
    scene.add_triangles(o3d.t.geometry.TriangleMesh.from_legacy(o3d.geometry.TriangleMesh.create_box()))
    rays = o3d.core.Tensor([[0.5, 0.5, 3, 0, 0, -1]], dtype=o3d.core.Dtype.Float32)
    return bool(np.isfinite(scene.cast_rays(rays)["t_hit"].numpy()).all())


CASTS = open3d_casts_rays()
needs_casting = pytest.mark.skipif(
    not CASTS, reason=f"Open3D {o3d.__version__} casts no rays here (every t_hit inf on a box): nothing to compare values with"
)


def as_numpy(result):
    return {k: v.numpy() for k, v in result.items()} if isinstance(result, dict) else result.numpy()


@pytest.fixture(scope="module")
def both():
    """The same sphere mesh in Open3D's scene and in revolve's, and pinhole rays at it."""
    legacy = o3d.geometry.TriangleMesh.create_sphere(radius=1.0, resolution=24)
    vertices = np.asarray(legacy.vertices, dtype=np.float32)
    triangles = np.asarray(legacy.triangles, dtype=np.uint32)
    theirs = Open3DScene()
    theirs.add_triangles(o3d.core.Tensor(vertices), o3d.core.Tensor(triangles))
    ours = revolve.RaycastingScene()
    ours.add_triangles(vertices, triangles)
    rays = revolve.RaycastingScene.create_rays_pinhole(fov_deg=60, center=[0, 0, 0], eye=[0.3, -3, 0.8], up=[0, 0, 1], width_px=40, height_px=30)
    return theirs, ours, rays


def test_invalid_id_is_open3ds():
    assert revolve.RaycastingScene.INVALID_ID == Open3DScene.INVALID_ID


def test_results_have_open3ds_keys_shapes_and_dtypes(both):
    theirs, ours, rays = both
    points = np.random.default_rng(3).uniform(-2, 2, size=(5, 7, 3)).astype(np.float32)
    for method, arg in (("cast_rays", rays), ("test_occlusions", rays), ("count_intersections", rays),
                        ("compute_closest_points", points), ("compute_distance", points)):
        expected = as_numpy(getattr(theirs, method)(o3d.core.Tensor(arg)))
        got = getattr(ours, method)(arg)
        if isinstance(expected, dict):
            # Open3D 0.19's keys; older versions have fewer (0.16's closest points: no uvs, normals).
            assert set(expected) <= set(got), method
            if o3d.__version__ >= "0.19":
                assert set(expected) == set(got), method
            for key in expected:
                assert (got[key].shape, got[key].dtype) == (expected[key].shape, expected[key].dtype), (method, key)
        else:
            assert (got.shape, got.dtype) == (expected.shape, expected.dtype), method
    # Signed distance and occupancy: revolve answers them for closed profiles, Open3D for meshes.
    solid = revolve.RaycastingScene()
    solid.add_revolution(semicircle(1.0, 24))
    for method in ("compute_signed_distance", "compute_occupancy"):
        expected = getattr(theirs, method)(o3d.core.Tensor(points)).numpy()
        got = getattr(solid, method)(points)
        assert (got.shape, got.dtype) == (expected.shape, expected.dtype), method


def test_pinhole_rays_are_open3ds():
    intrinsic = np.array([[300.0, 0, 160], [0, 310, 119.5], [0, 0, 1]])
    extrinsic = np.eye(4)
    extrinsic[:3, :3] = np.array([[0.36, 0.48, -0.8], [-0.8, 0.6, 0], [0.48, 0.64, 0.6]])
    extrinsic[:3, 3] = [0.5, -1, 4]
    cases = [
        ((intrinsic, extrinsic, 32, 24), {}),
        ((), dict(fov_deg=75, center=[0, 0, 0.5], eye=[2, 3, 4], up=[0, 0, 1], width_px=33, height_px=17)),
    ]
    for args, kwargs in cases:
        ours = revolve.RaycastingScene.create_rays_pinhole(*args, **kwargs)
        o3d_args = [o3d.core.Tensor(a) if isinstance(a, np.ndarray) else a for a in args]
        o3d_kwargs = {k: (o3d.core.Tensor(np.asarray(v, np.float64)) if isinstance(v, list) else v) for k, v in kwargs.items()}
        theirs = Open3DScene.create_rays_pinhole(*o3d_args, **o3d_kwargs).numpy()
        assert ours.shape == theirs.shape and ours.dtype == theirs.dtype == np.float32
        # The same construction in float: equal up to the order of the last additions (a few ulps).
        assert np.allclose(ours, theirs, rtol=4 * 2.0**-23, atol=1e-6)


@needs_casting
def test_cast_rays_values_are_open3ds(both):
    theirs, ours, rays = both
    expected = as_numpy(theirs.cast_rays(o3d.core.Tensor(rays)))
    got = ours.cast_rays(rays)
    hit = np.isfinite(expected["t_hit"])
    assert hit.sum() > 300 and (~hit).sum() > 100
    assert np.array_equal(np.isfinite(got["t_hit"]), hit)
    assert np.allclose(got["t_hit"][hit], expected["t_hit"][hit], rtol=1e-6)
    assert np.array_equal(got["geometry_ids"], expected["geometry_ids"])
    # Away from triangle edges (where either neighbour may answer), the same triangle, barycentrics and normal.
    u, v = expected["primitive_uvs"][..., 0], expected["primitive_uvs"][..., 1]
    inside = hit & (u > 1e-4) & (v > 1e-4) & (1 - u - v > 1e-4)
    assert np.array_equal(got["primitive_ids"][inside], expected["primitive_ids"][inside])
    assert np.allclose(got["primitive_uvs"][inside], expected["primitive_uvs"][inside], atol=1e-5)
    assert np.allclose(got["primitive_normals"][hit], expected["primitive_normals"][hit], atol=1e-6)
    assert np.array_equal(got["primitive_ids"][~hit], expected["primitive_ids"][~hit])
    assert np.array_equal(got["primitive_normals"][~hit], expected["primitive_normals"][~hit])
    assert np.array_equal(ours.count_intersections(rays), theirs.count_intersections(o3d.core.Tensor(rays)).numpy())
    assert np.array_equal(ours.test_occlusions(rays), theirs.test_occlusions(o3d.core.Tensor(rays)).numpy())


def test_closest_points_are_open3ds(both):
    theirs, ours, _ = both
    points = np.random.default_rng(4).uniform(-2, 2, size=(2000, 3)).astype(np.float32)
    expected = as_numpy(theirs.compute_closest_points(o3d.core.Tensor(points)))
    got = ours.compute_closest_points(points)
    # As near as Open3D's; the same point on the same triangle (elsewhere, a tie between two).
    near = np.linalg.norm(got["points"] - points, axis=1)
    assert np.allclose(near, np.linalg.norm(expected["points"] - points, axis=1), atol=1e-6)
    same = got["primitive_ids"] == expected["primitive_ids"]
    assert same.mean() > 0.95
    assert np.allclose(got["points"][same], expected["points"][same], atol=1e-6)
    assert np.array_equal(got["geometry_ids"], expected["geometry_ids"])
    assert np.allclose(ours.compute_distance(points), theirs.compute_distance(o3d.core.Tensor(points)).numpy(), atol=2e-6)
    if "primitive_normals" in expected:
        assert np.allclose(got["primitive_normals"][same], expected["primitive_normals"][same], atol=1e-5)
        assert np.allclose(got["primitive_uvs"][same], expected["primitive_uvs"][same], atol=1e-4)


@needs_casting
def test_inside_agrees_with_open3ds_vote_on_a_fine_mesh_away_from_the_surface():
    """Occupancy and signed distance of a torus decided from its profile, against Open3D's ray votes
    on the same torus tessellated finely, for points farther from the surface than the mesh's error."""
    profile = np.stack([0.35 + 0.15 * np.cos(np.linspace(0, 2 * np.pi, 129)), 0.15 * np.sin(np.linspace(0, 2 * np.pi, 129))], axis=1)
    profile[-1] = profile[0]
    ours = revolve.RaycastingScene()
    ours.add_revolution(profile)
    vertices, triangles = revolve.tessellate(profile, 256)
    theirs = Open3DScene()
    theirs.add_triangles(o3d.core.Tensor(vertices), o3d.core.Tensor(triangles))
    points = np.random.default_rng(5).uniform([-0.6, -0.6, -0.25], [0.6, 0.6, 0.25], size=(4000, 3)).astype(np.float32)
    signed = ours.compute_signed_distance(points)
    mesh_error = 0.5 * (1 - math.cos(math.pi / 256)) + 1e-6
    clear = np.abs(signed) > 10 * mesh_error
    assert clear.sum() > 3000
    assert np.array_equal(ours.compute_occupancy(points)[clear], theirs.compute_occupancy(o3d.core.Tensor(points)).numpy()[clear])
    assert np.allclose(signed[clear], theirs.compute_signed_distance(o3d.core.Tensor(points)).numpy()[clear], atol=mesh_error)
