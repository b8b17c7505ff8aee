// Spline validation: every rule checked once, here, with a message naming the point (or piece), its
// value and the rule, as Profile does for polylines.
#include <revolve/core.h>

#include "curve/cubic.h"
#include "curve/curve_self_intersection.h"
#include "curve/monotone_parts.h"
#include "curve/spline_pieces.h"
#include "profile/points.h"
#include "util/format.h"

#include <algorithm>
#include <cmath>

namespace revolve {
namespace {

using detail::formatNumber;

struct KindName {
  SplineKind kind;
  const char* name;
};
constexpr KindName kKindNames[] = {{SplineKind::linear, "linear"},
                                   {SplineKind::quadratic, "quadratic"},
                                   {SplineKind::bezier, "bezier"},
                                   {SplineKind::catmullRom, "catmull-rom"},
                                   {SplineKind::natural, "natural"}};

std::string describePoint(std::size_t index, Point2 p) { return detail::describePoint("spline", index, p); }

// Whether the curve passes through point i (Bezier control points off the curve may have r < 0).
bool onCurve(SplineKind kind, std::size_t i) {
  switch (kind) {
    case SplineKind::quadratic:
      return i % 2 == 0;
    case SplineKind::bezier:
      return i % 3 == 0;
    default:
      return true;
  }
}

// The points a piece advances by in points() (a linear spline keeps its own table: repeats dropped).
std::size_t pointsPerPiece(SplineKind kind) {
  return kind == SplineKind::bezier ? 3 : kind == SplineKind::quadratic ? 2 : 1;
}

void checkCount(SplineKind kind, std::size_t n) {
  const std::string name = splineKindName(kind);
  const std::size_t last = n == 0 ? 0 : n - 1;
  if (n > Spline::kMaxPoints) {
    throw ProfileError(ProfileError::Rule::tooManyPoints, Spline::kMaxPoints,
                       name + " spline has " + std::to_string(n) + " points; at most " +
                           std::to_string(Spline::kMaxPoints) +
                           " are supported (32-bit tree node indices over its monotone parts)");
  }
  switch (kind) {
    case SplineKind::quadratic:
      if (n < 3 || n % 2 == 0) {
        throw ProfileError(ProfileError::Rule::badPointCount, last,
                           "quadratic spline has " + std::to_string(n) +
                               " points; quadratic Bezier pieces sharing their ends need 2n + 1 (3, 5, 7, ...)");
      }
      return;
    case SplineKind::bezier:
      if (n < 4 || n % 3 != 1) {
        throw ProfileError(ProfileError::Rule::badPointCount, last,
                           "bezier spline has " + std::to_string(n) +
                               " points; cubic Bezier pieces sharing their ends need 3n + 1 (4, 7, 10, ...)");
      }
      return;
    default:
      if (n < 2) {
        throw ProfileError(ProfileError::Rule::tooFewPoints, last,
                           name + " spline has " + std::to_string(n) + " point(s); at least 2 are needed");
      }
  }
}

void checkPoint(SplineKind kind, std::size_t index, Point2 p) {
  detail::checkFinite("spline", index, p);
  detail::checkWithinRange("spline", index, p);
  if (p.r < 0.0 && onCurve(kind, index)) {
    throw ProfileError(ProfileError::Rule::negativeRadius, index,
                       describePoint(index, p) +
                           ": r must be >= 0 at a point the curve passes through (r is the distance from the z axis)");
  }
}

}  // namespace

const char* splineKindName(SplineKind kind) noexcept {
  for (const KindName& k : kKindNames) {
    if (k.kind == kind) return k.name;
  }
  return "unknown";
}

std::optional<SplineKind> splineKindNamed(std::string_view name) noexcept {
  for (const KindName& k : kKindNames) {
    if (name == k.name) return k.kind;
  }
  return std::nullopt;
}

Spline::Spline(SplineKind kind, std::span<const Point2> input) : kind_(kind) {
  checkCount(kind, input.size());
  if (kind == SplineKind::linear) {
    const Profile polyline(input);  // the polyline rules, and its dropped repeats
    points_.assign(polyline.points().begin(), polyline.points().end());
    warnings_ = polyline.warnings();
    bezier_ = detail::bezierOfPolyline(points_);
    for (std::size_t i = 0; i + 1 < points_.size(); ++i) linearPieceStart_.push_back(polyline.sourceIndex()[i]);
    closed_ = polyline.closed();
    return;
  }
  for (std::size_t i = 0; i < input.size(); ++i) checkPoint(kind, i, input[i]);
  points_.assign(input.begin(), input.end());
  double extent = 0.0;
  for (const Point2& p : points_) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  detail::checkExtent("spline", 0, extent);

  const bool interpolating = kind == SplineKind::catmullRom || kind == SplineKind::natural;
  if (interpolating) {
    for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
      if (points_[i].r == points_[i + 1].r && points_[i].z == points_[i + 1].z) {
        throw ProfileError(ProfileError::Rule::segmentTooShort, i + 1,
                           describePoint(i + 1, points_[i + 1]) + " repeats point " + std::to_string(i) + "; a " +
                               splineKindName(kind) +
                               " spline is parametrised by its chords, which must have a length");
      }
    }
  }
  const std::size_t step = pointsPerPiece(kind);
  switch (kind) {
    case SplineKind::quadratic:
      bezier_ = detail::bezierOfQuadratic(points_);
      break;
    case SplineKind::bezier:  // its points are its control points: bezier() gives them, no copy kept
      break;
    case SplineKind::catmullRom:
      bezier_ = detail::bezierOfCatmullRom(points_);
      break;
    case SplineKind::natural:
      bezier_ = detail::bezierOfNatural(points_);
      break;
    case SplineKind::linear:
      break;
  }
  const std::size_t pieces = pieceCount();
  const auto describePiece = [&](std::size_t piece) {
    const std::size_t first = pieceStart(piece), last = first + step;
    return "the piece from " + describePoint(first, points_[first]) + " to " + describePoint(last, points_[last]);
  };

  // Every piece: finite (the interpolating kinds' controls come from solving a system), inside the
  // coordinate range, long enough, and never below r = 0.
  const double shortest = extent * Profile::kMinSegmentFraction;
  for (std::size_t i = 0; i < pieces; ++i) {
    const Point2* c = &bezier()[3 * i];
    double reach = 0.0;  // how far the control hull reaches from the first point
    for (int k = 0; k < 4; ++k) {
      if (!(std::abs(c[k].r) <= Profile::kMaxCoordinate && std::abs(c[k].z) <= Profile::kMaxCoordinate)) {
        throw ProfileError(ProfileError::Rule::outOfRange, pieceStart(i),
                           describePiece(i) + " has a control point (r = " + formatNumber(c[k].r) +
                               ", z = " + formatNumber(c[k].z) + ") beyond +-2^60");
      }
      reach = std::max(reach, std::hypot(c[k].r - c[0].r, c[k].z - c[0].z));
    }
    if (reach < shortest) {
      throw ProfileError(ProfileError::Rule::segmentTooShort, pieceStart(i),
                         describePiece(i) + " is " + formatNumber(reach) + " long at most, below 2^-60 of the extent " +
                             formatNumber(extent) + ", which the kernel cannot resolve");
    }
    const double r[4] = {c[0].r, c[1].r, c[2].r, c[3].r};
    // A piece whose control values of r are all zero lies on the axis all along (r never turns
    // there, so the test below would not see it): a surface of no area between its points.
    if (r[0] == 0.0 && r[1] == 0.0 && r[2] == 0.0 && r[3] == 0.0) {
      throw ProfileError(ProfileError::Rule::crossesAxis, pieceStart(i),
                         describePiece(i) +
                             " lies on the axis (r = 0 all along); the curve must keep r > 0 between the points it "
                             "passes through (it may reach the axis only at such a point)");
    }
    double turns[2];
    for (int k = 0, count = detail::derivativeSignChanges(r, turns); k < count; ++k) {
      // Between the points it passes through the curve must stay off the axis: r = 0 at a turn of r
      // inside a piece is a touch, which the rule refuses as it refuses a crossing. r(u) is known
      // within de Casteljau's rounding (kCubicAtError max |r_i|): a minimum no farther from the
      // axis than that cannot be told from a touch.
      const double radius = detail::cubicAt(r, turns[k]);
      const double rounding =
          detail::kCubicAtError * std::max({std::abs(r[0]), std::abs(r[1]), std::abs(r[2]), std::abs(r[3])});
      if (radius <= rounding) {
        throw ProfileError(
            ProfileError::Rule::crossesAxis, pieceStart(i),
            describePiece(i) + (radius < 0.0 ? " crosses the axis: r = " : " touches the axis: r = ") +
                formatNumber(radius) + (radius < 0.0 ? "" : " (zero within rounding)") +
                " at u = " + formatNumber(turns[k]) +
                "; the curve must keep r > 0 between the points it passes through (it may reach the axis "
                "only at such a point)");
      }
    }
  }

  const std::vector<detail::MonotonePart> parts = detail::monotoneParts(bezier(), extent);
  if (parts.size() > 0xfffffff0u) {
    throw ProfileError(ProfileError::Rule::tooManyPoints, points_.size() - 1,
                       "spline has too many monotone parts for 32-bit tree indices");
  }
  if (const auto pair = detail::findCurveSelfIntersection(parts, extent)) {
    const std::size_t a = parts[pair->first].piece, b = parts[pair->second].piece;
    const std::string where = a == b ? describePiece(a) + " crosses or touches itself"
                                     : describePiece(a) + " and " + describePiece(b) + " cross or touch";
    throw ProfileError(ProfileError::Rule::selfIntersecting, pieceStart(a),
                       where +
                           " (or come within 2^-40 of the extent, run that close for long, or fold back in a cusp); a "
                           "profile must not cross or touch itself");
  }

  const Point2 first = bezier().front(), last = bezier().back();
  closed_ = (first.r == last.r && first.z == last.z) || (first.r == 0.0 && last.r == 0.0);
}

std::size_t Spline::pieceStart(std::size_t piece) const noexcept {
  return kind_ == SplineKind::linear ? linearPieceStart_[piece] : piece * pointsPerPiece(kind_);
}

std::size_t Spline::memoryBytes() const noexcept {
  std::size_t bytes = points_.capacity() * sizeof(Point2) + bezier_.capacity() * sizeof(Point2) +
                      linearPieceStart_.capacity() * sizeof(std::size_t) +
                      warnings_.capacity() * sizeof(ProfileWarning);
  for (const ProfileWarning& warning : warnings_) {
    if (warning.message.capacity() > std::string().capacity()) bytes += warning.message.capacity() + 1;
  }
  return bytes;
}

Point2 Spline::at(std::size_t piece, double u) const noexcept {
  const Point2* c = &bezier()[3 * piece];
  const double r[4] = {c[0].r, c[1].r, c[2].r, c[3].r}, z[4] = {c[0].z, c[1].z, c[2].z, c[3].z};
  return {detail::cubicAt(r, u), detail::cubicAt(z, u)};
}

}  // namespace revolve
