#include "round_curve.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace revolve::bench {
namespace {

constexpr double kPi = std::numbers::pi;

// A piece the curve sweeps: a line, or an arc from angle a0 turning by `turn` that rises or falls
// all along (cut at its highest and lowest points).
struct SweptPiece {
  Point2 start, end;
  double radius = 0.0;  // 0 for a line
  Point2 centre{};
  double a0 = 0.0, turn = 0.0;
  int segments = 1;
  double error() const { return radius * std::pow(std::abs(turn) / segments, 6); }  // ~ the Bézier's
};

std::string text(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

// The polar angles (about the centre) strictly inside the arc's sweep where its tangent is
// horizontal: the circle's top and bottom, +-pi / 2.
std::vector<double> extremaInside(const ProfilePiece& arc) {
  std::vector<double> cuts;
  for (double target : {kPi / 2, -kPi / 2}) {
    // The first angle a0 + s turn (0 < s < 1) equal to target modulo 2 pi.
    double along = arc.turn > 0 ? target - arc.angle0 : arc.angle0 - target;  // how far, in the turn's sense
    along = std::fmod(along, 2 * kPi);
    if (along < 0) along += 2 * kPi;
    for (; along < std::abs(arc.turn); along += 2 * kPi) {
      if (along > 0) cuts.push_back(along);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  return cuts;  // distances along the turn, in radians
}

void appendControl(std::vector<float>& points, Point2 p) {
  points.insert(points.end(), {0.0f, 0.0f, float(p.z), float(p.r)});
}

}  // namespace

std::variant<RoundCurveFit, std::string> fitRoundCurve(const SmoothProfile& profile, int segments) {
  const std::vector<ProfilePiece>& pieces = profile.pieces();
  RoundCurveFit fit;
  std::vector<SweptPiece> swept;
  std::vector<bool> joinsPrevious;  // the piece starts where the previous swept piece ended
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const ProfilePiece& piece = pieces[i];
    if (piece.radius == 0.0) {
      if (float(piece.start.z) == float(piece.end.z)) {  // flat in the floats Embree stores
        const bool disc = (i == 0 && piece.start.r == 0.0) || (i + 1 == pieces.size() && piece.end.r == 0.0);
        if (!disc) {
          return "its flat ring at z = " + text(piece.start.z) + " (r from " + text(piece.start.r) + " to " +
                 text(piece.end.r) + "): a round curve cannot sweep a horizontal piece (z'(u) = 0 leaves its circle " +
                 "undefined), and Embree's discs are whole";
        }
        fit.discs.push_back(
            {piece.start.z, std::max(piece.start.r, piece.end.r), piece.end.r > piece.start.r ? -1.0 : 1.0});
        continue;
      }
      SweptPiece line;
      line.start = piece.start;
      line.end = piece.end;
      joinsPrevious.push_back(!swept.empty());
      swept.push_back(line);
      continue;
    }
    double from = 0.0;
    std::vector<double> cuts = extremaInside(piece);
    cuts.push_back(std::abs(piece.turn));
    for (double to : cuts) {
      SweptPiece arc;
      arc.radius = piece.radius;
      arc.centre = piece.centre;
      const double sense = piece.turn > 0 ? 1.0 : -1.0;
      arc.a0 = piece.angle0 + sense * from;
      arc.turn = sense * (to - from);
      arc.start = from == 0.0 ? piece.start
                              : Point2{piece.centre.r + piece.radius * std::cos(arc.a0),
                                       piece.centre.z + piece.radius * std::sin(arc.a0)};
      arc.end = to == std::abs(piece.turn) ? piece.end
                                           : Point2{piece.centre.r + piece.radius * std::cos(arc.a0 + arc.turn),
                                                    piece.centre.z + piece.radius * std::sin(arc.a0 + arc.turn)};
      joinsPrevious.push_back(!swept.empty());
      swept.push_back(arc);
      from = to;
    }
  }
  if (segments < int(swept.size())) {
    return std::to_string(segments) + " segments cannot fit its " + std::to_string(swept.size()) +
           " rising or falling pieces (one Bézier segment each at least)";
  }
  // Lines are exact with one segment; the rest go to the arc whose Béziers are worst.
  for (int used = int(swept.size()); used < segments; ++used) {
    SweptPiece* worst = nullptr;
    for (SweptPiece& piece : swept) {
      if (piece.radius > 0.0 && (worst == nullptr || piece.error() > worst->error())) worst = &piece;
    }
    if (worst == nullptr) break;  // only lines: more segments would add nothing
    ++worst->segments;
  }

  for (std::size_t i = 0; i < swept.size(); ++i) {
    const SweptPiece& piece = swept[i];
    // Consecutive pieces share their joining control point.
    if (!joinsPrevious[i]) appendControl(fit.controlPoints, piece.start);
    for (int j = 0; j < piece.segments; ++j) {
      fit.firstControl.push_back(std::uint32_t(fit.controlPoints.size() / 4 - 1));
      if (piece.radius == 0.0) {
        const Point2 d{piece.end.r - piece.start.r, piece.end.z - piece.start.z};
        appendControl(fit.controlPoints, {piece.start.r + d.r / 3, piece.start.z + d.z / 3});
        appendControl(fit.controlPoints, {piece.start.r + 2 * d.r / 3, piece.start.z + 2 * d.z / 3});
        appendControl(fit.controlPoints, piece.end);
        continue;
      }
      const double step = piece.turn / piece.segments;
      const double a = piece.a0 + j * step, b = a + step;
      const double handle = 4.0 / 3.0 * std::tan(std::abs(step) / 4) * piece.radius;
      const double sense = step > 0 ? 1.0 : -1.0;  // tangent of travel: sense (-sin, cos)
      const Point2 p0{piece.centre.r + piece.radius * std::cos(a), piece.centre.z + piece.radius * std::sin(a)};
      const Point2 p3 = j + 1 == piece.segments ? piece.end
                                                : Point2{piece.centre.r + piece.radius * std::cos(b),
                                                         piece.centre.z + piece.radius * std::sin(b)};
      appendControl(fit.controlPoints, {p0.r - handle * sense * std::sin(a), p0.z + handle * sense * std::cos(a)});
      appendControl(fit.controlPoints, {p3.r + handle * sense * std::sin(b), p3.z - handle * sense * std::cos(b)});
      appendControl(fit.controlPoints, p3);
    }
  }
  return fit;
}

void attachRoundCurve(RTCDevice device, RTCScene scene, const RoundCurveFit& fit) {
  RTCGeometry curve = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE);
  if (curve == nullptr) throw std::runtime_error("rtcNewGeometry(RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE) failed");
  auto* points = static_cast<float*>(rtcSetNewGeometryBuffer(curve, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                             4 * sizeof(float), fit.controlPoints.size() / 4));
  auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(curve, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT,
                                                                      sizeof(std::uint32_t), fit.firstControl.size()));
  if (points == nullptr || indices == nullptr) {
    rtcReleaseGeometry(curve);
    throw std::runtime_error("allocating a round curve failed");
  }
  std::copy(fit.controlPoints.begin(), fit.controlPoints.end(), points);
  std::copy(fit.firstControl.begin(), fit.firstControl.end(), indices);
  rtcCommitGeometry(curve);
  rtcAttachGeometry(scene, curve);
  rtcReleaseGeometry(curve);
  if (fit.discs.empty()) return;

  RTCGeometry discs = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT);
  if (discs == nullptr) throw std::runtime_error("rtcNewGeometry(RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT) failed");
  auto* centres = static_cast<float*>(rtcSetNewGeometryBuffer(discs, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                              4 * sizeof(float), fit.discs.size()));
  auto* normals = static_cast<float*>(rtcSetNewGeometryBuffer(discs, RTC_BUFFER_TYPE_NORMAL, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), fit.discs.size()));
  if (centres == nullptr || normals == nullptr) {
    rtcReleaseGeometry(discs);
    throw std::runtime_error("allocating Embree discs failed");
  }
  for (std::size_t i = 0; i < fit.discs.size(); ++i) {
    const RoundCurveFit::Disc& disc = fit.discs[i];
    const float centre[4] = {0.0f, 0.0f, float(disc.z), float(disc.radius)};
    const float normal[3] = {0.0f, 0.0f, float(disc.normalZ)};
    std::copy(centre, centre + 4, centres + 4 * i);
    std::copy(normal, normal + 3, normals + 3 * i);
  }
  rtcCommitGeometry(discs);
  rtcAttachGeometry(scene, discs);
  rtcReleaseGeometry(discs);
}

}  // namespace revolve::bench
