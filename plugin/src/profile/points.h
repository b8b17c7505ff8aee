// What every point of a profile or a spline must be, and exact equality of points: the rules of
// coordinates and of size shared by Profile and Spline, each with its message, in one place.
#pragma once

#include <revolve/core.h>

#include <cstddef>
#include <string>

namespace revolve::detail {

inline bool samePoint(Point2 a, Point2 b) { return a.r == b.r && a.z == b.z; }

// "profile point 3 (r = 1, z = 2)": `what` names the kind of point.
std::string describePoint(const char* what, std::size_t index, Point2 p);

// Throws ProfileError (nonFinite) unless both coordinates are finite.
void checkFinite(const char* what, std::size_t index, Point2 p);
// Throws ProfileError (outOfRange) unless both coordinates lie within +-Profile::kMaxCoordinate.
void checkWithinRange(const char* what, std::size_t index, Point2 p);
// Throws ProfileError (outOfRange, at `index`) when `extent`, the largest coordinate magnitude of
// the points `what` names ("profile", "spline"), is below Profile::kMinExtent.
void checkExtent(const char* what, std::size_t index, double extent);

}  // namespace revolve::detail
