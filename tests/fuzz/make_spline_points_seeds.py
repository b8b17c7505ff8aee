#!/usr/bin/env python3
"""Writes the seed inputs of fuzz_spline_points into corpus/fuzz_spline_points/.

The byte layout is described at the top of fuzz_spline_points.cpp: byte 0 holds the kind (value
mod 5) and, in bits 4-5, the decoding; the rest are points. Rerun after changing that layout.
"""
import math
import os
import struct

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "fuzz_spline_points")
LINEAR, QUADRATIC, BEZIER, CATMULL_ROM, NATURAL = range(5)
RAW, GRID, NUDGED = 0, 1, 2


def raw(kind, points):
    return bytes([kind | RAW << 4]) + b"".join(struct.pack("<dd", r, z) for r, z in points)


def grid(kind, points):
    # (r, z) in sixteenths: r a u8, z an i8
    return bytes([kind | GRID << 4]) + b"".join(struct.pack("<Bb", r, z) for r, z in points)


def nudged(kind, points):
    # (r, z, dr, dz): r / 16 + dr 2^-40, z / 16 + dz 2^-40
    return bytes([kind | NUDGED << 4]) + b"".join(struct.pack("<Bbbb", *p) for p in points)


def sphere(radius, pieces):
    points = [(0.0, -radius)]
    theta = math.pi / pieces
    k = 4 / 3 * math.tan(theta / 4) * radius
    for i in range(pieces):
        a0 = -math.pi / 2 + i * theta
        a1 = a0 + theta
        p0 = (radius * math.cos(a0), radius * math.sin(a0))
        p1 = (radius * math.cos(a1), radius * math.sin(a1))
        points += [(p0[0] - k * math.sin(a0), p0[1] + k * math.cos(a0)), (p1[0] + k * math.sin(a1), p1[1] - k * math.cos(a1)), p1]
    points[-1] = (0.0, radius)
    return points


SEEDS = {
    "raw-bezier-sphere": raw(BEZIER, sphere(0.5, 4)),
    "raw-bezier-sphere-tiny": raw(BEZIER, [(r * 1e-12, z * 1e-12) for r, z in sphere(0.5, 2)]),
    "raw-natural-nan": raw(NATURAL, [(0, 0), (math.nan, 1), (0, 2)]),
    "raw-catmull-rom-huge": raw(CATMULL_ROM, [(0, 0), (1e18, 1), (0, 2e18)]),
    "grid-catmull-rom-vase": grid(CATMULL_ROM, [(0, 0), (3, 0), (5, 2), (7, 6), (6, 12), (3, 15), (4, 18), (0, 19)]),
    "grid-natural-goblet": grid(NATURAL, [(0, 0), (5, 0), (2, 2), (1, 5), (3, 8), (5, 12), (6, 15), (0, 16)]),
    "grid-natural-loop": grid(NATURAL, [(16, 0), (12, 8), (8, 0), (12, -8), (16, 0)]),
    "grid-catmull-rom-loop": grid(CATMULL_ROM, [(16, 0), (12, 8), (8, 0), (12, -8), (16, 0)]),
    "grid-quadratic-cup": grid(QUADRATIC, [(1, 0), (5, 0), (6, 1), (8, 8), (8, 16), (8, 17), (7, 17), (7, 16),
                                           (7, 8), (6, 2), (3, 1), (1, 1), (1, 0)]),
    "grid-bezier-bottle-straight-pieces": grid(BEZIER, [(0, 0), (2, 0), (3, 0), (4, 0), (5, 0), (5, 0), (5, 1),
                                                        (5, 4), (5, 6), (5, 8), (5, 10), (2, 10), (2, 12),
                                                        (2, 13), (2, 15), (2, 16), (1, 16), (0, 16)]),
    "grid-bezier-hourglass-pinch": grid(BEZIER, [(0, -16), (4, -16), (8, -16), (10, -16), (10, -8), (2, -3), (0, 0),
                                                 (2, 3), (10, 8), (10, 16), (6, 16), (3, 16), (0, 16)]),
    "grid-bezier-crossing": grid(BEZIER, [(0, 0), (5, 5), (10, 10), (16, 16), (16, 10), (6, 5), (0, 16)]),
    "grid-bezier-cusp": grid(BEZIER, [(0, 0), (5, 5), (10, 10), (16, 16), (11, 11), (6, 6), (3, 3)]),
    "raw-bezier-crosses-axis": raw(BEZIER, [(0.5, 0), (-1, 0.3), (-1, 0.7), (0.5, 1)]),
    "grid-quadratic-even-count": grid(QUADRATIC, [(0, 0), (8, 8), (0, 16), (4, 20)]),
    "grid-catmull-rom-repeated": grid(CATMULL_ROM, [(0, 0), (8, 8), (8, 8), (0, 16)]),
    "grid-linear-cup": grid(LINEAR, [(0, 0), (8, 0), (8, 16), (7, 16), (7, 1), (0, 1)]),
    "nudged-natural-near-axis": nudged(NATURAL, [(16, 0, 0, 0), (1, 2, 1, 0), (16, 4, 0, 0), (1, 6, -1, 0), (16, 8, 0, 0)]),
    "nudged-bezier-near-touch": nudged(BEZIER, [(0, 0, 0, 0), (16, 0, 0, 0), (16, 16, 0, 0), (8, 16, 0, 0),
                                                (15, 15, 0, 0), (15, 1, 0, 1), (0, 1, 0, 1)]),
}


def main():
    os.makedirs(HERE, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(HERE, name + ".bin"), "wb") as out:
            out.write(data)


if __name__ == "__main__":
    main()
