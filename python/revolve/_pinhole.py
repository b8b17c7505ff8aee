"""Pinhole camera rays with Open3D's conventions (RaycastingScene.create_rays_pinhole)."""

import math
import numbers
import operator

import numpy as np

# The largest image: 2^28 rays (6 GiB of float32 rays), far beyond any camera, short of what
# numpy could not allocate.
_MAX_RAYS = 1 << 28


def _matrix(value, name, shape):
    try:
        array = np.asarray(value.numpy() if hasattr(value, "numpy") else value, dtype=np.float64)
    except (TypeError, ValueError) as error:
        raise ValueError(f"{name}: not an array of numbers of shape {shape} ({error})") from None
    if array.shape != shape:
        raise ValueError(f"{name}: shape {array.shape}; expected {shape}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name}: every entry must be finite")
    return array


def _size(value, name):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name}: a {type(value).__name__}; expected a whole number of pixels")
    size = operator.index(value)
    if not 1 <= size <= _MAX_RAYS:
        raise ValueError(f"{name} = {size}: must lie in [1, 2^28]")
    return size


def _image(width, height):
    if width * height > _MAX_RAYS:
        raise ValueError(f"width_px x height_px = {width} x {height}: more than 2^28 rays (6 GiB of float32 rays)")
    return width, height


def _rays_from_matrices(intrinsic, extrinsic, width, height):
    # Pixel (x, y) looks through its centre (x + 1/2, y + 1/2): direction R^T K^-1 (x + 1/2, y + 1/2, 1),
    # from the camera centre -R^T t, for the world-to-camera extrinsic [R t]. The 3x3 product is
    # formed in double and rounded to float once; each direction is then summed in float, column
    # by column, as Open3D does.
    rotation, translation = extrinsic[:3, :3], extrinsic[:3, 3]
    if abs(np.linalg.det(intrinsic)) == 0:
        raise ValueError("intrinsic_matrix is singular")
    to_world = (rotation.T @ np.linalg.inv(intrinsic)).astype(np.float32)
    centre = (-rotation.T @ translation).astype(np.float32)
    xs = np.arange(width, dtype=np.float32) + np.float32(0.5)
    ys = np.arange(height, dtype=np.float32) + np.float32(0.5)
    px, py = np.meshgrid(xs, ys)
    rays = np.empty((height, width, 6), dtype=np.float32)
    rays[..., :3] = centre
    for axis in range(3):
        rays[..., 3 + axis] = to_world[axis, 0] * px + to_world[axis, 1] * py + to_world[axis, 2]
    return rays


def create_rays_pinhole(*args, **kwargs):
    """Rays of a pinhole camera, shape (height_px, width_px, 6), float32, as Open3D makes them.

    create_rays_pinhole(intrinsic_matrix, extrinsic_matrix, width_px, height_px): a 3x3 intrinsic
    matrix and a 4x4 world-to-camera extrinsic matrix.
    create_rays_pinhole(fov_deg, center, eye, up, width_px, height_px): a horizontal field of view in
    degrees, the point looked at, the camera's position and its up vector.
    Directions are not unit length: t is in their units, as for any ray.
    """
    names_matrices = ("intrinsic_matrix", "extrinsic_matrix", "width_px", "height_px")
    names_view = ("fov_deg", "center", "eye", "up", "width_px", "height_px")
    if len(args) + len(kwargs) == 4 and "fov_deg" not in kwargs:
        bound = dict(zip(names_matrices, args), **kwargs)
        missing = [n for n in names_matrices if n not in bound]
        if missing or len(bound) != 4:
            raise TypeError(f"create_rays_pinhole: expected {', '.join(names_matrices)}")
        intrinsic = _matrix(bound["intrinsic_matrix"], "intrinsic_matrix", (3, 3))
        extrinsic = _matrix(bound["extrinsic_matrix"], "extrinsic_matrix", (4, 4))
        width, height = _image(_size(bound["width_px"], "width_px"), _size(bound["height_px"], "height_px"))
        return _rays_from_matrices(intrinsic, extrinsic, width, height)
    bound = dict(zip(names_view, args), **kwargs)
    missing = [n for n in names_view if n not in bound]
    if missing or len(bound) != 6:
        raise TypeError(f"create_rays_pinhole: expected ({', '.join(names_matrices)}) or ({', '.join(names_view)})")
    fov = bound["fov_deg"]
    if isinstance(fov, bool) or not isinstance(fov, numbers.Real):
        raise TypeError(f"fov_deg: a {type(fov).__name__}; expected a number of degrees")
    fov = float(fov)
    if not 0 < fov < 180:
        raise ValueError(f"fov_deg = {fov!r}: must lie in (0, 180)")
    width, height = _image(_size(bound["width_px"], "width_px"), _size(bound["height_px"], "height_px"))
    center = _matrix(bound["center"], "center", (3,))
    eye = _matrix(bound["eye"], "eye", (3,))
    up = _matrix(bound["up"], "up", (3,))
    focal = 0.5 * width / math.tan(0.5 * math.radians(fov))
    intrinsic = np.array([[focal, 0, 0.5 * width], [0, focal, 0.5 * height], [0, 0, 1]])
    # The camera frame: z towards the centre, x = up x z, y = z x x: image rows run along y, which is
    # `up` made square to z (as in Open3D: row 0 lies farthest against `up`; -up gives upright images).
    forward = center - eye
    if not np.linalg.norm(forward) > 0 or not np.linalg.norm(up) > 0:
        raise ValueError("eye must differ from center, and up must not be zero")
    z = forward / np.linalg.norm(forward)
    x = np.cross(up / np.linalg.norm(up), z)
    if not np.linalg.norm(x) > 0:
        raise ValueError("up must not be parallel to the viewing direction (center - eye)")
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    extrinsic = np.eye(4)
    extrinsic[:3, :3] = np.stack([x, y, z])
    extrinsic[:3, 3] = -extrinsic[:3, :3] @ eye
    return _rays_from_matrices(intrinsic, extrinsic, width, height)
