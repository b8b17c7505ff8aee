#include "ospray_session.h"

#include <stdexcept>
#include <utility>

namespace revolve::ospray_test {

Session::Session() {
  if (ospInit(nullptr, nullptr) != OSP_NO_ERROR) throw std::runtime_error("ospInit failed");
  ospDeviceSetErrorCallback(ospGetCurrentDevice(), &Session::onError, this);
  if (ospLoadModule("revolve") != OSP_NO_ERROR) {
    throw std::runtime_error(
        "ospLoadModule(\"revolve\") failed: is libospray_module_revolve.so on LD_LIBRARY_PATH? OSPRay says: " +
        std::string(ospDeviceGetLastErrorMsg(ospGetCurrentDevice())));
  }
}

Session::~Session() { ospShutdown(); }

void Session::onError(void* session, OSPError code, const char* message) {
  static_cast<Session*>(session)->errors_.push_back(ReportedError{code, message});
}

std::vector<ReportedError> Session::takeErrors() { return std::exchange(errors_, {}); }

namespace {}  // namespace

// OSPRay reads shared data when it uses it, not when it is committed: the copy lets the caller's
// array go.
OSPData ownedData(const void* items, OSPDataType type, std::size_t count) {
  OSPData shared = ospNewSharedData(items, type, count);
  OSPData copy = ospNewData(type, count);
  ospCopyData(shared, copy);
  ospRelease(shared);
  return copy;
}

namespace {

OSPData profileData(const std::vector<std::array<float, 2>>& points) {
  return ownedData(points.data(), OSP_VEC2F, points.size());
}

}  // namespace

OSPGeometry newRevolutions(const std::vector<std::vector<std::array<float, 2>>>& profiles, const std::string& spline) {
  OSPGeometry geometry = ospNewGeometry("revolution");
  if (profiles.size() == 1) {
    OSPData one = profileData(profiles[0]);
    ospSetObject(geometry, "profile", one);
    ospRelease(one);
  } else {
    std::vector<OSPData> each;
    for (const auto& points : profiles) each.push_back(profileData(points));
    OSPData copy = ownedData(each.data(), OSP_DATA, each.size());
    for (OSPData one : each) ospRelease(one);
    ospSetObject(geometry, "profile", copy);
    ospRelease(copy);
  }
  // ospSetParam with the characters: OSPRay 3.2's ospSetString passes the pointer's address instead.
  if (!spline.empty()) ospSetParam(geometry, "spline", OSP_STRING, spline.c_str());
  ospCommit(geometry);
  return geometry;
}

OSPInstance newInstance(OSPGeometricModel model, const Affine& transform) {
  OSPGroup group = ospNewGroup();
  OSPData models = ownedData(&model, OSP_GEOMETRIC_MODEL, 1);
  ospSetObject(group, "geometry", models);
  ospCommit(group);
  OSPInstance instance = ospNewInstance(group);
  ospSetParam(instance, "transform", OSP_AFFINE3F, transform.data());
  ospCommit(instance);
  ospRelease(models);
  ospRelease(group);
  return instance;
}

}  // namespace revolve::ospray_test
