"""A profile swept into a triangle mesh: what a user of a triangle ray caster (Open3D's
RaycastingScene, revolve's add_triangles) traces in place of the exact surface."""

import operator

import numpy as np


def tessellate(points, slices):
    """The profile (N, 2) of (r, z) swept about the z axis in `slices` equal steps: vertices on the
    exact circles, float32 (N * slices, 3), and 2 (N - 1) slices triangles, uint32 (M, 3), facing
    the side revolve's normals face (outwards for a profile listed from bottom to top).

    Its distance from the surface is at most r_max (1 - cos(pi / slices)) for the circles plus the
    profile's own distance from the curve it samples."""
    try:
        profile = np.asarray(points, dtype=np.float64)
    except (TypeError, ValueError) as error:  # a ragged list, strings, None: numpy says which
        raise ValueError(f"points: not an (N, 2) array of numbers ({error})") from None
    if profile.ndim != 2 or profile.shape[1] != 2 or len(profile) < 2:
        raise ValueError(f"points: shape {profile.shape}; expected (N, 2) with N >= 2")
    if not np.all(np.isfinite(profile)) or np.any(profile[:, 0] < 0):
        raise ValueError("points: every r and z must be finite, and r >= 0")
    if isinstance(slices, bool):
        raise TypeError("slices: a bool; expected a whole number, at least 3")
    try:
        slices = operator.index(slices)
    except TypeError:
        raise TypeError(f"slices: a {type(slices).__name__}; expected a whole number, at least 3") from None
    if slices < 3:
        raise ValueError(f"slices = {slices}: must be a whole number, at least 3")
    if slices > 1 << 24:
        raise ValueError(f"slices = {slices}: at most 2^24 (16,777,216) steps about the axis")
    phi = 2 * np.pi * np.arange(slices) / slices
    r, z = profile[:, 0][:, None], profile[:, 1][:, None]
    vertices = np.stack([r * np.cos(phi), r * np.sin(phi), np.broadcast_to(z, (len(profile), slices))], axis=2)
    ring = np.arange(len(profile) - 1)[:, None] * slices
    j = np.arange(slices)[None, :]
    a, b = ring + j, ring + (j + 1) % slices  # on ring i; c, d above them on ring i + 1
    c, d = b + slices, a + slices
    triangles = np.concatenate([np.stack([a, b, c], axis=2), np.stack([a, c, d], axis=2)], axis=1)
    return vertices.reshape(-1, 3).astype(np.float32), triangles.reshape(-1, 3).astype(np.uint32)
