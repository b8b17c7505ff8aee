#include "Revolutions.h"

#include "Revolutions_ispc.h"
#include "revolution_hits.h"

#include <exception>
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

// OSPRay's getParam answers "not given" for a parameter of another type, and ignores names it was
// not asked for: a misspelt or wrongly typed parameter would silently change what is traced.
void Revolutions::refuseUnknownOrMistypedParameters() {
  for (auto param = params_begin(); param != params_end(); ++param) {
    const std::string& name = (*param)->name;
    const rkcommon::utility::Any& value = (*param)->data;
    if (name == "profile") {  // an object here; its element type is checked where it is read
      if (!value.is<ManagedObject*>()) {
        throw std::invalid_argument("'profile' is not a data array (set it with ospSetObject)");
      }
    } else if (name == "spline") {
      if (!value.is<std::string>()) {
        throw std::invalid_argument("'spline' is not a string (set it with OSP_STRING)");
      }
    } else if (name == "tolerance") {
      if (!value.is<float>()) {
        throw std::invalid_argument("'tolerance' is not a float (set it with OSP_FLOAT, e.g. ospSetFloat)");
      }
    } else {
      throw std::invalid_argument("unknown parameter '" + name +
                                  "': the parameters are 'profile', 'spline' and 'tolerance'");
    }
  }
}

RevolutionParameters Revolutions::readParameters() {
  refuseUnknownOrMistypedParameters();
  RevolutionParameters parameters;
  Data* profile = getParamObject<Data>("profile");
  if (profile != nullptr && profile->is<vec2f, 1>()) {
    parameters.profiles.push_back(pointsOf(profile->as<vec2f, 1>()));
  } else if (profile != nullptr && profile->is<Data*, 1>()) {
    std::size_t index = 0;
    for (Data* one : profile->as<Data*, 1>()) {
      if (one == nullptr || !one->is<vec2f, 1>()) {
        throw std::invalid_argument("'profile' " + std::to_string(index) +
                                    " is not a 1D array of OSP_VEC2F (r, z) points");
      }
      parameters.profiles.push_back(pointsOf(one->as<vec2f, 1>()));
      ++index;
    }
  } else if (profile != nullptr) {
    throw std::invalid_argument("'profile' has element type " + stringFor(profile->type) +
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
  } catch (const std::exception& error) {
    // Any refusal (a bad point or a wrongly typed parameter): keep a valid (possibly empty) Embree
    // geometry, so that a group holding this one keeps its other models' Embree geometry IDs.
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
