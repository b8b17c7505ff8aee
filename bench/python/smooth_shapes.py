"""The benchmark's five test shapes (bench/test_shapes.cpp) as lines and circular arcs, in numpy: the
true surfaces every method's error is measured against, with their closed-form distances and
polylines of a given chord error. Nothing here uses revolve or Open3D."""

import math

import numpy as np


class SmoothProfile:
    """A profile drawn turtle-fashion from `start`, heading `heading` degrees from +r towards +z:
    lines, arcs (turning left for a positive turn) and sharp corners."""

    def __init__(self, name, start, heading):
        self.name = name
        self.cursor = np.array(start, dtype=np.float64)
        self.heading = math.radians(heading)
        self.pieces = []  # (start, end, radius, centre, angle0, turn); radius 0 for a line

    def line(self, length):
        end = self.cursor + length * np.array([math.cos(self.heading), math.sin(self.heading)])
        self.pieces.append((self.cursor.copy(), end, 0.0, None, 0.0, 0.0))
        self.cursor = end
        return self

    def arc(self, radius, turn_degrees):
        turn = math.radians(turn_degrees)
        side = 1.0 if turn > 0 else -1.0  # the centre lies to the left when turning left
        normal = side * np.array([-math.sin(self.heading), math.cos(self.heading)])
        centre = self.cursor + radius * normal
        angle0 = math.atan2(self.cursor[1] - centre[1], self.cursor[0] - centre[0])
        end = centre + radius * np.array([math.cos(angle0 + turn), math.sin(angle0 + turn)])
        self.pieces.append((self.cursor.copy(), end, radius, centre, angle0, turn))
        self.cursor = end
        self.heading += turn
        return self

    def corner(self, turn_degrees):
        self.heading += math.radians(turn_degrees)
        return self

    def line_to_axis(self):
        step = math.cos(self.heading)
        assert step < 0, "the heading must point towards the axis"
        return self.line(-self.cursor[0] / step)

    def extent(self):
        """r_max, z_low, z_high of the curve itself (arcs' extreme points included)."""
        points = self._dense(4096)
        return points[:, 0].max(), points[:, 1].min(), points[:, 1].max()

    def size(self):
        """The largest extent of the bounding box: 2 r_max across, or the height."""
        r_max, low, high = self.extent()
        return max(2 * r_max, high - low)

    def _dense(self, per_piece):
        out = []
        for start, end, radius, centre, angle0, turn in self.pieces:
            s = np.linspace(0, 1, per_piece)[:, None]
            if radius == 0:
                out.append(start + s * (end - start))
            else:
                phi = angle0 + s[:, 0] * turn
                out.append(centre + radius * np.stack([np.cos(phi), np.sin(phi)], axis=1))
        return np.concatenate(out)

    def polyline(self, chord_error):
        """A polyline through points of the curve within `chord_error` of it: every join a vertex,
        lines their two ends, each arc the fewest equal chords whose sagitta R (1 - cos(a / 2)) is
        within the error. Returns the points and their largest sagitta (the polyline's error)."""
        points, worst = [self.pieces[0][0]], 0.0
        for start, end, radius, centre, angle0, turn in self.pieces:
            if radius == 0:
                points.append(end)
                continue
            step = 2 * math.acos(max(-1.0, 1 - chord_error / radius))
            count = max(1, math.ceil(abs(turn) / step - 1e-12))
            phi = angle0 + turn * np.arange(1, count + 1) / count
            arc = centre + radius * np.stack([np.cos(phi), np.sin(phi)], axis=1)
            arc[-1] = end
            points.extend(arc)
            worst = max(worst, radius * (1 - math.cos(abs(turn) / count / 2)))
        points = np.array(points)
        points[np.abs(points[:, 0]) < 1e-15, 0] = 0.0  # ends on the axis exactly there
        if np.linalg.norm(points[-1] - points[0]) < 1e-12:
            points[-1] = points[0]  # a loop closes exactly
        return points, worst

    def distance(self, rho, z):
        """The distance from each meridian point (rho, z) to the curve, in closed form."""
        p = np.stack([rho, z], axis=1)
        best = np.full(len(p), np.inf)
        for start, end, radius, centre, angle0, turn in self.pieces:
            if radius == 0:
                e = end - start
                s = np.clip((p - start) @ e / (e @ e), 0, 1)
                d = np.linalg.norm(p - (start + s[:, None] * e), axis=1)
            else:
                offset = p - centre
                phi = np.arctan2(offset[:, 1], offset[:, 0])
                along = np.mod((phi - angle0) if turn >= 0 else (angle0 - phi), 2 * math.pi)
                inside = along <= abs(turn)
                ends = np.minimum(np.linalg.norm(p - start, axis=1), np.linalg.norm(p - end, axis=1))
                d = np.where(inside, np.abs(np.linalg.norm(offset, axis=1) - radius), ends)
            best = np.minimum(best, d)
        return best


def sphere():
    return SmoothProfile("sphere", (0, 0), 0).arc(0.5, 180)


def torus():
    return SmoothProfile("torus", (0.35, 0), 0).arc(0.15, 360)


def vase():
    return (SmoothProfile("vase", (0, 0), 0).line(0.16).arc(0.04, 80).arc(0.60, 30).arc(0.50, -50).arc(0.10, -30)
            .corner(150).line_to_axis())


def goblet():
    return (SmoothProfile("goblet", (0, 0), 0).line(0.24).arc(0.012, 180).line(0.12).arc(0.08, -90).line(0.14)
            .arc(0.03, -60).arc(0.03, 120).arc(0.03, -60).line(0.10).arc(0.06, -75).arc(0.28, 80).arc(0.006, 180)
            .arc(0.268, -80).arc(0.05, -15).line_to_axis())


def bottle():
    return (SmoothProfile("bottle", (0, 0), 0).line(0.16).arc(0.04, 90).line(0.50).arc(0.12, 60).line(0.08).arc(0.05, -60)
            .line(0.20).arc(0.012, -90).line(0.012).arc(0.012, 180).line_to_axis())


SHAPES = [sphere, torus, vase, goblet, bottle]
