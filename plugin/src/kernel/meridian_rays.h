// The meridian set-up of several rays at once, for packets (rtcIntersect4/8/16): the same
// operations as setUpMeridianRay in the same order, lane by lane, so that each lane's MeridianRay
// equals the single-ray set-up's bit for bit (KernelPacketTest checks it). The set-up is a chain
// of two square roots and two divisions that a single ray waits for; a packet waits once.
#pragma once

#include "kernel/meridian_ray.h"
#include "util/isa.h"
#include "util/simd.h"

#include <cmath>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

// The rays' fields as Embree lays out a packet: kLanes consecutive floats each.
struct RayLanes {
  const float *ox, *oy, *oz, *dx, *dy, *dz, *tnear, *tfar;
};

// Sets up out[0 .. kLanes) from the packet's lanes; returns a bit per lane whose set-up succeeded
// (the lanes setUpMeridianRay would accept). Rejected lanes' entries are left unspecified.
inline unsigned setUpMeridianRays(const ShapeFrame& frame, const RayLanes& in, MeridianRay* out) noexcept {
  const Lanes huge = splat(HUGE_VAL), zero = splat(0.0);
  const Lanes ox = loadFloats(in.ox), oy = loadFloats(in.oy), originZ = loadFloats(in.oz);
  const Lanes oz = originZ - splat(frame.zCentre);
  const Lanes Dx = loadFloats(in.dx), Dy = loadFloats(in.dy), Dz = loadFloats(in.dz);
  const Lanes tnear = loadFloats(in.tnear), tfar = loadFloats(in.tfar);
  const Lanes length2 = Dx * Dx + Dy * Dy + Dz * Dz;
  unsigned ok = bits((zero < length2) & (length2 < huge) & (abs(ox) < huge) & (abs(oy) < huge) & (abs(oz) < huge) &
                     (abs(tnear) < huge) & (tnear <= tfar));

  const Lanes tCentre = -(ox * Dx + oy * Dy + oz * Dz) / length2;
  const Lanes qx = ox + tCentre * Dx, qy = oy + tCentre * Dy, qz = oz + tCentre * Dz;
  const Lanes R = splat(frame.sphereRadius);
  const Lanes halfChord2 = R * R - (qx * qx + qy * qy + qz * qz);
  ok &= bits(zero <= halfChord2);
  const Lanes w = sqrt(maxOf(halfChord2, zero));  // the max only keeps rejected lanes quiet

  const Lanes length = sqrt(length2);
  const Lanes invLength = splat(1.0) / length;
  const Lanes dx = Dx * invLength, dy = Dy * invLength, dz = Dz * invLength;
  const Lanes lo = maxOf((tnear - tCentre) * length, -w);
  const Lanes hi = minOf((minOf(tfar, splat(kLargestFloat)) - tCentre) * length, w);  // as setUpMeridianRay
  ok &= bits(lo <= hi);

  const Lanes a = dx * dx + dy * dy;
  const Lanes cross = qx * dy - qy * dx;
  const Lanes invA = select(zero < a, splat(1.0) / a, zero);
  const Lanes beta = cross * cross * invA;
  const Lanes sAxis = -(qx * dx + qy * dy) * invA;
  const LaneMask inPlane = Dz == zero;
  const Lanes invDz = select(inPlane, zero, length / Dz);
  const unsigned inPlaneBits = bits(inPlane);
  const Lanes lineSlack = splat(2.0 * kUnitRoundoff) *
                          (abs(ox) + abs(oy) + abs(originZ) + splat(std::abs(frame.zCentre)) + abs(tCentre) * length);

  alignas(32) double fields[17][kLanes];
  store(fields[0], qx), store(fields[1], qy), store(fields[2], qz), store(fields[3], dx), store(fields[4], dy);
  store(fields[5], dz), store(fields[6], tCentre), store(fields[7], length), store(fields[8], lo), store(fields[9], hi);
  store(fields[10], a), store(fields[11], cross), store(fields[12], sAxis), store(fields[13], invDz);
  store(fields[14], invA), store(fields[15], beta), store(fields[16], lineSlack);
  // Read back lane by lane through memory: left to itself, GCC's x86-64-v4 code took each lane out
  // of its register with a shuffle (68 of them), which made the AVX-512 copy's set-up 2.4x as costly
  // as the AVX2 copy's (perf, camera packets of the 64-point vase); a store and loads cost less.
  asm("" : : "m"(fields) : "memory");
  for (int lane = 0; lane < kLanes; ++lane) {
    MeridianRay& ray = out[lane];
    ray.ox = fields[0][lane];
    ray.oy = fields[1][lane];
    ray.oz = fields[2][lane];
    ray.dx = fields[3][lane];
    ray.dy = fields[4][lane];
    ray.dz = fields[5][lane];
    ray.t0 = fields[6][lane];
    ray.tScale = fields[7][lane];
    ray.lo = fields[8][lane];
    ray.hi = fields[9][lane];
    ray.a = fields[10][lane];
    ray.cross = fields[11][lane];
    ray.sAxis = fields[12][lane];
    ray.invDz = fields[13][lane];
    ray.inPlane = (inPlaneBits >> lane) & 1;
    ray.invA = fields[14][lane];
    ray.beta = fields[15][lane];
    ray.rho2Slack = frame.rho2Slack;
    ray.rho2Margin = frame.rho2Margin;
    ray.bandMargin = frame.bandMargin;
    ray.lineSlack = fields[16][lane];
  }
  return ok;
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
