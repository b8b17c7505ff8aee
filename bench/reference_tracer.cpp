#include "reference_tracer.h"

#include <algorithm>
#include <cmath>

namespace revolve::bench {

ReferenceTracer::ReferenceTracer(const SmoothProfile& profile) : profile_(profile) {
  double zLow = INFINITY, zHigh = -INFINITY;
  for (const Point2& p : profile.sample(4096)) zLow = std::min(zLow, p.z), zHigh = std::max(zHigh, p.z);
  zCentre_ = 0.5 * (zLow + zHigh);
  // Every point of the solid lies within this sphere: the curve's farthest point from the centre is
  // at most the sampled one's distance plus the sampling's sagitta; 1% more leaves room.
  double radius = 0.0;
  for (const Point2& p : profile.sample(4096)) radius = std::max(radius, std::hypot(p.r, p.z - zCentre_));
  radius_ = 1.01 * (radius + profile.sampleError(4096));
  // Roots to 2^-44 of the size (far below the float resolution of any method's t), and grazing
  // undecided below 1e-10 of the size: the smallest error the benchmark reports is ~1e-8.
  rootTolerance_ = 0x1p-44 * profile.size();
  grazeTolerance_ = 1e-10 * profile.size();
}

ClosestPoint ReferenceTracer::closestTo(const double p[3]) const {
  return profile_.closest({std::hypot(p[0], p[1]), p[2]});
}

ReferenceHit ReferenceTracer::trace(const Ray& ray) const {
  ReferenceHit result;
  const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (double& c : d) c /= length;
  // Clip the unit-speed ray to the bounding sphere and to [tnear, tfar].
  const double oc[3] = {o[0], o[1], o[2] - zCentre_};
  const double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
  const double c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - radius_ * radius_;
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return result;
  const double root = std::sqrt(discriminant);
  double lo = std::max(-b - root, double(ray.tnear) * length);
  double hi = std::min(-b + root, double(ray.tfar) * length);
  if (!(lo <= hi)) return result;

  const auto signedDistance = [&](double s) {
    const double p[3] = {o[0] + s * d[0], o[1] + s * d[1], o[2] + s * d[2]};
    return closestTo(p).signedDistance;
  };
  const auto sameSign = [](double x, double y) { return (x > 0.0 && y > 0.0) || (x < 0.0 && y < 0.0); };

  // Depth-first, earlier half first: the first interval proven to hold a sign change is the hit.
  struct Interval {
    double a, fa, b, fb;
  };
  Interval stack[256];
  int top = 0;
  // An interval the bound cannot clear down to grazeTolerance: the ray comes that close to the
  // surface. It leaves the verdict open only if no crossing is found: a hit is a hit whatever
  // touch might precede it (the error measures compare hit/miss, never the reference's t).
  bool undecided = false;
  stack[top++] = {lo, signedDistance(lo), hi, signedDistance(hi)};
  while (top > 0) {
    const Interval interval = stack[--top];
    const double width = interval.b - interval.a;
    if (sameSign(interval.fa, interval.fb)) {
      if (std::abs(interval.fa) + std::abs(interval.fb) > width) continue;  // no root: |SD| stays > 0
      if (width < grazeTolerance_) {
        undecided = true;  // too close to the surface to rule a touch out
        continue;
      }
    } else if (width <= rootTolerance_ || interval.fa == 0.0) {
      const double s = interval.fa == 0.0 ? interval.a : 0.5 * (interval.a + interval.b);
      result.hit = true;
      result.t = s / length;
      for (int i = 0; i < 3; ++i) result.point[i] = o[i] + s * d[i];
      const ClosestPoint closest = closestTo(result.point);
      const double rho = std::hypot(result.point[0], result.point[1]);
      const double cosPhi = rho > 0.0 ? result.point[0] / rho : 1.0, sinPhi = rho > 0.0 ? result.point[1] / rho : 0.0;
      result.normal[0] = closest.normal.r * cosPhi;
      result.normal[1] = closest.normal.r * sinPhi;
      result.normal[2] = closest.normal.z;
      return result;
    }
    if (top + 2 > 256) {  // cannot happen above the tolerances (depth <= log2(size / tolerance) ~ 60)
      undecided = true;
      continue;
    }
    const double m = 0.5 * (interval.a + interval.b), fm = signedDistance(m);
    stack[top++] = {m, fm, interval.b, interval.fb};  // later half below: searched second
    stack[top++] = {interval.a, interval.fa, m, fm};
  }
  result.grazing = undecided;
  return result;
}

}  // namespace revolve::bench
