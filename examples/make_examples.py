#!/usr/bin/env python3
"""Writes the bundled example files (run from the repository root; the outputs are committed).

vase.csv: a hollow vase of revolution: the outer wall from the foot (on the axis) up to the lip,
then the inner wall back down to the axis, so the profile is closed and not monotone in z.
vase_rays.csv: a 48 x 48 pinhole camera looking at it from the side and a little above.
"""
import math

def vase_profile():
    outer, inner = [], []
    n = 40
    for i in range(n + 1):
        s = i / n
        z = 1.2 * s
        r = 0.28 + 0.22 * math.sin(math.pi * (0.15 + 0.85 * s)) ** 2 - 0.12 * s + 0.04 * math.cos(6 * s)
        outer.append((r, z))
    thickness = 0.03
    for (r, z) in reversed(outer[1:]):
        if z < 0.08:
            break
        inner.append((r - thickness, z))
    inner.append((0.0, 0.08))
    points = [(0.0, 0.0)] + outer + [(outer[-1][0] - thickness / 2, 1.2 + 0.01)] + inner
    return points

def write_profile(path, points):
    with open(path, "w") as f:
        f.write("r,z\n")
        for r, z in points:
            f.write(f"{r:.6f},{z:.6f}\n")

def write_camera_rays(path, width, height):
    eye = (2.2, -1.4, 1.3)
    target = (0.0, 0.0, 0.55)
    up = (0.0, 0.0, 1.0)
    fwd = [t - e for t, e in zip(target, eye)]
    norm = math.sqrt(sum(c * c for c in fwd)); fwd = [c / norm for c in fwd]
    right = [fwd[1] * up[2] - fwd[2] * up[1], fwd[2] * up[0] - fwd[0] * up[2], fwd[0] * up[1] - fwd[1] * up[0]]
    norm = math.sqrt(sum(c * c for c in right)); right = [c / norm for c in right]
    cam_up = [right[1] * fwd[2] - right[2] * fwd[1], right[2] * fwd[0] - right[0] * fwd[2], right[0] * fwd[1] - right[1] * fwd[0]]
    half = math.tan(math.radians(18))
    with open(path, "w") as f:
        f.write("ox,oy,oz,dx,dy,dz,tnear,tfar\n")
        for j in range(height):
            for i in range(width):
                x = (2 * (i + 0.5) / width - 1) * half
                y = (1 - 2 * (j + 0.5) / height) * half
                d = [fwd[k] + x * right[k] + y * cam_up[k] for k in range(3)]
                f.write(f"{eye[0]},{eye[1]},{eye[2]},{d[0]:.7f},{d[1]:.7f},{d[2]:.7f},0,inf\n")

if __name__ == "__main__":
    write_profile("examples/vase.csv", vase_profile())
    write_camera_rays("examples/vase_rays.csv", 48, 48)
