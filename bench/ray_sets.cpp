#include "ray_sets.h"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace revolve::bench {
namespace {

struct Sphere {
  double centre[3], radius;
};

// d / |d| rounded to float.
Vec3 unitDirection(const double d[3]) {
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return {float(d[0] / length), float(d[1] / length), float(d[2] / length)};
}

Sphere boundingSphere(const Box& box) {
  Sphere sphere{};
  double diagonal2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    sphere.centre[i] = 0.5 * (box.lower[i] + box.upper[i]);
    diagonal2 += (box.upper[i] - box.lower[i]) * (box.upper[i] - box.lower[i]);
  }
  sphere.radius = 0.5 * std::sqrt(diagonal2);
  return sphere;
}

}  // namespace

std::vector<Ray> incoherentRays(const Box& box, std::size_t count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal;
  const Sphere sphere = boundingSphere(box);
  std::vector<Ray> rays;
  rays.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    double u[3] = {normal(random), normal(random), normal(random)};
    const double length = std::hypot(u[0], u[1], u[2]);
    Ray ray;
    float origin[3], target[3];
    for (int k = 0; k < 3; ++k) {
      origin[k] = float(sphere.centre[k] + 3.0 * sphere.radius * u[k] / length);
      target[k] = float(box.lower[k] + unit(random) * (box.upper[k] - box.lower[k]));
    }
    ray.origin = {origin[0], origin[1], origin[2]};
    const double direction[3] = {double(target[0]) - origin[0], double(target[1]) - origin[1],
                                 double(target[2]) - origin[2]};
    ray.direction = unitDirection(direction);
    rays.push_back(ray);
  }
  return rays;
}

std::vector<Ray> cameraRays(const Box& box, int width, int height) {
  if (width % 4 != 0 || height % 2 != 0) throw std::invalid_argument("camera rays: width % 4 and height % 2 must be 0");
  const Sphere sphere = boundingSphere(box);
  // Camera on a sphere of 3 radii, 35 degrees round from +x, 30 degrees up, looking at the centre;
  // a vertical field of view that just holds the bounding sphere.
  const double azimuth = 35.0 * std::numbers::pi / 180.0, elevation = 30.0 * std::numbers::pi / 180.0;
  const double distance = 3.0 * sphere.radius;
  const double back[3] = {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                          std::sin(elevation)};  // from the centre towards the camera
  double eye[3];
  for (int i = 0; i < 3; ++i) eye[i] = sphere.centre[i] + distance * back[i];
  // right = up x back normalised, with up = +z; true up = back x right.
  double right[3] = {-back[1], back[0], 0.0};
  const double rightLength = std::hypot(right[0], right[1]);
  for (double& c : right) c /= rightLength;
  const double up[3] = {back[1] * right[2] - back[2] * right[1], back[2] * right[0] - back[0] * right[2],
                        back[0] * right[1] - back[1] * right[0]};
  const double halfHeight = std::tan(std::asin(sphere.radius / distance));  // at unit distance
  const double halfWidth = halfHeight * width / height;

  std::vector<Ray> rays;
  rays.reserve(std::size_t(width) * height);
  for (int tileY = 0; tileY < height; tileY += 2) {
    for (int tileX = 0; tileX < width; tileX += 4) {
      for (int y = tileY; y < tileY + 2; ++y) {
        for (int x = tileX; x < tileX + 4; ++x) {
          const double sx = (2.0 * (x + 0.5) / width - 1.0) * halfWidth;
          const double sy = (1.0 - 2.0 * (y + 0.5) / height) * halfHeight;
          Ray ray;
          ray.origin = {float(eye[0]), float(eye[1]), float(eye[2])};
          double d[3];
          for (int i = 0; i < 3; ++i) d[i] = -back[i] + sx * right[i] + sy * up[i];
          ray.direction = unitDirection(d);
          rays.push_back(ray);
        }
      }
    }
  }
  return rays;
}

}  // namespace revolve::bench
