"""RaycastingScene against closed forms: ray hits, normals, surface parameters, occlusion and
crossing counts, closest points, distances and inside/outside, for cylinders, cones, a paraboloid
(an exact quadratic spline), polylines inscribed in a sphere and a torus, placed or not, and a
triangle mesh beside them. The answers come from closed_forms.py, never from revolve."""

import math

import numpy as np
import pytest

import revolve
from closed_forms import (
    SEED,
    circle_loop,
    cone_hits,
    incoherent_rays,
    paraboloid_hits,
    placement,
    segment_distances,
    semicircle,
)


def rays_about(points, count, rng, spread=3.0):
    """Incoherent rays about a profile's padded box."""
    rmax, zlo, zhi = points[:, 0].max(), points[:, 1].min(), points[:, 1].max()
    lower, upper = np.array([-rmax, -rmax, zlo]) * 1.05, np.array([rmax, rmax, zhi]) * 1.05
    centre = 0.5 * (lower + upper)
    radius = 0.5 * np.linalg.norm(upper - lower)
    return incoherent_rays(rng, count, centre, radius, lower, upper, spread), 2 * radius


def ambiguous(truth, rays, size):
    """Rays whose closed-form verdict flips when the origin moves by 1e-9 of the size along an
    axis: within rounding of a silhouette or an edge, where either answer is right."""
    base = np.isfinite(truth(rays))
    flips = np.zeros(len(rays), dtype=bool)
    for axis in range(3):
        for sign in (-1, 1):
            moved = rays.astype(np.float64).copy()
            moved[:, axis] += sign * 1e-9 * size
            flips |= np.isfinite(truth(moved)) != base
    return flips


def cosine(rays, normals):
    d = rays[:, 3:].astype(np.float64)
    return np.abs(np.einsum("ij,ij->i", d, normals)) / np.linalg.norm(d, axis=1)


def t_bound(t, size, rays, cos):
    # As tests/analytic_shapes_test.cpp: float rounding of t (counted twice) plus the kernel's error,
    # a few units of double rounding times the size along the normal, generous by 2^10.
    length = np.linalg.norm(rays[:, 3:].astype(np.float64), axis=1)
    return 2.0**-23 * np.abs(t) + 2.0**-40 * size / (length * np.maximum(cos, 1e-6))


CONES = {
    "cylinder": [(0.75, -0.5), (0.75, 1.25)],
    "cone": [(0.2, -0.5), (0.9, 1.0)],
    "apex cone": [(1.0, -0.5), (0.0, 1.0)],
}


@pytest.mark.parametrize("name", CONES)
def test_one_segment_is_a_cone_hit_as_its_closed_form(name):
    print(f"seed {SEED}")
    rng = np.random.default_rng(SEED)
    points = np.array(CONES[name])
    (r0, z0), (r1, z1) = points
    scene = revolve.RaycastingScene()
    gid = scene.add_revolution(points)
    rays, size = rays_about(points, 20000, rng)
    got = scene.cast_rays(rays)

    def truth(r):
        return cone_hits(r, r0, z0, r1, z1)

    expected = truth(rays)
    hit = np.isfinite(expected)
    disagree = np.isfinite(got["t_hit"]) != hit
    assert not np.any(disagree & ~ambiguous(truth, rays, size)), "hit/miss differs from the closed form away from edges"
    assert hit.sum() > 5000 and (~hit).sum() > 2000

    both = hit & np.isfinite(got["t_hit"])
    o, d = rays[:, :3].astype(np.float64), rays[:, 3:].astype(np.float64)
    p = o + expected[:, None] * d
    rho = np.hypot(p[:, 0], p[:, 1])
    # The outward normal: (ez x / rho, ez y / rho, -er) over the segment's length.
    er, ez = r1 - r0, z1 - z0
    with np.errstate(invalid="ignore", divide="ignore"):
        normal = np.stack([ez * p[:, 0] / rho, ez * p[:, 1] / rho, np.full(len(p), -er)], axis=1) / math.hypot(er, ez)
    cos = cosine(rays, normal)
    assert np.all(np.abs(got["t_hit"][both] - expected[both]) <= t_bound(expected, size, rays, cos)[both])
    assert np.all(got["geometry_ids"][both] == gid) and np.all(got["primitive_ids"][both] == 0)
    away = both & (rho > 1e-3 * size)  # the normal's azimuth is ill-conditioned at the axis
    assert np.allclose(got["primitive_normals"][away], normal[away], atol=1e-6)
    # u = azimuth / 2 pi, v = the fraction of the way along the segment.
    u = np.mod(np.arctan2(p[:, 1], p[:, 0]) / (2 * np.pi), 1.0)
    du = np.abs(got["primitive_uvs"][away, 0] - u[away])
    assert np.all(np.minimum(du, 1 - du) < 1e-6)
    v = np.hypot(rho - r0, p[:, 2] - z0) / math.hypot(er, ez)
    assert np.allclose(got["primitive_uvs"][away, 1], v[away], atol=1e-5)
    miss = ~np.isfinite(got["t_hit"])
    assert np.all(got["geometry_ids"][miss] == revolve.RaycastingScene.INVALID_ID)
    assert np.all(got["primitive_normals"][miss] == 0)


def test_placed_cylinder_is_hit_where_the_placement_puts_it():
    """A similarity placement (scale 2.5, 30 degrees about (1, 1, 0), a translation): world rays
    mapped into the object in double meet the closed form at the same t; normals turn with it."""
    print(f"seed {SEED}")
    rng = np.random.default_rng(SEED + 1)
    points = np.array(CONES["cylinder"])
    matrix = placement(2.5, (1, 1, 0), 30, (3, -1, 2))
    scene = revolve.RaycastingScene()
    scene.add_revolution(points, transform=matrix)
    corners = np.array([[x, y, z, 1] for x in (-0.8, 0.8) for y in (-0.8, 0.8) for z in (-0.5, 1.25)]) @ matrix.T
    lower, upper = corners[:, :3].min(axis=0), corners[:, :3].max(axis=0)
    size = np.linalg.norm(upper - lower)
    rays = incoherent_rays(rng, 20000, 0.5 * (lower + upper), 0.5 * size, lower, upper)
    got = scene.cast_rays(rays)
    inverse = np.linalg.inv(matrix[:3, :3])

    def truth(r):
        local = np.concatenate([(r[:, :3] - matrix[:3, 3]) @ inverse.T, r[:, 3:] @ inverse.T], axis=1)
        return cone_hits(local, 0.75, -0.5, 0.75, 1.25)

    expected = truth(rays.astype(np.float64))
    hit = np.isfinite(expected)
    disagree = np.isfinite(got["t_hit"]) != hit
    assert not np.any(disagree & ~ambiguous(truth, rays, size))
    assert hit.sum() > 5000
    both = hit & np.isfinite(got["t_hit"])
    o, d = rays[:, :3].astype(np.float64), rays[:, 3:].astype(np.float64)
    local = (o + np.where(hit, expected, 0)[:, None] * d - matrix[:3, 3]) @ inverse.T
    normal = np.stack([local[:, 0], local[:, 1], np.zeros(len(local))], axis=1) @ inverse  # (L^-T n) as rows
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    cos = cosine(rays, normal)
    # Embree maps the ray into the object in float: within gamma(4) |L| |L^-1| (|o| + |T| + |t d|) of
    # the world ray's point (platform/scene/embree_scene.h), divided by |d| cos along the ray.
    reach = np.abs(o).max(axis=1) + np.abs(matrix[:3, 3]).max() + np.abs(expected[:, None] * d).max(axis=1)
    condition = np.abs(matrix[:3, :3]).sum(axis=1).max() * np.abs(inverse).sum(axis=1).max()
    bound = 4 * 2.0**-24 * condition * reach / (np.linalg.norm(d, axis=1) * np.maximum(cos, 1e-6))
    bound += t_bound(expected, size, rays, cos)
    assert np.all(np.abs(got["t_hit"][both] - expected[both]) <= bound[both])
    assert np.allclose(got["primitive_normals"][both & (cos > 1e-3)], normal[both & (cos > 1e-3)], atol=1e-5)


def test_quadratic_spline_is_the_paraboloid_traced_exactly_or_within_its_tolerance():
    """Quadratic Bezier control points (0, 0), (1/2, 0), (1, 1) are exactly the parabola z = r^2."""
    print(f"seed {SEED}")
    rng = np.random.default_rng(SEED + 2)
    points = np.array([[0.0, 0.0], [0.5, 0.0], [1.0, 1.0]])
    exact, sampled = revolve.RaycastingScene(), revolve.RaycastingScene()
    exact.add_revolution(points, spline="quadratic")
    sampled.add_revolution(points, spline="quadratic", tolerance=1e-4)
    rays, size = rays_about(points, 20000, rng)

    def truth(r):
        return paraboloid_hits(r, 1.0)

    expected = truth(rays)
    got = exact.cast_rays(rays)
    hit = np.isfinite(expected)
    assert not np.any((np.isfinite(got["t_hit"]) != hit) & ~ambiguous(truth, rays, size))
    assert hit.sum() > 5000
    both = hit & np.isfinite(got["t_hit"])
    o, d = rays[:, :3].astype(np.float64), rays[:, 3:].astype(np.float64)
    p = o + np.where(hit, expected, 0)[:, None] * d
    normal = np.stack([2 * p[:, 0], 2 * p[:, 1], -np.ones(len(p))], axis=1)  # outward: below the bowl
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    cos = cosine(rays, normal)
    # The curve kernel solves in double like the cone kernel; its bound here 2^3 looser.
    assert np.all(np.abs(got["t_hit"][both] - expected[both]) <= 8 * t_bound(expected, size, rays, cos)[both])
    assert np.allclose(got["primitive_normals"][both & (cos > 1e-3)], normal[both & (cos > 1e-3)], atol=1e-5)

    # Sampled within 1e-4: every hit lies within 1e-4 of the paraboloid (vertically, within
    # 1e-4 sqrt(1 + slope^2)), and some lie measurably off it (the polyline is not the curve).
    got = sampled.cast_rays(rays)
    hits = np.isfinite(got["t_hit"])
    q = o[hits] + got["t_hit"][hits, None].astype(np.float64) * d[hits]
    rho = np.hypot(q[:, 0], q[:, 1])
    off = np.abs(q[:, 2] - rho**2)
    assert np.all(off <= 1e-4 * np.sqrt(1 + 4 * rho**2) + 1e-6)
    assert off.max() > 1e-5


def test_inscribed_sphere_hits_occlusions_and_crossings_lie_between_the_sphere_and_its_inner_bound():
    print(f"seed {SEED}")
    rng = np.random.default_rng(SEED + 3)
    radius, segments = 1.0, 48
    inner = radius * math.cos(math.pi / (2 * segments))  # the polygon's sagitta below the circle
    scene = revolve.RaycastingScene()
    scene.add_revolution(semicircle(radius, segments))
    rays, _ = rays_about(semicircle(radius, segments), 20000, rng)
    o, d = rays[:, :3].astype(np.float64), rays[:, 3:].astype(np.float64)

    def sphere_entry(r):
        a, b, c = np.einsum("ij,ij->i", d, d), 2 * np.einsum("ij,ij->i", o, d), np.einsum("ij,ij->i", o, o) - r * r
        disc = b * b - 4 * a * c
        with np.errstate(invalid="ignore"):
            return np.where(disc > 0, (-b - np.sqrt(disc)) / (2 * a), np.inf)

    outer_t, inner_t = sphere_entry(radius), sphere_entry(inner)
    got = scene.cast_rays(rays)
    t = got["t_hit"].astype(np.float64)
    clear_miss, clear_hit = ~np.isfinite(sphere_entry(radius * 1.000001)), np.isfinite(sphere_entry(inner * 0.999999))
    assert np.all(~np.isfinite(t[clear_miss])) and np.all(np.isfinite(t[clear_hit]))
    assert clear_hit.sum() > 5000 and clear_miss.sum() > 2000
    p = o[clear_hit] + t[clear_hit, None] * d[clear_hit]
    distance = np.linalg.norm(p, axis=1)
    assert np.all(distance >= inner - 1e-6) and np.all(distance <= radius + 1e-6)
    # Occluded before the outer sphere: never; beyond the inner sphere's entry: always.
    near = scene.test_occlusions(rays[clear_hit], tfar=float("inf"))
    assert near.dtype == np.bool_ and np.all(near)
    some = np.flatnonzero(clear_hit)[:500]
    for i in some[:100]:
        assert not scene.test_occlusions(rays[i : i + 1], tfar=float(outer_t[i]) * 0.999)[0]
        assert scene.test_occlusions(rays[i : i + 1], tfar=float(inner_t[i]) * 1.001)[0]
        assert scene.test_occlusions(rays[i : i + 1], tnear=float(inner_t[i]) * 1.001)[0]  # the far side remains
    # A line through a convex solid from outside crosses its surface twice.
    counts = scene.count_intersections(rays)
    assert counts.dtype == np.int32
    assert np.all(counts[clear_hit] == 2) and np.all(counts[clear_miss] == 0)


def test_torus_loop_counts_four_crossings_through_its_tube_twice():
    scene = revolve.RaycastingScene()
    scene.add_revolution(circle_loop(0.35, 0.15, 64))
    # Along x at heights inside the tube: through both sides of the tube, and so both walls twice.
    z = np.linspace(-0.1, 0.1, 21)
    rays = np.stack([np.full_like(z, -2), np.zeros_like(z), z, np.ones_like(z), np.zeros_like(z), np.zeros_like(z)], axis=1)
    assert np.all(scene.count_intersections(rays.astype(np.float32)) == 4)
    # Down the axis, through the hole: nothing.
    hole = np.array([[0, 0, 2, 0, 0, -1], [0.1, 0.05, 2, 0, 0, -1]], np.float32)
    assert np.all(scene.count_intersections(hole) == 0) and not np.any(scene.test_occlusions(hole))


def placed_sphere():
    """A polyline sphere of radius 1 placed with scale 2 about a tilted axis, moved: a sphere of
    radius 2 about (1, -2, 0.5) in the world."""
    return placement(2.0, (0.3, -1, 0.2), 40, (1, -2, 0.5)), np.array([1, -2, 0.5])


@pytest.mark.parametrize("placed", [False, True])
def test_closest_points_and_distances_are_the_meridian_polyline_distances(placed):
    print(f"seed {SEED}")
    rng = np.random.default_rng(SEED + 4)
    profile = semicircle(1.0, 24)
    matrix, centre = placed_sphere() if placed else (np.eye(4), np.zeros(3))
    scale = 2.0 if placed else 1.0
    scene = revolve.RaycastingScene()
    scene.add_revolution(profile, transform=matrix)
    world = (centre + rng.uniform(-3, 3, size=(4000, 3)) * scale).astype(np.float32)
    local = (world.astype(np.float64) - matrix[:3, 3]) @ np.linalg.inv(matrix[:3, :3]).T
    rho = np.hypot(local[:, 0], local[:, 1])
    expected, segment, nearest, second = segment_distances(rho, local[:, 2], profile)
    distance = scene.compute_distance(world)
    assert distance.dtype == np.float32 and distance.shape == (4000,)
    assert np.allclose(distance, scale * expected, rtol=2e-7, atol=1e-7 * scale)
    closest = scene.compute_closest_points(world)
    cx, cy = local[:, 0] / rho, local[:, 1] / rho
    point = np.stack([nearest[:, 0] * cx, nearest[:, 0] * cy, nearest[:, 1]], axis=1) @ matrix[:3, :3].T + matrix[:3, 3]
    assert np.allclose(closest["points"], point, atol=1e-6 * scale)
    # Away from ties between two segments, the nearest segment and, inside it, its normal.
    clear = second - expected > 1e-6
    assert np.all(closest["primitive_ids"][clear] == segment[clear])
    e = np.diff(profile, axis=0)[segment]
    n_meridian = np.stack([e[:, 1], -e[:, 0]], axis=1) / np.linalg.norm(e, axis=1)[:, None]
    normal = np.stack([n_meridian[:, 0] * cx, n_meridian[:, 0] * cy, n_meridian[:, 1]], axis=1) @ np.linalg.inv(matrix[:3, :3])
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    a, b = profile[segment], profile[segment + 1]
    s = np.einsum("ij,ij->i", nearest - a, b - a) / np.einsum("ij,ij->i", b - a, b - a)
    inside_segment = clear & (s > 1e-6) & (s < 1 - 1e-6)
    assert inside_segment.sum() > 1000
    assert np.allclose(closest["primitive_normals"][inside_segment], normal[inside_segment], atol=1e-5)
    assert np.all(closest["geometry_ids"] == 0)


def test_signed_distance_and_occupancy_from_the_profile():
    print(f"seed {SEED}")
    rng = np.random.default_rng(SEED + 5)
    matrix, centre = placed_sphere()
    scene = revolve.RaycastingScene()
    scene.add_revolution(semicircle(1.0, 48), transform=matrix)  # radius 2 in the world
    inner = 2 * math.cos(math.pi / 96)
    # Torus: tube 0.15 about the circle of radius 0.35, far from the sphere.
    torus_at = np.array([6.0, 0, 0])
    torus = np.eye(4)
    torus[:3, 3] = torus_at
    scene.add_revolution(circle_loop(0.35, 0.15, 64), transform=torus)
    tube_inner = 0.15 * math.cos(math.pi / 64)
    # The paraboloid closed by its top disc, far from both: inside where r^2 < z < 1.
    bowl_at = np.array([-6.0, 0, 0])
    bowl = np.eye(4)
    bowl[:3, 3] = bowl_at
    scene.add_revolution([[0, 0], [0.5, 0], [1, 1], [0.5, 1], [0, 1]], transform=bowl, spline="quadratic")

    sphere_q = centre + rng.uniform(-3, 3, size=(3000, 3))
    r = np.linalg.norm(sphere_q - centre, axis=1)
    sphere_in, sphere_out = r < inner - 1e-4, r > 2 + 1e-4
    torus_q = torus_at + rng.uniform(-0.6, 0.6, size=(3000, 3)) * [1, 1, 0.4]
    tube = np.hypot(np.hypot(torus_q[:, 0] - 6, torus_q[:, 1]) - 0.35, torus_q[:, 2])
    torus_in, torus_out = tube < tube_inner - 1e-4, tube > 0.15 + 1e-4
    bowl_q = bowl_at + rng.uniform([-1.2, -1.2, -0.2], [1.2, 1.2, 1.2], size=(3000, 3))
    lz, lr2 = bowl_q[:, 2], (bowl_q[:, 0] + 6) ** 2 + bowl_q[:, 1] ** 2
    bowl_in = (lz > lr2 + 1e-4) & (lz < 1 - 1e-4)
    bowl_out = (lz < lr2 - 1e-4) | (lz > 1 + 1e-4) | (lz < -1e-4)

    queries = np.concatenate([sphere_q, torus_q, bowl_q]).astype(np.float32)
    inside = np.concatenate([sphere_in, torus_in, bowl_in])
    outside = np.concatenate([sphere_out, torus_out, bowl_out])
    assert inside.sum() > 1500 and outside.sum() > 3000
    occupancy = scene.compute_occupancy(queries)
    assert occupancy.dtype == np.float32
    assert np.all(occupancy[inside] == 1) and np.all(occupancy[outside] == 0)
    signed = scene.compute_signed_distance(queries)
    unsigned = scene.compute_distance(queries)
    assert np.all(signed[inside] == -unsigned[inside]) and np.all(signed[outside] == unsigned[outside])
    assert np.all(unsigned[inside] > 0)


def unit_cube():
    vertices = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], np.float32)
    # Outward-facing triangles (counter-clockwise seen from outside), two a face.
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    triangles = [t for a, b, c, d in faces for t in ((a, b, c), (a, c, d))]
    return vertices, np.array(triangles, np.uint32)


def test_meshes_beside_revolutions():
    scene = revolve.RaycastingScene()
    sphere = scene.add_revolution(semicircle(0.5, 32), transform=placement(1, (0, 0, 1), 0, (-2, 0.5, 0.5)))
    cube = scene.add_triangles(*unit_cube())
    assert (sphere, cube) == (0, 1)
    rays = np.array(
        [[0.5, 0.5, 5, 0, 0, -1], [3, 0.25, 0.75, -2, 0, 0], [-2, 0.5, 5, 0, 0, -1], [5, 5, 5, 0, 0, 1]], np.float32
    )
    got = scene.cast_rays(rays)
    assert np.allclose(got["t_hit"], [4, 1, 4, np.inf], rtol=1e-6)
    assert got["geometry_ids"].tolist() == [cube, cube, sphere, revolve.RaycastingScene.INVALID_ID]
    assert np.allclose(got["primitive_normals"][:2], [[0, 0, 1], [1, 0, 0]], atol=1e-7)
    # The top cone of the polyline, hit at its apex: within its half-angle, pi / 64, of the axis.
    assert got["primitive_normals"][2, 2] >= math.cos(math.pi / 64) - 1e-7
    # The second ray goes on through the sphere (its line passes 0.35 from the centre).
    assert scene.count_intersections(rays).tolist() == [2, 4, 2, 0]
    points = np.array([[2, 0.5, 0.5], [0.5, 0.5, 0.75], [-2, 0.5, 2]], np.float32)
    closest = scene.compute_closest_points(points)
    assert np.allclose(closest["points"][:2], [[1, 0.5, 0.5], [0.5, 0.5, 1]], atol=1e-7)
    assert closest["geometry_ids"].tolist() == [cube, cube, sphere]
    assert np.allclose(scene.compute_distance(points), [1, 0.25, 1.0], atol=1e-7)
    with pytest.raises(ValueError, match="geometry 1 is a triangle mesh"):
        scene.compute_occupancy(points)


def test_load_places_a_scene_files_objects_and_quads(tmp_path):
    # A cylinder of radius 0.5 and height 2, scaled by 2, turned 90 degrees about x (its axis
    # along -y), moved to (0, 0, 3); a floor quad at z = 0.
    (tmp_path / "scene.json").write_text(
        """{"camera": {"from": [0, -10, 3], "to": [0, 0, 3], "up": [0, 0, 1], "fov": 40},
  "profiles": {"can": {"points": [[0, 0], [0.5, 0], [0.5, 2], [0, 2]]}},
  "materials": {"grey": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
  "objects": [{"profile": "can", "material": "grey", "scale": 2, "rotate": [1, 0, 0, 90], "translate": [0, 0, 3]}],
  "quads": [{"corners": [[-5, -5, 0], [5, -5, 0], [5, 5, 0], [-5, 5, 0]], "material": "grey"}]}"""
    )
    scene = revolve.RaycastingScene()
    assert scene.load(str(tmp_path / "scene.json")) == [0, 1]
    rays = np.array([[0, -2, 10, 0, 0, -1], [0, -10, 3, 0, 1, 0], [4, 0, 10, 0, 0, -1]], np.float32)
    got = scene.cast_rays(rays)
    # Down onto the side of the lying cylinder (radius 1 about z = 3): z = 4; along its axis from
    # -y: its end cap at y = -4 (the profile's top, z = 2, scaled by 2, turned to -y); the floor.
    assert np.allclose(got["t_hit"], [6, 6, 10], rtol=1e-6)
    assert got["geometry_ids"].tolist() == [0, 0, 1]
    assert np.allclose(got["primitive_normals"][:2], [[0, 0, 1], [0, -1, 0]], atol=1e-6)


def test_tessellate_sweeps_the_profile_into_outward_triangles_within_its_bound():
    profile = semicircle(1.0, 32)
    slices = 48
    vertices, triangles = revolve.tessellate(profile, slices)
    assert vertices.dtype == np.float32 and triangles.dtype == np.uint32
    assert vertices.shape == (33 * slices, 3) and triangles.shape == (2 * 32 * slices, 3)
    # Every vertex on its circle: at its profile point's radius and height.
    rows = np.repeat(profile, slices, axis=0)
    assert np.allclose(np.hypot(vertices[:, 0], vertices[:, 1]), rows[:, 0], atol=1e-6)
    assert np.allclose(vertices[:, 2], rows[:, 1], atol=1e-7)
    # Outward: each non-degenerate triangle's normal points away from the centre.
    a, b, c = (vertices[triangles[:, k]].astype(np.float64) for k in range(3))
    n = np.cross(b - a, c - a)
    area = np.linalg.norm(n, axis=1)
    assert np.all(np.einsum("ij,ij->i", n[area > 1e-12], (a + b + c)[area > 1e-12]) > 0)
    # Traced, its hits lie within its error bound (the polygon's sagitta plus the slices') of the sphere.
    scene = revolve.RaycastingScene()
    scene.add_triangles(vertices, triangles)
    rays, _ = rays_about(profile, 5000, np.random.default_rng(SEED + 6))
    t = scene.cast_rays(rays)["t_hit"].astype(np.float64)
    hit = np.isfinite(t)
    p = rays[hit, :3] + t[hit, None] * rays[hit, 3:]
    bound = (1 - math.cos(math.pi / 64)) + (1 - math.cos(math.pi / slices))
    assert hit.sum() > 1000 and np.all(np.abs(np.linalg.norm(p, axis=1) - 1) <= bound + 1e-6)
    with pytest.raises(ValueError, match=r"slices = 2: must be a whole number, at least 3"):
        revolve.tessellate(profile, 2)


def test_memory_bytes_counts_the_meshes_arrays_and_grows_with_the_profile():
    rays = np.array([[0, 0, 5, 0, 0, -1]], np.float32)
    small, large = revolve.RaycastingScene(), revolve.RaycastingScene()
    small.add_revolution(semicircle(1.0, 16))
    large.add_revolution(semicircle(1.0, 4096))
    small.cast_rays(rays), large.cast_rays(rays)  # built
    assert 0 < small.memory_bytes() < large.memory_bytes()
    assert large.memory_bytes() > 4096 * 2 * 8  # at least its points, two doubles each
    vertices, triangles = revolve.tessellate(semicircle(1.0, 64), 128)
    mesh = revolve.RaycastingScene()
    mesh.add_triangles(vertices, triangles)
    mesh.cast_rays(rays)
    # The arrays' copies, and Embree's BVH over 16384 triangles on top of them.
    assert mesh.memory_bytes() > vertices.nbytes + triangles.nbytes + 16384 * 16
