// Independent curve oracle: see curve_reference.h. Long double throughout; no library code.
#include "support/curve_reference.h"

#include <algorithm>
#include <cmath>

namespace revolve::reference {
namespace {

using Real = long double;

struct Cubic {
  Real r[4], z[4];
};

Real bezier3(const Real c[4], Real u) {
  const Real v = 1 - u;
  return v * v * v * c[0] + 3 * v * v * u * c[1] + 3 * v * u * u * c[2] + u * u * u * c[3];
}

Real bezier3Derivative(const Real c[4], Real u) {
  const Real v = 1 - u;
  return 3 * (v * v * (c[1] - c[0]) + 2 * v * u * (c[2] - c[1]) + u * u * (c[3] - c[2]));
}

std::vector<Cubic> piecesOf(std::span<const Point2> bezier) {
  std::vector<Cubic> pieces;
  for (std::size_t i = 0; i + 3 < bezier.size(); i += 3) {
    Cubic c;
    for (int k = 0; k < 4; ++k) c.r[k] = bezier[i + k].r, c.z[k] = bezier[i + k].z;
    pieces.push_back(c);
  }
  return pieces;
}

// Parameters in [0, 1] cutting the piece into ranges where z is monotone: the ends and the real
// roots of z'(u), a quadratic solved by the textbook formula.
std::vector<Real> zBreaks(const Cubic& c) {
  std::vector<Real> breaks{0};
  const Real d0 = c.z[1] - c.z[0], d1 = c.z[2] - c.z[1], d2 = c.z[3] - c.z[2];
  const Real a = d0 - 2 * d1 + d2, b = 2 * (d1 - d0), k = d0;
  if (a != 0) {
    const Real disc = b * b - 4 * a * k;
    if (disc >= 0) {
      for (const Real sign : {-1.0L, 1.0L}) {
        const Real u = (-b + sign * std::sqrt(disc)) / (2 * a);
        if (u > 0 && u < 1) breaks.push_back(u);
      }
    }
  } else if (b != 0) {
    const Real u = -k / b;
    if (u > 0 && u < 1) breaks.push_back(u);
  }
  breaks.push_back(1);
  std::sort(breaks.begin(), breaks.end());
  return breaks;
}

Real pointAtT(const RefRay& ray, Real t, int axis) {
  return axis == 0 ? ray.ox + t * ray.dx : axis == 1 ? ray.oy + t * ray.dy : ray.oz + t * ray.dz;
}

RefHit hitAt(const Cubic& c, Real u, Real t, const RefRay& ray, std::size_t piece) {
  Real tr = bezier3Derivative(c.r, u), tz = bezier3Derivative(c.z, u);
  if (tr == 0 && tz == 0) {  // a repeated control point at an end: the next one's direction
    tr = u < 0.5L ? c.r[2] - c.r[0] : c.r[3] - c.r[1];
    tz = u < 0.5L ? c.z[2] - c.z[0] : c.z[3] - c.z[1];
  }
  const Real length = std::hypot(tr, tz);
  const Real nr = tz / length, nz = -tr / length;
  const Real x = pointAtT(ray, t, 0), y = pointAtT(ray, t, 1), rho = std::hypot(x, y);
  const Real nx = rho > 0 ? nr * x / rho : nr, ny = rho > 0 ? nr * y / rho : 0;
  return {t, nx, ny, nz, piece};
}

// The u in [u0, u1] (z monotone there) where z(u) = target, by bisection (an end if beyond).
Real parameterAtHeight(const Cubic& c, Real u0, Real u1, Real target) {
  const Real za = bezier3(c.z, u0), zb = bezier3(c.z, u1);
  const bool up = zb > za;
  if (up ? target <= za : target >= za) return u0;
  if (up ? target >= zb : target <= zb) return u1;
  Real lo = u0, hi = u1;
  for (int i = 0; i < 70 && lo < hi; ++i) {  // long double's 64 bits, and room
    const Real m = (lo + hi) / 2;
    ((bezier3(c.z, m) < target) == up ? lo : hi) = m;
  }
  return (lo + hi) / 2;
}

// The ray's heights [zLow, zHigh] where it is within `radius` of the axis and tnear <= t <= tfar;
// false when it never is (a ray with dz != 0).
bool heightsNearTheAxis(const RefRay& ray, Real radius, Real& zLow, Real& zHigh) {
  const Real a = ray.dx * ray.dx + ray.dy * ray.dy, b = ray.ox * ray.dx + ray.oy * ray.dy;
  const Real c = ray.ox * ray.ox + ray.oy * ray.oy - radius * radius;
  Real t0 = ray.tnear, t1 = ray.tfar;
  if (a == 0) {
    if (c > 0) return false;
  } else {
    const Real disc = b * b - a * c;
    if (disc < 0) return false;
    t0 = std::max(t0, (-b - std::sqrt(disc)) / a);
    t1 = std::min(t1, (-b + std::sqrt(disc)) / a);
    if (!(t0 <= t1)) return false;
  }
  const Real z0 = ray.oz + t0 * ray.dz, z1 = ray.oz + t1 * ray.dz;
  zLow = std::min(z0, z1), zHigh = std::max(z0, z1);
  return true;
}

// The roots of f on [a, b] (f evaluated in long double): sign changes between `samples` equal
// steps, bisected; and root pairs hidden between samples, found by a golden-section search for the
// minimum of f about every sample that is a local minimum of f > 0 (a dip that may cross zero), or
// of -f about every local maximum of f < 0.
template <class F>
std::vector<Real> rootsOf(F&& f, Real a, Real b, int samples) {
  std::vector<Real> roots;
  std::vector<Real> x(samples + 1), y(samples + 1);
  for (int i = 0; i <= samples; ++i) {
    x[i] = i == samples ? b : a + (b - a) * i / samples;
    y[i] = f(x[i]);
  }
  const auto bisect = [&](Real lo, Real hi) {
    const bool negativeLo = f(lo) < 0;
    for (int k = 0; k < 70 && lo < hi; ++k) {
      const Real m = (lo + hi) / 2;
      if (m == lo || m == hi) break;
      ((f(m) < 0) == negativeLo ? lo : hi) = m;
    }
    return (lo + hi) / 2;
  };
  for (int i = 0; i <= samples; ++i) {
    if (y[i] == 0) {
      roots.push_back(x[i]);
      continue;
    }
    if (i > 0 && y[i - 1] != 0 && (y[i] < 0) != (y[i - 1] < 0)) roots.push_back(bisect(x[i - 1], x[i]));
    // A dip towards zero at sample i (or at an end): search the neighbourhood for a crossing.
    const Real sign = y[i] > 0 ? 1 : -1;
    const bool dip = (i == 0 || sign * y[i] <= sign * y[i - 1]) && (i == samples || sign * y[i] <= sign * y[i + 1]);
    if (!dip) continue;
    Real lo = x[std::max(0, i - 1)], hi = x[std::min(samples, i + 1)];
    const Real golden = (std::sqrt(5.0L) - 1) / 2;
    for (int k = 0; k < 90; ++k) {  // 0.618^90: below long double's resolution of the interval
      const Real c1 = hi - golden * (hi - lo), c2 = lo + golden * (hi - lo);
      if (sign * f(c1) < sign * f(c2)) {
        hi = c2;
      } else {
        lo = c1;
      }
    }
    const Real m = (lo + hi) / 2;
    if (sign * f(m) < 0) {
      const Real left = x[std::max(0, i - 1)], right = x[std::min(samples, i + 1)];
      if ((f(left) < 0) != (f(m) < 0)) roots.push_back(bisect(left, m));
      if ((f(right) < 0) != (f(m) < 0)) roots.push_back(bisect(m, right));
    }
  }
  std::sort(roots.begin(), roots.end());
  roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
  return roots;
}

void appendHits(const Cubic& c, std::size_t piece, const RefRay& ray, Real reach, std::vector<RefHit>& hits) {
  constexpr int kSamples = 512;
  const std::vector<Real> breaks = zBreaks(c);
  for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
    Real u0 = breaks[b], u1 = breaks[b + 1];
    const Real za = bezier3(c.z, u0), zb = bezier3(c.z, u1);
    if (ray.dz == 0) {
      // In a horizontal plane: where z(u) = oz (half-open at the range's upper end), the circle.
      const Real zLow = std::min(za, zb), zHigh = std::max(za, zb);
      if (!(zLow <= ray.oz && ray.oz < zHigh)) continue;
      const Real u = parameterAtHeight(c, u0, u1, ray.oz), radius = bezier3(c.r, u);
      const Real a = ray.dx * ray.dx + ray.dy * ray.dy, bb = ray.ox * ray.dx + ray.oy * ray.dy;
      const Real cc = ray.ox * ray.ox + ray.oy * ray.oy - radius * radius, disc = bb * bb - a * cc;
      if (a == 0 || disc < 0) continue;
      for (const Real sign : {-1.0L, 1.0L}) {
        const Real t = (-bb + sign * std::sqrt(disc)) / a;
        if (t >= ray.tnear && t <= ray.tfar) hits.push_back(hitAt(c, u, t, ray, piece));
      }
      continue;
    }
    if (za == zb) {
      // Horizontal range: the plane, between the range's radii.
      const Real t = (za - ray.oz) / ray.dz;
      if (!(t >= ray.tnear && t <= ray.tfar)) continue;
      const Real rho = std::hypot(pointAtT(ray, t, 0), pointAtT(ray, t, 1));
      const Real ra = bezier3(c.r, u0), rb = bezier3(c.r, u1);
      if (rho >= std::min(ra, rb) && rho <= std::max(ra, rb)) hits.push_back(hitAt(c, (u0 + u1) / 2, t, ray, piece));
      continue;
    }
    // Only where the ray is near the axis (within every control point's radius).
    Real zLow, zHigh;
    if (!heightsNearTheAxis(ray, reach, zLow, zHigh)) continue;
    zLow = std::max(zLow, std::min(za, zb)), zHigh = std::min(zHigh, std::max(za, zb));
    if (!(zLow <= zHigh)) continue;
    const Real ua = parameterAtHeight(c, u0, u1, zLow), ub = parameterAtHeight(c, u0, u1, zHigh);
    u0 = std::min(ua, ub), u1 = std::max(ua, ub);
    // Which parameter to solve in: u when the ray climbs steeply enough that t(u) = (z(u) - oz) / dz
    // keeps its digits (z's rounding divided by dz); t when the ray is nearly horizontal (then u(t),
    // the height's parameter on the curve, is found by bisection instead).
    const Real tA = (zLow - ray.oz) / ray.dz, tB = (zHigh - ray.oz) / ray.dz;
    if (std::abs(ray.dz) >= 1e-3L * std::sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz)) {
      const auto F = [&](Real u) {
        const Real t = (bezier3(c.z, u) - ray.oz) / ray.dz;
        const Real x = pointAtT(ray, t, 0), y = pointAtT(ray, t, 1), r = bezier3(c.r, u);
        return x * x + y * y - r * r;
      };
      for (const Real u : rootsOf(F, u0, u1, kSamples)) {
        const Real t = (bezier3(c.z, u) - ray.oz) / ray.dz;
        if (t >= ray.tnear && t <= ray.tfar) hits.push_back(hitAt(c, u, t, ray, piece));
      }
    } else {
      const auto G = [&](Real t) {
        const Real u = parameterAtHeight(c, u0, u1, ray.oz + t * ray.dz);
        const Real x = pointAtT(ray, t, 0), y = pointAtT(ray, t, 1), r = bezier3(c.r, u);
        return x * x + y * y - r * r;
      };
      for (const Real t : rootsOf(G, std::min(tA, tB), std::max(tA, tB), kSamples)) {
        if (t >= ray.tnear && t <= ray.tfar)
          hits.push_back(hitAt(c, parameterAtHeight(c, u0, u1, ray.oz + t * ray.dz), t, ray, piece));
      }
    }
  }
}

}  // namespace

std::vector<RefHit> allCurveHits(std::span<const Point2> bezier, const RefRay& ray) {
  std::vector<RefHit> hits;
  const bool valid = std::isfinite(ray.ox) && std::isfinite(ray.oy) && std::isfinite(ray.oz) && std::isfinite(ray.dx) &&
                     std::isfinite(ray.dy) && std::isfinite(ray.dz) && (ray.dx != 0 || ray.dy != 0 || ray.dz != 0) &&
                     ray.tnear <= ray.tfar;
  if (!valid) return hits;
  const std::vector<Cubic> pieces = piecesOf(bezier);
  Real reach = 0;
  for (const Point2& p : bezier) reach = std::max(reach, std::abs(Real(p.r)) * 1.01L);
  for (std::size_t i = 0; i < pieces.size(); ++i) appendHits(pieces[i], i, ray, reach, hits);
  std::sort(hits.begin(), hits.end(), [](const RefHit& a, const RefHit& b) { return a.t < b.t; });
  return hits;
}

std::optional<RefHit> intersectCurve(std::span<const Point2> bezier, const RefRay& ray) {
  const std::vector<RefHit> hits = allCurveHits(bezier, ray);
  if (hits.empty()) return std::nullopt;
  return hits.front();
}

long double curveMeridianDistance(std::span<const Point2> bezier, long double x, long double y, long double z) {
  const Real rho = std::hypot(x, y);
  Real best = INFINITY;
  for (const Cubic& c : piecesOf(bezier)) {
    // The control points' box holds the piece: a piece whose box lies farther than the best so far
    // cannot hold a nearer point.
    const Real rLow = std::min({c.r[0], c.r[1], c.r[2], c.r[3]}), rHigh = std::max({c.r[0], c.r[1], c.r[2], c.r[3]});
    const Real zLow = std::min({c.z[0], c.z[1], c.z[2], c.z[3]}), zHigh = std::max({c.z[0], c.z[1], c.z[2], c.z[3]});
    const Real gapR = std::max({rLow - rho, Real(0), rho - rHigh}), gapZ = std::max({zLow - z, Real(0), z - zHigh});
    if (std::hypot(gapR, gapZ) > best) continue;
    const auto distance = [&](Real u) { return std::hypot(bezier3(c.r, u) - rho, bezier3(c.z, u) - z); };
    constexpr int kSamples = 256;
    for (int i = 0; i <= kSamples; ++i) {
      // Golden-section search about each sample that beats its neighbours.
      const Real u = Real(i) / kSamples;
      const Real here = distance(u);
      best = std::min(best, here);
      if ((i > 0 && distance(Real(i - 1) / kSamples) < here) ||
          (i < kSamples && distance(Real(i + 1) / kSamples) < here))
        continue;
      Real a = std::max<Real>(0, Real(i - 1) / kSamples), b = std::min<Real>(1, Real(i + 1) / kSamples);
      const Real golden = (std::sqrt(5.0L) - 1) / 2;
      for (int k = 0; k < 90; ++k) {
        const Real c1 = b - golden * (b - a), c2 = a + golden * (b - a);
        if (distance(c1) < distance(c2)) {
          b = c2;
        } else {
          a = c1;
        }
      }
      best = std::min(best, distance((a + b) / 2));
    }
  }
  return best;
}

bool curveVerdictIsFragile(std::span<const Point2> bezier, const RefRay& ray, long double nudge, long double size) {
  if (ray.dz == 0) {
    for (const Cubic& c : piecesOf(bezier)) {
      for (const Real u : zBreaks(c)) {
        if (std::abs(bezier3(c.z, u) - ray.oz) <= nudge) return true;
      }
    }
  }
  const std::optional<RefHit> base = intersectCurve(bezier, ray);
  for (int axis = 0; axis < 3; ++axis) {
    for (const Real sign : {-1.0L, 1.0L}) {
      RefRay moved = ray;
      (axis == 0 ? moved.ox : axis == 1 ? moved.oy : moved.oz) += sign * nudge;
      const std::optional<RefHit> other = intersectCurve(bezier, moved);
      if (other.has_value() != base.has_value()) return true;
      if (other && std::abs(other->t - base->t) * std::sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz) >
                       1e-6L * size) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace revolve::reference
