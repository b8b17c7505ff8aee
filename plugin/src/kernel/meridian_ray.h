// A ray as the kernels see it: re-centred on the shape and mapped into the meridian (rho, z) view.
//
// Why re-centre: a ray whose origin is far away (10^4 object sizes, say) would make every quantity
// below the difference of two large numbers. Moving the origin to the ray's point closest to the
// shape's centre, and measuring t in object units (unit direction), keeps every magnitude within
// the shape's bounding sphere, so each rounding error is a small multiple of u * R, whatever the
// caller's frame. All arithmetic is double: the float inputs carry 24 bits, the kernel keeps 53, so
// even ill-conditioned (near-tangent) roots, which lose half the digits, stay within a float ulp.
#pragma once

#include <revolve/core.h>

#include "util/isa.h"
#include "util/rounding.h"

#include <cmath>
#include <limits>

namespace revolve::detail {

// Shape constants the ray set-up needs.
struct ShapeFrame {
  double zCentre;  // kernels work in a local frame with z_local = z - zCentre
  // Radius of a sphere about (0, 0, zCentre) holding the surface, padded by the factor
  // (1 + 2^-20). The padding makes the points where a ray leaves the sphere lie outside the solid
  // by at least 2^-20 R, so inside/outside signs evaluated there are decided with a margin of
  // (2^-20 R)^2 = 2^-40 R^2 in rho^2, 2^8 times the 64 u R^2 rounding bound below.
  double sphereRadius;
  // Per-shape parts of MeridianRay's bounds (see there), computed once.
  double rho2Slack, rho2Margin, bandMargin;
};

inline ShapeFrame makeShapeFrame(double zCentre, double sphereRadius) {
  ShapeFrame frame{zCentre, sphereRadius, 0.0, 0.0, 0.0};
  frame.rho2Slack = 64.0 * kUnitRoundoff * sphereRadius * sphereRadius;
  frame.rho2Margin = 2.0 * frame.rho2Slack;
  frame.bandMargin = 2.0 * std::sqrt(frame.rho2Slack) + 8.0 * kUnitRoundoff * sphereRadius;
  return frame;
}

inline namespace REVOLVE_ISA {

struct MeridianRay {
  // Re-centred ray in the local frame: point(s) = origin + s * dir, |dir| = 1, s in object units.
  double ox, oy, oz;
  double dx, dy, dz;
  double t0;      // caller's parameter of `origin`
  double tScale;  // caller's |direction|: caller t = t0 + s / tScale
  double lo, hi;  // active range of s: [tnear, tfar] clipped to the bounding sphere (finite)
  double a;       // dx^2 + dy^2: rho^2(s) = a s^2 + 2 b s + c
  double cross;   // ox dy - oy dx: a * (distance of the ray's line from the axis)^2 = cross^2
  double sAxis;   // s of the closest approach to the axis (when a > 0)
  double invDz;   // 1 / dz (when dz != 0)
  bool inPlane;   // dz == 0: the ray stays in the plane z = oz
  double invA;    // 1 / a (when a > 0)
  double beta;    // cross^2 / a: rho^2 at the closest approach to the axis (when a > 0)
  // Rounding bounds, from the set-up's magnitudes (|origin| <= R, |s| <= R within [lo, hi]):
  // each of px, py of a point has absolute error <= 3 u R and magnitude <= 2 R, so
  // rho^2 = px^2 + py^2 carries < 40 u R^2; rho2Slack = 64 u R^2 bounds it with room.
  double rho2Slack;
  // Margins of the shell tests, which compare a value computed one way with values the leaves
  // compute another way (two slacks): 2 rho2Slack in rho^2; in nr rho + nz z, twice rho's error
  // (sqrt(rho2Slack), its worst case near the axis) plus 8 u R for z and the band's own rounding.
  double rho2Margin;
  double bandMargin;
  // Bound on the distance between this double-precision line and the caller's float ray: the
  // shift to the local frame and the re-centring round `origin` by at most
  // 2 u (|caller origin| + |zCentre| + |t0 * caller direction|).
  double lineSlack;

  double planeS(double z) const noexcept { return (z - oz) * invDz; }
  // rho^2 at s. Every plane crossing uses exactly this expression (the library is built without
  // floating-point contraction), so neighbouring segments and tree nodes compare bit-identical
  // values at a shared vertex plane: the basis of the watertight seams.
  double rho2At(double s) const noexcept {
    const double px = ox + s * dx;
    const double py = oy + s * dy;
    return px * px + py * py;
  }
  double zAt(double s) const noexcept { return oz + s * dz; }
};

// Builds the meridian view of `ray` for a shape. Returns false when the ray cannot hit: a
// non-finite or zero direction, a non-finite origin or range, tnear > tfar, or a line that misses
// the bounding sphere within [tnear, tfar].
// The largest finite float: where a hit's t ends (see setUpMeridianRay).
inline constexpr double kLargestFloat = std::numeric_limits<float>::max();

inline bool setUpMeridianRay(const ShapeFrame& frame, const Ray& ray, MeridianRay& out) noexcept {
  const double ox = ray.origin.x, oy = ray.origin.y, oz = double(ray.origin.z) - frame.zCentre;
  const double Dx = ray.direction.x, Dy = ray.direction.y, Dz = ray.direction.z;
  const double length2 = Dx * Dx + Dy * Dy + Dz * Dz;  // float inputs: finite, no overflow
  // Written so that NaN fails every test.
  if (!(length2 > 0.0 && length2 < HUGE_VAL) || !(std::abs(ox) < HUGE_VAL && std::abs(oy) < HUGE_VAL &&
                                                  std::abs(oz) < HUGE_VAL && std::abs(double(ray.tnear)) < HUGE_VAL)) {
    return false;
  }
  if (!(ray.tnear <= ray.tfar)) return false;

  // The closest point to the centre, in the caller's t, from the raw direction: this chain (the
  // set-up's longest, up to the sphere's half chord) then waits for one division, not for a
  // square root and a division before the direction is unit. Its t is t0 exactly, so the re-centred
  // origin and t0 agree to the rounding of q alone.
  const double tCentre = -(ox * Dx + oy * Dy + oz * Dz) / length2;
  const double qx = ox + tCentre * Dx, qy = oy + tCentre * Dy, qz = oz + tCentre * Dz;
  const double R = frame.sphereRadius;
  const double halfChord2 = R * R - (qx * qx + qy * qy + qz * qz);
  if (!(halfChord2 >= 0.0)) return false;
  const double w = std::sqrt(halfChord2);

  // Meanwhile the unit direction.
  const double length = std::sqrt(length2);
  const double invLength = 1.0 / length;
  const double dx = Dx * invLength, dy = Dy * invLength, dz = Dz * invLength;

  out.ox = qx;
  out.oy = qy;
  out.oz = qz;
  out.dx = dx;
  out.dy = dy;
  out.dz = dz;
  out.tScale = length;
  out.t0 = tCentre;
  out.lo = std::max((double(ray.tnear) - tCentre) * length, -w);
  // A hit's t is a float: beyond the largest finite one it would round to inf, a hit nowhere (a
  // direction of subnormal length puts the surface there), so the range ends at it. Any tfar
  // reaching it (inf) then gives w, as every ray of ordinary length does.
  out.hi = std::min((std::min(double(ray.tfar), kLargestFloat) - tCentre) * length, w);
  if (!(out.lo <= out.hi)) return false;

  out.a = dx * dx + dy * dy;
  out.cross = qx * dy - qy * dx;
  out.invA = out.a > 0.0 ? 1.0 / out.a : 0.0;
  out.beta = out.cross * out.cross * out.invA;
  out.sAxis = -(qx * dx + qy * dy) * out.invA;
  out.inPlane = Dz == 0.0;
  out.invDz = out.inPlane ? 0.0 : length / Dz;  // 1 / dz
  out.rho2Slack = frame.rho2Slack;
  out.rho2Margin = frame.rho2Margin;
  out.bandMargin = frame.bandMargin;
  out.lineSlack = 2.0 * kUnitRoundoff *
                  (std::abs(ox) + std::abs(oy) + std::abs(double(ray.origin.z)) + std::abs(frame.zCentre) +
                   std::abs(tCentre) * length);
  return true;
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
