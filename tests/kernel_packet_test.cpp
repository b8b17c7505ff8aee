// The packet set-up (src/kernel/meridian_rays.h) must give each lane the very MeridianRay the
// single-ray set-up gives, bit for bit: rtcIntersect4/8/16 then find the hits rtcIntersect1 finds.
#include "kernel/meridian_rays.h"
#include "shape/shape_impl.h"
#include "shape/shape_search.h"
#include "shape/surface_hit.h"
#include "support/test_profiles.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

namespace revolve {
namespace {

template <class T>
bool sameBits(T a, T b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(KernelPacketTest, PacketSetUpEqualsTheSingleRaySetUpBitForBit) {
  std::mt19937_64 random(0x9ac4);
  const Shape shape{Profile(testing::hollowVase())};
  std::vector<Ray> rays = testing::incoherentRays(shape, random, 20000);
  const std::vector<Ray> awkward = testing::axisAlignedRays(shape, random, 4000);
  rays.insert(rays.end(), awkward.begin(), awkward.end());
  // And rays the set-up must reject: zero direction, tnear > tfar, missing the bounding sphere.
  rays.push_back({{0, 0, 0}, {0, 0, 0}});
  rays.push_back({{0, 0, 0}, {1, 0, 0}, 2.0f, 1.0f});
  rays.push_back({{100, 100, 100}, {1, 0, 0}});
  while (rays.size() % detail::kLanes != 0) rays.push_back(rays.front());

  std::size_t accepted = 0;
  for (std::size_t first = 0; first < rays.size(); first += detail::kLanes) {
    float fields[8][detail::kLanes];
    for (int lane = 0; lane < detail::kLanes; ++lane) {
      const Ray& r = rays[first + lane];
      const float values[8] = {r.origin.x,    r.origin.y,    r.origin.z, r.direction.x,
                               r.direction.y, r.direction.z, r.tnear,    r.tfar};
      for (int f = 0; f < 8; ++f) fields[f][lane] = values[f];
    }
    detail::MeridianRay packet[detail::kLanes];
    const unsigned ok = detail::setUpMeridianRays(
        detail::implOf(shape).frame,
        {fields[0], fields[1], fields[2], fields[3], fields[4], fields[5], fields[6], fields[7]}, packet);
    for (int lane = 0; lane < detail::kLanes; ++lane) {
      detail::MeridianRay single;
      const bool singleOk = detail::setUpMeridianRay(detail::implOf(shape).frame, rays[first + lane], single);
      ASSERT_EQ(singleOk, bool((ok >> lane) & 1)) << "ray " << first + lane;
      if (!singleOk) continue;
      ++accepted;
      const detail::MeridianRay& p = packet[lane];
      const double a[] = {single.ox,   single.oy,        single.oz,         single.dx,         single.dy,
                          single.dz,   single.t0,        single.tScale,     single.lo,         single.hi,
                          single.a,    single.cross,     single.sAxis,      single.invDz,      single.invA,
                          single.beta, single.rho2Slack, single.rho2Margin, single.bandMargin, single.lineSlack};
      const double b[] = {p.ox,     p.oy,   p.oz,        p.dx,         p.dy,         p.dz,       p.t0,
                          p.tScale, p.lo,   p.hi,        p.a,          p.cross,      p.sAxis,    p.invDz,
                          p.invA,   p.beta, p.rho2Slack, p.rho2Margin, p.bandMargin, p.lineSlack};
      for (std::size_t f = 0; f < std::size(a); ++f)
        ASSERT_TRUE(sameBits(a[f], b[f])) << "ray " << first + lane << " field " << f;
      ASSERT_EQ(single.inPlane, p.inPlane);
    }
  }
  EXPECT_GT(accepted, 15000u);
}

TEST(KernelPacketTest, PacketAttributesEqualTheSingleHitsBitForBit) {
  // Every hit of a few profiles' incoherent and axis rays, kLanes at a time; and a needle 2e-160
  // from the axis, whose hit points need the scaled azimuth (the lanes report them for surfaceHit).
  std::mt19937_64 random(0x9ac5);
  std::size_t compared = 0, scaledSeen = 0;
  std::vector<std::vector<Point2>> profiles{testing::hollowVase(), testing::cup(), testing::spindle(40)};
  profiles.push_back({{0.0, -1.0}, {2e-160, -0.5}, {2e-160, 0.5}, {0.0, 1.0}});
  for (const std::vector<Point2>& points : profiles) {
    const Shape shape{Profile(points)};
    const detail::ShapeImpl& impl = detail::implOf(shape);
    std::vector<Ray> rays = testing::incoherentRays(shape, random, 6000);
    const std::vector<Ray> awkward = testing::axisAlignedRays(shape, random, 2000);
    rays.insert(rays.end(), awkward.begin(), awkward.end());
    struct Found {
      detail::MeridianRay meridian;
      Ray ray;
      double s;
      std::uint32_t segment;
    };
    std::vector<Found> hits;
    for (const Ray& ray : rays) {
      detail::MeridianRay meridian;
      if (!detail::setUpMeridianRay(impl.frame, ray, meridian)) continue;
      double hi = meridian.hi;
      Stats stats;
      detail::NearestHit<false> nearest{impl, meridian, hi, stats};
      detail::searchShape<false>(impl, meridian, hi, nearest, stats);
      if (nearest.found()) hits.push_back({meridian, ray, nearest.s, nearest.segment});
    }
    for (std::size_t first = 0; first + detail::kLanes <= hits.size(); first += detail::kLanes) {
      detail::HitLanes in;
      for (int lane = 0; lane < detail::kLanes; ++lane) {
        const Found& f = hits[first + lane];
        in.ray[lane] = &f.meridian;
        in.s[lane] = f.s;
        in.segment[lane] = f.segment;
        in.tnear[lane] = f.ray.tnear;
        in.tfar[lane] = f.ray.tfar;
      }
      detail::HitAttributes out{};
      const unsigned scaled = detail::surfaceHitLanes(impl, in, out);
      for (int lane = 0; lane < detail::kLanes; ++lane) {
        const Found& f = hits[first + lane];
        if ((scaled >> lane) & 1) {
          ++scaledSeen;
          continue;
        }
        const Hit single = detail::surfaceHit(impl, f.meridian, f.ray, f.s, f.segment);
        ++compared;
        ASSERT_TRUE(sameBits(single.t, out.t[lane]) && sameBits(single.normal.x, out.nx[lane]) &&
                    sameBits(single.normal.y, out.ny[lane]) && sameBits(single.normal.z, out.nz[lane]) &&
                    sameBits(single.u, out.u[lane]) && sameBits(single.v, out.v[lane]))
            << "hit " << first + lane << ": t " << single.t << " vs " << out.t[lane] << ", u " << single.u << " vs "
            << out.u[lane] << ", v " << single.v << " vs " << out.v[lane];
      }
    }
  }
  EXPECT_GT(compared, 10000u);
  EXPECT_GT(scaledSeen, 100u);  // the needle's hits take the scalar path
}

}  // namespace
}  // namespace revolve
