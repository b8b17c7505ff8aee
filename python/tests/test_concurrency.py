"""Queries racing additions: RaycastingScene is used from several Python threads
at once, every kind of query on some while another adds geometry of every kind (add_revolution with
and without a transform, add_revolutions, add_triangles, load). The rule: no crash, and every answer is one the scene
could give at some moment: the probes never see the added geometry (it lies far away), so each
answers exactly as before any addition; counts are never negative; geometry_count never goes back;
an id the writer got back is at once traced by its own next query; and a signed distance or an
occupancy is refused (ValueError) only once a mesh is in the scene.

The race runs in a child interpreter (this file run as a script), so that a crash fails the test
rather than killing pytest. Nothing is timed: the writer waits, after each addition, until every
reader has made a whole query since, so the threads interleave whatever the machine's speed. The
scene starts with a thousand small revolutions (far from the probes), so that each rebuild after an
addition takes long enough for the other threads to meet it there."""

import json
import pathlib
import sys
import threading

if __name__ != "__main__":
    import pytest

    from isolated import how_it_ended, run_python

CAN = [[0, 0], [1, 0], [1, 1], [0, 1]]
READERS = 3
PREPOPULATED = 300  # revolutions in a row at y = -50, before the threads start
ADDITIONS = 120

# Probes near the can (radius 1, z from 0 to 1, at the origin): steep or vertical rays, which leave
# the slab 0 <= z <= 1 (where everything added lies, 9 or more away) within a few units.
PROBE_RAYS = [
    [0.5, 0, 5, 0, 0, -1],  # down through the lid and the floor
    [0.3, 0.2, -3, 0.05, 0.02, 1],  # up through the floor and the lid
    [-3, 0, 0.2, 1, 0, 0.25],  # in through the side, out through the lid
    [3, 3, 5, 0, 0, -1],  # beside the can: no hit at all
    [0.2, 0, 0.5, 0, 0, 1],  # from inside, out through the lid
]
PROBE_POINTS = [[0.5, 0, 2], [0.2, 0.1, 0.5], [2, 0, 0.5], [0, 0, -1]]


def _stress(mode, folder):
    import numpy as np

    import revolve

    s = revolve.RaycastingScene()
    assert s.add_revolution(CAN) == 0
    small = [[0, 0], [0.1, 0], [0.1, 1], [0, 1]]
    for i in range(PREPOPULATED):
        m = np.eye(4)
        m[:3, 3] = [10 + 3 * i, -50, 0]
        s.add_revolution(small, transform=m)
    rays = np.array(PROBE_RAYS * 300, np.float32)  # 1500 rays: two of the queries' 1024-ray blocks
    points = np.array(PROBE_POINTS * 300, np.float32)

    queries = {
        "cast_rays": lambda n: s.cast_rays(rays, nthreads=n),
        "test_occlusions": lambda n: s.test_occlusions(rays, nthreads=n),
        "count_intersections": lambda n: s.count_intersections(rays, nthreads=n),
        "list_intersections": lambda n: s.list_intersections(rays, nthreads=n),
        "compute_closest_points": lambda n: s.compute_closest_points(points, nthreads=n),
        "compute_distance": lambda n: s.compute_distance(points, nthreads=n),
        "compute_signed_distance": lambda n: s.compute_signed_distance(points, nthreads=n),
        "compute_occupancy": lambda n: s.compute_occupancy(points, nthreads=n),
        "memory_bytes": lambda n: s.memory_bytes(),
        "geometry_count": lambda n: s.geometry_count(),
    }
    reference = {name: query(1) for name, query in queries.items() if name not in ("memory_bytes", "geometry_count")}
    assert (reference["count_intersections"] >= 0).all()

    failures, lock = [], threading.Lock()
    mesh_added = threading.Event()
    writing = threading.Event()
    writing.set()
    progress = [0] * READERS
    calls_while_writing = {name: 0 for name in queries}
    turn = threading.Condition()

    def fail(text):
        with lock:
            if len(failures) < 20:
                failures.append(text)

    def same(a, b):
        if isinstance(b, dict):
            return a.keys() == b.keys() and all(np.array_equal(a[k], b[k], equal_nan=True) for k in b)
        return a.dtype == b.dtype and np.array_equal(a, b, equal_nan=True)

    def check(name, result, last_count):
        if name == "memory_bytes":
            if not (isinstance(result, int) and 0 < result < 2**40):
                fail(f"memory_bytes() = {result!r}")
        elif name == "geometry_count":
            if not (isinstance(result, int) and last_count <= result <= 1 + PREPOPULATED + 3 * ADDITIONS):
                fail(f"geometry_count() = {result!r} after {last_count}")
            return result
        elif name == "count_intersections" and (result < 0).any():
            fail(f"count_intersections: negative counts {result[result < 0][:5].tolist()}")
        elif not same(result, reference[name]):
            fail(f"{name}: an answer that differs from the scene's before any addition")
        return last_count

    def reader(j):
        names = list(queries)
        last_count, k = 0, j
        while writing.is_set() or k < j + 2 * len(names):
            name = names[k % len(names)]
            threads = (0, 1, 2)[k % 3]
            k += 1
            during = writing.is_set()
            try:
                result = queries[name](threads)
            except ValueError as error:
                solid = name in ("compute_signed_distance", "compute_occupancy")
                if not (solid and mesh_added.is_set() and "mesh" in str(error)):
                    fail(f"{name}: ValueError: {error}")
            except Exception as error:  # noqa: BLE001 -- reported
                fail(f"{name}: {type(error).__name__}: {error}")
            else:
                try:
                    last_count = check(name, result, last_count)
                except Exception as error:  # noqa: BLE001 -- an answer the checks cannot even read
                    fail(f"{name}: checking {result!r:.200}: {type(error).__name__}: {error}")
            with turn:
                progress[j] += 1
                if during:
                    calls_while_writing[name] += 1
                turn.notify_all()

    scene_file = pathlib.Path(folder) / "far.json"
    scene_file.write_text(json.dumps({
        "camera": {"from": [0, -5, 1], "to": [0, 0, 0.5], "up": [0, 0, 1], "fov": 40},
        "profiles": {"post": {"points": [[0, 0], [0.2, 0], [0.2, 1], [0, 1]]}},
        "materials": {"m": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
        "objects": [{"profile": "post", "material": "m", "translate": [-500, 500, 0]},
                    {"profile": "post", "material": "m", "translate": [-505, 500, 0]}],
        "quads": [{"corners": [[-600, 600, 0.5], [-590, 600, 0.5], [-590, 610, 0.5], [-600, 610, 0.5]], "material": "m"}],
    }))
    ring = [[5000, 0], [5001, 0], [5001, 1], [5000, 1], [5000, 0]]  # about the axis, 5000 away: no transform needed
    triangles = (np.array([[-1000, -1000, 0], [-999, -1000, 0], [-999, -999, 1], [-1000, -999, 1]], np.float32),
                 np.array([[0, 1, 2], [0, 2, 3]], np.uint32))
    kinds = ["transform", "no transform", "bulk"] if mode == "revolutions" else ["transform", "no transform", "bulk", "triangles", "load"]

    threads = [threading.Thread(target=reader, args=(j,)) for j in range(READERS)]
    for t in threads:
        t.start()
    count, visible = s.geometry_count(), 0
    for i in range(ADDITIONS):
        # Meshes only in the second half: the first races the signed queries too.
        kind = kinds[i % 2] if i < ADDITIONS // 2 else kinds[i % len(kinds)]
        if kind == "transform":
            m = np.eye(4)
            m[:3, :3] *= 0.5 + (i % 3) * 0.25  # a similarity: distances stay exact
            m[:3, 3] = [10 + 3 * i, 50, 0]
            ids = [s.add_revolution(small, transform=m)]
            # The writer's own next query sees what it added, under its id.
            x = np.float32(10 + 3 * i)
            hit = s.cast_rays(np.array([[x, 40, 0.25, 0, 1, 0]], np.float32), nthreads=(i % 2) * 2)
            if hit["geometry_ids"][0] != ids[0] or not abs(hit["t_hit"][0] - (10 - 0.1 * m[0, 0])) < 1e-4:
                fail(f"addition {i}: the ray at geometry {ids[0]} hit {hit['geometry_ids'][0]} at t = {hit['t_hit'][0]}")
            visible += 1
        elif kind == "no transform":
            ids = [s.add_revolution(ring)]
        elif kind == "bulk":
            # Two at once (add_revolutions builds them on TBB's threads without the GIL), at y = 70 and 80.
            m = np.stack([np.eye(4)] * 2)
            m[:, :3, 3] = [[10 + 3 * i, 70, 0], [10 + 3 * i, 80, 0]]
            ids = list(s.add_revolutions(np.array([small, small], np.float64), transforms=m))
            x = np.float32(10 + 3 * i)
            hit = s.cast_rays(np.array([[x, 75, 0.25, 0, 1, 0]], np.float32), nthreads=(i % 2) * 2)
            if len(ids) != 2 or hit["geometry_ids"][0] != ids[1] or not abs(hit["t_hit"][0] - 4.9) < 1e-4:
                fail(f"addition {i}: ids {ids}; the ray towards the second hit {hit['geometry_ids'][0]} at t = {hit['t_hit'][0]}")
            visible += 1
        elif kind == "triangles":
            mesh_added.set()
            ids = [s.add_triangles(*triangles)]
        else:
            mesh_added.set()
            ids = s.load(str(scene_file))
        if ids != list(range(count, count + len(ids))):
            fail(f"addition {i} ({kind}): ids {ids}, expected from {count}")
        count += len(ids)
        with turn:  # every reader makes a whole query after this addition before the next
            target = [p + 2 for p in progress]
            turn.wait_for(lambda: all(progress[j] >= target[j] or not threads[j].is_alive() for j in range(READERS)))
    writing.clear()
    for t in threads:
        t.join()
    if s.geometry_count() != count:
        fail(f"geometry_count() = {s.geometry_count()} at the end, {count} added")
    for name in ("cast_rays", "test_occlusions", "count_intersections", "compute_closest_points", "compute_distance"):
        if not same(queries[name](0), reference[name]):
            fail(f"{name} after the additions: differs from before them")
    print(json.dumps({"failures": failures, "calls_while_writing": calls_while_writing, "visible": visible}), flush=True)


if __name__ == "__main__":
    _stress(sys.argv[1], sys.argv[2])
    sys.exit(0)


@pytest.mark.parametrize("mode", ["revolutions", "every kind of geometry"])
def test_queries_of_every_kind_racing_additions(mode, tmp_path):
    """Rule: queries of every kind on three threads while a fourth adds geometry neither crash nor
    answer anything the scene could not have answered (see the module's docstring)."""
    done = run_python(pathlib.Path(__file__), "revolutions" if mode == "revolutions" else "all", tmp_path, cwd=tmp_path)
    assert done.returncode == 0, f"the racing threads' interpreter ended with {how_it_ended(done)}"
    report = json.loads(done.stdout.strip().splitlines()[-1])
    assert not report["failures"], "\n".join(report["failures"])
    # Every kind of query ran while additions were going on (the writer waited for them).
    assert all(n > 0 for n in report["calls_while_writing"].values()), report["calls_while_writing"]
    assert report["visible"] > 0
