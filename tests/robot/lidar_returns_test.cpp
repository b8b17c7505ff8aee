// A beam's footprint and its returns: a beam of divergence delta sampled by sub-rays on Vogel's
// sunflower (robot/beam_footprint.h), its hits grouped into returns by range
// (robot/beam_returns.h), reported first, last, strongest or all. Checked against closed forms
// written here from those documented rules: a pole of radius a in front of a wall, the beam aimed
// at the pole's edge (two returns: the pole's and the wall's) or wholly on the pole (one); the
// sub-ray pattern recomputed from its formula and each sub-ray intersected with the cylinder and
// the plane in closed form.
#include "robot/beam_footprint.h"
#include "robot/beam_returns.h"
#include "robot/lidar.h"
#include "robot_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

namespace revolve {
namespace {

using testing::Vec3d;

constexpr double kPoleX = 4, kPoleRadius = 0.25, kWallX = 8;
constexpr double kDivergence = 0.02;
constexpr int kSubrays = 16;

// The pole (x - 4)^2 + y^2 = 0.25^2 for z in [-2, 2], and the wall x = 8 behind it.
io::SceneDescription poleBeforeWall() {
  return testing::sceneOf({{testing::cylinderProfile(kPoleRadius, -2, 2), testing::at(kPoleX, 0), "pole"}},
                          {{Vec3d{kWallX, -6, -3}, Vec3d{kWallX, 6, -3}, Vec3d{kWallX, 6, 3}, Vec3d{kWallX, -6, 3}}});
}

// One beam at `azimuth` in the XY plane from the origin.
io::SensorDescription oneBeam(double azimuth, io::ReturnMode mode, int subrays = kSubrays,
                              double divergence = kDivergence) {
  io::SensorDescription s;
  s.horizontal = {1, azimuth, azimuth};
  s.elevations = {0.0};
  s.rangeMin = 0;
  s.rangeMax = 100;
  s.divergence = divergence;
  s.subrays = subrays;
  s.returns = mode;
  return s;
}

// What each sub-ray of the beam at `azimuth` hits, in closed form: the sub-ray directions from the
// documented formula (rho_k = (delta/2) sqrt((k + 1/2) / n), phi_k = k pi (3 - sqrt 5), from the
// direction of increasing azimuth toward increasing elevation), each intersected with the pole's
// side and the wall.
struct ClosedForm {
  double poleRange = INFINITY, wallRange = INFINITY;  // the nearest sub-ray hit on each
  double poleIntensity = 0, wallIntensity = 0;        // summed r |cos| / t^2 over n
  int onPole = 0, onWall = 0;
};

ClosedForm closedForm(double azimuth, int n, double delta) {
  ClosedForm c;
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  const Vec3d axis{std::cos(azimuth), std::sin(azimuth), 0}, across{-std::sin(azimuth), std::cos(azimuth), 0},
      up{0, 0, 1};
  for (int k = 0; k < n; ++k) {
    const double rho = n == 1 ? 0 : delta / 2 * std::sqrt((k + 0.5) / n), phi = k * golden;
    Vec3d d;
    for (int i = 0; i < 3; ++i)
      d[i] = std::cos(rho) * axis[i] + std::sin(rho) * (std::cos(phi) * across[i] + std::sin(phi) * up[i]);
    // |(t d_x - 4, t d_y)| = a: t^2 (dx^2 + dy^2) - 8 t dx + 16 - a^2 = 0, the nearer root.
    const double A = d[0] * d[0] + d[1] * d[1], B = -kPoleX * d[0], C = kPoleX * kPoleX - kPoleRadius * kPoleRadius;
    const double disc = B * B - A * C;
    if (disc >= 0) {
      const double t = (-B - std::sqrt(disc)) / A;
      const Vec3d p{t * d[0], t * d[1], t * d[2]};
      const Vec3d normal{(p[0] - kPoleX) / kPoleRadius, p[1] / kPoleRadius, 0};
      const double cosine = std::abs(normal[0] * d[0] + normal[1] * d[1]);
      c.poleRange = std::min(c.poleRange, t);
      c.poleIntensity += cosine / (t * t) / n;
      ++c.onPole;
    } else {
      const double t = kWallX / d[0];
      c.wallRange = std::min(c.wallRange, t);
      c.wallIntensity += std::abs(d[0]) / (t * t) / n;
      ++c.onWall;
    }
  }
  return c;
}

std::vector<io::BeamReturn> scanOnce(const io::SensorDescription& s, int threads = 0) {
  const scene::EmbreeScene built(poleBeforeWall(), {});
  const robot::Lidar lidar(built, s);
  return lidar.scan(std::vector<io::RobotPose>{io::RobotPose{}}, threads).points;
}

// Origin and directions rounded to float, the hit's distance in float: within 2^-24 of the lengths
// involved each; 2^-20 leaves a margin. Intensities: a few float roundings of each term.
void expectReturn(const io::BeamReturn& got, double range, double intensity, double azimuth) {
  const double tolerance = 0x1p-20 * (range + kPoleX);
  EXPECT_NEAR(got.range, range, tolerance);
  EXPECT_NEAR(got.intensity, intensity, 1e-5 * intensity);
  // The point lies along the beam's axis at the measured range.
  EXPECT_NEAR(got.x, range * std::cos(azimuth), tolerance);
  EXPECT_NEAR(got.y, range * std::sin(azimuth), tolerance);
  EXPECT_NEAR(got.z, 0, tolerance);
}

// The edge of the pole seen from the origin: the tangent's azimuth asin(a / D).
const double kEdge = std::asin(kPoleRadius / kPoleX);

TEST(LidarReturnsTest, ABeamStraddlingThePolesEdgeReturnsFromThePoleAndTheWall) {
  const ClosedForm c = closedForm(kEdge, kSubrays, kDivergence);
  ASSERT_GT(c.onPole, 0);
  ASSERT_GT(c.onWall, 0);  // the footprint straddles the edge
  const std::vector<io::BeamReturn> all = scanOnce(oneBeam(kEdge, io::ReturnMode::all));
  ASSERT_EQ(all.size(), 2u);  // max_returns 2: two layers
  expectReturn(all[0], c.poleRange, c.poleIntensity, kEdge);
  EXPECT_EQ(all[0].object, 0);  // the pole
  expectReturn(all[1], c.wallRange, c.wallIntensity, kEdge);
  EXPECT_EQ(all[1].object, 1);  // the wall: the quad after the one object

  const std::vector<io::BeamReturn> first = scanOnce(oneBeam(kEdge, io::ReturnMode::first));
  ASSERT_EQ(first.size(), 1u);
  expectReturn(first[0], c.poleRange, c.poleIntensity, kEdge);
  const std::vector<io::BeamReturn> last = scanOnce(oneBeam(kEdge, io::ReturnMode::last));
  expectReturn(last[0], c.wallRange, c.wallIntensity, kEdge);
  const std::vector<io::BeamReturn> strongest = scanOnce(oneBeam(kEdge, io::ReturnMode::strongest));
  if (c.poleIntensity > c.wallIntensity)
    expectReturn(strongest[0], c.poleRange, c.poleIntensity, kEdge);
  else
    expectReturn(strongest[0], c.wallRange, c.wallIntensity, kEdge);
  // The pole is nearer and faces the beam more squarely: its share is the stronger here unless
  // nearly all sub-rays miss it.
  EXPECT_EQ(strongest[0].object, c.poleIntensity > c.wallIntensity ? 0 : 1);
}

TEST(LidarReturnsTest, ABeamWhollyOnThePoleHasOneReturn) {
  const ClosedForm c = closedForm(0, kSubrays, kDivergence);
  ASSERT_EQ(c.onWall, 0);
  const std::vector<io::BeamReturn> all = scanOnce(oneBeam(0, io::ReturnMode::all));
  ASSERT_EQ(all.size(), 2u);
  expectReturn(all[0], c.poleRange, c.poleIntensity, 0);
  EXPECT_TRUE(std::isinf(all[1].range));  // the second layer is empty
  EXPECT_EQ(all[1].object, -1);
  // Head-on, the share of every sub-ray's light is nearly the axis's: 1 / (D - a)^2.
  EXPECT_NEAR(all[0].intensity, 1 / ((kPoleX - kPoleRadius) * (kPoleX - kPoleRadius)), 1e-3);
  for (const io::ReturnMode mode : {io::ReturnMode::first, io::ReturnMode::last, io::ReturnMode::strongest}) {
    const std::vector<io::BeamReturn> one = scanOnce(oneBeam(0, mode));
    expectReturn(one[0], c.poleRange, c.poleIntensity, 0);
  }
}

// A beam of no divergence is its axis: "all" reports it in layer 0, nothing in layer 1, exactly
// what "first" reports.
TEST(LidarReturnsTest, ABeamWithoutDivergenceIsItsAxis) {
  const io::BeamReturn axis = scanOnce(oneBeam(kEdge - 0.01, io::ReturnMode::first, 1, 0))[0];
  const std::vector<io::BeamReturn> all = scanOnce(oneBeam(kEdge - 0.01, io::ReturnMode::all, 1, 0));
  EXPECT_EQ(std::memcmp(&all[0], &axis, sizeof axis), 0);
  EXPECT_TRUE(std::isinf(all[1].range));
}

// Noisy returns of a footprint of 64 sub-rays over a 3-D sensor: every thread count gives the same
// scan bit for bit.
TEST(LidarReturnsTest, ThreadCountsGiveTheSameReturns) {
  io::SensorDescription s = oneBeam(0, io::ReturnMode::all, 64, 0.05);
  s.horizontal = {301, -0.6, 0.6};
  s.elevations = {-0.1, 0.0, 0.1};
  s.planar = false;
  s.noiseStddev = 0.01;
  s.noiseSeed = 7;
  s.intensityNoiseStddev = 0.1;
  s.maxReturns = 3;
  const std::vector<io::BeamReturn> one = scanOnce(s, 1), two = scanOnce(s, 2);
  ASSERT_EQ(one.size(), 301u * 3 * 3);
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(io::BeamReturn)), 0);
  std::size_t second = 0;
  for (std::size_t i = 301 * 3; i < 2 * 301 * 3; ++i) second += std::isinf(one[i].range) ? 0 : 1;
  EXPECT_GT(second, 0u);  // beams across the pole's edges have second returns
}

// A scan of several layers crosses blocks at whole poses: 150 poses of 903 beams x 3 layers take
// several blocks (robot/lidar.h), and each pose's points are those of the pose scanned alone (its
// noise drawn as pose i's), bit for bit; the returns come nearest first even where the noise
// (larger than the separation) swaps what was traced.
TEST(LidarReturnsTest, BlocksOfSeveralLayersHoldWholePosesAndReturnsComeNearestFirst) {
  io::SensorDescription s = oneBeam(0, io::ReturnMode::all, 4, 0.04);
  s.horizontal = {301, -0.7, 0.7};
  s.elevations = {-0.05, 0.0, 0.05};
  s.planar = false;
  s.maxReturns = 3;
  s.noiseStddev = 0.3;  // three times the separation
  s.noiseSeed = 11;
  s.returnSeparation = 0.1;
  const scene::EmbreeScene built(poleBeforeWall(), {});
  const robot::Lidar lidar(built, s);
  std::vector<io::RobotPose> poses(150);
  for (std::size_t i = 0; i < poses.size(); ++i) poses[i].y = -0.3 + 0.004 * double(i);
  ASSERT_GT(poses.size() * 903 * 3, 2 * robot::Lidar::kBlockBeams);
  const io::ScanTable whole = lidar.scan(poses, 2);
  const std::size_t perPose = 903 * 3;
  ASSERT_EQ(whole.points.size(), poses.size() * perPose);
  std::size_t second = 0;
  for (std::size_t i = 0; i < poses.size(); i += 7) {
    std::vector<io::BeamReturn> alone(perPose);
    lidar.scan(
        std::span(poses.data() + i, 1),
        [&](std::uint64_t first, std::span<const io::BeamReturn> points) {
          std::copy(points.begin(), points.end(), alone.begin() + std::ptrdiff_t(first));
        },
        1, nullptr, i);
    ASSERT_EQ(std::memcmp(alone.data(), whole.points.data() + i * perPose, perPose * sizeof(io::BeamReturn)), 0)
        << "pose " << i;
  }
  for (std::size_t p = 0; p < poses.size(); ++p) {
    for (std::size_t beam = 0; beam < 903; ++beam) {
      const std::size_t ring = beam / 301, column = beam % 301;
      for (std::size_t layer = 1; layer < 3; ++layer) {
        const io::BeamReturn& nearer = whole.at(p, ring, column, layer - 1);
        const io::BeamReturn& farther = whole.at(p, ring, column, layer);
        if (std::isinf(farther.range)) continue;
        ++second;
        EXPECT_FALSE(std::isinf(nearer.range));
        EXPECT_LE(nearer.range, farther.range);
      }
    }
  }
  EXPECT_GT(second, 100u);
}

// The grouping rule on its own: neighbours in range further apart than the separation start a new
// return; a return has its nearest hit's range and object and its hits' light over the sub-rays.
TEST(LidarReturnsTest, HitsAreGroupedByGapsInRange) {
  using robot::Echo;
  std::vector<Echo> hits{{1.15, 0.4, 3}, {1.00, 0.1, 1}, {1.30, 0.8, 4}, {1.05, 0.2, 2}, {1.10, 0.3, 5}};
  std::vector<Echo> returns(hits.size());
  // Steps of 0.05 chain 1.00 .. 1.15 into one return (single linkage); 1.30 is 0.15 beyond.
  ASSERT_EQ(robot::groupEchoes(hits, 0.1, 8, returns), 2u);
  EXPECT_EQ(returns[0].range, 1.00);
  EXPECT_EQ(returns[0].object, 1);
  EXPECT_DOUBLE_EQ(returns[0].intensity, (0.1 + 0.2 + 0.3 + 0.4) / 8);
  EXPECT_EQ(returns[1].range, 1.30);
  EXPECT_EQ(returns[1].object, 4);
  EXPECT_DOUBLE_EQ(returns[1].intensity, 0.8 / 8);
  // A separation below every gap: each hit its own return.
  EXPECT_EQ(robot::groupEchoes(hits, 0.01, 8, returns), 5u);
  EXPECT_EQ(robot::groupEchoes(std::span<Echo>(), 0.1, 8, returns), 0u);
}

// The sunflower's sub-rays are unit vectors within the cone's half-angle, spread around the axis
// (their mean direction is the axis to within the pattern's residual), none twice.
TEST(LidarReturnsTest, SubraysFillTheConeOfTheDivergence) {
  for (const int n : {1, 4, 16, 256}) {
    SCOPED_TRACE(n);
    const std::vector<robot::SubrayOffset> offsets = robot::footprintOffsets(0.02, n);
    ASSERT_EQ(offsets.size(), std::size_t(n));
    double meanAcross = 0, meanUp = 0, largest = 0;
    for (const robot::SubrayOffset& o : offsets) {
      EXPECT_NEAR(o.along * o.along + o.across * o.across + o.up * o.up, 1, 1e-15);
      const double angle = std::atan2(std::hypot(o.across, o.up), o.along);
      EXPECT_LE(angle, 0.01 * (1 + 1e-12));
      largest = std::max(largest, angle);
      meanAcross += o.across / n;
      meanUp += o.up / n;
    }
    if (n == 1) {
      EXPECT_EQ(largest, 0);  // the axis itself
    } else {
      EXPECT_GT(largest, 0.01 * std::sqrt((n - 0.5) / n) * (1 - 1e-12));  // the outermost reaches the rim
      EXPECT_LT(std::hypot(meanAcross, meanUp), 0.01 / std::sqrt(double(n)));
    }
  }
}

}  // namespace
}  // namespace revolve
