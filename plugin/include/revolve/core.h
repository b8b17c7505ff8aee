// revolve's core: surfaces of revolution and their exact queries, without Embree.
//
// A surface of revolution (SoR) is a profile of points (r, z), a polyline or a spline, swept a full
// turn about the z axis. revolve builds a MIBIT search tree over the profile (Baciu, Jia & Lam
// 2001) and intersects rays with the truncated cones of its segments (Wang 1989), or with the
// curve's own surface at the leaves for a spline. This header needs no Embree: profiles, splines,
// shapes, ray and point queries, shading normals and clearance. revolve/embree.h adds the Embree
// user geometry; revolve/revolve.h includes both.
//
// Conventions
// - Object space: the axis of revolution is the z axis; profile points have r >= 0.
// - A ray is origin + t * direction; t is in units of `direction`, which need not be unit length.
//   Queries answer the nearest hit with tnear <= t <= tfar.
// - Normals point to the right of the profile's direction of travel in the (r, z) half-plane, i.e.
//   outwards for a profile listed from bottom to top. They are not flipped towards the ray.
// - u = phi / 2pi in [0, 1), phi = atan2(y, x) of the hit; v = arc length along the profile from its
//   first point, normalised to [0, 1]; `segment` (Embree's primID) is the index of the profile
//   segment hit (segment i joins points i and i + 1 of Profile::points()); for a spline shape, the
//   monotone part of the curve hit (Shape::splinePiece names its Bezier piece).
// - Every query is thread-safe on a built Shape, never allocates, throws or locks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace revolve {

struct Point2 {
  double r;  // distance from the z axis, >= 0
  double z;  // height along the axis
};

struct Vec3 {
  float x, y, z;
};

// ---------------------------------------------------------------------------------------------
// Profile: a validated generatrix.

// Thrown for an invalid profile. what() names the point, the value and the rule it breaks.
class ProfileError : public std::invalid_argument {
 public:
  enum class Rule {
    tooFewPoints,
    nonFinite,
    negativeRadius,
    selfIntersecting,
    tooManyPoints,
    outOfRange,       // a coordinate beyond kMaxCoordinate, or an extent below kMinExtent
    segmentTooShort,  // a segment shorter than kMinSegmentFraction of the profile's extent
    badPointCount,    // a spline whose point count its kind cannot take (2n + 1, 3n + 1)
    crossesAxis,      // a spline whose curve reaches r <= 0 between the points it passes through
  };
  ProfileError(Rule rule, std::size_t index, const std::string& message)
      : std::invalid_argument(message), rule_(rule), index_(index) {}
  Rule rule() const noexcept { return rule_; }
  // Index (in the caller's input) of the first point involved.
  std::size_t index() const noexcept { return index_; }

 private:
  Rule rule_;
  std::size_t index_;
};

struct ProfileWarning {
  std::size_t index;  // index in the caller's input of the point concerned
  std::string message;
};

class Spline;

// Index in the caller's input of each point a Profile kept: k itself, unless repeated points were
// dropped before it (only then are the indices stored). Reads as a span of them would.
class SourceIndices {
 public:
  SourceIndices(const std::size_t* stored, std::size_t count) noexcept : stored_(stored), count_(count) {}
  std::size_t operator[](std::size_t k) const noexcept { return stored_ != nullptr ? stored_[k] : k; }
  std::size_t size() const noexcept { return count_; }
  // Whether every point kept its own index (nothing was dropped, nothing is stored).
  bool identity() const noexcept { return stored_ == nullptr; }

  class Iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = std::size_t;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = std::size_t;
    Iterator() noexcept = default;
    Iterator(const SourceIndices* indices, std::size_t k) noexcept : indices_(indices), k_(k) {}
    std::size_t operator*() const noexcept { return (*indices_)[k_]; }
    Iterator& operator++() noexcept { return ++k_, *this; }
    Iterator operator++(int) noexcept { return {indices_, k_++}; }
    bool operator==(const Iterator& other) const noexcept { return k_ == other.k_; }

   private:
    const SourceIndices* indices_ = nullptr;
    std::size_t k_ = 0;
  };
  Iterator begin() const noexcept { return {this, 0}; }
  Iterator end() const noexcept { return {this, count_}; }

 private:
  const std::size_t* stored_;
  std::size_t count_;
};

class Profile {
 public:
  // Largest accepted point count: tree node indices are 32-bit and a tree has up to 2 nodes a point.
  static constexpr std::size_t kMaxPoints = std::size_t{1} << 31;
  // The range the kernel and Embree support. Embree drops boxes beyond 1.8e18 (its single-precision
  // bounds); within [2^-60, 2^60] for the extent and 2^-60 of it for a segment, every product the
  // kernel forms (up to the sixth power of the size, down to squared segment lengths) stays well
  // inside double's range.
  static constexpr double kMaxCoordinate = 0x1p60;        // |r|, |z| <= 2^60 (about 1.15e18)
  static constexpr double kMinExtent = 0x1p-60;           // largest |r| or |z| >= 2^-60 (about 8.7e-19)
  static constexpr double kMinSegmentFraction = 0x1p-60;  // segment length >= 2^-60 of that extent

  // Validates `points` and keeps them in order. Throws ProfileError for: fewer than 2 distinct
  // points; a non-finite coordinate; r < 0; a coordinate beyond kMaxCoordinate or a profile whose
  // extent is below kMinExtent; a segment shorter than kMinSegmentFraction of the extent; a
  // self-intersecting polyline (two segments sharing a point other than the vertex joining
  // neighbours, or the closing point of a loop); more than kMaxPoints points. Exactly repeated consecutive points are
  // dropped and listed in warnings(). Horizontal segments (discs, annuli), vertical ones (cylinders), points on the
  // axis (apexes) and profiles that are not monotone in z are all valid.
  explicit Profile(std::span<const Point2> points);

  // Points on `curve` whose polyline stays within `tolerance` of it: from each point, the chord
  // reaching farthest along the curve whose largest distance from the arc it replaces (computed
  // exactly, piece by piece, from the cubics) is within the tolerance. Adaptive in curvature: a
  // straight run gets no point between its ends, and a chord may span a smooth join; the ends and
  // every corner (a join where the tangent turns) are kept as vertices. Where two chords would cross
  // or touch (a tolerance wider than the gap between two parts of the curve: a thin rim, a stem in
  // a foot), both are split along their arcs until none does, so the result is always a valid
  // profile within the tolerance. A linear spline gives its own points. curveParameters() records
  // where each point lies on the curve. Throws std::invalid_argument unless tolerance > 0 and
  // finite and at least 2^-40 of the curve's extent (double-precision chords resolve no finer).
  [[nodiscard]] static Profile fromCurve(const Spline& curve, double tolerance);
  // What a polyline tolerance must be (the rule fromCurve holds it to), and the rule as every
  // message that refuses one states it.
  static constexpr bool toleranceAllowed(double tolerance) noexcept {
    return tolerance > 0.0 && tolerance < std::numeric_limits<double>::infinity();
  }
  static constexpr const char* kToleranceRule =
      "a polyline tolerance is a finite number > 0 (the polyline's largest distance from the curve, in the "
      "profile's units)";

  std::span<const Point2> points() const noexcept { return points_; }
  std::size_t segmentCount() const noexcept { return points_.size() - 1; }
  // Closed: the profile bounds a solid (its ends meet, or both lie on the axis).
  bool closed() const noexcept { return closed_; }
  // Cumulative arc length at each point; arcLength().back() is the total length.
  std::span<const double> arcLength() const noexcept { return arcLength_; }
  // Index in the caller's input of each kept point.
  SourceIndices sourceIndex() const noexcept {
    return {sourceIndex_.empty() ? nullptr : sourceIndex_.data(), points_.size()};
  }
  // For a profile made by fromCurve from a curved spline: where each point lies on the curve, as
  // T = k + u (the point is curve.at(k, u); T = pieceCount() is the curve's end). Empty otherwise.
  std::span<const double> curveParameters() const noexcept { return curveParameters_; }
  const std::vector<ProfileWarning>& warnings() const noexcept { return warnings_; }

 private:
  void checkScale() const;

  std::vector<Point2> points_;
  std::vector<double> arcLength_;
  std::vector<std::size_t> sourceIndex_;  // empty while no point was dropped (SourceIndices)
  std::vector<double> curveParameters_;
  std::vector<ProfileWarning> warnings_;
  bool closed_ = false;

  // A Shape built from a Spline reports its pieces' ends through profile(): not validated as a
  // polyline (the curve was), see Shape::profile().
  friend class Shape;
  struct Unchecked {};
  Profile(Unchecked, std::vector<Point2> points, std::vector<double> arcLength, bool closed);
};

// ---------------------------------------------------------------------------------------------
// Spline: a smooth profile, traced exactly (Shape) or as a polyline within a tolerance
// (Profile::fromCurve).

enum class SplineKind {
  // A polyline through the points: the same profile as Profile(points).
  linear,
  // Quadratic Bezier pieces: 2n + 1 points; piece i has the control points 2i, 2i + 1, 2i + 2, so
  // neighbours share their end point and the curve passes through the even-numbered points.
  quadratic,
  // Cubic Bezier pieces: 3n + 1 points; piece i has the control points 3i to 3i + 3, neighbours
  // sharing their end point. A straight piece has its two inner points on the chord.
  bezier,
  // A centripetal Catmull-Rom curve through every point (Yuksel, Schaefer & Keyser 2011: knot
  // spacing sqrt(chord length); no cusp or self-intersection within a piece). At an open end the
  // curve leaves along the first (last) chord (the missing neighbour is the mirror image of the
  // second point); when the first and last points are equal it closes smoothly (periodic). Unlike
  // POV-Ray's cubic_spline, whose first and last points only steer, it passes through every point.
  catmullRom,
  // The natural cubic spline through every point, parametrised by chord length: C2 everywhere,
  // zero second derivative at an open end; periodic (C2 across the join) when the first and last
  // points are equal.
  natural,
};

// "linear", "quadratic", "bezier", "catmull-rom", "natural" (the names the scene file and
// revolve-trace take), and back; nothing for an unknown name.
[[nodiscard]] const char* splineKindName(SplineKind kind) noexcept;
[[nodiscard]] std::optional<SplineKind> splineKindNamed(std::string_view name) noexcept;

class Spline {
 public:
  // Validates the points and converts the curve to cubic Bezier pieces. Throws ProfileError for:
  // a point count the kind cannot take (linear, catmull-rom and natural need at least 2 points,
  // quadratic 2n + 1 >= 3, bezier 3n + 1 >= 4); a non-finite coordinate; a coordinate or extent
  // outside Profile's range; r < 0 at a point the curve passes through (Bezier control points off
  // the curve may have r < 0); a curve that reaches r < 0 anywhere, or r = 0 between the points
  // it passes through (crossesAxis: it may touch the axis only at a point it passes through,
  // where a part of the curve ends exactly on it); two equal consecutive points of catmull-rom or
  // natural (their chord has no length to parametrise); a piece with all its points equal, or
  // shorter than Profile::kMinSegmentFraction of the extent; a curve that crosses or touches itself
  // (checked conservatively on the pieces' control hulls: see below); more than kMaxPoints points.
  // A linear spline is validated as Profile(points) is (repeated points dropped with a warning).
  //
  // Self-intersection: the curve, split where r or z turns (so that every part is monotone in
  // both and lies in the box of its ends), is checked part against part by subdivision: two parts
  // are apart when their boxes are, or when their chords lie farther apart than the distances of
  // their control points from them (the control hull lies that close to the chord); parts that meet
  // at a join are apart when the cones from the join holding their control hulls meet only there.
  // Parts that cannot be separated before they are 2^-40 of the extent long, or within 2^16
  // subdivisions of the pair, count as touching: a curve coming that close to itself (or running
  // that close to itself for a long stretch), or folding back on itself in a cusp, is refused.
  Spline(SplineKind kind, std::span<const Point2> points);

  // Index and cost limits: the monotone parts (up to 5 a cubic piece) index 32-bit tree nodes.
  static constexpr std::size_t kMaxPoints = std::size_t{1} << 28;

  SplineKind kind() const noexcept { return kind_; }
  std::span<const Point2> points() const noexcept { return points_; }  // as given (linear: as kept)
  // The curve as cubic Bezier pieces: piece i has control points bezier()[3 i] to bezier()[3 i + 3]
  // (quadratic pieces degree-elevated, linear segments with their inner points at the thirds).
  std::span<const Point2> bezier() const noexcept { return kind_ == SplineKind::bezier ? points_ : bezier_; }
  std::size_t pieceCount() const noexcept { return (bezier().size() - 1) / 3; }
  // Index in points() of the point where piece i starts (for messages and the readers' lines).
  std::size_t pieceStart(std::size_t piece) const noexcept;
  // The point of piece `piece` at parameter u in [0, 1] (de Casteljau).
  [[nodiscard]] Point2 at(std::size_t piece, double u) const noexcept;
  // Closed: the curve bounds a solid (its ends meet, or both lie on the axis).
  bool closed() const noexcept { return closed_; }
  const std::vector<ProfileWarning>& warnings() const noexcept { return warnings_; }
  std::size_t memoryBytes() const noexcept;  // heap bytes held by the spline

 private:
  SplineKind kind_;
  std::vector<Point2> points_;
  std::vector<Point2> bezier_;  // empty for the bezier kind, whose points are its control points
  // A linear spline's pieceStart (the kept points' indices in the input); the other kinds' pieces
  // start at every first, second or third point, which the kind says.
  std::vector<std::size_t> linearPieceStart_;
  std::vector<ProfileWarning> warnings_;
  bool closed_ = false;
};

// ---------------------------------------------------------------------------------------------
// Shape: a profile with its search structure, ready to trace.

// The MIBIT paper's switches (Baciu, Jia & Lam 2001: other searches, shell kinds, no monotone split,
// no range search, the binary tree), for comparisons: revolve/baselines.h. A Shape built without
// them is the fastest search measured here, the one an application wants.
struct BuildOptions;

// Counters of work done, per query or accumulated; counting costs nothing when not asked for.
struct Stats {
  std::uint64_t rays = 0;
  std::uint64_t nodesVisited = 0;  // tree nodes (MIBIT / strip tree) popped and examined
  std::uint64_t shellTests = 0;    // bounding-shell or strip intersection tests
  std::uint64_t quadratics = 0;    // ray / truncated-cone quadratics solved (Wang), or curve parts solved
  Stats& operator+=(const Stats& other) noexcept;
};

struct Bounds {
  Vec3 lower, upper;
};

class Shape;
namespace detail {
struct ShapeImpl;  // the built search structure: private to the library
const ShapeImpl& implOf(const Shape& shape) noexcept;
}  // namespace detail

class Shape {
 public:
  explicit Shape(Profile profile);
  Shape(Profile profile, const BuildOptions& options);  // revolve/baselines.h
  // A smooth profile traced exactly: the curve is split where r or z turns, into parts monotone in
  // both that take the place of segments in the search (each lies in the box of its ends), and each
  // part's surface is solved exactly at the leaves (README, How it works). Methods: mibit (every
  // shell kind, tree and option) and linear; Method::kajiya throws std::invalid_argument (its strips
  // bound polylines). A linear spline builds the polyline shape of Profile(curve.points()).
  explicit Shape(Spline curve);
  Shape(Spline curve, const BuildOptions& options);  // revolve/baselines.h
  ~Shape();
  Shape(Shape&&) noexcept;
  Shape& operator=(Shape&&) noexcept;

  // The profile. For a spline shape: the ends of its monotone parts in order, with the curve's arc
  // lengths (segment k stands for part k, as Hit::segment numbers them); not validated as a
  // polyline (its chords are not the surface and may cross where the curve does not).
  const Profile& profile() const noexcept;
  // The curve a spline shape traces; nullptr for a polyline shape (and for a linear spline).
  const Spline* spline() const noexcept;
  // For a spline shape, the piece of spline()->bezier() that part `segment` belongs to.
  // Precondition: spline() != nullptr and segment < profile().segmentCount().
  std::uint32_t splinePiece(std::uint32_t segment) const noexcept;
  const BuildOptions& options() const noexcept;
  // Whether the shape bounds a solid: its profile, or its spline, is closed (its ends meet, or
  // both lie on the axis).
  bool closed() const noexcept;
  // Object-space box, padded by 2^-12 of its largest coordinate so that Embree's single-precision
  // box test does not cull hits where the surface touches it, for rays starting up to ~10^5 times
  // that coordinate away (measured; farther, rays that graze the box's edges may lose such hits).
  Bounds bounds() const noexcept;
  std::size_t treeNodeCount() const noexcept;  // nodes of the search structure in use
  std::size_t memoryBytes() const noexcept;    // heap bytes held by the shape

 private:
  friend const detail::ShapeImpl& detail::implOf(const Shape& shape) noexcept;
  std::unique_ptr<detail::ShapeImpl> impl_;
};

// ---------------------------------------------------------------------------------------------
// Queries without Embree.

struct Ray {
  Vec3 origin;
  Vec3 direction;  // need not be unit length; must be finite and non-zero
  float tnear = 0.0f;
  float tfar = std::numeric_limits<float>::infinity();
};

struct Hit {
  float t;      // tnear <= t <= tfar, and finite: a hit beyond float's range (a direction of subnormal length) is none
  Vec3 point;   // hit point, computed in double precision from the exact solution
  Vec3 normal;  // unit geometric normal (see Conventions)
  float u, v;   // surface parameters (see Conventions)
  std::uint32_t segment;
};

// Nearest hit of `ray` with the surface, or nothing. A ray with a non-finite or zero direction,
// a non-finite origin, or tnear > tfar misses.
[[nodiscard]] std::optional<Hit> intersect(const Shape& shape, const Ray& ray, Stats* stats = nullptr) noexcept;
// Whether any hit with tnear <= t <= tfar exists.
[[nodiscard]] bool occluded(const Shape& shape, const Ray& ray, Stats* stats = nullptr) noexcept;
// A hit's every attribute afterwards, from what a lean hit keeps (Geometry::Options): `ray` as it
// was traced (its tnear and tfar before the call, which wrote t into tfar), the hit's `segment`
// (Embree's primID) and its `t`. Equal bit for bit to the Hit intersect gives and to what the
// Embree callbacks write with every attribute on, when `ray` is exactly the ray traced (for an
// instanced geometry: the object-space ray Embree handed the callback, which its rounding of the
// transform makes; a ray transformed otherwise gives the hit on `segment` nearest to t). Nothing
// when the ray does not meet that segment (or segment is no segment of the shape).
[[nodiscard]] std::optional<Hit> surfaceAttributes(const Shape& shape, const Ray& ray, std::uint32_t segment,
                                                   float t) noexcept;

struct SurfacePoint {
  Vec3 point;  // closest point of the surface
  float distance;
  std::uint32_t segment;
};
// Exact closest point of the surface to p (the 2-D closest point in p's meridian plane). p must be
// finite; otherwise the distance is NaN.
[[nodiscard]] SurfacePoint closestPoint(const Shape& shape, Vec3 p) noexcept;

// ---------------------------------------------------------------------------------------------
// Secondary rays.

// Origin for a ray leaving the hit at `t` of `ray` in direction `newDirection`: the point
// origin + t * direction, moved along the normal to the side `newDirection` points to, by the
// bound on that point's rounding error (as pbrt-v4's OffsetRayOrigin). A ray spawned from it with
// tnear = 0 does not re-hit the surface it leaves, yet finds every other surface, including the
// same surface elsewhere. `normal` need not be unit length (Embree's Ng may be passed as is).
[[nodiscard]] Vec3 offsetRayOrigin(const Ray& ray, float t, Vec3 normal, Vec3 newDirection) noexcept;

// ---------------------------------------------------------------------------------------------
// Smooth shading normals.

// Per-vertex normals of a profile for smooth shading: the geometry stays exact (hits, Ng), only
// the normal used for shading varies smoothly across the vertex circles where the profile turns by
// at most a crease angle. Elsewhere (a rim, the edge of a base) each segment keeps its own normal,
// so sharp edges stay sharp.
//
// A vertex normal is that of the circle through the vertex and its two neighbours: the two
// segments' unit normals each weighted by the other segment's length. A polyline inscribed in a
// circle (a sphere's profile, evenly sampled or not) thus gets the circle's normals at its
// vertices, and since a chord point (1 - s) p0 + s p1 then has the direction (1 - s) n0 + s n1
// from the centre, normalised linear interpolation gives the sphere's normal everywhere on the
// polyline, up to rounding. An end of the profile on the axis has the segment's mirror image as its
// neighbour (smooth there gives the axis direction, a pole; a crease, a cone's tip); a closed loop
// joins its last segment to its first. Normals lie on the side of Ng (see Conventions).
class ShadingNormals {
 public:
  // A typical crease angle: smooths curves sampled at up to 30 degrees a segment.
  static constexpr double kDefaultCreaseDegrees = 30.0;

  // Throws std::invalid_argument unless 0 <= creaseDegrees <= 180 (0: every vertex is a crease,
  // flat shading; 180: nothing is).
  ShadingNormals(const Profile& profile, double creaseDegrees);

  // The curve's own normals, for a polyline made from `curve` by Profile::fromCurve: a hit on a
  // segment stands for the point of the segment's arc whose projection on the segment is the hit's
  // (found from v by safeguarded Newton steps on the cubic), and shades with the curve's normal
  // there. A coarse polyline then shades as the curve does: no interpolation between chords, and
  // no creases but the curve's own corners. Throws std::invalid_argument unless `polyline`'s
  // curveParameters() place its points on `curve`.
  ShadingNormals(const Profile& polyline, const Spline& curve);

  // Unit object-space shading normal at a hit on `segment` (Embree's primID) with surface
  // parameters u, v (see Conventions; v is clamped to the segment). The azimuth comes from u, not
  // from a normal, so discs (whose geometric normal is the axis) shade right too. Precondition:
  // segment < the profile's segment count.
  [[nodiscard]] Vec3 normal(std::uint32_t segment, float u, float v) const noexcept;

  std::size_t segmentCount() const noexcept { return segmentStart_.size(); }
  std::size_t memoryBytes() const noexcept;

 private:
  struct Meridian {  // a normal in the (r, z) half-plane, unit length
    double r, z;
  };
  std::vector<Meridian> startNormal_, endNormal_;     // at each segment's first and second point
  std::vector<double> segmentStart_, segmentLength_;  // in units of the total arc length
  // From a curve: each point's place on it (Profile::curveParameters) and its cubic pieces'
  // control points; empty for normals interpolated along the polyline.
  std::vector<double> curveParameter_;
  std::vector<Point2> vertex_, bezier_;
  Meridian curveNormal(std::uint32_t segment, double s) const noexcept;
};

// ---------------------------------------------------------------------------------------------
// Clearance: distances in the meridian plane.
//
// A point at distance rho from the axis and height z lies as far from the surface as (rho, z) lies
// from the profile polyline in the (r, z) half-plane (law of cosines: the nearest surface point is
// in the point's own meridian plane). So the distance to a point, and the clearance of a vertical
// cylinder beside an upright shape, are 2-D problems, solved here exactly (up to double rounding)
// with the MIBIT tree's meridian boxes pruning far segments. For a spline shape the same holds of
// its curve: each monotone part is solved to double rounding (the depth inside a rectangle is the
// least of four monotone functions of the curve's parameter; apart, the nearest feature is a side,
// at a part's end or strip boundary, or a corner, at a root of a degree-5 polynomial).

struct MeridianPoint {
  Point2 point;     // the closest point of the profile polyline
  double distance;  // from the query point
  std::uint32_t segment;
};
// The closest point of the profile polyline to `query` = (rho, z), rho >= 0, in double precision:
// the distance from any point at distance rho from the axis and height z to the surface. A
// non-finite query or rho < 0 gives a NaN distance.
[[nodiscard]] MeridianPoint closestMeridianPoint(const Shape& shape, Point2 query) noexcept;

// Whether the point at distance `query.r` >= 0 from the axis and height `query.z` lies inside the
// solid a closed shape bounds (Shape::closed()): the crossing number, in the meridian plane, of the
// half-line {(r, z) : r > query.r} with the profile (a spline's own curve, each Bezier piece split
// where z turns) closed along the axis. Points within rounding of the surface may land on either
// side; their distance to it is zero to that rounding anyway. The point x, y, z of object space is
// (hypot(x, y), z). An open shape, a non-finite query or query.r < 0 gives an unspecified answer.
[[nodiscard]] bool insideSolid(const Shape& shape, Point2 query) noexcept;

// A solid vertical cylinder with flat ends (a robot's body), upright beside an upright shape: its
// axis parallel to the shape's axis at distance `axisDistance`, radius `radius`, and heights
// [zMin, zMax] in the shape's z (after MeridianScale). radius = 0 with zMin = zMax is a point.
struct UprightCylinder {
  double axisDistance;  // >= 0
  double radius;        // >= 0
  double zMin, zMax;    // zMin <= zMax
};

// The shape as placed: its meridian mapped (r, z) -> (radial r, axial z) before distances are
// taken. An object scaled by (s, s, sz) and turned only about its axis has radial = s, axial = sz;
// turned upside down (180 degrees about a horizontal axis), axial = -sz.
struct MeridianScale {
  double radial = 1;  // > 0
  double axial = 1;   // non-zero
};

struct CylinderClearance {
  // The signed distance from the cylinder to the surface: min over surface points q of the
  // cylinder's signed distance function at q. Positive: the gap between the cylinder and the
  // surface (Euclidean, exact). Zero or negative: the surface touches or enters the cylinder, and
  // -clearance is the deepest a surface point lies inside it, measured to the cylinder's nearest
  // boundary (its side or an end). Only the surface counts: a cylinder wholly inside a closed shape
  // without touching it has a positive clearance, the distance to the shape's inner wall.
  double clearance;
  // The profile point (scaled meridian) realising it; in 3-D it lies in the half-plane from the
  // shape's axis towards the cylinder's axis (any half-plane when the axes coincide).
  Point2 point;
  std::uint32_t segment;
};
// Exact: in the meridian plane, the cylinder is the rectangle [d - radius, d + radius] x [zMin,
// zMax] (d = axisDistance; a surface point at radius r is nearest the cylinder's axis, at
// horizontal distance |r - d|, in that half-plane), and the clearance is the least signed distance
// from that rectangle to the scaled profile polyline. Segments are solved in closed form (a
// vertex-to-edge distance when apart, the deepest point of the clipped segment when inside).
// Preconditions as stated in the structs; a non-finite value or a violated one gives NaN.
[[nodiscard]] CylinderClearance cylinderClearance(const Shape& shape, const UprightCylinder& cylinder,
                                                  MeridianScale scale = {}) noexcept;

}  // namespace revolve
