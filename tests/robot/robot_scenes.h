// Scenes built in code for the robot tests, and the closed forms they are checked against: the
// nearest hit of a ray with a capped cylinder, a cone and a sphere, written here from the
// quadratics, in double (independent of revolve's kernel and of Embree).
#pragma once

#include "geometry/vec3d.h"
#include "io/scene_file.h"

#include <revolve/revolve.h>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace revolve::testing {

using app::Vec3d;

struct PlacedProfile {
  std::vector<Point2> points;
  app::Transform transform;
  std::string name;
};

inline app::Transform at(double x, double y, double z = 0) {
  app::Transform t;
  t.translate = {x, y, z};
  return t;
}

// A description as the scene reader would return it: one profile per object, one material.
inline io::SceneDescription sceneOf(const std::vector<PlacedProfile>& objects,
                                    const std::vector<std::array<Vec3d, 4>>& quads = {}) {
  io::SceneDescription scene;
  scene.file = "test scene";
  scene.camera = {{0, -5, 1}, {0, 0, 1}, {0, 0, 1}, 40, {}, {}, {}};
  scene.materials.push_back({"grey", io::MaterialType::diffuse, {0.5, 0.5, 0.5}, 0, 1.5, {1, 1, 1}});
  for (std::size_t i = 0; i < objects.size(); ++i) {
    std::string name = "p";  // appended: GCC 12 warns falsely (-Wrestrict) on "p" + string
    name += std::to_string(i);
    scene.profiles.push_back({name, Profile(objects[i].points), ShadingNormals::kDefaultCreaseDegrees, {}, {}});
    scene.objects.push_back({objects[i].name, i, 0, objects[i].transform});
  }
  for (const auto& corners : quads) scene.quads.push_back({corners, 0});
  return scene;
}

inline std::vector<Point2> cylinderProfile(double radius, double z0, double z1) {
  return {{0, z0}, {radius, z0}, {radius, z1}, {0, z1}};
}

// A polyline inscribed in a circle of `radius` about the origin, from the bottom pole to the top:
// its surface lies between the sphere and the sphere of radius * cos(pi / (2 segments)).
inline std::vector<Point2> sphereProfile(double radius, int segments) {
  std::vector<Point2> points;
  for (int i = 0; i <= segments; ++i) {
    const double theta = M_PI * i / segments;
    points.push_back({i == 0 || i == segments ? 0.0 : radius * std::sin(theta), -radius * std::cos(theta)});
  }
  return points;
}

inline double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Smallest root > 0 of a t^2 + 2 b t + c = 0 that passes `accept`, or nothing.
template <class Accept>
std::optional<double> firstRoot(double a, double b, double c, Accept accept) {
  if (a == 0) {
    if (b == 0) return std::nullopt;
    const double t = -c / (2 * b);
    return t > 0 && accept(t) ? std::optional<double>(t) : std::nullopt;
  }
  const double disc = b * b - a * c;
  if (disc < 0) return std::nullopt;
  const double s = std::sqrt(disc);
  double roots[2] = {(-b - s) / a, (-b + s) / a};
  if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
  for (const double t : roots) {
    if (t > 0 && accept(t)) return t;
  }
  return std::nullopt;
}

inline std::optional<double> minPositive(std::optional<double> a, std::optional<double> b) {
  if (!a) return b;
  if (!b) return a;
  return std::min(*a, *b);
}

// A horizontal disc of `radius` at height z about (cx, cy).
inline std::optional<double> rayDisc(const Vec3d& o, const Vec3d& u, double cx, double cy, double z, double radius) {
  if (u[2] == 0) return std::nullopt;
  const double t = (z - o[2]) / u[2];
  if (!(t > 0)) return std::nullopt;
  const double x = o[0] + t * u[0] - cx, y = o[1] + t * u[1] - cy;
  return x * x + y * y <= radius * radius ? std::optional<double>(t) : std::nullopt;
}

// A closed cylinder: side x^2 + y^2 = a^2 for z in [z0, z1], and its two end discs.
inline std::optional<double> rayCappedCylinder(const Vec3d& o, const Vec3d& u, double cx, double cy, double a,
                                               double z0, double z1) {
  const double px = o[0] - cx, py = o[1] - cy;
  const auto onSide = [&](double t) {
    const double z = o[2] + t * u[2];
    return z >= z0 && z <= z1;
  };
  const std::optional<double> side =
      firstRoot(u[0] * u[0] + u[1] * u[1], px * u[0] + py * u[1], px * px + py * py - a * a, onSide);
  return minPositive(side, minPositive(rayDisc(o, u, cx, cy, z0, a), rayDisc(o, u, cx, cy, z1, a)));
}

// A cone of base radius b at z = base, apex at z = base + height: x^2 + y^2 = (k (top - z))^2,
// k = b / height, on z in [base, top] (not the mirror nappe), and its base disc.
inline std::optional<double> rayCone(const Vec3d& o, const Vec3d& u, double cx, double cy, double base, double b,
                                     double height) {
  const double k = b / height, top = base + height;
  const double px = o[0] - cx, py = o[1] - cy, pz = top - o[2];  // height below the apex
  const auto onNappe = [&](double t) {
    const double z = o[2] + t * u[2];
    return z >= base && z <= top;
  };
  // (px + t ux)^2 + (py + t uy)^2 - k^2 (pz - t uz)^2 = 0
  const std::optional<double> side =
      firstRoot(u[0] * u[0] + u[1] * u[1] - k * k * u[2] * u[2], px * u[0] + py * u[1] + k * k * pz * u[2],
                px * px + py * py - k * k * pz * pz, onNappe);
  return minPositive(side, rayDisc(o, u, cx, cy, base, b));
}

// A sphere of `radius` about c: the entry (or, from inside, the exit).
inline std::optional<double> raySphere(const Vec3d& o, const Vec3d& u, const Vec3d& c, double radius) {
  const Vec3d p{o[0] - c[0], o[1] - c[1], o[2] - c[2]};
  return firstRoot(dot(u, u), dot(p, u), dot(p, p) - radius * radius, [](double) { return true; });
}

}  // namespace revolve::testing
