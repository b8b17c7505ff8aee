"""Bad input answered with a Python exception naming the value, where it was and the rule: never a
crash, never a silent guess. (A crash would take the test process with it.)"""

import math

import numpy as np
import pytest

import revolve


@pytest.fixture
def scene():
    s = revolve.RaycastingScene()
    s.add_revolution([[0, 0], [1, 0], [1, 1], [0, 1]])
    return s


RAY = [0, 0, 5, 0, 0, -1]


@pytest.mark.parametrize("method", ["cast_rays", "test_occlusions", "count_intersections"])
def test_rays_of_the_wrong_dtype_shape_or_layout(scene, method):
    query = getattr(scene, method)
    with pytest.raises(TypeError, match=r"rays: dtype float64; expected float32"):
        query(np.array([RAY], dtype=np.float64))
    with pytest.raises(TypeError, match=r"rays: a list; expected a numpy array of float32 with shape \(\.\.\., 6\)"):
        query([RAY])
    with pytest.raises(TypeError, match=r"rays: a str"):
        query("rays.csv")
    with pytest.raises(ValueError, match=r"rays: shape \(2, 5\); the last axis must hold 6 numbers \(ox, oy, oz, dx, dy, dz\)"):
        query(np.zeros((2, 5), np.float32))
    with pytest.raises(ValueError, match=r"rays: shape \(\); the last axis"):
        query(np.array(1.0, np.float32))
    strided = np.zeros((4, 12), np.float32)[:, ::2]
    with pytest.raises(ValueError, match=r"rays: not C-contiguous; .* numpy.ascontiguousarray\(rays\)"):
        query(strided)


@pytest.mark.parametrize("method", ["cast_rays", "test_occlusions", "count_intersections"])
@pytest.mark.parametrize(
    "where, value, message",
    [
        ((2, 1, 2), math.nan, r"rays\[2, 1\]: origin z = nan is not finite"),
        ((0, 1, 4), math.inf, r"rays\[0, 1\]: direction y = inf is not finite"),
        ((1, 0, 0), 1e13, r"rays\[1, 0\]: origin x = 9\.99\d*e\+12 lies beyond \+-4.4e12"),
        ((1, 1, 5), 2e12, r"rays\[1, 1\]: direction z = 1\.99\d*e\+12 lies beyond \+-1.1e12"),
    ],
)
def test_a_bad_ray_is_named_by_its_index_and_rule(scene, method, where, value, message):
    rays = np.tile(np.array(RAY, np.float32), (3, 2, 1))
    rays[where] = value
    with pytest.raises(ValueError, match=message):
        getattr(scene, method)(rays)


def test_a_zero_direction_is_refused(scene):
    rays = np.array([RAY, [0, 0, 5, 0, 0, 0]], np.float32)
    with pytest.raises(ValueError, match=r"rays\[1\]: direction \(0, 0, 0\) is zero: a ray needs a direction"):
        scene.cast_rays(rays)


@pytest.mark.parametrize("method", ["compute_closest_points", "compute_distance", "compute_signed_distance", "compute_occupancy"])
def test_bad_query_points(scene, method):
    query = getattr(scene, method)
    with pytest.raises(TypeError, match=r"query_points: dtype int64; expected float32"):
        query(np.zeros((2, 3), np.int64))
    with pytest.raises(ValueError, match=r"query_points: shape \(2, 2\); the last axis must hold 3 numbers \(x, y, z\)"):
        query(np.zeros((2, 2), np.float32))
    with pytest.raises(ValueError, match=r"not C-contiguous"):
        query(np.asfortranarray(np.zeros((4, 3), np.float32)))
    points = np.zeros((4, 3), np.float32)
    points[3, 1] = np.nan
    with pytest.raises(ValueError, match=r"query_points\[3\]: point y = nan is not finite"):
        query(points)


def test_occlusion_interval(scene):
    rays = np.array([RAY], np.float32)
    with pytest.raises(ValueError, match=r"need 0 <= tnear <= tfar"):
        scene.test_occlusions(rays, tnear=2.0, tfar=1.0)
    with pytest.raises(ValueError, match=r"need 0 <= tnear <= tfar"):
        scene.test_occlusions(rays, tnear=math.nan)
    with pytest.raises(ValueError, match=r"need 0 <= tnear <= tfar"):
        scene.test_occlusions(rays, tnear=-1.0)


def test_profiles_are_refused_naming_the_point_and_the_rule():
    s = revolve.RaycastingScene()
    with pytest.raises(revolve.ProfileError, match=r"points: the segment from profile point 0 .* intersect; a profile must not cross or touch itself") as crossing:
        s.add_revolution([[0, 0], [1, 1], [1, 0], [0, 1]])
    assert crossing.value.rule == "self_intersecting" and crossing.value.index == 0
    assert isinstance(crossing.value, ValueError)
    with pytest.raises(revolve.ProfileError, match=r"profile point 1 \(r = -0.5, z = 1\): r must be >= 0") as negative:
        s.add_revolution([[0, 0], [-0.5, 1]])
    assert (negative.value.rule, negative.value.index) == ("negative_radius", 1)
    with pytest.raises(revolve.ProfileError, match=r"profile point 2 \(r = nan, z = 1\): coordinates must be finite") as nan:
        s.add_revolution([[0, 0], [1, 0], [math.nan, 1]])
    assert nan.value.rule == "non_finite"
    with pytest.raises(revolve.ProfileError, match=r"at least 2 are needed"):
        s.add_revolution([[1, 1]])
    with pytest.raises(revolve.ProfileError) as count:
        s.add_revolution([[0, 0], [1, 0], [1, 1], [0, 1]], spline="quadratic")
    assert count.value.rule == "bad_point_count"
    with pytest.raises(ValueError, match=r'spline = "cubic": not a spline kind; expected linear, quadratic, bezier, catmull-rom or natural'):
        s.add_revolution([[0, 0], [1, 1]], spline="cubic")
    with pytest.raises(ValueError, match=r"tolerance applies to a spline profile"):
        s.add_revolution([[0, 0], [1, 1]], tolerance=1e-3)
    with pytest.raises(ValueError, match=r"tolerance: 0.0 is out of range: a polyline tolerance is a finite number > 0"):
        s.add_revolution([[0, 0], [1, 0], [1, 1]], spline="quadratic", tolerance=0.0)
    with pytest.raises(ValueError, match=r"points: shape \(3, 3\); expected \(N, 2\)"):
        s.add_revolution(np.zeros((3, 3)))
    with pytest.raises(TypeError, match=r"points: dtype <U1; expected real numbers"):
        s.add_revolution([["a", "b"], ["c", "d"]])
    with pytest.warns(UserWarning, match=r"points: profile point 2 .* repeats point 1 exactly; dropped"):
        s.add_revolution([[0, 0], [1, 0], [1, 0], [1, 1]])
    assert s.geometry_count() == 1  # only the last, with its repeat dropped, was added


def test_transforms_are_refused_naming_the_entry_and_the_rule():
    s = revolve.RaycastingScene()
    profile = [[0, 0], [1, 0], [1, 1], [0, 1]]
    bad = np.eye(4)
    bad[1, 2] = math.inf
    with pytest.raises(ValueError, match=r"transform\[1, 2\] = inf is not finite"):
        s.add_revolution(profile, transform=bad)
    projective = np.eye(4)
    projective[3, 0] = 0.5
    with pytest.raises(ValueError, match=r"transform's last row is \(0.5, 0, 0, 1\); a placement is affine"):
        s.add_revolution(profile, transform=projective)
    with pytest.raises(ValueError, match=r"transform's 3x3 part scales by 1e-06 \(its smallest singular value\): "
                                         r"scale factors lie in \[2\^-16, 2\^40\]"):
        s.add_revolution(profile, transform=np.diag([1e-6, 1, 1, 1]))
    with pytest.raises(ValueError, match=r"transform's 3x3 part is singular \(a scale factor of 0\): scale factors lie"):
        s.add_revolution(profile, transform=np.diag([0, 1, 1, 1]))
    far = np.eye(4)
    far[0, 3] = 2e12
    with pytest.raises(ValueError, match=r"transform: the placed object reaches 2e\+12, beyond the coordinate limit"):
        s.add_revolution(profile, transform=far)
    with pytest.raises(ValueError, match=r"transform: shape \(3, 3\); expected \(4, 4\)"):
        s.add_revolution(profile, transform=np.eye(3))
    assert s.geometry_count() == 0


def test_distances_need_a_similarity_and_signs_need_closed_profiles():
    points = np.zeros((1, 3), np.float32)
    stretched = revolve.RaycastingScene()
    stretched.add_revolution([[0, 0], [1, 0], [1, 1], [0, 1]], transform=np.diag([1, 1, 2, 1]))
    assert np.isfinite(stretched.cast_rays(np.array([RAY], np.float32))["t_hit"]).all()  # rays are fine
    with pytest.raises(ValueError, match=r"compute_distance: geometry 0 is placed by a transform that is not a similarity"):
        stretched.compute_distance(points)
    open_profile = revolve.RaycastingScene()
    open_profile.add_revolution([[1, 0], [1, 1]])
    assert open_profile.compute_distance(points)[0] == pytest.approx(1.0)
    with pytest.raises(ValueError, match=r"compute_signed_distance: geometry 0's profile is open"):
        open_profile.compute_signed_distance(points)
    with pytest.raises(ValueError, match=r"compute_occupancy: geometry 0's profile is open"):
        open_profile.compute_occupancy(points)
    with pytest.raises(ValueError, match=r"nsamples = 0: must lie in \[1, 2147483647\]"):
        open_profile.compute_occupancy(points, nsamples=0)


def test_meshes_with_bad_indices_or_vertices():
    s = revolve.RaycastingScene()
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.float32)
    with pytest.raises(ValueError, match=r"triangle_indices\[0, 2\] = 3 is not a vertex: there are 3"):
        s.add_triangles(vertices, np.array([[0, 1, 3]], np.uint32))
    with pytest.raises(ValueError, match=r"triangle_indices\[0, 0\] = -1 is not a vertex"):
        s.add_triangles(vertices, np.array([[-1, 1, 2]]))
    with pytest.raises(ValueError, match=r"triangle_indices\[0, 1\] = 18446744073709551615 is not a vertex"):
        s.add_triangles(vertices, np.array([[0, 2**64 - 1, 2]], np.uint64))
    with pytest.raises(TypeError, match=r"triangle_indices: dtype float32; expected an integer array"):
        s.add_triangles(vertices, np.array([[0, 1, 2]], np.float32))
    with pytest.raises(ValueError, match=r"vertex_positions\[1, 0\] = nan is not finite"):
        s.add_triangles(np.array([[0, 0, 0], [math.nan, 0, 0], [0, 1, 0]]), np.array([[0, 1, 2]]))
    with pytest.raises(ValueError, match=r"vertex_positions\[2, 1\] = 5.*beyond the coordinate limit"):
        s.add_triangles(np.array([[0, 0, 0], [1, 0, 0], [0, 5e12, 0]]), np.array([[0, 1, 2]]))
    assert s.geometry_count() == 0


def test_scene_files_sensors_and_poses():
    with pytest.raises(ValueError, match=r'geometry = "voxels": expected "mibit" \(exact\) or "mesh"'):
        revolve.Scene("missing.json", geometry="voxels")  # checked before the file is read
    with pytest.raises(ValueError, match=r"slices = 2: must lie in \[3, 65536\]"):
        revolve.Scene("missing.json", geometry="mesh", slices=2)
    with pytest.raises(ValueError, match=r"missing.json"):
        revolve.RaycastingScene().load("missing.json")
    with pytest.raises(ValueError, match=r"horizontal.samples"):
        revolve.Lidar({"pose": {"position": [0, 0, 0]}, "horizontal": {"samples": 0, "min_angle": 0, "max_angle": 0},
                       "range": {"min": 0, "max": 10}})
    with pytest.raises(ValueError, match=r"poses: shape \(2, 8\); expected \(N, 3\) \[x, y, yaw\], \(N, 4\)"):
        revolve.cylinder_clearance(__file__, np.zeros((2, 8)), 0.3, 0, 1)
    # (N, 6) and (N, 7): roll and pitch before the yaw, the time last; the clearance robot stands upright.
    with pytest.raises(ValueError, match=r"poses: pose 1 \(counting from 0\) has roll = 0.25, pitch = 0: the clearance robot is an upright cylinder"):
        revolve.cylinder_clearance(__file__, np.array([[0, 0, 0, 0, 0, 0], [0, 0, 0, 0.25, 0, 0]]), 0.3, 0, 1)
    with pytest.raises(ValueError, match=r"poses\[1, 6\]: time = 0 does not increase"):
        revolve.cylinder_clearance(__file__, np.zeros((2, 7)), 0.3, 0, 1)
    # (N, 5): the fifth column is the time, strictly increasing (the poses file's rule).
    with pytest.raises(ValueError, match=r"poses\[1, 4\]: time = 0 does not increase: times are strictly increasing \(poses\[0, 4\] = 0\)"):
        revolve.cylinder_clearance(__file__, np.zeros((2, 5)), 0.3, 0, 1)
    with pytest.raises(ValueError, match=r"poses\[0, 4\]: time = 2000000000000 is out of range: a pose's time is a number of seconds within \+-1e12"):
        revolve.cylinder_clearance(__file__, np.array([[0, 0, 0, 0, 2e12]]), 0.3, 0, 1)
