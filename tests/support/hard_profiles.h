// Closed profiles for the hard-case tests, and an independent inside test for their solids.
#pragma once

#include <revolve/revolve.h>

#include <random>
#include <string>
#include <vector>

namespace revolve::testing {

struct ClosedProfile {
  std::string name;
  std::vector<Point2> points;  // closed: ends on the axis, or first point == last point
};

// At least eight closed profiles: the standard closed ones plus runs of horizontal and vertical
// segments, tiny segments (1e-6 of the object), near-duplicate points, 50+ monotone intervals and
// 20,000+ points.
std::vector<ClosedProfile> closedProfiles();

std::vector<Point2> stairs(int steps);          // alternating horizontal and vertical runs
std::vector<Point2> tinySegments(double tiny);  // a cylinder whose corners are cut by segments of length `tiny`
std::vector<Point2> nearDuplicates(
    std::mt19937_64& random);                   // a sphere-like outline with clusters of points 1e-9 apart
std::vector<Point2> manyPointVase(int points);  // a smooth vase outline of `points` points
std::vector<Point2> nearlyFlatCaps();           // caps horizontal to within 1e-6 and 1e-7

// Whether (rho, z) lies inside the region a closed profile bounds in the meridian half-plane
// (closed by the axis when both ends lie on it): crossing number of the ray from (rho, z)
// towards +r, in long double, half-open at vertices. Written apart from the library.
bool insideMeridianRegion(std::span<const Point2> profile, long double rho, long double z);

// Random points of the profile's solid at least `margin` from its surface (by the oracle's
// meridianDistance), in float.
std::vector<Vec3> interiorPoints(std::span<const Point2> profile, std::mt19937_64& random, std::size_t count,
                                 double margin);

}  // namespace revolve::testing
