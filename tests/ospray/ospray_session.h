// One OSPRay device for a test program, with the revolve module loaded and every error OSPRay
// reports kept (message and code) for the tests to read, plus small helpers over the C API.
#pragma once

#include <ospray/ospray.h>
#include <ospray/ospray_util.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace revolve::ospray_test {

struct ReportedError {
  OSPError code;
  std::string message;
};

// ospInit, the module, an error callback. Throws std::runtime_error when OSPRay or the module
// cannot be loaded (the message says which and OSPRay's reason).
class Session {
 public:
  Session();
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // The errors reported since the last call, then forgets them.
  std::vector<ReportedError> takeErrors();

 private:
  static void onError(void* session, OSPError code, const char* message);
  std::vector<ReportedError> errors_;
};

// An OSPRay-owned copy of `count` items (the caller's array may go once this returns).
OSPData ownedData(const void* items, OSPDataType type, std::size_t count);

// A "revolution" geometry of the given profiles ((r, z) pairs), committed; spline empty: none.
OSPGeometry newRevolutions(const std::vector<std::vector<std::array<float, 2>>>& profiles,
                           const std::string& spline = "");

// A column-major 3x4 affine transform (OSPRay's affine3f): linear part then translation.
using Affine = std::array<float, 12>;
OSPInstance newInstance(OSPGeometricModel model, const Affine& transform);

}  // namespace revolve::ospray_test
