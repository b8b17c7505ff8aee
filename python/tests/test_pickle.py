"""Pickling, copy and deepcopy of RaycastingScene, Scene, Lidar and RangeSensors: the object built
again from its pickle answers every query bit for bit as the original, with the same geometry ids;
the pickle holds what builds it (a Scene's file texts, so that no file is needed to load it) and a
format version, another version being refused."""

import copy
import json
import multiprocessing
import pickle
import shutil

import numpy as np
import pytest

import revolve
from conftest import SOURCE_DIR
from pickle_child import cast_in_child
from robot_inputs import NOISY_SENSOR, corridor_poses

VASE = [[0, 0], [0.3, 0], [0.4, 0.3], [0.25, 0.7], [0.3, 0.9], [0, 0.9]]
# Points each spline kind takes (quadratic 2n + 1, bezier 3n + 1), closed on the axis at both ends.
SPLINE_POINTS = {
    "linear": VASE,
    "quadratic": [[0, 0], [0.5, 0], [0.5, 0.5], [0.5, 1], [0, 1]],
    "bezier": [[0, 0], [0.6, 0], [0.6, 1], [0, 1]],
    "catmull-rom": VASE,
    "natural": VASE,
}


def placement():
    """A similarity (rotation about a tilted axis, uniform scale, translation), so that every
    query, distances included, runs through the placement."""
    angle = 0.7
    c, s = np.cos(angle), np.sin(angle)
    rotation = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]) @ np.array([[1, 0, 0], [0, np.cos(0.3), -np.sin(0.3)], [0, np.sin(0.3), np.cos(0.3)]])
    matrix = np.eye(4)
    matrix[:3, :3] = 1.5 * rotation
    matrix[:3, 3] = [0.2, -0.1, 0.05]
    return matrix


def rays_at(center, count=4000, seed=1):
    """Rays from a sphere of radius 4 about `center` aimed near it: most hit."""
    rng = np.random.default_rng(seed)
    origins = rng.normal(size=(count, 3))
    origins = 4 * origins / np.linalg.norm(origins, axis=1, keepdims=True) + center
    targets = center + rng.uniform(-0.8, 0.8, size=(count, 3))
    return np.concatenate([origins, targets - origins], axis=1).astype(np.float32)


def points_near(center, count=2000, seed=2):
    return (center + np.random.default_rng(seed).uniform(-1.5, 1.5, size=(count, 3))).astype(np.float32)


def answers(scene, rays, points, solid):
    """Every query's arrays, as bytes (bit for bit, nan or not)."""
    out = {f"cast_rays.{k}": v.tobytes() for k, v in scene.cast_rays(rays).items()}
    out["test_occlusions"] = scene.test_occlusions(rays, tnear=0.5, tfar=5.0).tobytes()
    out["count_intersections"] = scene.count_intersections(rays).tobytes()
    out.update({f"list_intersections.{k}": v.tobytes() for k, v in scene.list_intersections(rays).items()})
    out.update({f"closest.{k}": v.tobytes() for k, v in scene.compute_closest_points(points).items()})
    out["compute_distance"] = scene.compute_distance(points).tobytes()
    if solid:
        out["compute_signed_distance"] = scene.compute_signed_distance(points).tobytes()
        out["compute_occupancy"] = scene.compute_occupancy(points).tobytes()
    return out


def assert_same_answers(original, rebuilt, rays, points, solid):
    assert rebuilt.geometry_count() == original.geometry_count()
    expected, got = answers(original, rays, points, solid), answers(rebuilt, rays, points, solid)
    assert expected.keys() == got.keys()
    for key in expected:
        assert got[key] == expected[key], key


def round_trip(obj, protocol=5):
    return pickle.loads(pickle.dumps(obj, protocol=protocol))


CASES = [("polyline", None, None)] + [(kind, kind, None) for kind in SPLINE_POINTS] + [
    (f"{kind} within 1e-4", kind, 1e-4) for kind in SPLINE_POINTS if kind != "linear"]


@pytest.mark.parametrize("name, spline, tolerance", CASES, ids=[c[0] for c in CASES])
def test_a_revolution_round_trips_bit_for_bit(name, spline, tolerance):
    scene = revolve.RaycastingScene()
    points = VASE if spline is None else SPLINE_POINTS[spline]
    geometry = scene.add_revolution(points, transform=placement(), spline=spline, tolerance=tolerance)
    center = placement()[:3, 3]
    rays = rays_at(center)
    hits = scene.cast_rays(rays)
    assert np.mean(hits["geometry_ids"] == geometry) > 0.3  # the comparison is about hits, not misses
    for protocol in (2, 5):
        rebuilt = round_trip(scene, protocol)
        assert type(rebuilt) is revolve.RaycastingScene
        assert_same_answers(scene, rebuilt, rays, points_near(center), solid=True)
    # What the pickle keeps is the profile as given, not a tessellation or Embree's memory.
    (kind, kept, transform, kept_spline, kept_tolerance), = scene._additions()
    assert kind == "revolution" and kept_spline == spline and kept_tolerance == tolerance
    assert np.array_equal(kept, np.asarray(points, float)) and np.array_equal(transform, placement())
    assert len(pickle.dumps(scene, protocol=5)) < 2000 < scene.memory_bytes()


def test_a_mesh_round_trips_and_its_arrays_travel_out_of_band():
    scene = revolve.RaycastingScene()
    vertices, triangles = revolve.tessellate(VASE, 48)
    vertices = np.asarray(vertices, np.float32)
    geometry = scene.add_triangles(vertices, triangles)
    rays, points = rays_at(np.zeros(3) + [0, 0, 0.45]), points_near(np.array([0, 0, 0.45]))
    assert np.mean(scene.cast_rays(rays)["geometry_ids"] == geometry) > 0.2
    buffers = []
    payload = pickle.dumps(scene, protocol=5, buffer_callback=buffers.append)
    # The vertex and index arrays go out of band, whole; the pickle itself is a few hundred bytes.
    sizes = sorted(memoryview(b).nbytes for b in buffers)
    assert sizes == sorted([vertices.size * 4, np.asarray(triangles).size * 4])
    assert len(payload) < 1000
    rebuilt = pickle.loads(payload, buffers=buffers)
    assert_same_answers(scene, rebuilt, rays, points, solid=False)
    assert_same_answers(scene, round_trip(scene, 4), rays, points, solid=False)


def test_a_mixed_scene_keeps_its_ids_in_order():
    scene = revolve.RaycastingScene()
    floor = np.array([[-30, -30, 0], [30, -30, 0], [30, 30, 0], [-30, 30, 0]], np.float32)
    ids = [scene.add_revolution(VASE, transform=placement(), spline="catmull-rom"),
           scene.add_triangles(floor, np.array([[0, 1, 2], [0, 2, 3]], np.int64)),
           *scene.load(SOURCE_DIR / "scenes" / "patio.json"),
           scene.add_revolution(SPLINE_POINTS["bezier"], spline="bezier", tolerance=1e-3)]
    assert ids == list(range(len(ids)))
    rebuilt = round_trip(scene)
    rays = rays_at(np.array([0, 0, 1.0]), count=20000)
    rays[:, :3] *= 2.5
    hit = scene.cast_rays(rays)["geometry_ids"]
    assert len(np.unique(hit)) > 10  # many geometries are hit, each by its own id
    assert_same_answers(scene, rebuilt, rays, points_near(np.array([0, 0, 1.0])), solid=False)
    # An addition after the round trip gets the next id in both.
    assert rebuilt.add_revolution(VASE) == scene.add_revolution(VASE) == len(ids)


def test_copy_and_deepcopy_are_independent_scenes():
    scene = revolve.RaycastingScene()
    scene.add_revolution(VASE, spline="natural")
    rays, points = rays_at(np.array([0, 0, 0.45])), points_near(np.array([0, 0, 0.45]))
    for duplicate in (copy.copy(scene), copy.deepcopy(scene)):
        assert duplicate is not scene
        assert_same_answers(scene, duplicate, rays, points, solid=True)
        duplicate.add_revolution(VASE, transform=placement())
        assert (duplicate.geometry_count(), scene.geometry_count()) == (2, 1)


def spawned_cast(payload, rays):
    with multiprocessing.get_context("spawn").Pool(1) as pool:
        return pool.apply(cast_in_child, (payload, rays))


def test_a_scene_sent_to_a_spawned_process_casts_the_same_rays():
    scene = revolve.RaycastingScene()
    scene.load(SOURCE_DIR / "scenes" / "patio.json")
    scene.add_revolution(VASE, transform=placement(), spline="catmull-rom", tolerance=1e-4)
    rays = rays_at(np.array([0, 0, 1.0]), count=5000)
    rays[:, :3] *= 2.0
    hits, count = spawned_cast(pickle.dumps(scene, protocol=5), rays)
    assert count == scene.geometry_count()
    expected = scene.cast_rays(rays)
    assert np.mean(expected["geometry_ids"] != revolve.RaycastingScene.INVALID_ID) > 0.3
    assert hits == {key: value.tobytes() for key, value in expected.items()}


def test_an_unknown_version_is_refused_naming_both_versions():
    class Forged:
        def __init__(self, obj, version):
            self.restore, args = obj.__reduce_ex__(5)
            self.args = (version, *args[1:])

        def __reduce__(self):
            return self.restore, self.args

    scene = revolve.RaycastingScene()
    scene.add_revolution(VASE)
    objects = [scene, revolve.Scene(SOURCE_DIR / "scenes" / "patio.json"), revolve.Lidar(NOISY_SENSOR),
               revolve.RangeSensors(SOURCE_DIR / "examples" / "robot" / "sonar_ring.json")]
    for obj in objects:
        assert type(round_trip(Forged(obj, 1))) is type(obj)  # the version this revolve writes loads
        with pytest.raises(ValueError, match=r"format version 99 is not supported; this revolve reads version 1"):
            pickle.loads(pickle.dumps(Forged(obj, 99)))
        with pytest.raises(ValueError, match=r"format version '2' is not supported"):
            pickle.loads(pickle.dumps(Forged(obj, "2")))


def scans_equal(a, b):
    assert a.keys() == b.keys()
    for key in a:
        assert a[key].tobytes() == b[key].tobytes(), key


@pytest.fixture
def patio_copy(tmp_path):
    """scenes/patio.json and the CSVs it reads, copied to a folder the test may delete."""
    folder = tmp_path / "patio"
    shutil.copytree(SOURCE_DIR / "scenes", folder)
    return folder


def test_a_scene_file_rebuilds_from_its_pickle_with_the_files_gone(patio_copy):
    poses = corridor_poses(6)
    lidar = revolve.Lidar(NOISY_SENSOR)
    for options in ({}, {"geometry": "mesh", "slices": 16}):
        scene = revolve.Scene(patio_copy / "patio.json", **options)
        expected = lidar.scan(scene, poses)
        assert np.isfinite(expected["ranges"]).mean() > 0.5
        path, text, csvs, geometry, slices = scene._sources()
        assert text == (patio_copy / "patio.json").read_bytes()
        assert csvs and all(open(name, "rb").read() == value for name, value in csvs.items())
        assert (geometry, slices) == (options.get("geometry", "mibit"), options.get("slices", 64))
        payload = pickle.dumps(scene, protocol=5)
        renamed = patio_copy.with_name("moved")
        patio_copy.rename(renamed)
        try:
            rebuilt = pickle.loads(payload)
            assert rebuilt.path == path and rebuilt.object_count == scene.object_count
            scans_equal(expected, lidar.scan(rebuilt, poses))
            scans_equal(expected, lidar.scan(copy.deepcopy(scene), poses))
            with pytest.raises(ValueError, match="cannot open"):
                revolve.Scene(path)  # the file really is gone
        finally:
            renamed.rename(patio_copy)
    # The build options travel: the mesh scan is not the exact one.
    exact, mesh = revolve.Scene(patio_copy / "patio.json"), revolve.Scene(patio_copy / "patio.json", "mesh", 16)
    assert lidar.scan(round_trip(exact), poses)["ranges"].tobytes() != lidar.scan(round_trip(mesh), poses)["ranges"].tobytes()


def test_a_scene_pickle_answers_clearance_as_the_original():
    scene = revolve.Scene(SOURCE_DIR / "scenes" / "robot_world.json")
    poses = corridor_poses(5)
    expected = revolve.cylinder_clearance(scene, poses, 0.3, 0.05, 1.2, ground=0.0)
    got = revolve.cylinder_clearance(round_trip(scene), poses, 0.3, 0.05, 1.2, ground=0.0)
    assert expected.keys() == got.keys()
    for key in expected:
        assert np.asarray(expected[key]).tobytes() == np.asarray(got[key]).tobytes(), key


def test_a_lidar_with_a_beam_pattern_rebuilds_with_its_files_gone(tmp_path):
    folder = tmp_path / "sensor"
    folder.mkdir()
    for name in ("lidar_vlp16_pattern.json", "vlp16_pattern.csv"):
        shutil.copy(SOURCE_DIR / "examples" / "robot" / name, folder / name)
    lidar = revolve.Lidar(folder / "lidar_vlp16_pattern.json")
    file, text, patterns = lidar._sources()
    assert text == (folder / "lidar_vlp16_pattern.json").read_bytes()
    assert patterns == {str(folder / "vlp16_pattern.csv"): (folder / "vlp16_pattern.csv").read_bytes()}
    scene = revolve.Scene(SOURCE_DIR / "scenes" / "robot_world.json")
    poses = corridor_poses(3)
    expected = lidar.scan(scene, poses)
    payload = pickle.dumps(lidar, protocol=5)
    shutil.rmtree(folder)
    rebuilt = pickle.loads(payload)
    assert rebuilt.beams_per_pose == lidar.beams_per_pose
    scans_equal(expected, rebuilt.scan(scene, poses))
    scans_equal(expected, copy.deepcopy(lidar).scan(scene, poses))
    with pytest.raises(ValueError, match="cannot open"):
        revolve.Lidar(file)


def test_a_lidar_from_a_dict_and_range_sensors_round_trip():
    scene = revolve.Scene(SOURCE_DIR / "scenes" / "robot_world.json")
    poses = corridor_poses(4)
    lidar = revolve.Lidar(NOISY_SENSOR)
    scans_equal(lidar.scan(scene, poses), round_trip(lidar).scan(scene, poses))
    scans_equal(lidar.scan(scene, poses), copy.copy(lidar).scan(scene, poses))
    sonars = revolve.RangeSensors(SOURCE_DIR / "examples" / "robot" / "sonar_ring.json")
    expected = sonars.read(scene, poses)
    assert np.isfinite(expected["range"]).any()
    rebuilt = round_trip(sonars)
    assert rebuilt.names == sonars.names
    scans_equal(expected, rebuilt.read(scene, poses))


def test_a_pickle_missing_a_file_text_is_refused_naming_the_file(tmp_path):
    # Rebuilding reads no file: a text the pickle lacks is refused, named as the original named it,
    # even where the file itself exists.
    scene = revolve.Scene(SOURCE_DIR / "scenes" / "patio.json")
    restore, (version, path, text, csvs, geometry, slices) = scene.__reduce_ex__(5)
    (csv,) = csvs
    with pytest.raises(ValueError, match=rf"{csv}: not among the files supplied"):
        restore(version, path, text, {}, geometry, slices)
    with pytest.raises(ValueError, match=rf"{csv}:2"):
        restore(version, path, text, {csv: b"r,z\nnot a number,0\n"}, geometry, slices)
    lidar = revolve.Lidar(SOURCE_DIR / "examples" / "robot" / "lidar_vlp16_pattern.json")
    restore, (version, file, text, patterns) = lidar.__reduce_ex__(5)
    (pattern,) = patterns
    with pytest.raises(ValueError, match=rf"pattern: {pattern}: not among the files supplied"):
        restore(version, file, text, {})


def test_a_loaded_scene_with_toleranced_splines_round_trips(tmp_path):
    # load() keeps a spline traced within a tolerance as the polyline it traces.
    folder = tmp_path / "scenes"
    shutil.copytree(SOURCE_DIR / "scenes", folder)
    description = json.loads((folder / "spline_still_life.json").read_text())
    curved = [p for p in description["profiles"].values() if p.get("spline", "linear") != "linear"]
    assert len(curved) >= 3
    for profile in curved:
        profile["tolerance"] = 1e-3
    (folder / "toleranced.json").write_text(json.dumps(description))
    scene = revolve.RaycastingScene()
    scene.load(folder / "toleranced.json")
    revolutions = [a for a in scene._additions() if a[0] == "revolution"]
    assert len(revolutions) == len(description["objects"]) and all(a[3] is None for a in revolutions)  # polylines
    rays = rays_at(np.array([0, 0, 0.5]), count=10000)
    rays[:, :3] *= 1.5
    assert np.mean(scene.cast_rays(rays)["geometry_ids"] != revolve.RaycastingScene.INVALID_ID) > 0.3
    assert_same_answers(scene, round_trip(scene), rays, points_near(np.array([0, 0, 0.5])), solid=False)
