#!/usr/bin/env python3
"""Writes the seed inputs of fuzz_profile_points into corpus/fuzz_profile_points/.

The byte layout is described at the top of fuzz_profile_points.cpp: byte 0 selects the decoding
(low 2 bits), the rest are points. Rerun after changing that layout; the seeds are tiny.
"""
import math
import os
import struct

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "fuzz_profile_points")
RAW, GRID, NUDGED, FLOATS = 0, 1, 2, 3


def raw(points, options=0):
    return bytes([RAW | options << 2]) + b"".join(struct.pack("<dd", r, z) for r, z in points)


def exponent_code(e):
    # The target reads code c as 2^c for |c| < 100 and as 2^(8c) beyond.
    code = e if abs(e) < 100 else e // 8
    assert (code if abs(code) < 100 else 8 * code) == e and -128 <= code <= 127, e
    return code


def grid(points, r_exponent=0, z_exponent=0, options=0):
    head = bytes([GRID | options << 2]) + struct.pack("<bb", exponent_code(r_exponent), exponent_code(z_exponent))
    return head + b"".join(struct.pack("<Bb", r, z) for r, z in points)


def nudged(points, options=0):
    # (r, z, dr, dz): r + dr 2^-30, z + dz 2^-30
    return bytes([NUDGED | options << 2]) + b"".join(struct.pack("<Bbbb", *p) for p in points)


def floats(points, options=0):
    return bytes([FLOATS | options << 2]) + b"".join(struct.pack("<ff", r, z) for r, z in points)


inf, nan = math.inf, math.nan
sphere = [(math.sin(math.pi * i / 8), -math.cos(math.pi * i / 8)) for i in range(9)]
sphere[0] = (0.0, -1.0)
sphere[-1] = (0.0, 1.0)
seeds = {
    "raw-capped-cylinder": raw([(0, 0), (1, 0), (1, 2), (0, 2)]),
    "raw-nan-and-inf": raw([(0, 0), (nan, 1), (inf, 2)]),
    "raw-near-double-max": raw([(0, -1e308), (1e308, 0), (1.7e308, 1e308), (0, 1.7e308)]),
    # Beyond Profile's range (extent below 2^-60): rejected, as the findings of this scale now are.
    "raw-tiny-1e-150": raw([(0, 0), (1e-150, 0), (1e-150, 1e-150), (0, 2e-150)]),
    # At the edges of Profile's range: extent 2^60; extent 2^-60 with a segment 2^-60 of it.
    "raw-extent-at-2pow60": raw([(0, -2.0**60), (2.0**60, -2.0**60), (2.0**60, 2.0**60), (0, 2.0**60)]),
    "raw-extent-at-2pow-60-segment-at-2pow-120": raw(
        [(0, 0), (2.0**-60, 0), (2.0**-60, 2.0**-120), (2.0**-61, 2.0**-61), (0, 2.0**-61)]),
    "raw-negative-zero-closed": raw([(-0.0, 0), (1, -0.0), (1, 1), (-0.0, -0.0)]),
    "raw-mixed-scales": raw([(0, 0), (1e-300, 1e300), (1e300, 1e-300), (0, 1)], options=0b101101),
    "raw-negative-radius": raw([(0, 0), (-1, 1)]),
    "grid-bowtie-crossing": grid([(0, 0), (2, 2), (2, 0), (0, 2)]),
    "grid-closed-square": grid([(1, 0), (2, 0), (2, 1), (1, 1), (1, 0)]),
    "grid-collinear-overlap": grid([(0, 0), (3, 0), (1, 0)]),
    "grid-vertex-touch-r-scaled-2pow1000-z-scaled-2pow-1024": grid([(0, 0), (4, 0), (4, 2), (2, 0)], 1000, -1024),
    "grid-closed-square-scaled-2pow50-2pow-60": grid([(1, 0), (2, 0), (2, 1), (1, 1), (1, 0)], 50, -60),
    "grid-zigzag-clean": grid([(0, 0), (7, 0)] + [(6 + i % 2, 1 + i) for i in range(9)] + [(0, 9)], options=0b011010),
    "grid-apexes-on-axis": grid([(0, -3), (2, -1), (2, 1), (0, 3)], -20, 30),
    "nudged-almost-touch": nudged([(0, 0, 0, 0), (4, 0, 0, 0), (4, 2, 0, 0), (2, 0, 0, 1)]),
    "nudged-exact-touch": nudged([(0, 0, 0, 0), (4, 0, 0, 0), (4, 2, 0, 0), (2, 0, 0, 0)]),
    "floats-sphere": floats(sphere, options=0b110001),
}

os.makedirs(HERE, exist_ok=True)
for name, data in seeds.items():
    with open(os.path.join(HERE, name + ".bin"), "wb") as out:
        out.write(data)
