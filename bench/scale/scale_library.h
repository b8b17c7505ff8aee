// revolve-bench scale --build library: the family's objects built with the library alone, as a C++
// program linking revolve would build them: each object's Profile or Spline made from its points,
// its Shape, and a placed revolve::Geometry attached to one Embree scene of the program's own,
// all on TBB's threads. Nothing else is kept: no scene description, none of the scene stack's
// records (scene/embree_scene.h), so its memory is the library's and Embree's alone.
#pragma once

#include "embree/embree_handles.h"
#include "embree/memory_monitor.h"
#include "scale/scale_family.h"

#include <revolve/revolve.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace revolve::bench {

class LibraryScene {
 public:
  // Objects 0 to count - 1 of `family`, placed on its grid for `count` objects, committed.
  LibraryScene(const ScaleFamily& family, std::size_t count);
  LibraryScene(const LibraryScene&) = delete;
  LibraryScene& operator=(const LibraryScene&) = delete;

  // Whether the ray (finite, as the benchmark makes them) hits anything: rtcIntersect1.
  bool hits(const Ray& ray) const noexcept;

  const Shape& shape(std::size_t i) const { return *shapes_[i]; }
  double buildSeconds() const noexcept { return buildSeconds_; }
  std::size_t revolveBytes() const noexcept;  // the shapes (Shape::memoryBytes)
  std::size_t recordBytes() const noexcept;   // the geometries' own (Geometry::memoryBytes) and the two arrays
  std::int64_t embreeBytes() const noexcept { return memory_->current.load(); }
  std::int64_t embreePeakBytes() const noexcept { return memory_->peak.load(); }

 private:
  // Destroyed in reverse: the scene (whose tree points into the geometries) first, then the
  // geometries, the shapes they trace, the device, and the counter the device reports to.
  std::unique_ptr<app::EmbreeMemory> memory_;
  app::Device device_;
  std::vector<std::optional<Shape>> shapes_;
  std::vector<std::optional<revolve::Geometry>> geometries_;
  app::Scene scene_;
  double buildSeconds_ = 0;
};

}  // namespace revolve::bench
