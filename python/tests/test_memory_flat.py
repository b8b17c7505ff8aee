"""Memory does not grow with the number of calls: a query or scan run on more
than one thread, called over and over, holds the process at the same resident size. (Each threaded
call used to leave a TBB task_arena behind, 5 to 7 KB at two threads, more with more.)

Each function runs in a child interpreter (this file run as a script): a warm-up, then N calls,
then 9 N more; the resident size (VmRSS) after the 10 N must be within TOLERANCE of that after the
N. At 5 KB a call the 9 N = 5,400 calls would add 27 MB; the tolerance, 3 MiB, is nine times
smaller, and far above what numpy's and the allocator's own churn moves (nothing at all, measured
on one thread). Nothing is timed.

The calls are made cheap (an empty scene, or beams that miss everything; 1,025 rays or points, one
more than the queries' block of 1,024, so that a second thread takes part): a call that ends before
the second thread has joined it is what left its arena behind. A second set of cases does real
work on the can, as a guard for the fixed code."""

import json
import sys

if __name__ != "__main__":
    import pytest

    from isolated import how_it_ended, run_python

WARM_UP = 300
N = {"cheap": 600, "real": 300}  # the real work's 2,700 calls would add 13 to 19 MB
TOLERANCE = 3 * 2**20

POLE_SCENE = {"camera": {"from": [0, -5, 1], "to": [2, 0, 1], "up": [0, 0, 1], "fov": 40},
              "profiles": {"pole": {"points": [[0, 0], [0.1, 0], [0.1, 2], [0, 2]]}},
              "materials": {"grey": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
              "objects": [{"profile": "pole", "material": "grey", "translate": [2, 0, 0]}]}


def _resident_bytes():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024
    raise RuntimeError("no VmRSS in /proc/self/status")


def _calls(function, threads, work, folder):
    import pathlib

    import numpy as np

    import revolve

    s = revolve.RaycastingScene()
    if work == "cheap":
        rays = np.tile(np.array([[100, 100, 100, 1, 0, 0]], np.float32), (1025, 1))
        points = np.tile(np.array([[0.5, 0, 2]], np.float32), (1025, 1))
        beams, facing = 257, (2, 4)  # one more than Lidar's block of 256 beams, all facing away from the pole
    else:
        s.add_revolution([[0, 0], [1, 0], [1, 1], [0, 1]])
        rays = np.array([[0.5, 0, 5, 0, 0, -1], [3, 3, 5, 0, 0, -1]] * 1024, np.float32)
        points = np.array([[0.5, 0, 2], [2, 0, 0.5]] * 1024, np.float32)
        beams, facing = 720, (-3, 3)
    scene_file = pathlib.Path(folder) / "pole.json"
    scene_file.write_text(json.dumps(POLE_SCENE))
    scene = revolve.Scene(scene_file)
    lidar = revolve.Lidar({"pose": {"position": [0, 0, 1]}, "horizontal": {"samples": beams, "min_angle": facing[0], "max_angle": facing[1]},
                           "range": {"min": 0.1, "max": 10}})
    poses = np.array([[0, 0, 0]] if work == "cheap" else [[0.5 * i, 0.1 * i, 0.2 * i] for i in range(2)])
    return {
        "cast_rays": lambda: s.cast_rays(rays, nthreads=threads),
        "test_occlusions": lambda: s.test_occlusions(rays, nthreads=threads),
        "count_intersections": lambda: s.count_intersections(rays, nthreads=threads),
        "compute_closest_points": lambda: s.compute_closest_points(points, nthreads=threads),
        "compute_distance": lambda: s.compute_distance(points, nthreads=threads),
        "compute_signed_distance": lambda: s.compute_signed_distance(points, nthreads=threads),
        "compute_occupancy": lambda: s.compute_occupancy(points, nthreads=threads),
        "Lidar.scan": lambda: lidar.scan(scene, poses, threads=threads),
        "cylinder_clearance": lambda: revolve.cylinder_clearance(scene, np.array([[0, 0, 0], [5, 0, 0]]), 0.3, 0.05, 1.2, threads=threads),
    }[function]


def _measure(function, threads, work, folder):
    call = _calls(function, threads, work, folder)
    for _ in range(WARM_UP):
        call()
    after_n, n = 0, N[work]
    for i in range(10 * n):
        call()
        if i == n - 1:
            after_n = _resident_bytes()
    print(json.dumps({"after_n": after_n, "after_10n": _resident_bytes()}), flush=True)


if __name__ == "__main__":
    _measure(sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4])
    sys.exit(0)


FUNCTIONS = ["cast_rays", "test_occlusions", "count_intersections", "compute_closest_points", "compute_distance",
             "compute_signed_distance", "compute_occupancy", "Lidar.scan", "cylinder_clearance"]
CASES = ([(f, 2, "cheap") for f in FUNCTIONS] + [(f, 0, "cheap") for f in ("cast_rays", "compute_distance", "Lidar.scan", "cylinder_clearance")]
         + [(f, 0, "real") for f in ("cast_rays", "compute_distance", "Lidar.scan")])


@pytest.mark.parametrize("function, threads, work", CASES)
def test_resident_memory_is_flat_over_repeated_threaded_calls(function, threads, work, tmp_path):
    """Rule: after a warm-up, the resident size after 10 N calls is that after N, within 3 MiB (the
    arena each call left would add 27 MB over the cheap calls' 9 N)."""
    import os
    import pathlib

    if os.environ.get("REVOLVE_SANITIZED"):
        pytest.skip("under AddressSanitizer the resident size measures its quarantine of freed memory, not the "
                    "package's: the Release suite holds this rule")
    done = run_python(pathlib.Path(__file__), function, threads, work, tmp_path)
    assert done.returncode == 0, f"the child ended with {how_it_ended(done)}"
    sizes = json.loads(done.stdout.strip().splitlines()[-1])
    growth, calls = sizes["after_10n"] - sizes["after_n"], 9 * N[work]
    assert growth < TOLERANCE, (f"{function}(threads={threads}): the process grew {growth / 2**20:.1f} MiB over {calls} calls "
                                f"({growth / calls:.0f} bytes a call): {sizes}")
