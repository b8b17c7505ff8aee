"""A seeded fuzz of the bindings' argument handling: random values (nested and ragged lists, numpy
arrays of every kind of dtype, shape, byte order and layout, paths as str, bytes, pathlib.Path and
other os.PathLike, thread counts huge and negative, None, strings, numbers of every kind) handed to
every function and method of the package that takes arguments.

The rule: every call either returns or raises TypeError or ValueError (revolve.ProfileError is a
ValueError) with a message of one non-empty line; never a crash, never another exception
(RuntimeError, SystemError, KeyError, OSError, MemoryError...), never pybind's "Unable to cast"
text or its multi-line "incompatible function arguments" listing.

The calls run in child interpreters (this file run as a script), in batches; a child that dies
during a call charges that call with the crash and a new child carries on from the next. Case i
of seed S is always the same call (its own random.Random(f"S/i")), so one failure can be run again
alone: `python3 test_argument_fuzz.py S i i+1 FOLDER` (PYTHONPATH as for the tests).

REVOLVE_FUZZ_SEED (default 20260101) and REVOLVE_FUZZ_CASES (default 1500) choose the cases."""

import json
import os
import sys

SEED = int(os.environ.get("REVOLVE_FUZZ_SEED", "20260101"))
CASES = int(os.environ.get("REVOLVE_FUZZ_CASES", "1500"))
ALLOWED = ("TypeError", "ValueError")

if __name__ != "__main__":
    import pathlib

    from conftest import SOURCE_DIR
    from isolated import child_env, how_it_ended, run_python


# ---------------------------------------------------------------------------------------------
# The child: builds case i from its seed, runs it, reports its outcome as a line of JSON.

class FsPath:
    """An os.PathLike that is not a pathlib.Path (its __fspath__ may return str or bytes)."""

    def __init__(self, path):
        self.path = path

    def __fspath__(self):
        return self.path

    def __repr__(self):
        return f"FsPath({self.path!r})"


class Tensorish:
    """Something with .numpy(), as Open3D's tensors, answering an array."""

    def __init__(self, array):
        self.array = array

    def numpy(self):
        return self.array

    def __repr__(self):
        return f"Tensorish({describe(self.array)})"


def describe(value, depth=0):
    import numpy as np

    if isinstance(value, np.ndarray):
        layout = "C" if value.flags.c_contiguous else "F" if value.flags.f_contiguous else "strided"
        return f"ndarray(shape={value.shape}, dtype={value.dtype.str}, {layout}{'' if value.flags.writeable else ', read-only'})"
    if isinstance(value, (list, tuple)) and depth < 2:
        inner = ", ".join(describe(v, depth + 1) for v in value[:6]) + (", ..." if len(value) > 6 else "")
        return ("[%s]" if isinstance(value, list) else "(%s)") % inner
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k!r}: {describe(v, depth + 1)}" for k, v in list(value.items())[:6]) + "}"
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


class Maker:
    """The random values of one case."""

    def __init__(self, rng, files):
        import numpy as np

        self.rng, self.np, self.files = rng, np, files

    def chance(self, p):
        return self.rng.random() < p

    def pick(self, options):
        return options[self.rng.randrange(len(options))]

    def number(self):
        np = self.np
        return self.pick([0, 1, -1, 0.5, 3, float("nan"), float("inf"), -float("inf"), 1e300, -1e-300, 2**31, 2**63, 2**64, -(2**63),
                          True, np.float32(0.3), np.float64(2.5), np.int64(5), np.uint64(2**63), np.float16(1), 1 + 2j, "1", b"1",
                          None, [], [1.0], {}, object()])

    def threads(self):
        np = self.np
        return self.pick([0, 1, 2, -1, -(2**31), 1024, 1025, 65537, 10**7, 2**31 - 1, 2**31, 2**63, 2**64, None, "2", b"2", 2.0,
                          2.5, True, np.int32(2), np.int64(-3), np.uint8(4), float("nan"), [2]])

    def count(self):
        np = self.np
        return self.pick([0, 1, 2, 3, 12, -1, 2**22, 2**31, 2**54, 2**63, 2**64 - 1, 2**64, None, "12", 12.0, 12.5, True,
                          np.int64(12), np.uint64(12), float("inf")])

    def string(self, valid):
        return self.pick(valid + ["", "CUBIC", "linear ", "catmull_rom", 3, None, b"linear", ["linear"], 0.5, "\x00"])

    def values(self, shape):
        np = self.np
        size = int(np.prod(shape)) if shape else 1
        kind = self.rng.randrange(6)
        if kind == 0:
            data = np.array([self.rng.uniform(-2, 2) for _ in range(size)])
        elif kind == 1:
            data = np.array([self.rng.uniform(0, 2) for _ in range(size)])
        elif kind == 2:
            data = np.array([self.pick([0.0, 1.0, -1.0, 0.5, float("nan"), float("inf"), 1e13, -1e-40, 2e12]) for _ in range(size)])
        else:
            data = np.array([self.rng.uniform(0, 1.5) for _ in range(size)])
        return data.reshape(shape)

    def array(self, width, rows=(1, 6), valid_dtype="float32"):
        """An array-like meant to be (N, width), or something hostile in its place."""
        np = self.np
        n = self.rng.randint(*rows)
        if self.chance(0.4):  # what the caller should pass
            return np.ascontiguousarray(self.values((n, width)), dtype=valid_dtype)
        if self.chance(0.55):
            shape = (n, width)
        else:
            shape = self.pick([(n, width + 1), (n, max(width - 1, 0)), (width,), (), (0, width), (n, 1, width), (2, 3, width),
                               (n, width, 1), (0,), (1, 0)])
        data = self.values(shape)
        form = self.rng.randrange(12)
        if form == 0:
            return data.tolist()  # nested lists
        if form == 1:
            rows_ = data.reshape(-1, width).tolist() if data.size and data.size % width == 0 else [[0.0] * width]
            if rows_:
                rows_[self.rng.randrange(len(rows_))] = self.pick([[1.0], [], [1.0] * (width + 1), [[1.0]] * width, None, "ab",
                                                                   [1.0, [2.0]], [float("nan")] * width])
            return rows_  # ragged, or with a stray element
        if form == 2:
            return self.pick([None, "points.csv", b"\x00\x01", 3, 2.5, {}, {"a": 1}, set(), iter([[0, 0], [1, 1]]), object(),
                              (1, 2), [[]], [], ((0, 0), (1, 1)), FsPath("x")])
        dtype = self.pick([valid_dtype, valid_dtype, "float32", "float64", "float16", ">f4", ">f8", "<f4", "int8", "uint8", "int64",
                           "uint64", ">i8", "bool", "complex64", "complex128", "object", "U3", "S3", "datetime64[s]", "V4",
                           np.dtype("f4").newbyteorder("=")])
        try:
            array = data.astype(dtype)
        except (TypeError, ValueError):
            array = data.astype("float32")
        layout = self.rng.randrange(7)
        if layout == 0 and array.ndim >= 2:
            array = np.asfortranarray(array)
        elif layout == 1 and array.ndim >= 1:
            bigger = np.zeros((array.shape[0] * 2,) + array.shape[1:], array.dtype)
            bigger[::2] = array
            array = bigger[::2]  # a strided view
        elif layout == 2:
            array = array.copy()
            array.flags.writeable = False
        elif layout == 3 and array.ndim >= 2 and array.shape[-1] > 1:
            array = np.ascontiguousarray(array[..., ::-1])[..., ::-1]  # negative strides
        elif layout == 4:
            return Tensorish(array)
        elif layout == 5:
            return tuple(map(tuple, array.reshape(-1, width).tolist())) if array.size and array.size % width == 0 and array.dtype.kind in "fiub" else array
        return array

    def path(self, kind):
        """A path meant to name a file of `kind`, in one of the forms a path takes, or something hostile."""
        files = self.files
        target = self.pick([files[kind]] * 4 + [files["missing"], files["folder"], files["empty"], files["garbage"],
                                                files["other"][kind]])
        form = self.rng.randrange(9)
        if form == 0:
            return os.fsencode(target)
        if form == 1:
            import pathlib

            return pathlib.Path(target)
        if form == 2:
            return FsPath(target)
        if form == 3:
            return FsPath(os.fsencode(target))
        if form == 4:
            return self.pick([None, 3, [target], {"path": target}, "", "\x00bad", target + "\x00", 2.5])
        return target

    def sensor(self):
        np = self.np
        sensor = {"pose": {"position": [0.1, 0.0, 0.7]}, "horizontal": {"samples": 16, "min_angle": -3, "max_angle": 3},
                  "range": {"min": 0.1, "max": 10}}
        for _ in range(self.rng.randrange(3)):
            where = self.pick([("pose", "position"), ("pose", "yaw"), ("horizontal", "samples"), ("horizontal", "max_angle"),
                               ("range", "min"), ("range", "max"), ("noise",), ("vertical",), ("pose",), ("extra",)])
            value = self.pick([self.number(), np.array([0, 0, 0.3]), np.array([0, 0]), [0, 0, float("nan")], [0, "a", 0],
                               {"samples": 4, "min_angle": -0.1, "max_angle": 0.1}, {"mean": 0, "stddev": 0.01, "seed": np.uint64(7)},
                               np.int64(8), np.float32(2.0), [[0, 0, 0]], "", None])
            holder = sensor
            for key in where[:-1]:
                holder = holder.setdefault(key, {}) if isinstance(holder.get(key, {}), dict) else {}
            holder[where[-1]] = value
        return sensor


def make_case(seed, i, files, objects):
    """(description, call) of case i."""
    import random

    import numpy as np

    import revolve

    rng = random.Random(f"{seed}/{i}")
    m = Maker(rng, files)
    can, lidar, tool_scene = objects["can"], objects["lidar"], objects["scene"]
    spline_points = {"quadratic": 3, "bezier": 4}
    function = m.pick(["add_revolution", "add_revolution", "add_revolutions", "add_triangles", "load", "cast_rays", "test_occlusions",
                       "count_intersections", "list_intersections", "compute_closest_points", "compute_distance", "compute_signed_distance",
                       "compute_occupancy", "create_rays_pinhole", "Scene", "Lidar", "Lidar.scan", "ScanFile", "ScanFile.write",
                       "cylinder_clearance", "read_poses", "scan_shard", "shard_poses", "tessellate"])
    args, kwargs = [], {}

    def maybe(name, make, p=0.6):
        if m.chance(p):
            kwargs[name] = make()

    if function == "add_revolution":
        kind = m.string(["linear", "quadratic", "bezier", "catmull-rom", "natural"]) if m.chance(0.5) else None
        rows = (spline_points.get(kind, 2), 7) if isinstance(kind, str) else (1, 7)
        args = [m.array(2, rows=rows, valid_dtype="float64")]
        if kind is not None or m.chance(0.2):
            kwargs["spline"] = kind
        maybe("transform", lambda: m.array(4, rows=(4, 4), valid_dtype="float64") if m.chance(0.7) else m.pick(
            [np.eye(4), np.diag([2.0, 2.0, 2.0, 1.0]), np.eye(4).tolist(), None]), 0.4)
        maybe("tolerance", lambda: m.pick([0.01, 0.5, 10.0, 0, -1, float("nan"), "0.1", [0.1], None, np.float32(0.1), True, 1e-300]), 0.3)
        call = lambda: revolve.RaycastingScene().add_revolution(*args, **kwargs)  # noqa: E731
    elif function == "add_revolutions":
        count = m.pick([1, 2, 3])
        profiles = [m.array(2, rows=(2, 6), valid_dtype="float64") for _ in range(count)]
        form = m.rng.randrange(4)
        if form == 0:  # an (N, P, 2) array when the profiles are arrays of one shape, else the list
            try:
                args = [np.stack([np.asarray(p, dtype="float64") for p in profiles])]
            except (TypeError, ValueError):
                args = [profiles]
        elif form == 1:
            args = [profiles]  # a sequence of (P, 2) array-likes, some hostile
        elif form == 2:
            args = [tuple(profiles)]
        else:
            args = [m.pick([profiles[0], np.zeros((count, 4, 3)), np.zeros((count, 0, 2)), np.zeros((0, 4, 2)), [], None, "points",
                            np.array([[[0, 0], [1, 0], [1, 1]]], dtype=complex), np.ones((count, 4, 2), dtype=bool)])]
        maybe("transforms", lambda: m.pick([np.stack([np.eye(4)] * count), np.stack([np.diag([2.0, 2.0, 2.0, 1.0])] * count),
                                             np.zeros((count, 4, 4)), np.stack([np.eye(4)] * (count + 1)), m.array(4, rows=(4, 4)),
                                             [np.eye(4).tolist()] * count, np.full((count, 4, 4), np.nan), None]), 0.5)
        maybe("spline", lambda: m.string(["linear", "quadratic", "bezier", "catmull-rom", "natural"]), 0.3)
        maybe("tolerance", lambda: m.pick([0.01, 0, -1, float("nan"), "0.1", None, np.float32(0.1)]), 0.2)
        call = lambda: revolve.RaycastingScene().add_revolutions(*args, **kwargs)  # noqa: E731
    elif function == "add_triangles":
        args = [m.array(3, rows=(3, 6), valid_dtype="float32"), m.array(3, rows=(1, 3), valid_dtype="uint32")]
        if m.chance(0.5) and isinstance(args[1], np.ndarray) and args[1].dtype.kind in "iu":
            args[1] = np.abs(args[1]) % 3
        call = lambda: revolve.RaycastingScene().add_triangles(*args)  # noqa: E731
    elif function == "load":
        args = [m.path("scene")]
        call = lambda: revolve.RaycastingScene().load(*args)  # noqa: E731
    elif function in ("cast_rays", "test_occlusions", "count_intersections", "list_intersections"):
        args = [m.array(6, rows=(1, 5))]
        maybe("nthreads", m.threads, 0.5)
        if function == "test_occlusions":
            maybe("tnear", m.number, 0.3)
            maybe("tfar", m.number, 0.3)
        call = lambda: getattr(can, function)(*args, **kwargs)  # noqa: E731
    elif function.startswith("compute_"):
        args = [m.array(3, rows=(1, 5))]
        maybe("nthreads", m.threads, 0.5)
        if function in ("compute_signed_distance", "compute_occupancy"):
            maybe("nsamples", m.count, 0.3)
        call = lambda: getattr(can, function)(*args, **kwargs)  # noqa: E731
    elif function == "create_rays_pinhole":
        if m.chance(0.5):
            args = [m.pick([60, 0, 180, -5, "60", None, float("nan"), np.float32(45)]),
                    m.pick([[0, 0, 0.5], np.array([0, 0, 0.5], np.float32), m.array(3, rows=(1, 1))]),
                    m.pick([[0, -4, 2], (0, -4, 2), [0, 0, 0.5], m.array(3, rows=(1, 1))]),
                    m.pick([[0, 0, 1], [0, 0, 0], [0, 1, 0], None, "up", np.array([0, 0, 1])]),
                    m.pick([4, 0, -1, 2.5, "4", None, 2**40, np.int64(3)]), m.pick([3, 0, True, 1e9, float("inf")])]
        else:
            args = [m.array(3, rows=(3, 3), valid_dtype="float64"), m.array(4, rows=(4, 4), valid_dtype="float64"),
                    m.pick([4, 0, -1, "4", None]), m.pick([3, 0, 2.5, None])]
        call = lambda: revolve.RaycastingScene.create_rays_pinhole(*args)  # noqa: E731
    elif function == "Scene":
        args = [m.path("scene")]
        maybe("geometry", lambda: m.string(["mibit", "mesh"]), 0.4)
        maybe("slices", lambda: m.pick([3, 2, 0, -1, 16, 65537, 2**32, None, "64", 64.0, np.int64(16), True]), 0.4)
        call = lambda: revolve.Scene(*args, **kwargs)  # noqa: E731
    elif function == "Lidar":
        args = [m.path("sensor") if m.chance(0.4) else m.sensor()]
        call = lambda: revolve.Lidar(*args)  # noqa: E731
    elif function == "Lidar.scan":
        args = [m.pick([tool_scene, tool_scene, m.path("scene")]), m.path("poses") if m.chance(0.3) else m.array(m.pick([3, 4, 5]), rows=(1, 3), valid_dtype="float64")]
        maybe("threads", m.threads, 0.5)
        maybe("first_pose", m.count, 0.3)
        maybe("sweeps", lambda: m.pick([None, 0, 1, 2, 4, -1, 2**64, "1", 1.0, True]), 0.3)
        call = lambda: lidar.scan(*args, **kwargs)  # noqa: E731
    elif function == "ScanFile":
        name = m.pick(["out.pcd", "out.csv", "out.txt", "out", "missing/out.pcd", ""])
        path = os.path.join(files["folder"], name)
        args = [m.pick([path, path, os.fsencode(path), FsPath(path), None, 3]), m.pick([lidar, lidar, None, "sensor.json"]), m.count()]
        maybe("data", lambda: m.string(["ascii", "binary"]), 0.4)
        maybe("inputs", lambda: m.pick([[files["scene"]], [m.path("poses")], [], "abc", None, [None], (files["sensor"],)]), 0.4)
        call = lambda: revolve.ScanFile(*args, **kwargs)  # noqa: E731
    elif function == "ScanFile.write":
        scan = objects["shard"]
        value = m.pick([scan, dict(scan), {}, None, {"ranges": m.array(3)}, {k: (v.astype("float64") if k != "ids" else v) for k, v in scan.items()},
                        {k: v[..., :-1] for k, v in scan.items()}, {"ranges": [[1], [1, 2]], "points": 1, "ids": 2}, [scan]])
        first = m.pick([0, 0, 1, -1, 2**64, None, "0", 0.0])

        def call():
            f = revolve.ScanFile(os.path.join(files["folder"], "written.csv"), lidar, 2)
            f.write(first, value)
            return f.poses_written
        args = [first, value]
    elif function == "cylinder_clearance":
        args = [m.pick([tool_scene, m.path("scene")]), m.path("poses") if m.chance(0.3) else m.array(m.pick([3, 4]), rows=(1, 3), valid_dtype="float64"),
                m.pick([0.3, 0, -1, float("nan"), "0.3", None, np.float32(0.3), 1e300]), m.pick([0.0, 1.0, float("inf"), None, np.int64(0)]),
                m.pick([1.2, 0.0, -1, float("nan"), "1"])]
        maybe("ground", lambda: m.pick([0.0, None, float("nan"), "0", np.float64(0), [0]]), 0.3)
        maybe("threads", m.threads, 0.4)
        call = lambda: revolve.cylinder_clearance(*args, **kwargs)  # noqa: E731
    elif function == "read_poses":
        args = [m.path("poses")]
        call = lambda: revolve.read_poses(*args)  # noqa: E731
    elif function == "scan_shard":
        args = [m.path("scene"), m.path("sensor"), m.path("poses") if m.chance(0.3) else m.array(3, rows=(1, 2), valid_dtype="float64"),
                m.pick([0, 1, -1, None, 2**64]), m.threads()]
        call = lambda: revolve.scan_shard(*args)  # noqa: E731
    elif function == "shard_poses":
        args = [m.path("poses") if m.chance(0.3) else m.array(m.pick([3, 4, 5]), rows=(1, 4), valid_dtype="float64"),
                m.pick([0, 1, 3, -1, 2**64, None, "0", 0.0, True]), m.pick([1, 2, 0, -1, 2**64, None, 1.5]),
                m.pick([lidar, lidar, None, "sensor.json"])]
        call = lambda: revolve.shard_poses(*args)  # noqa: E731
    else:  # tessellate
        args = [m.array(2, rows=(1, 6), valid_dtype="float64"), m.pick([3, 8, 2, 0, -1, 2.5, 8.0, "8", None, True, np.int64(8), float("nan")])]
        call = lambda: revolve.tessellate(*args)  # noqa: E731
    text = f"{function}(" + ", ".join([describe(a) for a in args] + [f"{k}={describe(v)}" for k, v in kwargs.items()]) + ")"
    return text, call


def write_files(folder):
    """The files the cases' paths name: valid ones, and an empty file, a garbage file, a missing one."""
    import numpy as np

    import revolve

    source = os.environ.get("REVOLVE_SOURCE_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    files = {"folder": folder, "scene": os.path.join(source, "scenes", "robot_world.json"), "missing": os.path.join(folder, "missing.json"),
             "empty": os.path.join(folder, "empty.json"), "garbage": os.path.join(folder, "garbage.json"),
             "sensor": os.path.join(folder, "sensor.json"), "poses": os.path.join(folder, "poses.csv")}
    with open(files["sensor"], "w") as out:
        json.dump({"pose": {"position": [0.1, 0, 0.7]}, "horizontal": {"samples": 16, "min_angle": -3, "max_angle": 3},
                   "range": {"min": 0.1, "max": 10}}, out)
    with open(files["poses"], "w") as out:
        out.write("x,y,yaw\n1,1.5,0\n2,1.5,0.5\n")
    open(files["empty"], "w").close()
    with open(files["garbage"], "wb") as out:
        out.write(b"\xff\xfe{not json,\x00\n1,2\n")
    files["other"] = {"scene": files["sensor"], "sensor": files["poses"], "poses": files["scene"]}  # a file of the wrong kind
    lidar = revolve.Lidar(files["sensor"])
    scene = revolve.Scene(files["scene"])
    can = revolve.RaycastingScene()
    can.add_revolution([[0, 0], [1, 0], [1, 1], [0, 1]])
    shard = revolve.scan_shard(files["scene"], files["sensor"], np.array([[1, 1.5, 0]]), 0, 1)
    return files, {"can": can, "lidar": lidar, "scene": scene, "shard": shard}


def run_cases(seed, first, last, folder):
    import resource
    import warnings

    warnings.simplefilter("ignore")
    # A case that asks for terabytes gets a MemoryError here instead of the machine's memory. (Not
    # under the sanitizers: AddressSanitizer reserves terabytes of address space for its shadow.)
    if not os.environ.get("REVOLVE_SANITIZED"):
        resource.setrlimit(resource.RLIMIT_AS, (16 * 2**30, resource.RLIM_INFINITY))
    os.chdir(folder)  # whatever a mangled path creates lands here
    files, objects = write_files(folder)
    for i in range(first, last):
        text, call = make_case(seed, i, files, objects)
        print(json.dumps({"started": i, "call": text}), flush=True)
        try:
            call()
        except BaseException as error:  # noqa: B036 -- the point is to report whatever comes out
            outcome = {"type": type(error).__name__, "mro": [c.__name__ for c in type(error).__mro__], "message": str(error)}
        else:
            outcome = {"type": None}
        outcome.update(case=i, call=text)
        print(json.dumps(outcome), flush=True)


if __name__ == "__main__":
    run_cases(int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), sys.argv[4])
    sys.exit(0)


# ---------------------------------------------------------------------------------------------
# The test.

def _fault(outcome):
    """Why an outcome breaks the rule, or None."""
    if outcome.get("crash"):
        return f"crashed: {outcome['crash'][:300]}"
    kind = outcome["type"]
    if kind is None:
        return None
    message = outcome["message"]
    if not any(allowed in outcome["mro"] for allowed in ALLOWED):
        return f"raised {kind}"
    if "Unable to cast" in message:
        return f"{kind} with pybind's 'Unable to cast'"
    if "incompatible function arguments" in message or "incompatible constructor arguments" in message:
        return f"{kind}: pybind's 'incompatible function arguments' listing"
    if "\n" in message.strip() or not message.strip():
        return f"{kind} with a message of {'no' if not message.strip() else 'more than one'} line"
    return None


def test_every_call_returns_or_raises_a_one_line_type_or_value_error(tmp_path):
    """Rule: see the module's docstring. The failures are grouped by function and fault, each with
    its first case (seed and index, to run it again alone)."""
    print(f"REVOLVE_FUZZ_SEED={SEED} REVOLVE_FUZZ_CASES={CASES}")
    script = pathlib.Path(__file__)
    env = child_env(REVOLVE_SOURCE_DIR=SOURCE_DIR)
    outcomes, next_case = {}, 0
    while next_case < CASES:
        done = run_python(script, SEED, next_case, CASES, tmp_path, cwd=tmp_path, env=env)
        started = None
        for line in done.stdout.splitlines():
            if not line.startswith("{"):
                continue
            record = json.loads(line)
            if "started" in record:
                started = record
            else:
                outcomes[record["case"]] = record
                started = None
        if started is not None:
            outcomes[started["started"]] = {"case": started["started"], "call": started["call"], "crash": how_it_ended(done)}
            next_case = started["started"] + 1
        elif done.returncode != 0:
            raise AssertionError(f"the fuzz child died outside any call (from case {next_case}): {how_it_ended(done)}")
        else:
            next_case = CASES
    assert len(outcomes) == CASES
    groups = {}
    for outcome in sorted(outcomes.values(), key=lambda o: o["case"]):
        fault = _fault(outcome)
        if fault:
            function = outcome["call"].split("(")[0]
            key = (function, fault.split(";")[0][:60] if outcome.get("crash") else fault)
            groups.setdefault(key, []).append(outcome)
    returned = sum(1 for o in outcomes.values() if not o.get("crash") and o["type"] is None)
    print(f"{CASES} cases: {returned} returned, {len(outcomes) - returned} raised or crashed")
    report = [f"{function}: {fault} -- {len(cases)} case(s), first #{cases[0]['case']} (seed {SEED}): {cases[0]['call']}"
              + ("" if cases[0].get("crash") else f"\n    -> {cases[0]['type']}: {cases[0]['message'][:300]!r}")
              for (function, fault), cases in sorted(groups.items())]
    assert not report, f"{sum(len(c) for c in groups.values())} of {CASES} calls broke the rule:\n" + "\n".join(report)
