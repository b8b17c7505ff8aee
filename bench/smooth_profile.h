// A smooth profile made of straight lines and circular arcs, the way turned parts are drawn: the
// "true" surface the benchmark measures every method's error against.
//
// Lines and arcs give closed forms for everything the error measures need: the distance from a
// meridian point to the curve, the curve's normal there, and the inside/outside sign. None of it
// uses the revolve library, so the errors it reports are independent of the code under test.
#pragma once

#include <revolve/revolve.h>

#include <cstddef>
#include <string>
#include <vector>

namespace revolve::bench {

// One piece of the profile, travelled from `start`. A line has radius 0; an arc turns by `turn`
// radians (positive: counter-clockwise in the (r, z) plane, i.e. to the left of travel).
struct ProfilePiece {
  Point2 start, end;
  double radius = 0.0;  // 0 for a line
  Point2 centre{};      // arcs only
  double angle0 = 0.0;  // arcs: polar angle of `start` about `centre`
  double turn = 0.0;    // arcs: signed angle swept
  double length() const;
  Point2 at(double fraction) const;  // the point a fraction of the way along
};

struct ClosestPoint {
  Point2 point;
  Point2 normal;          // unit, to the right of travel (revolve's convention: outwards for a solid)
  double distance;        // >= 0
  double signedDistance;  // negative inside the solid
};

class SmoothProfile {
 public:
  // Pieces are added turtle-fashion from `start`, heading `headingDegrees` from the +r axis
  // towards +z; each begins where the previous one ended, with its heading (G1 joins) unless a
  // corner is turned explicitly.
  SmoothProfile(std::string name, Point2 start, double headingDegrees);
  SmoothProfile& line(double length);
  SmoothProfile& arc(double radius, double turnDegrees);
  SmoothProfile& corner(double turnDegrees);  // a sharp corner: turn without moving
  // A straight line on the current heading that ends on the axis (r = 0); the heading must point
  // towards the axis.
  SmoothProfile& lineToAxis();

  const std::string& name() const { return name_; }
  const std::vector<ProfilePiece>& pieces() const { return pieces_; }
  // The solid is closed: both ends on the axis, or the loop closes on itself.
  bool closed() const;
  struct Extent {
    double rMax, zLow, zHigh;
  };
  Extent extent() const;  // of the curve itself (arcs' extreme points included)
  double size() const;    // the largest extent of the bounding box: 2 r_max across, or the height
  double rMax() const { return extent().rMax; }

  // Exact closest point of the curve to (rho, z), with the sign of the solid (pseudo-normal at
  // joins, so the sign is right at convex and concave corners alike).
  ClosestPoint closest(Point2 p) const;

  // A polyline through `points` points of the curve (points >= pieces + 1): every join is a
  // vertex, lines get their two ends, and arcs share the rest so that every chord has the same
  // sagitta (an arc of radius R gets chords of length ~ sqrt(8 R sagitta)). Returns the polyline.
  std::vector<Point2> sample(int points) const;
  // The largest sagitta of sample(points): its distance from the curve, in closed form.
  double sampleError(int points) const;
  // A polyline through `points` points spaced evenly along the curve (what sampling by hand at a
  // fixed step gives): every join is a vertex, and each piece gets a share of the segments in
  // proportion to its length (at least one), equal steps along it. Lines get points too.
  std::vector<Point2> sampleUniform(int points) const;
  double uniformError(int points) const;  // its largest sagitta, in closed form

 private:
  std::vector<int> arcSegments(int points) const;      // segments per arc for sample(points)
  std::vector<int> uniformSegments(int points) const;  // segments per piece for sampleUniform(points)
  std::vector<Point2> polylineOf(const std::vector<int>& segments) const;

  std::string name_;
  Point2 cursor_;
  double heading_;  // radians
  std::vector<ProfilePiece> pieces_;
};

}  // namespace revolve::bench
