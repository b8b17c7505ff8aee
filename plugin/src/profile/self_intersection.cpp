// Shamos–Hoey sweep for self-intersections of a polyline, with exact handling of degeneracies.
//
// Sweep order: events are the segment endpoints sorted lexicographically by (r, then z). The sweep
// line is vertical (constant r) and passes each line r = const from low z to high z, as if tilted
// infinitesimally; a segment's "left" endpoint is its lexicographically smaller one, so a vertical
// segment (constant r) starts at its lower end.
//
// Status: the segments crossing the sweep line, ordered bottom to top in a std::set whose
// comparator asks orient2d where the later-starting segment's left endpoint lies relative to the
// other segment (both segments starting there: which direction turns counter-clockwise first).
//
// At each event point v, in this order:
//   1. vertex check: every segment with an endpoint at v must meet there at one and the same
//      polyline vertex (the closing point of a closed loop counts as vertex 0). At most two
//      segments share a vertex, so three segments at v, or two that are not neighbours there
//      (e.g. a figure-eight through a repeated point), are reported without geometry;
//   2. segments ending at v leave the status; their former neighbours, now adjacent, are tested;
//   3. a segment still in the status whose line passes through v contains v in its interior
//      (T-junction or crossing at v); the status is ordered, so one lower_bound finds it;
//   4. segments starting at v enter the status; each is tested against its new neighbours.
// Every pair that ever becomes adjacent in the status is tested exactly over its whole length, so
// the classic argument applies to the lexicographically first forbidden contact q: if q is an
// endpoint, steps 1 and 3 (or the test of two segments starting at q) catch it; if q is interior
// to both segments, the segments between them just before q all pass through q too, so some
// adjacent pair meets there and was tested when it became adjacent. A collinear overlap begins at
// an endpoint of one segment lying on the other, or where both start together. Until then no
// forbidden contact lies behind the sweep, which keeps the comparator a strict weak order.
// Every report is an exact pair test's verdict, or (step 1) exact by construction.
#include "self_intersection.h"

#include "profile/points.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include "exact_predicates.h"

namespace revolve::detail {
namespace {

// The sweep order: by r, then by z.
bool sweepsBefore(Point2 a, Point2 b) { return a.r < b.r || (a.r == b.r && a.z < b.z); }

// For p collinear with a and b: whether p lies on the closed segment ab. Along a line the sweep
// order is monotone, so being between the endpoints in that order is being between them.
bool liesBetween(Point2 p, Point2 a, Point2 b) {
  const auto [low, high] = sweepsBefore(b, a) ? std::pair{b, a} : std::pair{a, b};
  return !sweepsBefore(p, low) && !sweepsBefore(high, p);
}

// Whether closed segments ab and cd share at least one point.
bool segmentsShareAPoint(Point2 a, Point2 b, Point2 c, Point2 d) {
  const int cSide = orient2d(a, b, c);
  const int dSide = orient2d(a, b, d);
  const int aSide = orient2d(c, d, a);
  const int bSide = orient2d(c, d, b);
  if (cSide * dSide < 0 && aSide * bSide < 0) return true;  // proper crossing
  return (cSide == 0 && liesBetween(c, a, b)) || (dSide == 0 && liesBetween(d, a, b)) ||
         (aSide == 0 && liesBetween(a, c, d)) || (bSide == 0 && liesBetween(b, c, d));
}

// Segments (p, vertex) and (vertex, q) share a point besides `vertex` exactly when they are
// collinear and p and q lie on the same side of the vertex: the polyline folds back onto itself.
bool foldsBack(Point2 p, Point2 vertex, Point2 q) {
  return orient2d(p, vertex, q) == 0 && sweepsBefore(p, vertex) == sweepsBefore(q, vertex);
}

// The polyline, seen as segments; segment i joins points i and i + 1.
class Polyline {
 public:
  explicit Polyline(std::span<const Point2> points)
      : points_(points), closed_(samePoint(points.front(), points.back())) {}

  std::size_t segmentCount() const { return points_.size() - 1; }
  Point2 point(std::size_t index) const { return points_[index]; }

  // The endpoint where the sweep meets the segment first, and the one where it leaves it.
  std::size_t leftPointIndex(std::size_t segment) const {
    return sweepsBefore(points_[segment + 1], points_[segment]) ? segment + 1 : segment;
  }
  Point2 leftEnd(std::size_t segment) const { return points_[leftPointIndex(segment)]; }
  Point2 rightEnd(std::size_t segment) const {  // the other one of points segment, segment + 1
    return points_[2 * segment + 1 - leftPointIndex(segment)];
  }

  // Which polyline vertex a point index stands for: a closed loop's last point is its first.
  std::size_t vertexOf(std::size_t pointIndex) const {
    return closed_ && pointIndex == points_.size() - 1 ? 0 : pointIndex;
  }

  // Whether segments `first` < `second` share a point they must not share.
  bool forbiddenContact(std::size_t first, std::size_t second) const {
    assert(first < second);
    if (second == first + 1) {
      return foldsBack(points_[first], points_[second], points_[second + 1]);
    }
    if (closed_ && first == 0 && second == segmentCount() - 1) {
      return foldsBack(points_[1], points_[0], points_[points_.size() - 2]);
    }
    return segmentsShareAPoint(points_[first], points_[first + 1], points_[second], points_[second + 1]);
  }

 private:
  std::span<const Point2> points_;
  bool closed_;
};

SegmentPair orderedPair(std::size_t a, std::size_t b) { return a < b ? SegmentPair{a, b} : SegmentPair{b, a}; }

// An event: one endpoint of one segment, encoded as 2 * segment + (0 for point `segment`, 1 for
// point `segment + 1`), so the point index is segment + low bit.
using Event = std::uint64_t;
std::size_t segmentOf(Event event) { return static_cast<std::size_t>(event >> 1); }
std::size_t pointIndexOf(Event event) { return segmentOf(event) + (event & 1); }

// Bottom-to-top order of the segments crossing the sweep line just after the current event point.
// Valid among segments with no forbidden contact before that point, which the sweep guarantees;
// transparent so that a point can be located among the segments (lower_bound).
class StatusOrder {
 public:
  using is_transparent = void;

  explicit StatusOrder(const Polyline& polyline) : polyline_(&polyline) {}

  bool operator()(std::size_t lower, std::size_t upper) const {
    const Point2 lowerLeft = polyline_->leftEnd(lower);
    const Point2 upperLeft = polyline_->leftEnd(upper);
    if (samePoint(lowerLeft, upperLeft)) {
      // Both start here: the lower one is the one the other turns counter-clockwise from.
      return orient2d(lowerLeft, polyline_->rightEnd(lower), polyline_->rightEnd(upper)) > 0;
    }
    // Compare where the later of the two starts; both exist there.
    if (sweepsBefore(lowerLeft, upperLeft)) return !passesAboveStartOf(lower, upper);
    return passesAboveStartOf(upper, lower);
  }

  // Whether the segment passes strictly below the point.
  bool operator()(std::size_t segment, Point2 point) const { return sideOf(segment, point) > 0; }
  // Whether the point lies strictly below the segment.
  bool operator()(Point2 point, std::size_t segment) const { return sideOf(segment, point) < 0; }

  // +1 when the point lies above the segment's line, -1 below, 0 on it.
  int sideOf(std::size_t segment, Point2 point) const {
    return orient2d(polyline_->leftEnd(segment), polyline_->rightEnd(segment), point);
  }

 private:
  // Whether `earlier` passes above the left endpoint of `later`, which starts after it. A start
  // exactly on `earlier` is a forbidden contact the sweep reports before inserting `later`; the
  // direction of `later` then merely keeps the answer consistent.
  bool passesAboveStartOf(std::size_t earlier, std::size_t later) const {
    if (const int side = sideOf(earlier, polyline_->leftEnd(later)); side != 0) return side < 0;
    return sideOf(earlier, polyline_->rightEnd(later)) < 0;
  }

  const Polyline* polyline_;
};

class SelfIntersectionSweep {
 public:
  explicit SelfIntersectionSweep(std::span<const Point2> points)
      : polyline_(points), status_(StatusOrder(polyline_)), positions_(polyline_.segmentCount()) {}
  // The status order points into polyline_.
  SelfIntersectionSweep(const SelfIntersectionSweep&) = delete;
  SelfIntersectionSweep& operator=(const SelfIntersectionSweep&) = delete;

  std::optional<SegmentPair> run() {
    const std::vector<Event> events = sortedEvents();
    for (std::size_t begin = 0; begin < events.size();) {
      const Point2 here = pointOf(events[begin]);
      std::size_t end = begin + 1;
      while (end < events.size() && samePoint(pointOf(events[end]), here)) ++end;
      const std::span<const Event> group(events.data() + begin, end - begin);
      if (auto contact = processEventPoint(here, group)) return contact;
      begin = end;
    }
    return std::nullopt;
  }

 private:
  using Status = std::set<std::size_t, StatusOrder>;

  Point2 pointOf(Event event) const { return polyline_.point(pointIndexOf(event)); }
  bool startsAt(Event event) const { return polyline_.leftPointIndex(segmentOf(event)) == pointIndexOf(event); }

  // All segment endpoints in sweep order (ties by encoding, for a deterministic result).
  std::vector<Event> sortedEvents() const {
    std::vector<Event> events(2 * polyline_.segmentCount());
    for (std::size_t i = 0; i < events.size(); ++i) events[i] = i;
    std::sort(events.begin(), events.end(), [this](Event x, Event y) {
      const Point2 p = pointOf(x);
      const Point2 q = pointOf(y);
      if (sweepsBefore(p, q)) return true;
      if (sweepsBefore(q, p)) return false;
      return x < y;
    });
    return events;
  }

  std::optional<SegmentPair> processEventPoint(Point2 here, std::span<const Event> group) {
    if (auto contact = checkSharedVertex(group)) return contact;
    for (const Event event : group) {
      if (startsAt(event)) continue;
      if (auto contact = remove(segmentOf(event))) return contact;
    }
    if (auto contact = checkPassingThrough(here, segmentOf(group.front()))) return contact;
    for (const Event event : group) {
      if (!startsAt(event)) continue;
      if (auto contact = insert(segmentOf(event))) return contact;
    }
    return std::nullopt;
  }

  // Step 1: the segments meeting at this point must all meet at one polyline vertex.
  std::optional<SegmentPair> checkSharedVertex(std::span<const Event> group) const {
    const std::size_t vertex = polyline_.vertexOf(pointIndexOf(group.front()));
    for (const Event event : group.subspan(1)) {
      if (polyline_.vertexOf(pointIndexOf(event)) != vertex) {
        return orderedPair(segmentOf(group.front()), segmentOf(event));
      }
    }
    return std::nullopt;
  }

  // Step 2.
  std::optional<SegmentPair> remove(std::size_t segment) {
    const Status::iterator position = positions_[segment];
    std::optional<SegmentPair> contact;
    if (position != status_.begin() && std::next(position) != status_.end()) {
      contact = testPair(*std::prev(position), *std::next(position));
    }
    status_.erase(position);
    return contact;
  }

  // Step 3: `incident` is any segment with an endpoint here; it touches the passing segment.
  std::optional<SegmentPair> checkPassingThrough(Point2 here, std::size_t incident) const {
    const auto firstNotBelow = status_.lower_bound(here);
    if (firstNotBelow == status_.end() || status_.key_comp().sideOf(*firstNotBelow, here) != 0) {
      return std::nullopt;
    }
    return orderedPair(*firstNotBelow, incident);
  }

  // Step 4.
  std::optional<SegmentPair> insert(std::size_t segment) {
    const auto [position, inserted] = status_.insert(segment);
    if (!inserted) {
      // Equivalent only when both start here in the same direction: they overlap.
      assert(testPair(segment, *position));
      return orderedPair(segment, *position);
    }
    positions_[segment] = position;
    if (position != status_.begin()) {
      if (auto contact = testPair(*std::prev(position), segment)) return contact;
    }
    if (std::next(position) != status_.end()) {
      if (auto contact = testPair(segment, *std::next(position))) return contact;
    }
    return std::nullopt;
  }

  std::optional<SegmentPair> testPair(std::size_t a, std::size_t b) const {
    const SegmentPair pair = orderedPair(a, b);
    if (polyline_.forbiddenContact(pair.first, pair.second)) return pair;
    return std::nullopt;
  }

  Polyline polyline_;
  Status status_;
  std::vector<Status::iterator> positions_;  // where each segment sits while in the status
};

// The documented precondition; violating it (NaN above all) would break the sort and set orders.
[[maybe_unused]] bool meetsPrecondition(std::span<const Point2> points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i].r) || !std::isfinite(points[i].z)) return false;
    if (i > 0 && samePoint(points[i - 1], points[i])) return false;
  }
  return true;
}

// Whether the polyline is monotone along one axis (never turning back along it) and never runs
// across that axis twice in a row: such a polyline is simple, decided with comparisons alone. Two
// segments i < j - 1 span ranges of the axis that meet only if every segment between them runs
// across it at one height h, i.e. j = i + 2 with segment i + 1 the single run; then segments i and
// j cross h only at their ends p[i + 1] and p[i + 2], which differ. Neighbours share their vertex
// and lie on opposite sides of it along the axis (or one runs across it), so they cannot fold back;
// the ends cannot meet (that needs the whole polyline at one height). Most profiles (a vase, a
// bottle: z up from the base) take this path and skip the sweep's sort, tree and predicates.
bool monotoneWithSingleRuns(std::span<const Point2> points, double Point2::*axis) {
  const double first = points.front().*axis, last = points.back().*axis;
  if (first == last) return false;
  const bool ascending = first < last;
  bool previousRun = false;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double from = points[i - 1].*axis, to = points[i].*axis;
    if (ascending ? to < from : to > from) return false;
    const bool run = to == from;
    if (run && previousRun) return false;
    previousRun = run;
  }
  return true;
}

}  // namespace

std::optional<SegmentPair> findSelfIntersection(std::span<const Point2> points) {
  assert(meetsPrecondition(points));
  if (points.size() < 3) return std::nullopt;  // at most one segment
  if (monotoneWithSingleRuns(points, &Point2::z) || monotoneWithSingleRuns(points, &Point2::r)) return std::nullopt;
  return SelfIntersectionSweep(points).run();
}

}  // namespace revolve::detail
