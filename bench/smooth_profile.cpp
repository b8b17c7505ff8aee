#include "smooth_profile.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace revolve::bench {
namespace {

constexpr double kPi = std::numbers::pi;

Point2 operator+(Point2 a, Point2 b) { return {a.r + b.r, a.z + b.z}; }
Point2 operator-(Point2 a, Point2 b) { return {a.r - b.r, a.z - b.z}; }
Point2 operator*(double s, Point2 a) { return {s * a.r, s * a.z}; }
double dot(Point2 a, Point2 b) { return a.r * b.r + a.z * b.z; }
double norm(Point2 a) { return std::hypot(a.r, a.z); }

// How far round from `from` the angle `to` lies, going in the direction of `sweep`, in [0, 2 pi).
double angleAlong(double from, double to, double sweep) {
  const double delta = sweep >= 0.0 ? to - from : from - to;
  const double wrapped = std::fmod(delta, 2.0 * kPi);
  return wrapped < 0.0 ? wrapped + 2.0 * kPi : wrapped;
}

// Unit normal to the right of travel at the point of `piece` at polar angle phi (arcs) or anywhere (lines).
Point2 rightNormal(const ProfilePiece& piece, double phi) {
  if (piece.radius == 0.0) {
    const Point2 e = (1.0 / piece.length()) * (piece.end - piece.start);
    return {e.z, -e.r};
  }
  const Point2 radial{std::cos(phi), std::sin(phi)};
  return piece.turn > 0.0 ? radial : -1.0 * radial;  // turning left: the centre lies to the left
}

struct PieceClosest {
  Point2 point;
  double distance;
  int end;  // -1: interior; 0: the start; 1: the end
  double phi;
};

PieceClosest closestOnPiece(const ProfilePiece& piece, Point2 p) {
  if (piece.radius == 0.0) {
    const Point2 e = piece.end - piece.start;
    const double along = dot(p - piece.start, e) / dot(e, e);
    if (along <= 0.0) return {piece.start, norm(p - piece.start), 0, 0.0};
    if (along >= 1.0) return {piece.end, norm(p - piece.end), 1, 0.0};
    const Point2 q = piece.start + along * e;
    return {q, norm(p - q), -1, 0.0};
  }
  const Point2 offset = p - piece.centre;
  const double phi = std::atan2(offset.z, offset.r);
  if (angleAlong(piece.angle0, phi, piece.turn) <= std::abs(piece.turn)) {
    const double distanceToCentre = norm(offset);
    const Point2 q = piece.centre + piece.radius * Point2{std::cos(phi), std::sin(phi)};
    return {q, std::abs(distanceToCentre - piece.radius), -1, phi};
  }
  const double toStart = norm(p - piece.start), toEnd = norm(p - piece.end);
  return toStart <= toEnd ? PieceClosest{piece.start, toStart, 0, piece.angle0}
                          : PieceClosest{piece.end, toEnd, 1, piece.angle0 + piece.turn};
}

}  // namespace

double ProfilePiece::length() const { return radius == 0.0 ? norm(end - start) : radius * std::abs(turn); }

Point2 ProfilePiece::at(double fraction) const {
  if (radius == 0.0) return start + fraction * (end - start);
  const double phi = angle0 + fraction * turn;
  return centre + radius * Point2{std::cos(phi), std::sin(phi)};
}

SmoothProfile::SmoothProfile(std::string name, Point2 start, double headingDegrees)
    : name_(std::move(name)), cursor_(start), heading_(headingDegrees * kPi / 180.0) {}

SmoothProfile& SmoothProfile::line(double length) {
  ProfilePiece piece;
  piece.start = cursor_;
  piece.end = cursor_ + length * Point2{std::cos(heading_), std::sin(heading_)};
  pieces_.push_back(piece);
  cursor_ = piece.end;
  return *this;
}

SmoothProfile& SmoothProfile::arc(double radius, double turnDegrees) {
  const double turn = turnDegrees * kPi / 180.0;
  // The centre lies to the left of travel for a left (positive) turn, to the right otherwise.
  const double side = turn > 0.0 ? 1.0 : -1.0;
  const Point2 left{-std::sin(heading_), std::cos(heading_)};
  ProfilePiece piece;
  piece.start = cursor_;
  piece.radius = radius;
  piece.centre = cursor_ + (side * radius) * left;
  const Point2 fromCentre = cursor_ - piece.centre;
  piece.angle0 = std::atan2(fromCentre.z, fromCentre.r);
  piece.turn = turn;
  piece.end = piece.at(1.0);
  // An arc meant to end on the axis misses it by a rounding of cos(pi / 2): put it there.
  if (std::abs(piece.end.r) <= 4.0 * std::numeric_limits<double>::epsilon() * radius) piece.end.r = 0.0;
  pieces_.push_back(piece);
  cursor_ = piece.end;
  heading_ += turn;
  return *this;
}

SmoothProfile& SmoothProfile::corner(double turnDegrees) {
  heading_ += turnDegrees * kPi / 180.0;
  return *this;
}

SmoothProfile& SmoothProfile::lineToAxis() {
  const double cosine = std::cos(heading_);
  if (!(cosine < 0.0)) throw std::logic_error(name_ + ": lineToAxis needs a heading towards the axis");
  ProfilePiece piece;
  piece.start = cursor_;
  const double length = cursor_.r / -cosine;
  piece.end = {0.0, cursor_.z + length * std::sin(heading_)};
  pieces_.push_back(piece);
  cursor_ = piece.end;
  return *this;
}

bool SmoothProfile::closed() const {
  const Point2 a = pieces_.front().start, b = pieces_.back().end;
  return (a.r == 0.0 && b.r == 0.0) || norm(a - b) <= 1e-12 * size();
}

SmoothProfile::Extent SmoothProfile::extent() const {
  Extent extent{0.0, pieces_.front().start.z, pieces_.front().start.z};
  const auto include = [&](Point2 p) {
    extent.rMax = std::max(extent.rMax, p.r);
    extent.zLow = std::min(extent.zLow, p.z);
    extent.zHigh = std::max(extent.zHigh, p.z);
  };
  for (const ProfilePiece& piece : pieces_) {
    include(piece.start);
    include(piece.end);
    if (piece.radius == 0.0) continue;
    // An arc's extreme points in r and z, where it passes the polar angles 0, pi / 2 and -pi / 2.
    for (double phi : {0.0, kPi / 2, -kPi / 2}) {
      if (angleAlong(piece.angle0, phi, piece.turn) <= std::abs(piece.turn)) {
        include(piece.centre + piece.radius * Point2{std::cos(phi), std::sin(phi)});
      }
    }
  }
  return extent;
}

double SmoothProfile::size() const {
  const Extent e = extent();
  return std::max(2.0 * e.rMax, e.zHigh - e.zLow);
}

ClosestPoint SmoothProfile::closest(Point2 p) const {
  std::size_t best = 0;
  PieceClosest bestPoint{};
  bestPoint.distance = INFINITY;
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    const PieceClosest candidate = closestOnPiece(pieces_[i], p);
    if (candidate.distance < bestPoint.distance) best = i, bestPoint = candidate;
  }
  const ProfilePiece& piece = pieces_[best];
  Point2 normal = rightNormal(piece, bestPoint.phi);
  // At a join the sign comes from the pseudo-normal, the sum of the normals meeting there: in the
  // plane it classifies every point whose closest point is that vertex correctly, corner or not.
  Point2 signNormal = normal;
  if (bestPoint.end >= 0) {
    const bool loop = pieces_.front().start.r != 0.0 || pieces_.back().end.r != 0.0;
    const std::size_t count = pieces_.size();
    const bool atStart = bestPoint.end == 0;
    const bool hasNeighbour = loop || (atStart ? best > 0 : best + 1 < count);
    if (hasNeighbour) {
      const ProfilePiece& other = pieces_[atStart ? (best + count - 1) % count : (best + 1) % count];
      signNormal = signNormal + rightNormal(other, atStart ? other.angle0 + other.turn : other.angle0);
    } else {
      signNormal = signNormal + Point2{-1.0, 0.0};  // an end on the axis: the solid continues along it
    }
  }
  const double side = dot(p - bestPoint.point, signNormal);
  return {bestPoint.point, normal, bestPoint.distance, side < 0.0 ? -bestPoint.distance : bestPoint.distance};
}

std::vector<int> SmoothProfile::arcSegments(int points) const {
  std::vector<std::size_t> arcs;
  int budget = points - 1;
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    if (pieces_[i].radius > 0.0)
      arcs.push_back(i);
    else
      budget -= 1;
  }
  if (budget < int(arcs.size())) {
    throw std::invalid_argument(name_ + ": " + std::to_string(points) + " points cannot sample " +
                                std::to_string(pieces_.size()) + " pieces (one segment each at least)");
  }
  // Segments an arc needs so that each chord's sagitta R (1 - cos(theta / 2m)) is at most `sagitta`.
  const auto needed = [&](std::size_t i, double sagitta) {
    const ProfilePiece& piece = pieces_[i];
    const double half = std::acos(std::max(-1.0, 1.0 - sagitta / piece.radius));
    return std::max(1, int(std::ceil(std::abs(piece.turn) / (2.0 * half) - 1e-9)));
  };
  double low = 0.0, high = size();  // bisect the common sagitta that fits the budget
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double middle = 0.5 * (low + high);
    int total = 0;
    for (std::size_t i : arcs) total += needed(i, middle);
    (total <= budget ? high : low) = middle;
  }
  std::vector<int> segments(pieces_.size(), 1);
  int used = 0;
  for (std::size_t i : arcs) used += segments[i] = needed(i, high);
  // Spend what is left on the arcs whose chords are currently worst.
  const auto sagittaOf = [&](std::size_t i) {
    return pieces_[i].radius * (1.0 - std::cos(std::abs(pieces_[i].turn) / (2.0 * segments[i])));
  };
  for (; used < budget; ++used) {
    std::size_t worst = arcs.front();
    for (std::size_t i : arcs)
      if (sagittaOf(i) > sagittaOf(worst)) worst = i;
    ++segments[worst];
  }
  return segments;
}

std::vector<int> SmoothProfile::uniformSegments(int points) const {
  const int budget = points - 1;
  if (budget < int(pieces_.size())) {
    throw std::invalid_argument(name_ + ": " + std::to_string(points) + " points cannot sample " +
                                std::to_string(pieces_.size()) + " pieces (one segment each at least)");
  }
  double total = 0.0;
  for (const ProfilePiece& piece : pieces_) total += piece.length();
  // Largest remainders: each piece its share of the budget by length, at least one segment.
  std::vector<int> segments(pieces_.size());
  std::vector<std::pair<double, std::size_t>> remainders;
  int used = 0;
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    const double share = budget * pieces_[i].length() / total;
    segments[i] = std::max(1, int(std::floor(share)));
    used += segments[i];
    remainders.push_back({share - std::floor(share), i});
  }
  std::sort(remainders.begin(), remainders.end(), std::greater<>());
  for (std::size_t k = 0; used < budget; k = (k + 1) % remainders.size(), ++used) ++segments[remainders[k].second];
  return segments;
}

std::vector<Point2> SmoothProfile::sampleUniform(int points) const { return polylineOf(uniformSegments(points)); }

double SmoothProfile::uniformError(int points) const {
  const std::vector<int> segments = uniformSegments(points);
  double worst = 0.0;
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    const ProfilePiece& piece = pieces_[i];
    if (piece.radius > 0.0)
      worst = std::max(worst, piece.radius * (1.0 - std::cos(std::abs(piece.turn) / (2.0 * segments[i]))));
  }
  return worst;
}

std::vector<Point2> SmoothProfile::sample(int points) const { return polylineOf(arcSegments(points)); }

std::vector<Point2> SmoothProfile::polylineOf(const std::vector<int>& segments) const {
  std::vector<Point2> polyline{pieces_.front().start};
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    for (int j = 1; j <= segments[i]; ++j) polyline.push_back(pieces_[i].at(double(j) / segments[i]));
    polyline.back() = pieces_[i].end;  // joins exactly where the pieces meet
  }
  // On the axis exactly, and a closed loop's last point exactly its first.
  if (pieces_.front().start.r == 0.0) polyline.front().r = 0.0;
  if (pieces_.back().end.r == 0.0) polyline.back().r = 0.0;
  if (closed() && pieces_.front().start.r != 0.0) polyline.back() = polyline.front();
  return polyline;
}

double SmoothProfile::sampleError(int points) const {
  const std::vector<int> segments = arcSegments(points);
  double worst = 0.0;
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    const ProfilePiece& piece = pieces_[i];
    if (piece.radius > 0.0)
      worst = std::max(worst, piece.radius * (1.0 - std::cos(std::abs(piece.turn) / (2.0 * segments[i]))));
  }
  return worst;
}

}  // namespace revolve::bench
