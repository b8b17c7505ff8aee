// Profiles and rays the tests share: analytic shapes, everyday objects, and awkward cases.
#pragma once

#include <revolve/revolve.h>

#include <random>
#include <string>
#include <vector>

namespace revolve::testing {

struct NamedProfile {
  std::string name;
  std::vector<Point2> points;
};

// Closed unless said otherwise. Each generator documents what makes it interesting.
std::vector<Point2> cappedCylinder(double radius, double z0, double z1);  // disc, side, disc (horizontal + vertical)
std::vector<Point2> sphereLike(double radius, int segments);  // inscribed polygon of a half circle, apexes on the axis
std::vector<Point2> torusLike(double major, double minor, int segments);  // closed loop off the axis
std::vector<Point2> hollowVase();             // outer wall up, inner wall down: non-monotone in z
std::vector<Point2> cup();                    // runs of horizontal and vertical segments
std::vector<Point2> hourglass();              // two cones meeting at an apex inside the profile
std::vector<Point2> zigzagColumn(int teeth);  // 2 * teeth monotone intervals
std::vector<Point2> spindle(int segments);    // apexes at both ends, smooth in between
std::vector<Point2> openCone();               // one oblique segment: open, apex on the axis
std::vector<Point2> annulus();                // one horizontal segment: open
std::vector<Point2> starShaped(std::mt19937_64& random, int points);  // random closed polygon in the half-plane

// At least ten profiles covering every feature above, for tests that sweep over "all profiles".
std::vector<NamedProfile> standardProfiles();

// Incoherent rays: origins on a sphere of `spread` times the shape's bounding radius about its
// centre, aimed at uniform points of its padded box, so that most hit and some graze or miss.
std::vector<Ray> incoherentRays(const Shape& shape, std::mt19937_64& random, std::size_t count, double spread = 3.0);

// Rays with the awkward directions: along the axis, through the axis, perpendicular to it (dz = 0),
// and in the planes of the profile's vertices.
std::vector<Ray> axisAlignedRays(const Shape& shape, std::mt19937_64& random, std::size_t count);

}  // namespace revolve::testing
