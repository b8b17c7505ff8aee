#include "Revolutions.h"

#include "Revolutions_ispc.h"
#include "revolution_hits.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace ospray::revolve_module {

using revolve::Point2;
using revolve::ospray_module::RevolutionParameters;

namespace {

std::vector<Point2> pointsOf(const DataT<vec2f>& data) {
  std::vector<Point2> points;
  points.reserve(data.size());
  for (const vec2f& p : data) points.push_back(Point2{p.x, p.y});
  return points;
}

}  // namespace

// FFG_BOX: OSPRay's feature flag for a user geometry whose callbacks come through the query's
// arguments (its dispatch), the way this geometry's do.
Revolutions::Revolutions(api::ISPCDevice& device) : AddStructShared(device.getDRTDevice(), device, FFG_BOX) {
  getSh()->super.postIntersect = ispc::Revolutions_postIntersect_addr();
  getSh()->super.intersect = ispc::Revolutions_intersect_addr();
}

RevolutionParameters Revolutions::readParameters() {
  RevolutionParameters parameters;
  Data* profile = getParamObject<Data>("profile");
  if (profile != nullptr && profile->is<vec2f, 1>()) {
    parameters.profiles.push_back(pointsOf(profile->as<vec2f, 1>()));
  } else if (profile != nullptr && profile->is<Data*, 1>()) {
    std::size_t index = 0;
    for (Data* one : profile->as<Data*, 1>()) {
      if (one == nullptr || !one->is<vec2f, 1>()) {
        throw std::runtime_error("revolution: 'profile' " + std::to_string(index) +
                                 " is not a 1D array of OSP_VEC2F (r, z) points");
      }
      parameters.profiles.push_back(pointsOf(one->as<vec2f, 1>()));
      ++index;
    }
  } else if (profile != nullptr) {
    throw std::runtime_error("revolution: 'profile' has element type " + stringFor(profile->type) +
                             ": it must be a 1D array of OSP_VEC2F (r, z) points, or a 1D array of such arrays");
  }
  // OSPRay keeps a string parameter as a std::string; empty: not given.
  if (const std::string spline = getParam<std::string>("spline", ""); !spline.empty()) parameters.spline = spline;
  if (auto tolerance = getOptParam<float>("tolerance")) parameters.tolerance = *tolerance;
  return parameters;
}

void Revolutions::commit() {
  std::vector<revolve::ospray_module::Revolution> built;
  try {
    built = revolve::ospray_module::buildRevolutions(readParameters());
  } catch (const std::invalid_argument& error) {
    // Keep a valid (possibly empty) Embree geometry, so that a world holding this one still works.
    if (embreeGeometry == nullptr) {
      getSh()->host = &revolutions_;
      createEmbreeUserGeometry(&revolutionBounds);
    }
    throw std::runtime_error(std::string("revolution: ") + error.what());
  }
  revolutions_ = std::move(built);
  getSh()->host = &revolutions_;
  createEmbreeUserGeometry(&revolutionBounds);
  getSh()->super.numPrimitives = int32_t(numPrimitives());
  postCreationInfo();
}

}  // namespace ospray::revolve_module
