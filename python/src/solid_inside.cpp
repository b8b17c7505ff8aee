#include "solid_inside.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace revolve::python {
namespace {

struct Cubic {
  double r[4], z[4];
  Point2 at(double u) const {
    const double s = 1 - u;
    const double b0 = s * s * s, b1 = 3 * s * s * u, b2 = 3 * s * u * u, b3 = u * u * u;
    return {b0 * r[0] + b1 * r[1] + b2 * r[2] + b3 * r[3], b0 * z[0] + b1 * z[1] + b2 * z[2] + b3 * z[3]};
  }
};

// Whether the part of `c` over [u0, u1], monotone in z, crosses the half-line.
bool partCrosses(const Cubic& c, double u0, double u1, double rho, double height) {
  // The ends exactly as given for the piece's ends (u = 0, 1), so that neighbours agree.
  const double z0 = u0 == 0 ? c.z[0] : c.at(u0).z, z1 = u1 == 1 ? c.z[3] : c.at(u1).z;
  const bool above0 = z0 > height, above1 = z1 > height;
  if (above0 == above1) return false;
  // Bisection on the side of the line: ~60 halvings reach double's resolution of u.
  double low = u0, high = u1;
  for (int i = 0; i < 200 && low < high; ++i) {
    const double middle = 0.5 * (low + high);
    if (middle <= low || middle >= high) break;
    ((c.at(middle).z > height) == above0 ? low : high) = middle;
  }
  return c.at(0.5 * (low + high)).r > rho;
}

// The parameters in (0, 1) where z'(u) = 0, in order (at most two).
int zTurns(const Cubic& c, double turns[2]) {
  // z'(u) / 3 = a u^2 + b u + d with the Bernstein differences.
  const double d0 = c.z[1] - c.z[0], d1 = c.z[2] - c.z[1], d2 = c.z[3] - c.z[2];
  const double a = d0 - 2 * d1 + d2, b = 2 * (d1 - d0), d = d0;
  int count = 0;
  const auto keep = [&](double u) {
    if (u > 0 && u < 1) turns[count++] = u;
  };
  if (a == 0) {
    if (b != 0) keep(-d / b);
  } else {
    const double disc = b * b - 4 * a * d;
    if (disc >= 0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      double u1 = q / a, u2 = q != 0 ? d / q : u1;
      if (u1 > u2) std::swap(u1, u2);
      keep(u1);
      if (u2 != u1) keep(u2);
    }
  }
  return count;
}

}  // namespace

bool insideSolid(const Shape& shape, double rho, double z) noexcept {
  bool inside = false;
  if (const Spline* spline = shape.spline()) {
    const std::span<const Point2> b = spline->bezier();
    for (std::size_t piece = 0; piece + 3 < b.size(); piece += 3) {
      const Cubic c{{b[piece].r, b[piece + 1].r, b[piece + 2].r, b[piece + 3].r},
                    {b[piece].z, b[piece + 1].z, b[piece + 2].z, b[piece + 3].z}};
      double turns[2];
      const int count = zTurns(c, turns);
      double start = 0;
      for (int i = 0; i <= count; ++i) {
        const double end = i < count ? turns[i] : 1;
        inside ^= partCrosses(c, start, end, rho, z);
        start = end;
      }
    }
    return inside;
  }
  const std::span<const Point2> p = shape.profile().points();
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const Point2 a = p[i], b = p[i + 1];
    if ((a.z > z) == (b.z > z)) continue;
    const double r = a.r + (b.r - a.r) * ((z - a.z) / (b.z - a.z));
    inside ^= r > rho;
  }
  return inside;
}

}  // namespace revolve::python
