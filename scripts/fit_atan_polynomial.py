#!/usr/bin/python3
"""Fits the polynomial behind revolve's azimuth (plugin/src/util/azimuth.h): atan(a) / a = P(a^2) on
[0, 1], degree 10 in a^2, minimising the largest relative error (Lawson's iteratively reweighted least
squares on Chebyshev and uniform nodes). Prints the coefficients and the error on 200,001 points.
Needs Debian's python3-numpy."""
import numpy as np

DEGREE = 10
a = np.concatenate([np.cos(np.linspace(0, np.pi, 4000)) * 0.5 + 0.5, np.linspace(0, 1, 4000)])
s = a * a
f = np.where(a > 0, np.arctan(a) / np.where(a > 0, a, 1), 1.0)
V = np.vander(s, DEGREE + 1, increasing=True)
w = np.ones_like(s)
for _ in range(200):
    root = np.sqrt(w)
    coefficients, *_ = np.linalg.lstsq(V * root[:, None], f * root, rcond=None)
    error = (V @ coefficients - f) / f
    w = w * np.abs(error)
    w /= w.sum()

check = np.linspace(0, 1, 200001)
exact = np.where(check > 0, np.arctan(check) / np.where(check > 0, check, 1), 1.0)
worst = np.max(np.abs((np.polyval(coefficients[::-1], check * check) - exact) / exact))
print(f"// degree {DEGREE} in a^2, largest relative error {worst:.2e}")
for i, c in enumerate(coefficients):
    print(f"c{i} = {c!r}")
