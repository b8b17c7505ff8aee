#include "curve/spline_pieces.h"

#include <cmath>

namespace revolve::detail {
namespace {

Point2 operator+(Point2 a, Point2 b) { return {a.r + b.r, a.z + b.z}; }
Point2 operator-(Point2 a, Point2 b) { return {a.r - b.r, a.z - b.z}; }
Point2 operator*(double s, Point2 a) { return {s * a.r, s * a.z}; }

double distance(Point2 a, Point2 b) { return std::hypot(b.r - a.r, b.z - a.z); }

bool closedLoop(std::span<const Point2> p) { return p.front().r == p.back().r && p.front().z == p.back().z; }

// Hermite data to Bezier: the piece from p0 to p1 over a parameter span h, with derivatives d0, d1.
void appendHermite(std::vector<Point2>& out, Point2 p0, Point2 d0, Point2 p1, Point2 d1, double h) {
  out.push_back(p0 + (h / 3.0) * d0);
  out.push_back(p1 - (h / 3.0) * d1);
  out.push_back(p1);
}

// Tridiagonal solve (Thomas): sub[i] x[i-1] + diag[i] x[i] + super[i] x[i+1] = rhs[i]. The systems
// here are strictly diagonally dominant, so no pivoting is needed.
std::vector<Point2> solveTridiagonal(const std::vector<double>& sub, std::vector<double> diag,
                                     const std::vector<double>& super, std::vector<Point2> rhs) {
  const std::size_t n = diag.size();
  for (std::size_t i = 1; i < n; ++i) {
    const double w = sub[i] / diag[i - 1];
    diag[i] -= w * super[i - 1];
    rhs[i] = rhs[i] - w * rhs[i - 1];
  }
  std::vector<Point2> x(n);
  x[n - 1] = (1.0 / diag[n - 1]) * rhs[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) x[i] = (1.0 / diag[i]) * (rhs[i] - super[i] * x[i + 1]);
  return x;
}

// The cyclic system (corner coefficients beta = row 0's of x[n-1], alpha = row n-1's of x[0]) by
// Sherman-Morrison on the tridiagonal part (Press et al., Numerical Recipes, "cyclic"); n >= 3.
std::vector<Point2> solveCyclic(const std::vector<double>& sub, const std::vector<double>& diag,
                                const std::vector<double>& super, double alpha, double beta,
                                const std::vector<Point2>& rhs) {
  const std::size_t n = diag.size();
  const double gamma = -diag[0];
  std::vector<double> modified = diag;
  modified[0] = diag[0] - gamma;
  modified[n - 1] = diag[n - 1] - alpha * beta / gamma;
  const std::vector<Point2> x = solveTridiagonal(sub, modified, super, rhs);
  std::vector<Point2> u(n, Point2{0.0, 0.0});
  u[0] = {gamma, gamma};
  u[n - 1] = {alpha, alpha};
  const std::vector<Point2> z = solveTridiagonal(sub, modified, super, u);
  std::vector<Point2> out(n);
  // Per coordinate: the correction factor differs for r and z.
  const double factorR = (x[0].r + beta * x[n - 1].r / gamma) / (1.0 + z[0].r + beta * z[n - 1].r / gamma);
  const double factorZ = (x[0].z + beta * x[n - 1].z / gamma) / (1.0 + z[0].z + beta * z[n - 1].z / gamma);
  for (std::size_t i = 0; i < n; ++i) out[i] = {x[i].r - factorR * z[i].r, x[i].z - factorZ * z[i].z};
  return out;
}

// A piece list's storage for `pieces` cubic pieces, its first point in: 3 points a piece and the
// first, reserved exactly, since a Spline keeps the list as it is (no growth slack to carry).
std::vector<Point2> startPieces(std::size_t pieces, Point2 first) {
  std::vector<Point2> out;
  out.reserve(3 * pieces + 1);
  out.push_back(first);
  return out;
}

}  // namespace

std::vector<Point2> bezierOfPolyline(std::span<const Point2> points) {
  std::vector<Point2> out = startPieces(points.size() - 1, points[0]);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Point2 a = points[i], b = points[i + 1];
    out.push_back(a + (1.0 / 3.0) * (b - a));
    out.push_back(b + (1.0 / 3.0) * (a - b));
    out.push_back(b);
  }
  return out;
}

std::vector<Point2> bezierOfQuadratic(std::span<const Point2> points) {
  std::vector<Point2> out = startPieces((points.size() - 1) / 2, points[0]);
  for (std::size_t i = 0; i + 2 < points.size(); i += 2) {
    const Point2 a = points[i], m = points[i + 1], b = points[i + 2];
    out.push_back(a + (2.0 / 3.0) * (m - a));
    out.push_back(b + (2.0 / 3.0) * (m - b));
    out.push_back(b);
  }
  return out;
}

std::vector<Point2> bezierOfCatmullRom(std::span<const Point2> p) {
  const std::size_t n = p.size(), m = n - 1;  // m pieces
  const bool loop = closedLoop(p) && n >= 3;
  // Centripetal knot spacing: the square root of each chord.
  std::vector<double> d(m);
  for (std::size_t i = 0; i < m; ++i) d[i] = std::sqrt(distance(p[i], p[i + 1]));
  // The tangent at point i from its neighbours (Barry-Goldman's pyramid differentiated at the knot):
  // (p_i - p_{i-1}) / d_{i-1} - (p_{i+1} - p_{i-1}) / (d_{i-1} + d_i) + (p_{i+1} - p_i) / d_i.
  const auto tangent = [](Point2 before, double dBefore, Point2 at, Point2 after, double dAfter) {
    return (1.0 / dBefore) * (at - before) - (1.0 / (dBefore + dAfter)) * (after - before) +
           (1.0 / dAfter) * (after - at);
  };
  std::vector<Point2> tangents(n);
  for (std::size_t i = 1; i < m; ++i) tangents[i] = tangent(p[i - 1], d[i - 1], p[i], p[i + 1], d[i]);
  if (loop) {
    tangents[0] = tangent(p[m - 1], d[m - 1], p[0], p[1], d[0]);
    tangents[m] = tangents[0];
  } else {
    // The missing neighbour is the mirror image of the second point (and of the last but one),
    // which makes the curve leave along the first chord: tangent (p1 - p0) / d0.
    tangents[0] = (1.0 / d[0]) * (p[1] - p[0]);
    tangents[m] = (1.0 / d[m - 1]) * (p[m] - p[m - 1]);
  }
  std::vector<Point2> out = startPieces(m, p[0]);
  for (std::size_t i = 0; i < m; ++i) appendHermite(out, p[i], tangents[i], p[i + 1], tangents[i + 1], d[i]);
  return out;
}

std::vector<Point2> bezierOfNatural(std::span<const Point2> p) {
  const std::size_t n = p.size(), m = n - 1;  // m pieces
  const bool loop = closedLoop(p) && n >= 3;
  std::vector<double> h(m);
  for (std::size_t i = 0; i < m; ++i) h[i] = distance(p[i], p[i + 1]);
  // The first-derivative form of the C2 conditions at an inner point i (derivatives D with respect to
  // the chord-length parameter): h_i D_{i-1} + 2 (h_{i-1} + h_i) D_i + h_{i-1} D_{i+1}
  //   = 3 (h_i (p_i - p_{i-1}) / h_{i-1} + h_{i-1} (p_{i+1} - p_i) / h_i).
  const auto rhsAt = [&](Point2 before, double hBefore, Point2 at, Point2 after, double hAfter) {
    return 3.0 * ((hAfter / hBefore) * (at - before) + (hBefore / hAfter) * (after - at));
  };
  std::vector<Point2> derivative;
  if (!loop) {
    // Natural ends (zero second derivative): 2 D_0 + D_1 = 3 (p_1 - p_0) / h_0, and alike at the end.
    std::vector<double> sub(n, 0.0), diag(n, 0.0), super(n, 0.0);
    std::vector<Point2> rhs(n);
    diag[0] = 2.0, super[0] = 1.0, rhs[0] = (3.0 / h[0]) * (p[1] - p[0]);
    for (std::size_t i = 1; i < m; ++i) {
      sub[i] = h[i], diag[i] = 2.0 * (h[i - 1] + h[i]), super[i] = h[i - 1];
      rhs[i] = rhsAt(p[i - 1], h[i - 1], p[i], p[i + 1], h[i]);
    }
    sub[m] = 1.0, diag[m] = 2.0, rhs[m] = (3.0 / h[m - 1]) * (p[m] - p[m - 1]);
    derivative = solveTridiagonal(sub, diag, super, rhs);
  } else {
    // Periodic: unknowns D_0 .. D_{m-1}, D_m = D_0, neighbours taken round the loop.
    std::vector<double> sub(m), diag(m), super(m);
    std::vector<Point2> rhs(m);
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t before = (i + m - 1) % m;
      sub[i] = h[i], diag[i] = 2.0 * (h[before] + h[i]), super[i] = h[before];
      rhs[i] = rhsAt(p[before], h[before], p[i], p[i + 1], h[i]);
    }
    if (m == 2) {
      // Both neighbours of each unknown are the other one: a 2 x 2 system.
      const double a = diag[0], b = sub[0] + super[0], c = sub[1] + super[1], e = diag[1];
      const double det = a * e - b * c;
      derivative = {(1.0 / det) * (e * rhs[0] - b * rhs[1]), (1.0 / det) * (a * rhs[1] - c * rhs[0])};
    } else {
      derivative = solveCyclic(sub, diag, super, super[m - 1], sub[0], rhs);
    }
    derivative.push_back(derivative[0]);
  }
  std::vector<Point2> out = startPieces(m, p[0]);
  for (std::size_t i = 0; i < m; ++i) appendHermite(out, p[i], derivative[i], p[i + 1], derivative[i + 1], h[i]);
  return out;
}

}  // namespace revolve::detail
