#include "smooth_spline.h"

#include <cmath>

namespace revolve::bench {

double cubicArcError(double radius, double theta) {
  const double s = std::sin(std::abs(theta) / 4.0), c = std::cos(std::abs(theta) / 4.0);
  return radius * 2.0 * std::pow(s, 6) / (27.0 * c * c);
}

SmoothSpline bezierOf(const SmoothProfile& profile, double maxError) {
  SmoothSpline spline;
  spline.bezier.push_back(profile.pieces().front().start);
  for (const ProfilePiece& piece : profile.pieces()) {
    if (piece.radius == 0.0) {
      const Point2 a = piece.start, b = piece.end;
      spline.bezier.push_back({a.r + (b.r - a.r) / 3.0, a.z + (b.z - a.z) / 3.0});
      spline.bezier.push_back({b.r + (a.r - b.r) / 3.0, b.z + (a.z - b.z) / 3.0});
      spline.bezier.push_back(b);
      continue;
    }
    int count = 1;
    while (cubicArcError(piece.radius, piece.turn / count) > maxError) ++count;
    spline.error = std::max(spline.error, cubicArcError(piece.radius, piece.turn / count));
    const double theta = piece.turn / count;
    // Tangent length 4/3 tan(theta / 4) R along the travel direction at each end.
    const double k = 4.0 / 3.0 * std::tan(theta / 4.0) * piece.radius;
    const double side =
        piece.turn > 0.0 ? 1.0 : -1.0;  // travel is counter-clockwise about the centre when turning left
    for (int i = 0; i < count; ++i) {
      const double a0 = piece.angle0 + i * theta, a1 = a0 + theta;
      const Point2 p0 = piece.at(double(i) / count), p1 = i + 1 == count ? piece.end : piece.at(double(i + 1) / count);
      // The unit tangent of travel at polar angle a: side * (-sin a, cos a); |k| along it.
      const double kk = std::abs(k);
      spline.bezier.push_back({p0.r - side * kk * std::sin(a0), p0.z + side * kk * std::cos(a0)});
      spline.bezier.push_back({p1.r + side * kk * std::sin(a1), p1.z - side * kk * std::cos(a1)});
      spline.bezier.push_back(p1);
    }
  }
  // Exactly on the axis and exactly closed, as SmoothProfile::sample makes them.
  if (profile.pieces().front().start.r == 0.0) spline.bezier.front().r = 0.0;
  if (profile.pieces().back().end.r == 0.0) spline.bezier.back().r = 0.0;
  if (profile.closed() && profile.pieces().front().start.r != 0.0) spline.bezier.back() = spline.bezier.front();
  return spline;
}

}  // namespace revolve::bench
