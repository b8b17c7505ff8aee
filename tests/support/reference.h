// Independent test oracle for revolve: ray / surface-of-revolution intersections computed by brute
// force and by closed-form formulas, in long double (64-bit significand on x86-64).
//
// Nothing here includes or calls the revolve library beyond its Point2 type: the oracle is written
// the textbook way so that tests can compare the library's clever formulations against it.
//
// Conventions are the library's (see revolve/revolve.h):
// - A ray is origin + t * direction (direction need not be unit length); hits with
//   tnear <= t <= tfar count. A ray with a non-finite or zero direction, a non-finite origin, or
//   tnear > tfar misses (as in revolve::intersect).
// - The surface swept by a profile segment from (r0, z0) to (r1, z1) has the unit normal
//   (z1 - z0, -(r1 - r0)) / length in its meridian half-plane, rotated to the hit's angle
//   phi = atan2(y, x) (phi = 0 on the axis, where atan2(0, 0) = 0).
#pragma once

#include <revolve/revolve.h>

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace revolve::reference {

struct RefRay {
  long double ox, oy, oz;
  long double dx, dy, dz;
  long double tnear, tfar;
};

struct RefHit {
  long double t;
  long double nx, ny, nz;  // unit normal
  std::size_t segment;     // profile segment hit; 0 for the analytic primitives
};

// ---------------------------------------------------------------------------------------------
// Brute force over a profile.

// Every intersection of the ray with every segment's surface, with tnear <= t <= tfar, sorted by
// t then by segment. A hit on a point shared by two segments is listed once for each of them; a
// tangent (double) root is listed once. Not reported: a ray lying inside a horizontal segment's
// plane, or inside a segment's surface (infinitely many roots).
//
// Two rules of the library's decide what rounding cannot: the apex rule (a ray whose line passes
// through an apex, a profile point on the axis, touches the surface there: a hit for each
// non-horizontal segment meeting the apex), and for a ray in a horizontal plane (dz = 0) the
// half-open height rule (a segment owns the heights [zmin, zmax), so at a vertex's height the ray
// meets the circles of the segments continuing upwards from it, and at a top rim nothing).
std::vector<RefHit> allHits(std::span<const Point2> profile, const RefRay& ray);

// Nearest hit with tnear <= t <= tfar; ties go to the lower segment index.
std::optional<RefHit> intersectProfile(std::span<const Point2> profile, const RefRay& ray);

// Whether the oracle's answer for `ray` is fragile, so that a library answer differing from it is
// within rounding rather than wrong: nudging its origin by `nudge` along an axis changes the
// oracle's verdict or moves its hit by more than 1e-6 * size. Such a ray passes within `nudge` of
// a silhouette, a rim or an apex, where either answer is the exact one for a ray within rounding
// of it. A ray in a vertex's horizontal plane is nudged only along x and y: its answer there is
// the half-open rule's, exact, and nudging it off the plane would change the rule, not the ray.
bool verdictIsFragile(std::span<const Point2> profile, const RefRay& ray, long double nudge, long double size);

// Whether the ray's line passes within `distance` of an apex (a profile point on the axis ending a
// non-horizontal segment). Such a ray touches the surface at the apex, or misses it by less than
// `distance`: a verdict rounding may turn either way (the library's, or the oracle's near-double
// root), and the one fragile verdict the standard test rays meet by design.
bool passesNearAnApex(std::span<const Point2> profile, const RefRay& ray, long double distance);

// Distance from the point (x, y, z) to the surface of revolution: the 2-D distance from
// (sqrt(x^2 + y^2), z) to the profile polyline.
long double meridianDistance(std::span<const Point2> profile, long double x, long double y, long double z);

// ---------------------------------------------------------------------------------------------
// Closed-form primitives, each by its own formula. Each returns the nearest hit with
// tnear <= t <= tfar (segment = 0).
//
// The cylinder, cone and disc are the surfaces swept by the one-segment profile from the first
// to the second point their arguments name, and their normals follow the profile convention for
// that order: swapping the two points flips the normal. The sphere's and torus' normals point
// out of the solid.

// Lateral surface x^2 + y^2 = R^2 for z between z0 and z1 (segment (R, z0) -> (R, z1)): outward
// normal if z0 < z1. Solved geometrically in the xy plane (closest approach plus half chord).
std::optional<RefHit> intersectCylinder(long double radius, long double z0, long double z1, const RefRay& ray);

// The truncated cone swept by the segment (r0, z0) -> (r1, z1). Needs z0 != z1 (a horizontal
// segment is a disc: use intersectDisc); r0 == r1 is the cylinder. Solved in the apex / half-angle
// form ((P - V).a)^2 = cos^2(theta) |P - V|^2 on the nappe (P - V).a >= 0.
std::optional<RefHit> intersectCone(long double r0, long double z0, long double r1, long double z1, const RefRay& ray);

// The annulus min(rInner, rOuter) <= rho <= max(rInner, rOuter) of the plane z: the segment
// (rInner, z) -> (rOuter, z), whose normal is -z when rInner < rOuter (a bottom cap of a profile
// listed bottom to top) and +z when rInner > rOuter. A ray inside the plane misses.
std::optional<RefHit> intersectDisc(long double z, long double rInner, long double rOuter, const RefRay& ray);

// The full sphere of radius R centred at (0, 0, centerZ). Solved geometrically: closest approach
// of the ray to the centre, then half chord by Pythagoras.
std::optional<RefHit> intersectSphere(long double centerZ, long double radius, const RefRay& ray);

// The ring torus about the z axis centred at the origin: points at distance `minorRadius` from the
// circle of radius `majorRadius` in the plane z = 0. Needs 0 < minorRadius < majorRadius (a
// spindle torus' quartic also has the mirrored circle's roots); throws std::invalid_argument
// otherwise. The quartic's real roots are isolated exactly by the roots of its derivatives (see
// reference.cpp); a tangent (double) root counts as a hit.
std::optional<RefHit> intersectTorus(long double majorRadius, long double minorRadius, const RefRay& ray);

}  // namespace revolve::reference
