"""ROS 2 bags of a simulated robot: revolve's scans, range readings and camera frames in a rosbag2.

A bag is a folder (metadata.yaml beside NAME.mcap: rosbag2 format version 9, MCAP storage, the
message definitions of ROS 2 Jazzy) written through the rosbags library (Debian 13's
python3-rosbags), which encodes every message (CDR) and the MCAP file:

  sensor_msgs/msg/PointCloud2  a lidar scan, one message a pose: the points of a binary PCD of
                               revolve-lidar byte for byte (x y z range ring return object
                               intensity time, 31 bytes a point), in the world frame
  sensor_msgs/msg/Range        one message a range sensor (sonar, infrared) a pose
  sensor_msgs/msg/Image        a camera's frame (rgb8, rgba8, mono8 or mono16)
  sensor_msgs/msg/CameraInfo   its pinhole (plumb_bob, zero distortion)
  tf2_msgs/msg/TFMessage       the robot's pose on /tf (world -> base_link), the sensors'
                               mountings on /tf_static (base_link -> each sensor's frame)

Every message is stamped with its pose's time (pose_stamps). A bag is written into a temporary
folder beside its path and renamed into place by commit(); on an error, on KeyboardInterrupt
(SIGINT) and on SIGTERM or SIGHUP it is removed, and nothing is left at the path (docs/ros2.md).

Without python3-rosbags (Debian 12 has no package of it) importing this module raises ImportError
saying so, and `python3 -m revolve.ros2` says so and exits with status 1.
"""

import json
import math
import os
import pathlib
import shutil
import signal
import sys
import tempfile
import threading
import weakref

import numpy as np

NEEDS_ROSBAGS = ("revolve.ros2 needs python3-rosbags, Debian 13's package of the rosbags library "
                 "(apt install python3-rosbags); Debian 12 has none")

try:
    from rosbags.interfaces import Qos, QosDurability, QosHistory, QosLiveliness, QosReliability, QosTime
    from rosbags.rosbag2 import StoragePlugin, Writer
    from rosbags.typesys import Stores, get_typestore
except ImportError as _error:
    if __name__ == "__main__":
        print(f"{NEEDS_ROSBAGS} ({_error})", file=sys.stderr)
        sys.exit(1)
    raise ImportError(f"{NEEDS_ROSBAGS} ({_error})") from _error

__all__ = [
    "BagWriter",
    "DEFAULT_PERIOD",
    "OPTICAL_FROM_CAMERA",
    "POINT_FIELDS",
    "POINT_STEP",
    "point_cloud_data",
    "pose_stamps",
    "read_camera_frame",
    "sensor_mounting",
]

# The rosbag2 format version written (ROS 2 Jazzy's, which rosbags writes with Jazzy's definitions).
BAG_VERSION = 9
DEFAULT_PERIOD = 0.1  # seconds between poses that carry no time (10 Hz, a spinning lidar's usual rate)

# sensor_msgs/msg/PointField datatypes.
_INT32, _UINT8, _UINT16, _FLOAT32 = 5, 2, 4, 7
# The point of revolve-lidar's binary PCD (FIELDS x y z range ring return object intensity time, SIZE 4
# 4 4 4 2 1 4 4 4, TYPE F F F F U U I F F), packed: (name, byte offset, PointField datatype, count).
POINT_FIELDS = (
    ("x", 0, _FLOAT32, 1),
    ("y", 4, _FLOAT32, 1),
    ("z", 8, _FLOAT32, 1),
    ("range", 12, _FLOAT32, 1),
    ("ring", 16, _UINT16, 1),
    ("return", 18, _UINT8, 1),
    ("object", 19, _INT32, 1),
    ("intensity", 23, _FLOAT32, 1),
    ("time", 27, _FLOAT32, 1),
)
POINT_STEP = 31
_POINT_DTYPE = np.dtype({
    "names": [f[0] for f in POINT_FIELDS],
    "formats": ["<f4", "<f4", "<f4", "<f4", "<u2", "u1", "<i4", "<f4", "<f4"],
    "offsets": [f[1] for f in POINT_FIELDS],
    "itemsize": POINT_STEP,
})

# The optical frame of a camera (x right, y down, z forward: REP 103) in the camera's own frame (x
# forward, z up), as a mounting [x, y, z, yaw, pitch, roll]: R = Rz(-pi/2) Rx(-pi/2).
OPTICAL_FROM_CAMERA = (0.0, 0.0, 0.0, -math.pi / 2, 0.0, -math.pi / 2)

_RADIATION = {"ultrasound": 0, "infrared": 1}  # sensor_msgs/msg/Range's ULTRASOUND, INFRARED
_IMAGE_ENCODINGS = {("uint8", 1): "mono8", ("uint8", 3): "rgb8", ("uint8", 4): "rgba8", ("uint16", 1): "mono16"}
_STAMP_LIMIT = 2**31  # builtin_interfaces/msg/Time's sec is an int32; MCAP's log time is unsigned


# --- Stamps and poses -------------------------------------------------------------------------------

def _real_table(value, name):
    """A 2-D float64 copy of `value`, every entry finite, or a ValueError naming the entry."""
    try:
        table = np.array(value, dtype=np.float64, ndmin=2)
    except (TypeError, ValueError) as error:
        raise TypeError(f"{name}: not a table of numbers ({error})") from None
    if table.ndim != 2:
        raise ValueError(f"{name}: shape {table.shape}; expected (N, columns)")
    bad = np.argwhere(~np.isfinite(table))
    if len(bad):
        i, j = bad[0]
        raise ValueError(f"{name}[{i}, {j}] = {float(table[i, j])!r}: every value must be finite")
    return table


def _pose_table(poses):
    """(N, 6) [x, y, z, roll, pitch, yaw], the (N,) times or None, and the time's column, from any layout Lidar.scan
    takes: (N, 3) [x, y, yaw], (N, 4) [x, y, z, yaw], (N, 5) [x, y, z, yaw, time], (N, 6) [x, y, z,
    roll, pitch, yaw], (N, 7) [x, y, z, roll, pitch, yaw, time], or a POSES.csv path."""
    if isinstance(poses, (str, bytes, os.PathLike)):
        from . import read_poses  # the tools' own reader: the extension module

        poses = read_poses(poses)
    table = _real_table(poses, "poses")
    n, columns = table.shape
    if n == 0:
        raise ValueError("poses: no pose; expected at least one row")
    out = np.zeros((n, 6))
    if columns == 3:
        out[:, 0:2], out[:, 5] = table[:, 0:2], table[:, 2]
    elif columns in (4, 5):
        out[:, 0:3], out[:, 5] = table[:, 0:3], table[:, 3]
    elif columns in (6, 7):
        out[:] = table[:, 0:6]
    else:
        raise ValueError(f"poses: {columns} columns; expected 3 [x, y, yaw], 4 [x, y, z, yaw], 5 [x, y, z, yaw, time], "
                         "6 [x, y, z, roll, pitch, yaw] or 7 [x, y, z, roll, pitch, yaw, time]")
    times = table[:, -1].copy() if columns in (5, 7) else None
    return out, times, columns - 1


def pose_stamps(poses, period=None, start=0.0):
    """The stamp (seconds) of each pose: start + its time where the poses carry one (a POSES.csv
    `time` column; the last column of an (N, 5) or (N, 7) array); else start + (i + 1) * period,
    period DEFAULT_PERIOD (0.1 s) unless given: one period between poses, the first one period
    after the clock's zero. A stamp must lie in (0, 2^31) seconds: ROS 2's Time counts whole
    seconds in an int32, and a stamp of 0 means no time at all (tf2 reads it as "the latest"), so
    poses timed from 0, or from another epoch, need a `start` that brings them there."""
    table, times, time_column = _pose_table(poses)
    start = _real(start, "start")
    if times is not None:
        if period is not None:
            raise ValueError(f"period = {period}: the poses carry their own times (their last column); "
                             "a period is only for poses without one")
        stamps = times + start
        where = "poses[{i}, %s] (time) + start" % time_column
    else:
        period = DEFAULT_PERIOD if period is None else _real(period, "period")
        if not period > 0:
            raise ValueError(f"period = {period!r}: the time between poses must be positive")
        stamps = start + period * np.arange(1, len(table) + 1, dtype=np.float64)
        where = "start + ({i} + 1) * period"
    for i, stamp in enumerate(stamps):
        if not 0 < stamp < _STAMP_LIMIT:
            raise ValueError(f"{where.format(i=i)} = {float(stamp)!r} s: a ROS 2 stamp lies in (0, 2^31) seconds "
                             "(0 means no time); choose `start` to bring the poses' times there")
    return stamps


def _real(value, name):
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name}: a {type(value).__name__}; expected a number")
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"{name} = {value!r}: must be finite")
    return value


def _stamp_ns(stamp, name="stamp"):
    """Nanoseconds since the epoch of a stamp in seconds: the nearest integer to stamp * 1e9."""
    seconds = _real(stamp, name)
    ns = round(seconds * 1e9)
    if not 0 < ns < _STAMP_LIMIT * 10**9:
        raise ValueError(f"{name} = {seconds!r} s: a ROS 2 stamp lies in (0, 2^31) seconds (builtin_interfaces/Time; "
                         "0 means no time)")
    return ns


def sensor_mounting(sensor):
    """A sensor's mounting on the robot, [x, y, z, yaw, pitch, roll] (float64), from its sensor file
    (a path, or its JSON as a dict): `pose.position` and the angles, 0 where absent. Lidar and
    camera files alike; R = Rz(yaw) Ry(pitch) Rx(roll), as revolve-lidar reads it."""
    if isinstance(sensor, (str, bytes, os.PathLike)):
        path = os.fsdecode(sensor)
        with open(path, encoding="utf-8") as f:
            sensor = json.load(f)
        where = path
    else:
        where = "sensor"
    if not isinstance(sensor, dict) or not isinstance(sensor.get("pose"), dict):
        raise ValueError(f"{where}: no \"pose\" object (the sensor's mounting: position, yaw, pitch, roll)")
    pose = sensor["pose"]
    position = pose.get("position")
    if not isinstance(position, (list, tuple)) or len(position) != 3:
        raise ValueError(f"{where}: pose.position = {position!r}; expected [x, y, z]")
    values = [_real(v, f"{where}: pose.position[{i}]") for i, v in enumerate(position)]
    values += [_real(pose.get(angle, 0.0), f"{where}: pose.{angle}") for angle in ("yaw", "pitch", "roll")]
    return np.array(values)


def _quaternion(roll, pitch, yaw):
    """(x, y, z, w) of R = Rz(yaw) Ry(pitch) Rx(roll)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy,
            cr * cp * cy + sr * sp * sy)


# --- Point clouds -----------------------------------------------------------------------------------

_SCAN_KEYS = ("points", "ranges", "rings", "return", "ids", "intensity", "time")


def point_cloud_data(scan, pose):
    """The points of pose `pose` of a Lidar.scan result, as the bytes revolve-lidar writes for them in
    a binary PCD (POINT_FIELDS, POINT_STEP bytes a point, in the scan's point order: layer, ring,
    column): NaN x, y, z, range and intensity and object -1 where a beam has no return."""
    if not isinstance(scan, dict):
        raise TypeError(f"scan: a {type(scan).__name__}; expected the dict Lidar.scan returns")
    for key in _SCAN_KEYS:
        if key not in scan:
            raise ValueError(f"scan: no \"{key}\"; expected the dict Lidar.scan returns ({', '.join(_SCAN_KEYS)})")
    ranges = np.asarray(scan["ranges"])
    if ranges.ndim not in (3, 4):
        raise ValueError(f"scan[\"ranges\"]: shape {ranges.shape}; expected (poses, rings, azimuths) or "
                         "(poses, returns, rings, azimuths)")
    for key in _SCAN_KEYS:
        shape = np.shape(scan[key])
        expected = ranges.shape + ((3,) if key == "points" else ())
        if shape != expected:
            raise ValueError(f"scan[\"{key}\"]: shape {shape}; expected {expected}, as scan[\"ranges\"]")
    if isinstance(pose, bool) or not isinstance(pose, (int, np.integer)):
        raise TypeError(f"pose: a {type(pose).__name__}; expected the index of a pose of the scan")
    if not 0 <= pose < ranges.shape[0]:
        raise IndexError(f"pose = {pose}: the scan has {ranges.shape[0]} poses (0 to {ranges.shape[0] - 1})")
    r = ranges[pose].astype(np.float32).ravel()
    hit = ~np.isinf(r)
    nan = np.float32(np.nan)
    points = np.asarray(scan["points"][pose], dtype=np.float32).reshape(-1, 3)
    out = np.empty(r.size, dtype=_POINT_DTYPE)
    for axis, name in enumerate("xyz"):
        out[name] = np.where(hit, points[:, axis], nan)
    out["range"] = np.where(hit, r, nan)
    out["ring"] = np.asarray(scan["rings"][pose]).ravel()
    out["return"] = np.asarray(scan["return"][pose]).ravel()
    out["object"] = np.where(hit, np.asarray(scan["ids"][pose]).ravel(), -1)
    out["intensity"] = np.where(hit, np.asarray(scan["intensity"][pose], dtype=np.float32).ravel(), nan)
    out["time"] = np.asarray(scan["time"][pose], dtype=np.float32).ravel()
    return out.tobytes()


# --- Camera frames ----------------------------------------------------------------------------------

def read_camera_frame(path):
    """A frame revolve-render wrote along a path (`revolve-render --camera ... --poses ...`): `path` is
    its JSON (front_0003.json); returns (image, info): the PNG it names as a numpy array (H, W, 3)
    uint8 for RGB (H, W, 4) for RGBA, (H, W) for grey, read with Pillow (Debian's python3-pil), and
    the JSON as a dict (k, r, p, width, height, position, rotation, time, frame, ...)."""
    path = pathlib.Path(os.fsdecode(path))
    with open(path, encoding="utf-8") as f:
        info = json.load(f)
    if not isinstance(info, dict) or not isinstance(info.get("image"), str):
        raise ValueError(f"{path}: no \"image\" file name; expected a frame's JSON written by revolve-render --camera")
    image_path = path.parent / info["image"]
    if image_path.suffix.lower() != ".png":
        raise ValueError(f"{path}: image {info['image']!r} is not a PNG; a bag's Image holds 8- or 16-bit pixels "
                         "(render the frames with -o FRAME.png)")
    try:
        from PIL import Image as PilImage
    except ImportError as error:
        raise ImportError(f"read_camera_frame needs Pillow (Debian: python3-pil) to read {image_path} ({error})") from error
    with PilImage.open(image_path) as png:
        mode = png.mode
        if mode not in ("RGB", "RGBA", "L", "I;16"):
            raise ValueError(f"{image_path}: PNG mode {mode}; expected RGB, RGBA, L or I;16")
        image = np.asarray(png)
    if mode == "I;16":
        image = image.astype(np.uint16)
    return np.ascontiguousarray(image), info


# --- Removal of unfinished bags on SIGTERM / SIGHUP ---------------------------------------------------

_live = weakref.WeakSet()  # the BagWriters not yet committed or closed
_handlers_lock = threading.Lock()
_handlers_installed = False


def _on_termination(number, frame):
    for writer in list(_live):
        writer._remove_temporary()
    # Unwinds the program as `exit` would, so that its own cleanups (with-blocks, finally, a ScanFile's
    # temporary) run too; the status is the tools' on a signal: 128 + its number.
    raise SystemExit(128 + number)


def _install_handlers():
    """On SIGTERM and SIGHUP, where the program has no Python handler of its own (the default, or a
    handler installed outside Python such as a revolve ScanFile's), remove the unfinished bags and end
    with status 128 + the signal. Only from the main thread (Python's rule for signal handlers)."""
    global _handlers_installed
    with _handlers_lock:
        if _handlers_installed or threading.current_thread() is not threading.main_thread():
            return
        for number in (signal.SIGTERM, signal.SIGHUP):
            if signal.getsignal(number) in (signal.SIG_DFL, None):
                signal.signal(number, _on_termination)
        _handlers_installed = True


# --- The writer -------------------------------------------------------------------------------------

def _name(value, name):
    if not isinstance(value, str) or not value or value != value.strip() or any(c.isspace() for c in value):
        raise ValueError(f"{name} = {value!r}: expected a non-empty name without spaces")
    return value


def _topic(value, name="topic"):
    _name(value, name)
    if not value.startswith("/"):
        raise ValueError(f"{name} = {value!r}: a topic here is absolute (begins with '/')")
    return value


class BagWriter:
    """A rosbag2 (MCAP) being written at `path`, a folder that must not exist yet (overwrite=True
    replaces a bag already there, once this one is committed). Messages go to a temporary folder
    beside it; commit() renames it into place. Used as a context manager, it commits when the block
    ends normally and removes the temporary when it ends by an exception (KeyboardInterrupt too).

    Every write_* method takes the stamp in seconds (pose_stamps) and writes its messages with that
    stamp as both the header's and the bag's time."""

    def __init__(self, path, overwrite=False):
        self.path = pathlib.Path(os.fsdecode(path))
        self._overwrite = bool(overwrite)
        if not self.path.name or self.path.name in (".", ".."):
            raise ValueError(f"path = {os.fsdecode(path)!r}: expected a folder name for the bag")
        if os.path.lexists(self.path) and not self._overwrite:
            raise FileExistsError(f"{self.path}: exists already; a bag is written to a new folder (or overwrite=True)")
        if not self.path.parent.is_dir():
            raise FileNotFoundError(f"{self.path.parent}: no such folder for the bag {self.path.name}")
        self._typestore = get_typestore(Stores.ROS2_JAZZY)
        self._types = self._typestore.types
        self._connections = {}
        self.counts = {}
        _install_handlers()
        # The temporary is a folder beside the bag holding a folder of the bag's own name: rosbags names
        # the MCAP file after it, so that it is renamed into place whole.
        self._temporary = pathlib.Path(tempfile.mkdtemp(prefix=f".{self.path.name}.tmp-", dir=self.path.parent))
        _live.add(self)
        try:
            self._writer = Writer(self._temporary / self.path.name, version=BAG_VERSION,
                                  storage_plugin=StoragePlugin.MCAP)
            self._writer.open()
        except BaseException:
            self._remove_temporary()
            raise

    # Context manager: commit on success, remove on an exception.
    def __enter__(self):
        return self

    def __exit__(self, kind, value, traceback):
        if kind is None:
            self.commit()
        else:
            self.close()
        return False

    def __del__(self):
        self._remove_temporary()

    def _remove_temporary(self):
        temporary = getattr(self, "_temporary", None)
        if temporary is not None:
            self._temporary = None
            _live.discard(self)
            shutil.rmtree(temporary, ignore_errors=True)

    def _require_open(self):
        if self._temporary is None:
            raise ValueError(f"{self.path}: the bag is committed or closed already")

    def close(self):
        """Abandons the bag: its temporary folder is removed, nothing is written at the path."""
        self._writer = None  # its MCAP file is closed when collected; the folder goes now
        self._remove_temporary()

    def commit(self):
        """Finishes the bag (rosbags writes metadata.yaml and the MCAP summary) and renames it into
        place; with overwrite=True a bag already at the path is replaced."""
        self._require_open()
        try:
            self._writer.close()
            self._writer = None
            built = self._temporary / self.path.name
            if os.path.lexists(self.path):
                if not self._overwrite:
                    raise FileExistsError(f"{self.path}: appeared while the bag was written; not replaced")
                if not (self.path / "metadata.yaml").is_file():
                    raise FileExistsError(f"{self.path}: exists and is not a rosbag2 folder (no metadata.yaml); "
                                          "not replaced")
                os.rename(self.path, self._temporary / ".replaced")
            os.rename(built, self.path)
        except BaseException:
            self.close()
            raise
        self._remove_temporary()
        return self.path

    # --- messages -----------------------------------------------------------------------------------

    def _write(self, topic, msgtype, message, ns, qos=None):
        connection = self._connections.get(topic)
        if connection is None:
            profiles = [qos] if qos is not None else []
            connection = self._writer.add_connection(topic, msgtype, typestore=self._typestore,
                                                     offered_qos_profiles=profiles)
            self._connections[topic] = connection
            self.counts[topic] = 0
        elif connection.msgtype != msgtype:
            raise ValueError(f"topic = {topic!r}: carries {connection.msgtype} already, not {msgtype}")
        self._writer.write(connection, ns, self._typestore.serialize_cdr(message, msgtype))
        self.counts[topic] += 1

    def _header(self, ns, frame_id):
        return self._types["std_msgs/msg/Header"](
            stamp=self._types["builtin_interfaces/msg/Time"](sec=ns // 10**9, nanosec=ns % 10**9), frame_id=frame_id)

    def _transform(self, ns, parent, child, x, y, z, roll, pitch, yaw):
        t = self._types
        qx, qy, qz, qw = _quaternion(roll, pitch, yaw)
        return t["geometry_msgs/msg/TransformStamped"](
            header=self._header(ns, parent), child_frame_id=child,
            transform=t["geometry_msgs/msg/Transform"](
                translation=t["geometry_msgs/msg/Vector3"](x=float(x), y=float(y), z=float(z)),
                rotation=t["geometry_msgs/msg/Quaternion"](x=qx, y=qy, z=qz, w=qw)))

    def write_robot_pose(self, stamp, pose, world_frame="map", base_frame="base_link", topic="/tf"):
        """The robot's pose as a TFMessage of one transform world_frame -> base_frame on `topic`.
        pose: one row of a poses array, [x, y, yaw], [x, y, z, yaw], [x, y, z, yaw, time], [x, y, z,
        roll, pitch, yaw] or [x, y, z, roll, pitch, yaw, time] (a time in it is not used: `stamp` is)."""
        self._require_open()
        ns = _stamp_ns(stamp)
        row = np.asarray(pose, dtype=np.float64) if not isinstance(pose, (str, bytes)) else None
        if row is None or row.ndim != 1:
            raise ValueError(f"pose: shape {np.shape(pose)}; expected one pose, a row of 3 to 7 numbers")
        (x, y, z, roll, pitch, yaw), = _pose_table(row[None, :])[0]
        message = self._types["tf2_msgs/msg/TFMessage"](transforms=[
            self._transform(ns, _name(world_frame, "world_frame"), _name(base_frame, "base_frame"), x, y, z, roll, pitch, yaw)])
        self._write(_topic(topic), "tf2_msgs/msg/TFMessage", message, ns)

    def write_static_transforms(self, stamp, transforms, topic="/tf_static"):
        """Fixed transforms (the sensors' mountings) as one TFMessage on `topic`, offered as ROS's
        /tf_static is (reliable, transient local, so that a player re-sends it to late subscribers).
        transforms: (parent, child, mounting) triples, mounting [x, y, z, yaw, pitch, roll] (the
        child's frame in the parent's, R = Rz(yaw) Ry(pitch) Rx(roll): sensor_mounting, a range
        sensor's `mounting` row, OPTICAL_FROM_CAMERA)."""
        self._require_open()
        ns = _stamp_ns(stamp)
        items = []
        for i, item in enumerate(transforms):
            if not isinstance(item, (tuple, list)) or len(item) != 3:
                raise ValueError(f"transforms[{i}]: expected a (parent, child, mounting) triple")
            parent, child, mounting = item
            values = _real_table(mounting, f"transforms[{i}] mounting").ravel()
            if values.size != 6:
                raise ValueError(f"transforms[{i}] mounting: {values.size} values; expected [x, y, z, yaw, pitch, roll]")
            x, y, z, yaw, pitch, roll = values
            items.append(self._transform(ns, _name(parent, f"transforms[{i}] parent"), _name(child, f"transforms[{i}] child"),
                                         x, y, z, roll, pitch, yaw))
        if not items:
            raise ValueError("transforms: empty; expected at least one (parent, child, mounting)")
        latched = Qos(QosHistory.KEEP_LAST, 1, QosReliability.RELIABLE, QosDurability.TRANSIENT_LOCAL, QosTime(0, 0),
                      QosTime(0, 0), QosLiveliness.AUTOMATIC, QosTime(0, 0), False)
        self._write(_topic(topic), "tf2_msgs/msg/TFMessage", self._types["tf2_msgs/msg/TFMessage"](transforms=items), ns,
                    qos=latched)

    def write_point_cloud(self, stamp, scan, pose, frame_id="map", topic="/points"):
        """Pose `pose` of a Lidar.scan result as a PointCloud2: organised, height = returns x rings,
        width = azimuths (a beam pattern: returns x 1 by its beams), its data point_cloud_data(scan,
        pose), the binary PCD's points byte for byte; the points are in the world frame, as the PCD's,
        so frame_id is the world's. is_dense is false where some beam has no return (NaN points)."""
        self._require_open()
        ns = _stamp_ns(stamp)
        data = point_cloud_data(scan, pose)
        shape = np.shape(scan["ranges"])[1:]
        width = shape[-1]
        height = int(np.prod(shape[:-1]))
        t = self._types
        message = t["sensor_msgs/msg/PointCloud2"](
            header=self._header(ns, _name(frame_id, "frame_id")), height=height, width=width,
            fields=[t["sensor_msgs/msg/PointField"](name=n, offset=o, datatype=d, count=c) for n, o, d, c in POINT_FIELDS],
            is_bigendian=False, point_step=POINT_STEP, row_step=POINT_STEP * width,
            data=np.frombuffer(data, dtype=np.uint8),
            is_dense=bool(np.all(~np.isinf(np.asarray(scan["ranges"][pose])))))
        self._write(_topic(topic), "sensor_msgs/msg/PointCloud2", message, ns)

    def write_ranges(self, stamp, ranges, names, field_of_view, min_range, max_range, radiation_type, topic="/range",
                     variance=None):
        """One Range message a sensor, on `topic`/NAME with frame_id NAME (the sensor's frame, whose
        +X is the cone's axis): ranges (S,) the readings (inf: nothing within range, written +inf as
        REP 117 has it), and the sensors' metadata as RangeSensors gives it: names (S,), field_of_view
        (S,) the full cone angle in radians, min_range and max_range (S,), radiation_type (S,)
        "ultrasound" or "infrared"; variance (S,) the readings' variance in m^2 (RangeSensors'
        noise_stddev squared), or None for 0, the message's "unknown". Written as float32."""
        self._require_open()
        ns = _stamp_ns(stamp)
        readings = np.asarray(ranges, dtype=np.float64) if not isinstance(ranges, (str, bytes)) else np.array([])
        if readings.ndim != 1 or readings.size == 0:
            raise ValueError(f"ranges: shape {np.shape(ranges)}; expected (S,), one reading a sensor")
        count = readings.size
        if isinstance(names, str) or len(names) != count:
            raise ValueError(f"names: {0 if isinstance(names, str) else len(names)} names for {count} readings; expected one a sensor")
        columns = {}
        if variance is None:
            variance = np.zeros(count)
        for key, value in (("field_of_view", field_of_view), ("min_range", min_range), ("max_range", max_range),
                           ("variance", variance)):
            array = np.asarray(value, dtype=np.float64)
            if array.shape != (count,):
                raise ValueError(f"{key}: shape {array.shape}; expected ({count},), one a sensor")
            columns[key] = array
        if isinstance(radiation_type, str) or len(radiation_type) != count:
            raise ValueError(f"radiation_type: expected {count} entries, one a sensor (\"ultrasound\" or \"infrared\")")
        for i in range(count):
            _name(names[i], f"names[{i}]")
            fov, low, high = (float(columns[key][i]) for key in ("field_of_view", "min_range", "max_range"))
            if not 0 < fov <= math.pi:
                raise ValueError(f"field_of_view[{i}] = {fov!r}: a cone's full angle lies in (0, pi] radians")
            if not (math.isfinite(low) and low >= 0):
                raise ValueError(f"min_range[{i}] = {low!r}: must be finite and at least 0")
            if not (math.isfinite(high) and high > low):
                raise ValueError(f"max_range[{i}] = {high!r}: must be finite and above min_range = {low!r}")
            spread = float(columns["variance"][i])
            if not (math.isfinite(spread) and spread >= 0):
                raise ValueError(f"variance[{i}] = {spread!r}: must be finite and at least 0")
            if radiation_type[i] not in _RADIATION:
                raise ValueError(f"radiation_type[{i}] = {radiation_type[i]!r}: expected \"ultrasound\" or \"infrared\"")
            reading = float(readings[i])
            if math.isnan(reading) or reading < 0:
                raise ValueError(f"ranges[{i}] = {reading!r}: a reading is a distance (at least 0) or inf (none)")
        if len(set(names)) != count:
            raise ValueError(f"names: {list(names)} repeat a name; each sensor needs its own frame")
        base = _topic(topic)
        for i in range(count):
            message = self._types["sensor_msgs/msg/Range"](
                header=self._header(ns, names[i]), radiation_type=_RADIATION[radiation_type[i]],
                field_of_view=float(columns["field_of_view"][i]), min_range=float(columns["min_range"][i]),
                max_range=float(columns["max_range"][i]), range=float(readings[i]),
                variance=float(columns["variance"][i]))
            self._write(f"{base.rstrip('/')}/{names[i]}", "sensor_msgs/msg/Range", message, ns)

    def write_image(self, stamp, image, frame_id="camera_optical", topic="/camera/image_raw"):
        """An image as sensor_msgs/Image: (H, W, 3) uint8 rgb8, (H, W, 4) uint8 rgba8, (H, W) uint8
        mono8 or uint16 mono16 (little-endian), rows top first, as read_camera_frame reads a PNG."""
        self._require_open()
        ns = _stamp_ns(stamp)
        if not isinstance(image, np.ndarray):
            raise TypeError(f"image: a {type(image).__name__}; expected a numpy array (H, W[, channels])")
        channels = 1 if image.ndim == 2 else image.shape[2] if image.ndim == 3 else 0
        encoding = _IMAGE_ENCODINGS.get((image.dtype.name, channels))
        if encoding is None or 0 in image.shape:
            raise ValueError(f"image: {image.dtype} of shape {image.shape}; expected (H, W, 3) or (H, W, 4) uint8, "
                             "or (H, W) uint8 or uint16")
        height, width = image.shape[:2]
        data = np.ascontiguousarray(image, dtype=image.dtype.newbyteorder("<")).view(np.uint8).ravel()
        message = self._types["sensor_msgs/msg/Image"](
            header=self._header(ns, _name(frame_id, "frame_id")), height=height, width=width, encoding=encoding,
            is_bigendian=0, step=data.size // height, data=data)
        self._write(_topic(topic), "sensor_msgs/msg/Image", message, ns)

    def write_camera_info(self, stamp, info, frame_id="camera_optical", topic="/camera/camera_info"):
        """A pinhole as sensor_msgs/CameraInfo: info holds width, height, k (9), r (9) and p (12), as
        revolve-render's frame JSON does (read_camera_frame). revolve's cameras have no distortion:
        written as distortion_model "plumb_bob" with d five zeros, which ROS's image_geometry reads as
        undistorted; an info with another model or non-zero d is refused."""
        self._require_open()
        ns = _stamp_ns(stamp)
        if not isinstance(info, dict):
            raise TypeError(f"info: a {type(info).__name__}; expected a dict (width, height, k, r, p)")
        sizes = {}
        for key in ("width", "height"):
            value = info.get(key)
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 0 < value < 2**32:
                raise ValueError(f"info[\"{key}\"] = {value!r}: expected a positive whole number of pixels")
            sizes[key] = int(value)
        matrices = {}
        for key, size in (("k", 9), ("r", 9), ("p", 12)):
            if key not in info:
                raise ValueError(f"info: no \"{key}\" ({size} numbers, row-major)")
            values = _real_table(info[key], f"info[\"{key}\"]").ravel()
            if values.size != size:
                raise ValueError(f"info[\"{key}\"]: {values.size} numbers; expected {size}, row-major")
            matrices[key] = values
        model = info.get("distortion_model", "none")
        d = np.asarray(info.get("d", []), dtype=np.float64)
        if model not in ("none", "plumb_bob") or np.any(d != 0):
            raise ValueError(f"info: distortion_model {model!r} with d = {d.tolist()}: revolve's cameras are "
                             "undistorted pinholes (\"none\", or \"plumb_bob\" with zero d)")
        t = self._types
        message = t["sensor_msgs/msg/CameraInfo"](
            header=self._header(ns, _name(frame_id, "frame_id")), height=sizes["height"], width=sizes["width"],
            distortion_model="plumb_bob", d=np.zeros(5), k=matrices["k"], r=matrices["r"], p=matrices["p"],
            binning_x=0, binning_y=0,
            roi=t["sensor_msgs/msg/RegionOfInterest"](x_offset=0, y_offset=0, height=0, width=0, do_rectify=False))
        self._write(_topic(topic), "sensor_msgs/msg/CameraInfo", message, ns)


if __name__ == "__main__":
    print(__doc__.strip())
    print("\nUse it from Python (docs/ros2.md); examples/robot/write_bag.py writes a bag of scenes/robot_world.json.")
