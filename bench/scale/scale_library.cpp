#include "scale/scale_library.h"

#include "geometry/placement.h"

#include <tbb/parallel_for.h>

#include <chrono>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace revolve::bench {

LibraryScene::LibraryScene(const ScaleFamily& family, std::size_t count)
    : memory_(std::make_unique<app::EmbreeMemory>()), device_(app::newDevice()) {
  app::monitorMemory(device_.get(), memory_.get());
  scene_ = app::newScene(device_.get());
  const auto start = std::chrono::steady_clock::now();
  shapes_.resize(count);
  geometries_.resize(count);
  // Each object from its points alone: validated, built and placed on whichever thread takes it.
  // The family's objects are valid by construction; a fault here is the library's, and is raised.
  std::vector<std::exception_ptr> faults(count);
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
    try {
      const std::vector<Point2> points = family.points(i);
      Shape& shape = family.isSpline(i) ? shapes_[i].emplace(Spline(SplineKind::catmullRom, points))
                                        : shapes_[i].emplace(Profile(points));
      const app::Placement placed(family.transform(i, count));
      revolve::Placement placement;
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) placement.linear[r][c] = placed.linear()[r][c];
        placement.translate[r] = placed.translate()[r];
      }
      geometries_[i].emplace(device_.get(), shape, placement, revolve::Geometry::Options{});
    } catch (...) {
      faults[i] = std::current_exception();
    }
  });
  for (std::size_t i = 0; i < count; ++i) {
    if (faults[i]) std::rethrow_exception(faults[i]);
  }
  faults = {};
  for (std::size_t i = 0; i < count; ++i) rtcAttachGeometryByID(scene_.get(), geometries_[i]->handle(), unsigned(i));
  rtcCommitScene(scene_.get());
  if (const RTCError error = rtcGetDeviceError(device_.get()); error != RTC_ERROR_NONE)
    throw std::runtime_error("Embree could not build the scene (error " + std::to_string(int(error)) + ")");
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool LibraryScene::hits(const Ray& ray) const noexcept {
  RTCRayHit rayHit = embree::newRayHit(ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y,
                                       ray.direction.z, ray.tnear, ray.tfar);
  embree::RayQuery query;
  query.intersect(scene_.get(), rayHit);
  return rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
}

std::size_t LibraryScene::revolveBytes() const noexcept {
  std::size_t bytes = 0;
  for (const std::optional<Shape>& shape : shapes_) bytes += shape->memoryBytes();
  return bytes;
}

std::size_t LibraryScene::recordBytes() const noexcept {
  std::size_t bytes = shapes_.capacity() * sizeof(std::optional<Shape>) +
                      geometries_.capacity() * sizeof(std::optional<revolve::Geometry>);
  for (const std::optional<revolve::Geometry>& geometry : geometries_) bytes += geometry->memoryBytes();
  return bytes;
}

}  // namespace revolve::bench
