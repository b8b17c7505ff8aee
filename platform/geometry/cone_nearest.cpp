#include "geometry/cone_nearest.h"

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <numbers>

namespace revolve::app {
namespace {

// Polynomials are built in long double from the double inputs (the cone's basis, the profile's
// points) and solved in long double: their coefficients are sums of products of up to ten
// coordinates, and the roots are bisected to the last bit of long double (x86's 64-bit significand),
// so that the points come out of them with little more than their inputs' double rounding.
using Real = long double;

// A polynomial of degree <= 8: c[0] + c[1] t + ... + c[8] t^8.
struct Poly {
  std::array<Real, 9> c{};
  int degree = 0;
};

Poly poly(std::initializer_list<Real> coefficients) {
  Poly p;
  int k = 0;
  for (const Real c : coefficients) p.c[std::size_t(k++)] = c;
  p.degree = k - 1;
  return p;
}

Poly operator*(const Poly& a, const Poly& b) {
  Poly p;
  p.degree = a.degree + b.degree;
  for (int i = 0; i <= a.degree; ++i)
    for (int j = 0; j <= b.degree; ++j) p.c[std::size_t(i + j)] += a.c[std::size_t(i)] * b.c[std::size_t(j)];
  return p;
}

Poly operator+(const Poly& a, const Poly& b) {
  Poly p;
  p.degree = std::max(a.degree, b.degree);
  for (int i = 0; i <= p.degree; ++i) p.c[std::size_t(i)] = a.c[std::size_t(i)] + b.c[std::size_t(i)];
  return p;
}

Poly operator*(Real s, const Poly& a) {
  Poly p = a;
  for (int i = 0; i <= p.degree; ++i) p.c[std::size_t(i)] *= s;
  return p;
}

Real evaluate(const Real* c, int degree, Real t) {
  Real value = c[degree];
  for (int k = degree - 1; k >= 0; --k) value = value * t + c[k];
  return value;
}

// The real roots of c[0] + ... + c[degree] t^degree in [lo, hi], ascending, by isolation: the roots
// of the derivative (recursively) cut [lo, hi] into pieces on which the polynomial is monotone, and
// each piece whose ends differ in sign holds one root, bisected until its bracket cannot shrink. No
// division by the leading coefficient, so a nearly degenerate degree is harmless. With `stationary`,
// the derivative's roots are appended too (a double root, where the polynomial touches zero without
// changing sign, is one of them). Returns the count written to `out` (at most 2 degree - 1).
int realRoots(const Real* c, int degree, Real lo, Real hi, Real* out, bool stationary = false) {
  while (degree > 0 && c[degree] == 0) --degree;
  if (degree == 0) return 0;  // a constant: no isolated root (the callers' fixed samples cover zero)
  if (degree == 1) {
    const Real t = -c[0] / c[1];
    if (t >= lo && t <= hi) {
      out[0] = t;
      return 1;
    }
    return 0;
  }
  Real derivative[8]{}, critical[8]{};
  for (int k = 1; k <= degree; ++k) derivative[k - 1] = Real(k) * c[k];
  const int criticalCount = realRoots(derivative, degree - 1, lo, hi, critical);
  int count = 0;
  Real a = lo, fa = evaluate(c, degree, a);
  for (int i = 0; i <= criticalCount; ++i) {
    const Real b = i < criticalCount ? critical[i] : hi;
    const Real fb = evaluate(c, degree, b);
    if (fa == 0) {
      if (count == 0 || out[count - 1] != a) out[count++] = a;
    } else if (fb != 0 && (fa < 0) != (fb < 0)) {
      Real low = a, high = b;
      const bool risingAtLow = fa < 0;
      for (;;) {
        const Real middle = 0.5L * (low + high);
        if (!(middle > low && middle < high)) break;
        const Real fm = evaluate(c, degree, middle);
        if (fm == 0) {
          low = high = middle;
          break;
        }
        ((fm < 0) == risingAtLow ? low : high) = middle;
      }
      out[count++] = 0.5L * (low + high);
    }
    a = b;
    fa = fb;
  }
  if (fa == 0 && (count == 0 || out[count - 1] != a)) out[count++] = a;
  if (stationary)
    for (int i = 0; i < criticalCount; ++i) out[count++] = critical[i];
  return count;
}

int realRoots(const Poly& p, Real* out, bool stationary) {
  return realRoots(p.c.data(), p.degree, -1, 1, out, stationary);
}

Vec3d scaled(double s, const Vec3d& a) { return {s * a[0], s * a[1], s * a[2]}; }
double norm(const Vec3d& a) { return std::sqrt(dot(a, a)); }

// The cone's boundary, half-angle a about axis w, is the rays in the unit directions
//   d(theta) = cos a w + sin a (cos theta u + sin theta v).
// With t = tan(theta / 2) (cos theta = (1 - t^2) / (1 + t^2), sin theta = 2 t / (1 + t^2)),
// d = D(t) / (1 + t^2) and d' = dd/dtheta = E(t) / (1 + t^2) with D, E quadratics in t, one a
// coordinate. t in [-1, 1] covers theta in [-pi/2, pi/2]; the other half is the same with u, v
// negated (`half` 1), so every root is sought on a bounded interval.
struct Boundary {
  std::array<Poly, 3> D, E;
};

Boundary boundaryOf(const SensorCone& cone, int half) {
  const double c = cone.cosHalf(), s = half == 0 ? cone.sinHalf() : -cone.sinHalf();
  Boundary b;
  for (std::size_t i = 0; i < 3; ++i) {
    const Real w = cone.axis()[i], u = cone.u()[i], v = cone.v()[i];
    b.D[i] = poly({c * w + s * u, 2 * s * v, c * w - s * u});
    b.E[i] = poly({s * v, -2 * s * u, -s * v});
  }
  return b;
}

// The unit boundary direction at t of `half`, evaluated from D(t) / (1 + t^2) (unit up to rounding).
Vec3d boundaryDirection(const SensorCone& cone, int half, Real t) {
  const Real c = cone.cosHalf(), s = half == 0 ? cone.sinHalf() : -cone.sinHalf();
  const Real w1 = 1 + t * t, cosTheta = (1 - t * t) / w1, sinTheta = 2 * t / w1;
  Vec3d d;
  for (std::size_t i = 0; i < 3; ++i)
    d[i] = double(c * cone.axis()[i] + s * (cosTheta * cone.u()[i] + sinTheta * cone.v()[i]));
  return d;
}

// The roots s >= 0 of a s^2 + b s + c = 0 (in long double). A discriminant below zero by no more
// than its rounding bound is a tangent ray touching the surface: taken as zero, so that a cone whose
// boundary grazes a surface sees it. The bound: a, b, c are products of the boundary direction,
// rounded to double (2^-53 relative), so b^2 - 4ac is known to a few units of double's epsilon in
// b^2 + 4 |a c|; 8 of them.
int nonNegativeRoots(Real a, Real b, Real c, Real* out) {
  constexpr Real kUnit = std::numeric_limits<double>::epsilon();
  int count = 0;
  if (a == 0) {
    if (b != 0 && -c / b >= 0) out[count++] = -c / b;
    return count;
  }
  Real disc = b * b - 4 * a * c;
  if (disc < 0) {
    if (-disc > 8 * kUnit * (b * b + 4 * std::abs(a * c))) return 0;
    disc = 0;
  }
  const Real q = -0.5L * (b + std::copysign(std::sqrt(disc), b));
  const Real roots[2] = {q / a, q != 0 ? c / q : q / a};
  for (const Real r : roots)
    if (r >= 0) out[count++] = r;
  return count;
}

// --- A profile segment swept about z: the truncated cone between (r0, z0) and (r1, z1). ---------
//
// With dr = r1 - r0, dz = z1 - z0 (dz != 0) the surface is dz^2 (x^2 + y^2) = m(z)^2, m(z) = dz r0 +
// dr (z - z0) (= dz r(z)), for z between z0 and z1 (written multiplied by dz^2 so that nearly
// horizontal segments stay well scaled). On the boundary ray p + s d(theta) this is the quadratic
//   A s^2 + B s + C = 0,  A = dz^2 (dx^2 + dy^2) - dr^2 dz_^2,  B = 2 (dz^2 (px dx + py dy) - mp dr dz_),
//   C = dz^2 (px^2 + py^2) - mp^2,   mp = m(pz), dz_ the direction's z component,
// with A quadratic and B linear in (cos theta, sin theta), C constant. Along a branch s(theta) of the
// intersection curve, differentiating gives A' s^2 + (2 A s + B) s' + B' s = 0, so s' = 0 (s > 0)
// means s = -B' / A', and substituting: P = A B'^2 - B B' A' + C A'^2 = 0 (also when A' = B' = 0).
// Multiplied by (1 + t^2)^4, P is a polynomial of degree 8 in t: each stationary point of the
// distance along the curve is among its roots.

struct Segment {
  double r0, z0, r1, z1;
};

void offerBoundaryRay(const SensorCone& cone, const Segment& g, int half, Real t, ConeNearest& best) {
  const Vec3d d = boundaryDirection(cone, half, t);
  const Vec3d& p = cone.apex();
  const Real dr = g.r1 - g.r0, dz = g.z1 - g.z0;
  const Real mp = dz * g.r0 + dr * (Real(p[2]) - g.z0);
  const Real a = dz * dz * (Real(d[0]) * d[0] + Real(d[1]) * d[1]) - dr * dr * Real(d[2]) * d[2];
  const Real b = 2 * (dz * dz * (Real(p[0]) * d[0] + Real(p[1]) * d[1]) - mp * dr * d[2]);
  const Real c = dz * dz * (Real(p[0]) * p[0] + Real(p[1]) * p[1]) - mp * mp;
  Real s[2];
  const int n = nonNegativeRoots(a, b, c, s);
  const double zLow = std::min(g.z0, g.z1), zHigh = std::max(g.z0, g.z1);
  for (int i = 0; i < n; ++i) {
    const Vec3d x = plus(p, scaled(double(s[i]), d));
    if (x[2] >= zLow && x[2] <= zHigh) best.offer(double(s[i]), x);
  }
}

void boundaryOfSlopedSegment(const SensorCone& cone, const Segment& g, ConeNearest& best) {
  const Vec3d& p = cone.apex();
  const Real dr = g.r1 - g.r0, dz = g.z1 - g.z0, dz2 = dz * dz;
  const Real mp = dz * g.r0 + dr * (Real(p[2]) - g.z0);
  const Real c = dz2 * (Real(p[0]) * p[0] + Real(p[1]) * p[1]) - mp * mp;
  for (int half = 0; half < 2; ++half) {
    const Boundary b = boundaryOf(cone, half);
    const auto& D = b.D;
    const auto& E = b.E;
    const Poly a = dz2 * (D[0] * D[0] + D[1] * D[1]) + (-dr * dr) * (D[2] * D[2]);
    const Poly a1 = 2 * (dz2 * (D[0] * E[0] + D[1] * E[1]) + (-dr * dr) * (D[2] * E[2]));
    const Poly bb = 2 * (dz2 * (Real(p[0]) * D[0] + Real(p[1]) * D[1]) + (-mp * dr) * D[2]);
    const Poly b1 = 2 * (dz2 * (Real(p[0]) * E[0] + Real(p[1]) * E[1]) + (-mp * dr) * E[2]);
    const Poly stationary = a * (b1 * b1) + (-1) * (bb * (b1 * a1)) + c * (a1 * a1);
    Real t[15 + 3];  // roots and stationary points of a degree-8 polynomial, and the samples
    int n = realRoots(stationary, t, true);
    // Fixed samples: where P vanishes identically (the cone's axis on the segment's axis, say),
    // the distance is the same all along the curve and any point of it is the nearest.
    for (const Real sample : {-1.0L, 0.0L, 1.0L}) t[n++] = sample;
    for (int i = 0; i < n; ++i) offerBoundaryRay(cone, g, half, t[i], best);
  }
}

// A horizontal segment is the annulus z = z0, r between r0 and r1: the boundary ray meets its plane
// at s = (z0 - pz) / dz_(theta), stationary where dz_'(theta) = 0: theta = atan2(v_z, u_z) and
// that plus pi.
void boundaryOfFlatSegment(const SensorCone& cone, const Segment& g, ConeNearest& best) {
  const Vec3d& p = cone.apex();
  const double stationary = std::atan2(cone.v()[2], cone.u()[2]);
  const double rLow = std::min(g.r0, g.r1), rHigh = std::max(g.r0, g.r1);
  constexpr double kPi = std::numbers::pi;
  // Fixed samples: a vertical cone axis makes dz_ constant, every theta stationary.
  for (const double theta : {stationary, stationary + kPi, 0.0, 0.5 * kPi, kPi, 1.5 * kPi}) {
    Vec3d d;
    for (std::size_t i = 0; i < 3; ++i)
      d[i] = cone.cosHalf() * cone.axis()[i] +
             cone.sinHalf() * (std::cos(theta) * cone.u()[i] + std::sin(theta) * cone.v()[i]);
    if (d[2] == 0) continue;
    const double s = (g.z0 - p[2]) / d[2];
    if (!(s >= 0)) continue;
    const Vec3d x{p[0] + s * d[0], p[1] + s * d[1], g.z0};
    const double r = std::hypot(x[0], x[1]);
    if (r >= rLow && r <= rHigh) best.offer(s, x);
  }
}

// The circle of radius r > 0 at height z (a profile vertex swept): the distance from p is least at
// its point in p's meridian half-plane and greatest opposite, so on an arc of the circle inside the
// cone it is least at one of those two or at an end of the arc, where the circle crosses the cone's
// boundary: ((x - p) . w)^2 = cos^2 a |x - p|^2 with (x - p) . w >= 0 (not the cone's mirror
// image). The circle is taken from its point x0 = r e nearest p (e: p's meridian direction, f: e
// turned a quarter about z), psi the angle from there and t = tan(psi / 2), so that every
// coefficient is a difference computed before it is small (x0 - p, not x - p from far-apart
// values): with w1 = 1 + t^2, x - x0 = r (-2 t^2 e + 2 t f) / w1, and
//   (x - p) . w = L(t) / w1,     L = g w1 - 2 r (e . w) t^2 + 2 r (f . w) t,   g = (x0 - p) . w,
//   |x - p|^2  = Q(t) / w1,      Q = d0^2 w1 + 4 r rho t^2,                     d0 = |x0 - p|,
// so the crossings are the roots of the quartic L^2 - cos^2 a Q w1 (psi in [-pi/2, pi/2]; the other
// half, psi + pi, has x - x0 = -r (2 e + 2 t f) / w1: L = g w1 - 2 r (e . w) - 2 r (f . w) t, Q = d0^2
// w1 + 4 r rho). Each root, and each stationary point (a crossing where the circle touches the
// boundary, or every crossing of the half-space, cos a = 0, is a double root), is kept when its point
// lies on the boundary to within the rounding of its computation (SensorCone::onBoundary).
void nearestOnCircle(const SensorCone& cone, double r, double z, const Vec3d& meridian, ConeNearest& best) {
  const Vec3d& p = cone.apex();
  const Vec3d& w = cone.axis();
  for (const double side : {1.0, -1.0}) {
    const Vec3d x{side * r * meridian[0], side * r * meridian[1], z};
    if (cone.contains(x)) best.offer(norm(minus(x, p)), x);
  }
  const Vec3d e = meridian, f{-meridian[1], meridian[0], 0};
  const double rho = std::hypot(p[0], p[1]);
  const Real radial = Real(r) - rho, vertical = Real(z) - p[2];  // x0 - p = radial e + vertical z
  const Real g = radial * dot(e, w) + vertical * w[2], d2 = radial * radial + vertical * vertical;
  const Real ew = dot(e, w), fw = dot(f, w), c2 = Real(cone.cosHalf()) * cone.cosHalf();
  const Poly w1 = poly({1, 0, 1});
  for (int half = 0; half < 2; ++half) {
    const Poly l = half == 0 ? poly({g, 2 * r * fw, g - 2 * r * ew}) : poly({g - 2 * r * ew, -2 * r * fw, g});
    const Poly q = half == 0 ? poly({d2, 0, d2 + 4 * Real(r) * rho}) : poly({d2 + 4 * Real(r) * rho, 0, d2});
    const Poly crossing = l * l + (-c2) * (q * w1);
    Real t[8];
    const int n = realRoots(crossing, t, true);
    for (int i = 0; i < n; ++i) {
      const Real tt = t[i] * t[i], den = 1 + tt;
      // x - x0 along e and f: the first half's -2 r t^2 / w1 and 2 r t / w1; the second's -2 r / w1, -2 r t / w1.
      const Real alongE = half == 0 ? -2 * r * tt / den : -2 * r / den, alongF = (half == 0 ? 2 : -2) * r * t[i] / den;
      const Vec3d x{double(r * e[0] + alongE * e[0] + alongF * f[0]), double(r * e[1] + alongE * e[1] + alongF * f[1]),
                    z};
      if (cone.onBoundary(x)) best.offer(norm(minus(x, p)), x);
    }
  }
}

// Lower bounds on a segment's distance and whether it may reach into the cone: its surface lies in
// the ball about (0, 0, middle height) through its farthest rim, padded by 2^-20 of the radius (far
// above the rounding of the few operations computing it, so no segment reaching into the cone is
// dropped).
bool segmentMayMatter(const SensorCone& cone, const Segment& g, double within) {
  const double middle = 0.5 * (g.z0 + g.z1), halfHeight = 0.5 * std::abs(g.z1 - g.z0);
  const double radius = std::hypot(std::max(g.r0, g.r1), halfHeight) * (1 + 0x1p-20);
  return cone.mayReach({0, 0, middle}, radius, within);
}

}  // namespace

SensorCone::SensorCone(const Vec3d& apex, const Vec3d& axis, double halfAngle)
    : apex_(apex), halfAngle_(halfAngle), cos_(std::cos(halfAngle)), sin_(std::sin(halfAngle)) {
  const double length = norm(axis);
  axis_ = scaled(1 / length, axis);
  // Any unit vector not along the axis, crossed with it (Gram-Schmidt would do as well).
  const Vec3d other = std::abs(axis_[0]) < 0.6 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  const Vec3d u = cross(other, axis_);
  u_ = scaled(1 / norm(u), u);
  v_ = cross(axis_, u_);
  if (halfAngle_ == std::numbers::pi / 2) cos_ = 0;  // the half-space exactly, not cos(rounded pi/2)
}

bool SensorCone::contains(const Vec3d& x) const {
  const Vec3d d = minus(x, apex_);
  return dot(d, axis_) >= norm(d) * cos_;
}

bool SensorCone::onBoundary(const Vec3d& x) const {
  const Vec3d d = minus(x, apex_);
  const double distance = norm(d);
  // A crossing's point comes from double inputs through long double roots: within a few hundred
  // units of 2^-53 of the coordinates' size for a simple root; 2^-40 of it (2^13 units) leaves room
  // for a nearly double one. Seen from the apex that is an angle of 2^-40 size / distance. And 2^-30
  // radians more: the stationary point between two crossings that close (a cone within 2^-30 of a
  // half-space, a circle barely dipping into the boundary) stands for both. The angle itself by
  // atan2, accurate at every angle (so that a thin cone's boundary is told from its axis).
  const double position = 0x1p-40 * std::max(norm(x), norm(apex_));
  if (distance <= position) return true;  // the apex itself, to the point's rounding
  const double angle = std::atan2(norm(cross(d, axis_)), dot(d, axis_));
  return std::abs(angle - halfAngle_) <= position / distance + 0x1p-30;
}

bool SensorCone::mayReach(const Vec3d& centre, double radius, double within) const {
  const Vec3d d = minus(centre, apex_);
  const double distance = norm(d);
  if (distance - radius >= within) return false;
  if (distance <= radius) return true;
  // The angle from the axis by atan2, accurate at every angle (acos loses half the digits near 0).
  const double beta = std::atan2(norm(cross(d, axis_)), dot(d, axis_));
  // 2^-30 radians of slack: far above the rounding of atan2 and asin (a few units in 2^-52).
  return beta <= halfAngle_ + std::asin(radius / distance) + 0x1p-30;
}

void nearestOnRevolution(std::span<const Point2> profile, const SensorCone& cone, ConeNearest& best) {
  const Vec3d& p = cone.apex();
  const double rho = std::hypot(p[0], p[1]);
  // p's meridian direction; on the axis every half-plane is p's (the circles' crossings then
  // bound each arc, and their meridian points stand for the whole circle).
  const Vec3d meridian = rho > 0 ? Vec3d{p[0] / rho, p[1] / rho, 0} : Vec3d{1, 0, 0};

  for (const Point2 vertex : profile) {
    if (vertex.r == 0) {
      const Vec3d x{0, 0, vertex.z};
      if (cone.contains(x)) best.offer(norm(minus(x, p)), x);
    } else if (cone.mayReach({0, 0, vertex.z}, vertex.r * (1 + 0x1p-20), best.distance)) {
      nearestOnCircle(cone, vertex.r, vertex.z, meridian, best);
    }
  }
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    const Segment g{profile[i].r, profile[i].z, profile[i + 1].r, profile[i + 1].z};
    if (!segmentMayMatter(cone, g, best.distance)) continue;
    // The feet of the perpendiculars from p in its meridian plane: from (rho, pz) to the segment on
    // p's side of the axis, and from (-rho, pz) to it on the far side (its mirror image).
    const double dr = g.r1 - g.r0, dz = g.z1 - g.z0, length2 = dr * dr + dz * dz;
    for (const double side : {1.0, -1.0}) {
      const double lambda = ((side * rho - g.r0) * dr + (p[2] - g.z0) * dz) / length2;
      if (!(lambda > 0 && lambda < 1)) continue;
      const double r = g.r0 + lambda * dr, z = g.z0 + lambda * dz;
      const Vec3d x{side * r * meridian[0], side * r * meridian[1], z};
      if (cone.contains(x)) best.offer(norm(minus(x, p)), x);
    }
    if (dz == 0)
      boundaryOfFlatSegment(cone, g, best);
    else
      boundaryOfSlopedSegment(cone, g, best);
  }
}

// A triangle T in the plane n . x = h: T inside the cone is convex, and the distance from p is least
// at the foot of the perpendicular on the plane, at an edge's nearest point or a vertex (inside the
// cone), or on the cone's boundary: where an edge crosses it (a quadratic along the edge) or where
// the distance along the conic "plane meets boundary" is stationary: s(theta) = (h - n . p) /
// (n . d(theta)), stationary where n . d'(theta) = 0, theta = atan2(n . v, n . u) and that plus pi.
void nearestOnTriangle(const std::array<Vec3d, 3>& triangle, const SensorCone& cone, ConeNearest& best) {
  const Vec3d& p = cone.apex();
  const Vec3d centre =
      scaled(1.0 / 3.0, plus(triangle[0], plus(triangle[1], triangle[2])));  // a point inside, any would do
  double radius = 0;
  for (const Vec3d& vertex : triangle) radius = std::max(radius, norm(minus(vertex, centre)));
  if (!cone.mayReach(centre, radius * (1 + 0x1p-20), best.distance)) return;

  for (const Vec3d& vertex : triangle)
    if (cone.contains(vertex)) best.offer(norm(minus(vertex, p)), vertex);
  const Vec3d& w = cone.axis();
  const double c2 = cone.cosHalf() * cone.cosHalf();
  for (int k = 0; k < 3; ++k) {
    const Vec3d& a = triangle[std::size_t(k)];
    const Vec3d e = minus(triangle[std::size_t((k + 1) % 3)], a);
    const double length2 = dot(e, e);
    if (length2 == 0) continue;
    const Vec3d pa = minus(a, p);
    const double nearest = -dot(pa, e) / length2;
    if (nearest > 0 && nearest < 1) {
      const Vec3d x = plus(a, scaled(nearest, e));
      if (cone.contains(x)) best.offer(norm(minus(x, p)), x);
    }
    // Where the edge crosses the cone's boundary: from the point f of its line nearest p (so that
    // the coefficients are as small as the distances they stand for), x = f + m e, and
    // ((f - p + m e) . w)^2 - cos^2 a (|f - p|^2 + m^2 |e|^2) = 0 (f - p is square to e), a quadratic
    // in m; each root and the stationary point (the double root of a half-space's crossing, or of an
    // edge touching the boundary) kept when its point lies on the boundary (SensorCone::onBoundary).
    const Vec3d foot = plus(a, scaled(nearest, e)), fromApex = minus(foot, p);
    const double fw = dot(fromApex, w), ew = dot(e, w);
    const Real qa = Real(ew) * ew - c2 * length2, qb = 2 * Real(fw) * ew,
               qc = Real(fw) * fw - c2 * dot(fromApex, fromApex);
    const Real coefficients[3] = {qc, qb, qa};
    Real m[4];
    const int n = realRoots(coefficients, 2, -nearest, 1 - nearest, m, true);
    for (int i = 0; i < n; ++i) {
      const Vec3d x = plus(foot, scaled(double(m[i]), e));
      if (cone.onBoundary(x)) best.offer(norm(minus(x, p)), x);
    }
  }

  const Vec3d normal = cross(minus(triangle[1], triangle[0]), minus(triangle[2], triangle[0]));
  const double area2 = dot(normal, normal);
  if (area2 == 0) return;  // a degenerate triangle is its edges, done above
  const auto inside = [&](const Vec3d& x) {
    for (int k = 0; k < 3; ++k) {
      const Vec3d& a = triangle[std::size_t(k)];
      const Vec3d& b = triangle[std::size_t((k + 1) % 3)];
      if (dot(cross(minus(b, a), minus(x, a)), normal) < 0) return false;
    }
    return true;
  };
  const double height = dot(normal, minus(triangle[0], p));  // n . (a - p), n not unit
  const Vec3d foot = plus(p, scaled(height / area2, normal));
  if (inside(foot) && cone.contains(foot)) best.offer(norm(minus(foot, p)), foot);
  const double stationary = std::atan2(dot(normal, cone.v()), dot(normal, cone.u()));
  constexpr double kPi = std::numbers::pi;
  // Fixed samples: a plane square to the axis makes n . d constant, every theta stationary.
  for (const double theta : {stationary, stationary + kPi, 0.0, 0.5 * kPi, kPi, 1.5 * kPi}) {
    Vec3d d;
    for (std::size_t i = 0; i < 3; ++i)
      d[i] = cone.cosHalf() * w[i] + cone.sinHalf() * (std::cos(theta) * cone.u()[i] + std::sin(theta) * cone.v()[i]);
    const double along = dot(normal, d);
    if (along == 0) continue;
    const double s = height / along;
    if (!(s >= 0)) continue;
    const Vec3d x = plus(p, scaled(s, d));
    if (inside(x)) best.offer(s, x);
  }
}

}  // namespace revolve::app
