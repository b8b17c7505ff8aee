"""The package under hostile use: every
argument a caller can hand the bindings is either taken as documented or refused with a TypeError or
ValueError naming the argument and the rule; never a crash, never pybind's internal errors, never a
silently wrong answer. Calls that crashed the interpreter run in a child (isolated.py).

Items 3 (a query racing an addition), 4 (memory per threaded call), 5 (SIGTERM), 13 (a cluster
without workers) and the argument fuzz have files of their own."""

import json
import math
import multiprocessing
import os
import pathlib
import pickle
import subprocess

import numpy as np
import pytest

import revolve
from conftest import BIN_DIR, SOURCE_DIR, tool_env
from isolated import assert_raised, assert_returned, describe, run_calls
from robot_inputs import NOISY_SENSOR, corridor_poses, write_poses, write_sensor

CAN = [[0, 0], [1, 0], [1, 1], [0, 1]]
RAY = [0.5, 0, 5, 0, 0, -1]
ROBOT_WORLD = SOURCE_DIR / "scenes" / "robot_world.json"
STILL_LIFE = SOURCE_DIR / "scenes" / "still_life.json"


@pytest.fixture
def can():
    s = revolve.RaycastingScene()
    s.add_revolution(CAN)
    return s


# ---------------------------------------------------------------------------------------------
# 1. A ragged list is a ValueError naming the argument, not a SIGSEGV.

RAGGED = {
    "points": "revolve.RaycastingScene().add_revolution([[0, 0], [1], [0, 1]])",
    "points, nested deeper": "revolve.RaycastingScene().add_revolution([[0, 0], [1, [0.5]], [0, 1]])",
    "points, a ragged spline": "revolve.RaycastingScene().add_revolution([[0, 0], [1, 0.5, 2], [0, 1]], spline='quadratic')",
    "transform": "revolve.RaycastingScene().add_revolution(CAN, transform=[[1, 0, 0, 0], [0, 1, 0], [0, 0, 1, 0], [0, 0, 0, 1]])",
    "vertex_positions": "revolve.RaycastingScene().add_triangles([[0, 0, 0], [1, 0], [0, 1, 0]], [[0, 1, 2]])",
    "triangle_indices": "revolve.RaycastingScene().add_triangles([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2], [0, 1]])",
    "poses": "revolve.cylinder_clearance(ROBOT_WORLD, [[1, 1, 0], [2, 1]], 0.3, 0, 1)",
    "tessellate points": "revolve.tessellate([[0, 0], [1], [0, 1]], 8)",
}


def test_ragged_lists_are_value_errors_naming_the_argument():
    """Rule: a ragged nested list (rows of different lengths) given for points, transform,
    vertex_positions, triangle_indices or poses raises ValueError naming that argument (numpy cannot
    make an array of it; the binding must not read the null array that leaves)."""
    outcomes = run_calls(f"import revolve\nCAN = {CAN!r}\nROBOT_WORLD = {str(ROBOT_WORLD)!r}", RAGGED)
    failures = []
    for label, outcome in outcomes.items():
        argument = label.split(",")[0].replace("tessellate ", "")
        try:
            assert_raised(outcome, "ValueError", argument)
        except AssertionError as failure:
            failures.append(f"{label}: {failure}")
    assert not failures, "\n".join(failures)


# ---------------------------------------------------------------------------------------------
# 2. Thread counts: [1, 1024] as the tools' --threads; 0 (and, for RaycastingScene, a negative
#    number, as Open3D) means all threads; anything larger is a ValueError naming the argument.

SCENE_SETUP = f"""
import hashlib
import numpy as np, revolve
s = revolve.RaycastingScene()
s.add_revolution({CAN!r})
rays = np.array([{RAY!r}, [3, 0.1, 0.5, -1, 0, 0], [5, 5, 5, 1, 0, 0]] * 700, np.float32)  # several 1024-ray blocks
points = np.array([[0.5, 0, 2], [0.2, 0.1, 0.5], [3, 0, 0.5]] * 700, np.float32)
def digest(result):
    items = sorted(result.items()) if isinstance(result, dict) else [("", result)]
    return hashlib.sha256(b"".join(np.ascontiguousarray(v).tobytes() for _, v in items)).hexdigest()
"""

QUERIES = {
    "cast_rays": "digest(s.cast_rays(rays, nthreads={n}))",
    "test_occlusions": "digest(s.test_occlusions(rays, nthreads={n}))",
    "count_intersections": "digest(s.count_intersections(rays, nthreads={n}))",
    "compute_closest_points": "digest(s.compute_closest_points(points, nthreads={n}))",
    "compute_distance": "digest(s.compute_distance(points, nthreads={n}))",
    "compute_signed_distance": "digest(s.compute_signed_distance(points, nthreads={n}))",
    "compute_occupancy": "digest(s.compute_occupancy(points, nthreads={n}))",
}
TOO_MANY = [1025, 65537, 10**7, 2**31 - 1]
ALL_OR_SOME = [0, -1, -64, 2, 1024]  # 0 and negative: all threads (Open3D's meaning)


@pytest.mark.parametrize("method", sorted(QUERIES))
def test_raycasting_thread_counts_beyond_1024_are_refused(method):
    """Rule: nthreads > 1024 raises ValueError naming nthreads, the value and the bound 1024; 0 and
    negative values mean all threads (Open3D), 1 to 1024 that many; every accepted count gives the
    one-thread answer bit for bit."""
    calls = {str(n): QUERIES[method].format(n=n) for n in [1] + ALL_OR_SOME + TOO_MANY}
    outcomes = run_calls(SCENE_SETUP, calls)
    one = assert_returned(outcomes["1"])
    failures = []
    for n in TOO_MANY:
        try:
            assert_raised(outcomes[str(n)], "ValueError", "nthreads", str(n), "1024")
        except AssertionError as failure:
            failures.append(f"{method}(nthreads={n}): {failure}")
    for n in ALL_OR_SOME:
        if outcomes[str(n)].get("value") != one:
            failures.append(f"{method}(nthreads={n}): expected the one-thread answer; {describe(outcomes[str(n)])}")
    assert not failures, "\n".join(failures)


@pytest.mark.parametrize("n", [2**31, 2**63])
def test_thread_counts_beyond_a_c_int_are_refused_by_name_in_one_line(can, n):
    """Rule: a thread count no C int holds is refused like any other bad count, a TypeError or
    ValueError naming nthreads in one line, not pybind's multi-line 'incompatible function arguments'
    listing the signature."""
    rays = np.array([RAY], np.float32)
    with pytest.raises((TypeError, ValueError)) as refused:
        can.cast_rays(rays, nthreads=n)
    message = str(refused.value)
    assert "nthreads" in message and "\n" not in message and "incompatible function arguments" not in message, message


ROBOT_SETUP = f"""
import hashlib
import numpy as np, revolve
scene = revolve.Scene({str(ROBOT_WORLD)!r})
sensor = {{"pose": {{"position": [0.1, 0, 0.7]}}, "horizontal": {{"samples": 360, "min_angle": -3.1, "max_angle": 3.1}},
          "range": {{"min": 0.3, "max": 12}}}}
lidar = revolve.Lidar(sensor)
poses = np.array([[1, 1.5, 0], [2, 1.4, 0.3], [3, 1.6, -0.2], [4, 1.5, 0.1]])
def digest(result):
    return hashlib.sha256(b"".join(np.ascontiguousarray(v).tobytes() for _, v in sorted(result.items()))).hexdigest()
"""

ROBOT_CALLS = {
    "Lidar.scan": "digest(lidar.scan(scene, poses, threads={n}))",
    "cylinder_clearance": "digest(revolve.cylinder_clearance(scene, poses, 0.3, 0.05, 1.2, threads={n}))",
}


@pytest.mark.parametrize("function", sorted(ROBOT_CALLS))
def test_robot_thread_counts_beyond_1024_are_refused(function):
    """Rule: threads > 1024 raises ValueError naming threads, the value and the bound 1024 (the tools'
    --threads range); 0 keeps meaning all threads and a negative count stays refused, as today; every
    accepted count gives the one-thread answer bit for bit."""
    too_many = [1025, 70000, 10**7]
    calls = {str(n): ROBOT_CALLS[function].format(n=n) for n in [1, 0, 2, 1024, -1] + too_many}
    outcomes = run_calls(ROBOT_SETUP, calls)
    one = assert_returned(outcomes["1"])
    failures = []
    for n in too_many:
        try:
            assert_raised(outcomes[str(n)], "ValueError", "threads", str(n), "1024")
        except AssertionError as failure:
            failures.append(f"{function}(threads={n}): {failure}")
    try:
        assert_raised(outcomes["-1"], "ValueError", "threads = -1")
    except AssertionError as failure:
        failures.append(f"{function}(threads=-1): {failure}")
    for n in (0, 2, 1024):
        if outcomes[str(n)].get("value") != one:
            failures.append(f"{function}(threads={n}): expected the one-thread answer; {describe(outcomes[str(n)])}")
    assert not failures, "\n".join(failures)


def test_scan_shard_refuses_thread_counts_beyond_1024(tmp_path):
    """Rule: scan_shard (Lidar.scan underneath) refuses threads > 1024 by name, in the worker, not by a crash."""
    sensor = write_sensor(tmp_path / "sensor.json")
    outcomes = run_calls("import numpy as np, revolve\nposes = np.array([[1, 1.5, 0]])",
                         {"scan_shard": f"revolve.scan_shard({str(ROBOT_WORLD)!r}, {str(sensor)!r}, poses, 0, 10**7)"})
    assert_raised(outcomes["scan_shard"], "ValueError", "threads", "10000000", "1024")


# ---------------------------------------------------------------------------------------------
# 6. float32 is float32 whatever dtype object says so; only the byte order matters.

def _float32_array(shape):
    # Runs in a multiprocessing worker: the array comes back through pickle.
    return np.zeros(shape, np.float32)


def _same_float32_in_other_dtype_objects(array):
    unpickled = pickle.loads(pickle.dumps(array))
    native = array.astype(np.dtype("f4").newbyteorder("="))
    viewed = array.view(np.dtype("f4").newbyteorder("="))
    return {"pickled": unpickled, "protocol 2": pickle.loads(pickle.dumps(array, protocol=2)), "newbyteorder('=')": native,
            "view as '=f4'": viewed, "little-endian '<f4'": array.astype("<f4")}


@pytest.mark.parametrize("method", ["cast_rays", "test_occlusions", "count_intersections"])
def test_float32_rays_are_accepted_whatever_dtype_object_describes_them(can, method):
    """Rule: rays of dtype float32 in native byte order are accepted, whether the dtype object is
    numpy's own, unpickled, or made by newbyteorder('='); the answer is the plain array's."""
    rays = np.array([RAY, [3, 0.1, 0.5, -1, 0, 0], [5, 5, 5, 1, 0, 0]], np.float32)
    query = getattr(can, method)
    expected = query(rays)
    for how, same in _same_float32_in_other_dtype_objects(rays).items():
        got = query(same)
        if isinstance(expected, dict):
            assert all(np.array_equal(got[k], expected[k], equal_nan=True) for k in expected), how
        else:
            assert np.array_equal(got, expected), how


@pytest.mark.parametrize("method", ["compute_closest_points", "compute_distance", "compute_signed_distance", "compute_occupancy"])
def test_float32_points_are_accepted_whatever_dtype_object_describes_them(can, method):
    """Rule: as for rays, query points of native float32 are accepted from any dtype object."""
    points = np.array([[0.5, 0, 2], [0.2, 0.1, 0.5]], np.float32)
    query = getattr(can, method)
    expected = query(points)
    for how, same in _same_float32_in_other_dtype_objects(points).items():
        got = query(same)
        if isinstance(expected, dict):
            assert all(np.array_equal(got[k], expected[k]) for k in expected), how
        else:
            assert np.array_equal(got, expected), how


def test_float32_rays_from_a_multiprocessing_worker_are_accepted(can):
    """Rule: rays a multiprocessing.Pool worker made (and pickled back) are float32 and accepted."""
    with multiprocessing.get_context("spawn").Pool(1) as pool:
        rays = pool.apply(np.full, ((2, 6), 0.0, np.float32))
    rays[:] = RAY
    assert rays.dtype == np.float32
    assert can.cast_rays(rays)["t_hit"].tolist() == [4.0, 4.0]


@pytest.mark.parametrize("method, array", [("cast_rays", np.array([RAY], ">f4")), ("compute_distance", np.array([[0, 0, 2]], ">f4"))])
def test_big_endian_float32_is_refused_saying_byte_order(can, method, array):
    """Rule: float32 in the other byte order ('>f4' here) is refused (read in place it would be
    garbage), with a message that says byte order, not 'dtype float32; expected float32'."""
    with pytest.raises((TypeError, ValueError), match=r"byte order"):
        getattr(can, method)(array)


# ---------------------------------------------------------------------------------------------
# 7. A wrong type for spline or tolerance is a TypeError naming it, not "Unable to cast".

@pytest.mark.parametrize(
    "keywords, argument",
    [
        ({"spline": 3}, "spline"),
        ({"spline": ["quadratic"]}, "spline"),
        ({"spline": "quadratic", "tolerance": "0.1"}, "tolerance"),
        ({"spline": "quadratic", "tolerance": [0.1]}, "tolerance"),
        ({"spline": "quadratic", "tolerance": {"value": 0.1}}, "tolerance"),
    ],
)
def test_spline_and_tolerance_of_the_wrong_type_are_type_errors_naming_them(keywords, argument):
    """Rule: spline must be a str (or None) and tolerance a real number (or None); anything else is a
    TypeError naming the argument; pybind's RuntimeError 'Unable to cast Python instance' never
    reaches the caller."""
    s = revolve.RaycastingScene()
    with pytest.raises(TypeError, match=argument) as refused:
        s.add_revolution([[0, 0], [1, 0.5], [0, 1]], **keywords)
    assert "Unable to cast" not in str(refused.value)
    assert s.geometry_count() == 0


def test_numpy_numbers_are_tolerances():
    """Rule (kept): a numpy scalar is a number: tolerance=numpy.float32(0.1) is taken."""
    s = revolve.RaycastingScene()
    assert s.add_revolution([[0, 0], [1, 0.5], [0, 1]], spline="quadratic", tolerance=np.float32(0.1)) == 0


# ---------------------------------------------------------------------------------------------
# 8. No hit has no id.

def test_a_miss_has_invalid_ids(can):
    """Rule: wherever cast_rays gives t_hit = inf (no hit: here the can's side lies 1e40 direction
    units away, beyond float) geometry_ids and primitive_ids are INVALID_ID; wherever t_hit is
    finite, geometry_ids names the can."""
    tiny = can.cast_rays(np.array([[0, 0, 0.5, 1e-40, 0, 0]], np.float32))
    assert np.isinf(tiny["t_hit"][0])
    assert (tiny["geometry_ids"][0], tiny["primitive_ids"][0]) == (can.INVALID_ID, can.INVALID_ID), tiny
    rng = np.random.default_rng(8)
    origins = rng.uniform(-2, 2, (5000, 3))
    directions = rng.normal(size=(5000, 3)) * 10.0 ** rng.integers(-45, 3, (5000, 1))  # some far below float's normals
    rays = np.concatenate([origins, directions], axis=1).astype(np.float32)
    rays = rays[np.any(rays[:, 3:] != 0, axis=1)]
    hits = can.cast_rays(rays)
    miss = np.isinf(hits["t_hit"])
    assert miss.any() and (~miss).any()
    assert np.all(hits["geometry_ids"][miss] == can.INVALID_ID), f"{np.sum(hits['geometry_ids'][miss] != can.INVALID_ID)} misses with an id"
    assert np.all(hits["primitive_ids"][miss] == can.INVALID_ID)
    assert np.all(hits["geometry_ids"][~miss] == 0) and np.all(np.isfinite(hits["t_hit"][~miss]))


# ---------------------------------------------------------------------------------------------
# 9. Python's profile rules are the tools' and docs/splines.md's.

def _scene_file(path, profile):
    path.write_text(json.dumps({
        "camera": {"from": [0, -5, 1], "to": [0, 0, 0.5], "up": [0, 0, 1], "fov": 40},
        "profiles": {"p": profile},
        "materials": {"m": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
        "objects": [{"profile": "p", "material": "m"}],
    }))
    return path


def test_a_tolerance_that_collapses_the_curve_onto_the_axis_is_refused(tmp_path):
    """Rule (the scene file's and --tolerance's): a tolerance whose polyline has every point on the
    axis (nothing could hit it) is a ValueError saying it collapses the curve onto the axis."""
    points = [[0, 0], [1, 0.5], [0, 1]]
    with pytest.raises(ValueError, match=r"collapses the quadratic spline onto the axis"):
        revolve.RaycastingScene().load(str(_scene_file(tmp_path / "scene.json", {"points": points, "spline": "quadratic", "tolerance": 10})))
    s = revolve.RaycastingScene()
    with pytest.raises(ValueError, match=r"tolerance.*collapses the quadratic spline onto the axis"):
        s.add_revolution(points, spline="quadratic", tolerance=10)
    assert s.geometry_count() == 0
    assert s.add_revolution(points, spline="quadratic", tolerance=0.4) == 0  # below the curve's largest r, 0.5


AXIS_CURVES = {
    "quadratic": [[0, 0], [0, 0.5], [0, 1]],
    "bezier": [[0, 0], [0, 0.3], [0, 0.6], [0, 1]],
    "catmull-rom": [[0, 0], [0, 0.5], [0, 1]],
    "natural": [[0, 0], [0, 0.5], [0, 1]],
}


@pytest.mark.parametrize("kind", sorted(AXIS_CURVES))
def test_a_curve_lying_on_the_axis_is_refused(kind, tmp_path):
    """Rule (docs/splines.md, Spline's crossesAxis): a curve may reach r = 0 only at a point it
    passes through; one lying on the axis between its points is refused, ProfileError (a ValueError)
    with rule "crosses_axis", from add_revolution, with or without a tolerance, and from a scene file."""
    points = AXIS_CURVES[kind]
    s = revolve.RaycastingScene()
    with pytest.raises(revolve.ProfileError) as refused:
        s.add_revolution(points, spline=kind)
    assert refused.value.rule == "crosses_axis" and isinstance(refused.value, ValueError)
    assert str(refused.value).startswith("points: ")
    with pytest.raises(revolve.ProfileError):
        s.add_revolution(points, spline=kind, tolerance=0.01)
    with pytest.raises(ValueError, match=r"axis"):
        s.load(str(_scene_file(tmp_path / "scene.json", {"points": points, "spline": kind})))
    assert s.geometry_count() == 0


def test_revolve_trace_refuses_a_curve_lying_on_the_axis(tmp_path):
    """Rule: revolve-trace --spline catmull-rom refuses the same curve (exit status not 0, a message
    about the axis), as Python does."""
    tool = BIN_DIR / "revolve-trace"
    if not tool.exists():
        pytest.fail(f"{tool} is missing: build the tools first")
    (tmp_path / "axis.csv").write_text("r,z\n0,0\n0,0.5\n0,1\n")
    (tmp_path / "rays.csv").write_text("ox,oy,oz,dx,dy,dz,tnear,tfar\n0.5,0,5,0,0,-1,0,inf\n")
    done = subprocess.run([str(tool), "--profile", str(tmp_path / "axis.csv"), "--rays", str(tmp_path / "rays.csv"), "--out",
                           str(tmp_path / "hits.csv"), "--spline", "catmull-rom"], capture_output=True, text=True, env=tool_env())
    assert done.returncode != 0 and "axis" in done.stderr, f"exit status {done.returncode}: {done.stderr}"


def test_curves_that_touch_the_axis_at_their_points_are_still_taken():
    """Rule (kept): reaching the axis at a point the curve passes through is fine (a vase closed at
    both ends); the linear kind is a polyline, validated as one."""
    s = revolve.RaycastingScene()
    assert s.add_revolution([[0, 0], [0.3, 0.1], [0.4, 0.5], [0, 1]], spline="catmull-rom") == 0
    assert s.add_revolution([[0, 0], [0.3, 0.1], [0.4, 0.5], [0.2, 0.8], [0, 1]], spline="quadratic") == 1
    assert s.add_revolution([[0, 0], [0.5, 0], [0.5, 1], [0, 1]], spline="linear") == 2


# ---------------------------------------------------------------------------------------------
# 10. A scan's beam count is checked without wrapping.

@pytest.mark.parametrize("poses", [2**22, 2**32, 2**53, 2**54, 2**63, 2**64 - 1])
def test_scan_file_beam_counts_are_checked_without_overflow(tmp_path, poses):
    """Rule: poses x beams a pose must lie in [1, 2^31 - 1]; 2^54 poses of a 1,024-beam sensor (whose
    product wraps a 64-bit count to 0) is refused like 2^22, and leaves no file or temporary."""
    lidar = revolve.Lidar({"pose": {"position": [0, 0, 0.5]}, "horizontal": {"samples": 1024, "min_angle": -3, "max_angle": 3},
                           "range": {"min": 0.1, "max": 10}})
    assert lidar.beams_per_pose == 1024
    with pytest.raises(ValueError, match=r"2\^31 - 1 points"):
        scan_file = revolve.ScanFile(tmp_path / "scan.pcd", lidar, poses)
        del scan_file
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------------------------------------
# 11. A sensor dict's bad value is named by its key path; numpy values are numbers.

SENSOR = {"pose": {"position": [0, 0, 0.3]}, "horizontal": {"samples": 8, "min_angle": -1, "max_angle": 1},
          "range": {"min": 0.1, "max": 10}}


@pytest.mark.parametrize(
    "where, value, key",
    [
        (("pose", "position", 2), math.nan, "pose.position[2]"),
        (("pose", "position", 0), math.inf, "pose.position[0]"),
        (("horizontal", "max_angle"), math.inf, "horizontal.max_angle"),
        (("range", "max"), -math.inf, "range.max"),
        (("range", "min"), math.nan, "range.min"),
    ],
)
def test_a_non_finite_sensor_value_is_named_by_its_key(where, value, key):
    """Rule: nan or inf in a sensor dict is a ValueError naming the key path (pose.position[2]), not
    the JSON text's column after json.dumps wrote it as NaN."""
    sensor = json.loads(json.dumps(SENSOR))
    holder = sensor
    for k in where[:-1]:
        holder = holder[k]
    holder[where[-1]] = value
    with pytest.raises(ValueError) as refused:
        revolve.Lidar(sensor)
    assert key in str(refused.value) and "not valid JSON" not in str(refused.value), str(refused.value)


def test_numpy_values_in_a_sensor_dict_are_numbers():
    """Rule: numpy arrays and scalars stand where the sensor takes lists and numbers; the sensor is
    the one the plain values make."""
    plain = revolve.Lidar(SENSOR)
    with_numpy = revolve.Lidar({"pose": {"position": np.array([0, 0, 0.3]), "yaw": np.float64(0)},
                                "horizontal": {"samples": np.int64(8), "min_angle": np.float64(-1), "max_angle": np.int32(1)},
                                "range": {"min": np.float64(0.1), "max": np.uint16(10)}})
    assert with_numpy.beams_per_pose == plain.beams_per_pose
    assert np.array_equal(with_numpy.azimuths, plain.azimuths) and np.array_equal(with_numpy.elevations, plain.elevations)
    poses = np.array([[0, 0, 0], [0.5, 0.2, 1]])
    a, b = plain.scan(ROBOT_WORLD, poses, threads=1), with_numpy.scan(ROBOT_WORLD, poses, threads=1)
    assert np.array_equal(a["ranges"], b["ranges"])


# ---------------------------------------------------------------------------------------------
# 12. Paths: str, pathlib.Path or any os.PathLike, everywhere a path is taken.

class FsPath:
    """An os.PathLike that is not a pathlib.Path."""

    def __init__(self, path):
        self.path = str(path)

    def __fspath__(self):
        return self.path


PATH_KINDS = {"pathlib": pathlib.Path, "PathLike": FsPath}


@pytest.fixture(scope="module")
def robot_files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("paths")
    return {"sensor": write_sensor(folder / "sensor.json", dict(NOISY_SENSOR, horizontal={"samples": 36, "min_angle": -3, "max_angle": 3})),
            "poses": write_poses(folder / "poses.csv", corridor_poses(3)), "folder": folder}


@pytest.mark.parametrize("kind", sorted(PATH_KINDS))
def test_every_path_argument_takes_path_likes(kind, robot_files, tmp_path):
    """Rule: every argument that names a file (load, Scene, Lidar, read_poses, Lidar.scan's scene
    and poses, cylinder_clearance's, scan_shard's, ScanFile's path and inputs) takes an os.PathLike
    as it takes the str, with the same result."""
    wrap = PATH_KINDS[kind]
    sensor, poses = robot_files["sensor"], robot_files["poses"]
    failures = []

    def same(name, call, expected):
        try:
            got = call()
        except Exception as error:  # noqa: BLE001 -- reported below
            failures.append(f"{name}: {type(error).__name__}: {error}")
            return
        if not expected(got):
            failures.append(f"{name}: not the str path's answer")

    ids = revolve.RaycastingScene().load(str(STILL_LIFE))
    same("RaycastingScene.load", lambda: revolve.RaycastingScene().load(wrap(STILL_LIFE)), lambda got: got == ids)
    counts = revolve.Scene(str(ROBOT_WORLD))
    same("Scene", lambda: revolve.Scene(wrap(ROBOT_WORLD)),
         lambda got: (got.object_count, got.quad_count) == (counts.object_count, counts.quad_count))
    lidar = revolve.Lidar(str(sensor))
    same("Lidar", lambda: revolve.Lidar(wrap(sensor)), lambda got: np.array_equal(got.azimuths, lidar.azimuths))
    read = revolve.read_poses(str(poses))
    same("read_poses", lambda: revolve.read_poses(wrap(poses)), lambda got: np.array_equal(got, read))
    scan = lidar.scan(str(ROBOT_WORLD), str(poses), threads=1)
    same("Lidar.scan", lambda: lidar.scan(wrap(ROBOT_WORLD), wrap(poses), threads=1),
         lambda got: np.array_equal(got["ranges"], scan["ranges"]))
    clearance = revolve.cylinder_clearance(str(ROBOT_WORLD), str(poses), 0.3, 0, 1)
    same("cylinder_clearance", lambda: revolve.cylinder_clearance(wrap(ROBOT_WORLD), wrap(poses), 0.3, 0, 1),
         lambda got: np.array_equal(got["clearance"], clearance["clearance"]))
    same("scan_shard", lambda: revolve.scan_shard(wrap(ROBOT_WORLD), wrap(sensor), wrap(poses), 0, 1),
         lambda got: np.array_equal(got["ranges"], scan["ranges"]))

    def scan_file(path, inputs):
        f = revolve.ScanFile(path, lidar, len(read), inputs=inputs)
        f.write(0, scan)
        f.commit()
        return pathlib.Path(os.fspath(path)).read_bytes()

    expected = scan_file(str(tmp_path / "str.csv"), [str(ROBOT_WORLD), str(sensor), str(poses)])
    same("ScanFile", lambda: scan_file(wrap(tmp_path / "wrapped.csv"), [wrap(ROBOT_WORLD), wrap(sensor), wrap(poses)]),
         lambda got: got == expected)
    assert not failures, "\n".join(failures)


def test_bytes_paths_name_the_same_file_or_are_refused_as_bytes(robot_files, tmp_path, monkeypatch):
    """Rule: a bytes path (os.fspath's other answer) either names the same file the str does, or is a
    TypeError; it is never read as the text "b'...'" (a 'cannot open' for a file that exists, or a
    file of that name created)."""
    monkeypatch.chdir(tmp_path)  # anything created under a mangled name lands here
    encode = os.fsencode
    sensor, poses = robot_files["sensor"], robot_files["poses"]
    lidar = revolve.Lidar(str(sensor))
    calls = {
        "RaycastingScene.load": lambda: revolve.RaycastingScene().load(encode(STILL_LIFE)),
        "Scene": lambda: revolve.Scene(encode(ROBOT_WORLD)),
        "Lidar": lambda: revolve.Lidar(encode(sensor)),
        "read_poses": lambda: revolve.read_poses(encode(poses)),
        "Lidar.scan": lambda: lidar.scan(encode(ROBOT_WORLD), encode(poses), threads=1),
        "cylinder_clearance": lambda: revolve.cylinder_clearance(encode(ROBOT_WORLD), encode(poses), 0.3, 0, 1),
        "scan_shard": lambda: revolve.scan_shard(encode(ROBOT_WORLD), encode(sensor), encode(poses), 0, 1),
        "ScanFile": lambda: revolve.ScanFile(encode(tmp_path / "out.csv"), lidar, 3, inputs=[encode(sensor)]),
    }
    failures = []
    for name, call in calls.items():
        try:
            call()
        except TypeError:
            pass
        except Exception as error:  # noqa: BLE001 -- reported below
            failures.append(f"{name}: {type(error).__name__}: {error}")
    stray = [p.name for p in tmp_path.iterdir() if p.name.startswith("b'")]
    assert not failures and not stray, "\n".join(failures + [f"created {stray}"])
