// Profile validation: every rule has a test, and every message names the point, value and rule.
#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <sys/mman.h>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace revolve {
namespace {

using Rule = ProfileError::Rule;

// Constructs a profile expecting ProfileError; returns it for inspection.
ProfileError rejected(const std::vector<Point2>& points) {
  try {
    Profile profile(points);
  } catch (const ProfileError& error) {
    return error;
  }
  ADD_FAILURE() << "profile was accepted";
  return ProfileError(Rule::tooFewPoints, 0, "");
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ProfileTest, FewerThanTwoPointsIsRejected) {
  EXPECT_EQ(rejected({}).rule(), Rule::tooFewPoints);
  const ProfileError one = rejected({{1.0, 2.0}});
  EXPECT_EQ(one.rule(), Rule::tooFewPoints);
  EXPECT_TRUE(contains(one.what(), "1 distinct point")) << one.what();
  EXPECT_TRUE(contains(one.what(), "at least 2")) << one.what();
}

TEST(ProfileTest, TwoEqualPointsAreOneDistinctPoint) {
  const ProfileError error = rejected({{1.0, 2.0}, {1.0, 2.0}});
  EXPECT_EQ(error.rule(), Rule::tooFewPoints);
}

TEST(ProfileTest, NonFiniteCoordinateIsRejectedWithItsIndexAndValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const ProfileError error = rejected({{0, 0}, {1, 0}, {nan, 1}});
  EXPECT_EQ(error.rule(), Rule::nonFinite);
  EXPECT_EQ(error.index(), 2u);
  EXPECT_TRUE(contains(error.what(), "profile point 2")) << error.what();
  EXPECT_TRUE(contains(error.what(), "nan")) << error.what();
  EXPECT_TRUE(contains(error.what(), "finite")) << error.what();
  EXPECT_EQ(rejected({{0, 0}, {1, inf}}).rule(), Rule::nonFinite);
  EXPECT_EQ(rejected({{0, -inf}, {1, 0}}).index(), 0u);
}

TEST(ProfileTest, NegativeRadiusIsRejectedWithItsIndexAndValue) {
  const ProfileError error = rejected({{0, 0}, {1, 0}, {1, 1}, {-0.5, 2}});
  EXPECT_EQ(error.rule(), Rule::negativeRadius);
  EXPECT_EQ(error.index(), 3u);
  EXPECT_TRUE(contains(error.what(), "profile point 3 (r = -0.5, z = 2)")) << error.what();
  EXPECT_TRUE(contains(error.what(), "r must be >= 0")) << error.what();
}

TEST(ProfileTest, NegativeZeroRadiusIsTheAxis) {
  const Profile profile(std::vector<Point2>{{-0.0, 0}, {1, 1}});
  EXPECT_EQ(profile.segmentCount(), 1u);
}

TEST(ProfileTest, CrossingSegmentsAreRejectedNamingBothSegments) {
  // A bow tie: segment 0 (0,0)-(1,1) crosses segment 2 (1,0)-(0,1).
  const ProfileError error = rejected({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  EXPECT_EQ(error.rule(), Rule::selfIntersecting);
  EXPECT_EQ(error.index(), 0u);
  EXPECT_TRUE(contains(error.what(), "point 0 (r = 0, z = 0)")) << error.what();
  EXPECT_TRUE(contains(error.what(), "point 3 (r = 0, z = 1)")) << error.what();
  EXPECT_TRUE(contains(error.what(), "must not cross or touch itself")) << error.what();
}

TEST(ProfileTest, FoldingBackIsSelfIntersection) {
  EXPECT_EQ(rejected({{0, 0}, {2, 0}, {1, 0}}).rule(), Rule::selfIntersecting);
  EXPECT_EQ(rejected({{1, 0}, {1, 2}, {1, 1}}).rule(), Rule::selfIntersecting);
}

TEST(ProfileTest, VertexOnAnotherSegmentIsSelfIntersection) {
  EXPECT_EQ(rejected({{0, 0}, {2, 0}, {2, 1}, {1, 0}}).rule(), Rule::selfIntersecting);
}

TEST(ProfileTest, IndicesRefersToTheCallersInputAfterDroppedDuplicates) {
  // Point 1 repeats point 0 and is dropped; the negative radius is still reported as point 3.
  const ProfileError error = rejected({{0, 0}, {0, 0}, {1, 0}, {-1, 1}});
  EXPECT_EQ(error.index(), 3u);
}

TEST(ProfileTest, RepeatedConsecutivePointsAreDroppedWithAWarning) {
  const Profile profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 0}, {1, 1}, {1, 1}, {1, 1}, {0, 1}});
  EXPECT_EQ(profile.points().size(), 4u);
  ASSERT_EQ(profile.warnings().size(), 3u);
  EXPECT_EQ(profile.warnings()[0].index, 2u);
  EXPECT_TRUE(contains(profile.warnings()[0].message, "profile point 2 (r = 1, z = 0) repeats point 1"))
      << profile.warnings()[0].message;
  EXPECT_EQ(profile.sourceIndex()[2], 3u);
}

TEST(ProfileTest, SourceIndicesNameTheCallersPointsWhetherOrNotPointsWereDropped) {
  // Nothing dropped: every point is its own input point.
  const std::vector<Point2> input{{0, 0}, {1, 0}, {1, 1}, {0, 2}};
  const Profile kept(input);
  ASSERT_EQ(kept.sourceIndex().size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(kept.sourceIndex()[k], k);
  // Repeats dropped at the start, the middle and the end: each kept point names the input point
  // it was, read by index and by iteration alike.
  const std::vector<Point2> repeated{{0, 0}, {0, 0}, {1, 0}, {1, 1}, {1, 1}, {1, 1}, {0, 2}, {0, 2}};
  const Profile dropped(repeated);
  const std::vector<std::size_t> expected{0, 2, 3, 6};
  ASSERT_EQ(dropped.sourceIndex().size(), expected.size());
  std::vector<std::size_t> iterated;
  for (const std::size_t i : dropped.sourceIndex()) iterated.push_back(i);
  EXPECT_EQ(iterated, expected);
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(dropped.sourceIndex()[k], expected[k]);
    EXPECT_EQ(dropped.points()[k].r, repeated[expected[k]].r);
    EXPECT_EQ(dropped.points()[k].z, repeated[expected[k]].z);
  }
}

TEST(ProfileTest, MoreThanTheIndexTypesHoldIsRejected) {
  // A span of kMaxPoints + 1 points over untouched, unreserved virtual memory (zero pages if read):
  // the count is checked before any point is read.
  const std::size_t count = Profile::kMaxPoints + 1;
  const std::size_t bytes = count * sizeof(Point2);
  void* memory = mmap(nullptr, bytes, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (memory == MAP_FAILED) GTEST_SKIP() << "cannot reserve " << bytes << " bytes of address space";
  try {
    Profile profile(std::span<const Point2>(static_cast<const Point2*>(memory), count));
    ADD_FAILURE() << "accepted " << count << " points";
  } catch (const ProfileError& error) {
    EXPECT_EQ(error.rule(), Rule::tooManyPoints);
    EXPECT_TRUE(contains(error.what(), std::to_string(count) + " points")) << error.what();
  }
  munmap(memory, bytes);
}

TEST(ProfileTest, CoordinatesBeyond2To60AreRejected) {
  // Found by fuzzing: beyond about 1e50 the kernel's products overflow (and Embree drops boxes
  // beyond 1.8e18 anyway).
  const ProfileError error = rejected({{0, 0}, {1, 0}, {1.7976931348623157e308, 0.13}, {0, 1}});
  EXPECT_EQ(error.rule(), Rule::outOfRange);
  EXPECT_EQ(error.index(), 2u);
  EXPECT_TRUE(contains(error.what(), "profile point 2 (r = 1.7976931348623157e+308, z = 0.13)")) << error.what();
  EXPECT_TRUE(contains(error.what(), "2^60")) << error.what();
  EXPECT_EQ(rejected({{0, 0}, {1, -0x1.0000000000001p60}}).rule(), Rule::outOfRange);
  EXPECT_NO_THROW(Profile(std::vector<Point2>{{0, -0x1p60}, {0x1p60, 0x1p60}}));  // the limit itself is allowed
}

TEST(ProfileTest, ProfilesSmallerThan2ToMinus60AreRejected) {
  // Found by fuzzing: a profile of subnormal size gave NaN normals.
  const ProfileError error = rejected({{0, 0}, {1.265e-321, 0}, {1.265e-321, 1.265e-321}, {0, 2.53e-321}});
  EXPECT_EQ(error.rule(), Rule::outOfRange);
  EXPECT_TRUE(contains(error.what(), "extent")) << error.what();
  EXPECT_NO_THROW(Profile(std::vector<Point2>{{0, 0}, {0x1p-60, 0}}));
}

TEST(ProfileTest, SegmentsBelow2ToMinus60OfTheExtentAreRejected) {
  // Found by fuzzing: a segment of length 1e-317 in an ordinary profile (its squared length
  // underflows) gave a NaN normal.
  const ProfileError error = rejected({{0, 0}, {1, 0}, {1, 1e-317}, {1, 1}});
  EXPECT_EQ(error.rule(), Rule::segmentTooShort);
  EXPECT_EQ(error.index(), 1u);
  EXPECT_TRUE(contains(error.what(), "point 1 (r = 1, z = 0)")) << error.what();
  EXPECT_TRUE(contains(error.what(), "point 2 (r = 1, z = 1e-317)")) << error.what();
  EXPECT_TRUE(contains(error.what(), "merge the points")) << error.what();
  // 2^-60 of the extent exactly is allowed; a near-duplicate at 1e-9 is nowhere near the limit.
  EXPECT_NO_THROW(Profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 0x1p-60}, {1, 1}}));
  EXPECT_NO_THROW(Profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 1e-9}, {1, 1}}));
}

TEST(ProfileTest, AwkwardButValidProfilesAreAccepted) {
  // Horizontal and vertical runs, apexes on the axis, not monotone in z, a closed loop.
  const std::vector<std::vector<Point2>> valid = {
      {{0, 0}, {1, 0}, {1, 1}, {0.5, 1}, {0.5, 0.5}, {0, 0.5}},  // cup-like: goes back down
      {{0, -1}, {1, -1}, {0, 0}, {1, 1}, {0, 1}},                // an apex inside the profile
      {{1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 0}},                  // a closed square loop
      {{0.2, 0}, {0.6, 0}},                                      // one horizontal segment
      {{0, 0}, {0, 1}},                                          // a segment on the axis
  };
  for (const auto& points : valid) EXPECT_NO_THROW(Profile{points});
}

TEST(ProfileTest, ClosedWhenTheEndsMeetOrBothLieOnTheAxis) {
  EXPECT_TRUE(Profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}).closed());
  EXPECT_TRUE(Profile(std::vector<Point2>{{1, 0}, {2, 0}, {2, 1}, {1, 0}}).closed());
  EXPECT_FALSE(Profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}}).closed());
  EXPECT_FALSE(Profile(std::vector<Point2>{{1, 0}, {1, 1}}).closed());
}

TEST(ProfileTest, ArcLengthAccumulatesSegmentLengths) {
  const Profile profile(std::vector<Point2>{{0, 0}, {3, 4}, {3, 6}});
  ASSERT_EQ(profile.arcLength().size(), 3u);
  EXPECT_EQ(profile.arcLength()[1], 5.0);
  EXPECT_EQ(profile.arcLength()[2], 7.0);
}

}  // namespace
}  // namespace revolve
