// OSPRay's "revolution" geometry: any number of surfaces of revolution, one Embree user primitive
// each (primID = the revolution's index), traced exactly by revolve. Parameters (docs/ospray.md):
// `profile` (vec2f data of one profile, or data of such data, one per revolution), `spline`,
// `tolerance`.
#pragma once

#include "RevolutionsShared.h"
#include "geometry/Geometry.h"
#include "revolution_set.h"

#include <cstddef>
#include <string>
#include <vector>

namespace ospray::revolve_module {

struct Revolutions : public AddStructShared<Geometry, ispc::Revolutions> {
  explicit Revolutions(api::ISPCDevice& device);
  ~Revolutions() override = default;

  std::string toString() const override { return "ospray::Revolutions (revolve)"; }
  // Reads the parameters and builds every revolution. Bad parameters throw std::runtime_error
  // naming them; OSPRay's API turns that into an error through its callback, and the geometry keeps
  // what it had (nothing, before a first successful commit).
  void commit() override;
  size_t numPrimitives() const override { return revolutions_.size(); }

 private:
  void refuseUnknownOrMistypedParameters();
  revolve::ospray_module::RevolutionParameters readParameters();
  std::vector<revolve::ospray_module::Revolution> revolutions_;
};

}  // namespace ospray::revolve_module
