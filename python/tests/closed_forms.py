"""Closed-form answers the tests hold revolve to, computed here in double precision with numpy and
nothing of revolve: the surfaces the C++ tests use (tests/analytic_shapes_test.cpp: a cylinder, a
cone, a polyline inscribed in a sphere), a paraboloid (a quadratic Bezier spline is exactly z = r^2),
and distances to a polyline in the meridian plane."""

import numpy as np

SEED = 23  # every random draw of the Python tests; printed by the tests that use it


def incoherent_rays(rng, count, centre, radius, box_lower, box_upper, spread=3.0):
    """Origins on a sphere of `spread` times `radius` about `centre`, aimed at uniform points of
    the box, directions of random length (as tests/support/test_profiles.cpp's incoherentRays)."""
    u = rng.normal(size=(count, 3))
    u /= np.linalg.norm(u, axis=1)[:, None]
    origins = np.asarray(centre) + spread * radius * u
    targets = rng.uniform(box_lower, box_upper, size=(count, 3))
    scale = rng.uniform(0.5, 2.0, size=(count, 1))
    rays = np.concatenate([origins, (targets - origins) * scale], axis=1).astype(np.float32)
    return rays


def _smallest_root(a, b, c, accept):
    """The smallest root t >= 0 of a t^2 + b t + c with accept(t) true, per row; inf if none."""
    disc = b * b - 4 * a * c
    ok = disc >= 0
    sq = np.sqrt(np.where(ok, disc, 0))
    q = -0.5 * (b + np.copysign(sq, b))
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = np.where(a != 0, q / a, -c / b)
        t2 = np.where(q != 0, c / q, t1)
    lo, hi = np.minimum(t1, t2), np.maximum(t1, t2)
    best = np.full(a.shape, np.inf)
    for t in (hi, lo):  # lo last, so that it wins when both qualify
        good = ok & (t >= 0) & accept(t)
        best = np.where(good, t, best)
    return best


def split(rays):
    r = rays.astype(np.float64)
    return r[:, :3], r[:, 3:]


def cone_hits(rays, r0, z0, r1, z1):
    """t of the first hit with the surface swept by the segment (r0, z0)-(r1, z1), z0 != z1
    (a cylinder when r0 == r1); inf on a miss."""
    o, d = split(rays)
    k = (r1 - r0) / (z1 - z0)  # r(z) = r0 + k (z - z0) = m + k z
    m = r0 - k * z0
    a = d[:, 0] ** 2 + d[:, 1] ** 2 - (k * d[:, 2]) ** 2
    b = 2 * (o[:, 0] * d[:, 0] + o[:, 1] * d[:, 1] - k * d[:, 2] * (m + k * o[:, 2]))
    c = o[:, 0] ** 2 + o[:, 1] ** 2 - (m + k * o[:, 2]) ** 2
    lo, hi = min(z0, z1), max(z0, z1)

    def within(t):
        z = o[:, 2] + t * d[:, 2]
        return (z >= lo) & (z <= hi) & (m + k * z >= 0)

    return _smallest_root(a, b, c, within)


def paraboloid_hits(rays, top):
    """t of the first hit with z = x^2 + y^2, z <= top; inf on a miss."""
    o, d = split(rays)
    a = d[:, 0] ** 2 + d[:, 1] ** 2
    b = 2 * (o[:, 0] * d[:, 0] + o[:, 1] * d[:, 1]) - d[:, 2]
    c = o[:, 0] ** 2 + o[:, 1] ** 2 - o[:, 2]
    return _smallest_root(a, b, c, lambda t: o[:, 2] + t * d[:, 2] <= top)


def segment_distances(rho, z, points):
    """Distance from each meridian point (rho, z) to the polyline `points` (N, 2), brute force over
    its segments, with the index of the nearest segment, the nearest point, and the distance to the
    second nearest segment (how far the answer is from a tie)."""
    a, b = points[:-1], points[1:]
    e = b - a
    q = np.stack([rho, z], axis=1)[:, None, :]
    s = np.clip(np.einsum("psk,sk->ps", q - a[None], e) / np.einsum("sk,sk->s", e, e), 0, 1)
    nearest = a[None] + s[..., None] * e[None]
    dist = np.linalg.norm(q - nearest, axis=2)
    best = np.argmin(dist, axis=1)
    rows = np.arange(len(rho))
    second = np.sort(dist, axis=1)[:, 1] if dist.shape[1] > 1 else np.full(len(rho), np.inf)
    return dist[rows, best], best, nearest[rows, best], second


def semicircle(radius, segments):
    """A polyline inscribed in a half circle from the south pole to the north (as
    tests/support/test_profiles.cpp's sphereLike): revolved, a closed solid inscribed in a sphere,
    within radius (1 - cos(pi / (2 segments))) of it."""
    angles = np.linspace(-np.pi / 2, np.pi / 2, segments + 1)
    points = radius * np.stack([np.cos(angles), np.sin(angles)], axis=1)
    points[0, 0] = points[-1, 0] = 0.0
    return points


def circle_loop(centre_r, radius, segments):
    """A closed polyline inscribed in the circle about (centre_r, 0): revolved, a torus."""
    angles = np.linspace(0, 2 * np.pi, segments + 1)
    points = np.stack([centre_r + radius * np.cos(angles), radius * np.sin(angles)], axis=1)
    points[-1] = points[0]
    return points


def rotation(axis, degrees):
    """The 3x3 rotation about a unit axis (Rodrigues' formula), in double."""
    k = np.asarray(axis, dtype=np.float64)
    k = k / np.linalg.norm(k)
    theta = np.radians(degrees)
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(theta) * kx + (1 - np.cos(theta)) * kx @ kx


def placement(scale, axis, degrees, translate):
    """A 4x4 similarity: translate . rotate . uniform scale."""
    m = np.eye(4)
    m[:3, :3] = scale * rotation(axis, degrees)
    m[:3, 3] = translate
    return m
