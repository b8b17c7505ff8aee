// Owning handles for Embree objects in the applications, and a device that reports its errors.
#pragma once

#include <revolve/embree_api.h>

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace revolve::app {

struct DeviceRelease {
  void operator()(RTCDevice device) const noexcept { rtcReleaseDevice(device); }
};
struct SceneRelease {
  void operator()(RTCScene scene) const noexcept { rtcReleaseScene(scene); }
};
using Device = std::unique_ptr<RTCDeviceTy, DeviceRelease>;
using Scene = std::unique_ptr<RTCSceneTy, SceneRelease>;

inline Device newDevice(const char* config = nullptr) {
  RTCDevice device = rtcNewDevice(config);
  if (device == nullptr) {
    throw std::runtime_error("cannot create an Embree device (error " +
                             std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  }
  rtcSetDeviceErrorFunction(
      device,
      [](void*, RTCError code, const char* message) {
        std::fprintf(stderr, "Embree error %d: %s\n", int(code), message != nullptr ? message : "");
      },
      nullptr);
  return Device(device);
}

inline Scene newScene(RTCDevice device) {
  RTCScene scene = rtcNewScene(device);
  if (scene == nullptr) throw std::runtime_error("cannot create an Embree scene");
  return Scene(scene);
}

}  // namespace revolve::app
