// Fuzz target: a poses file (POSES.csv) as revolve-lidar and revolve-clearance read it. Expected:
// an InputError with a one-line message, or at least one pose, every value finite, x, y and z
// within the coordinate limit (common/ray_limits.h), z = 0 where the file gave none; the poses, written back as
// shortest round-trip text under the x,y,z,yaw header, read back bit for bit.
#include "fuzz_checks.h"
#include "geometry/ray_limits.h"
#include "io/poses_file.h"
#include "io/text_files.h"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

using namespace revolve;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<io::RobotPose> poses;
  try {
    poses = io::parsePosesCsv(text, "fuzz.csv");
  } catch (const io::InputError& error) {
    fuzz::checkOneLineMessage(error.what());
    return 0;
  }
  FUZZ_CHECK(!poses.empty());
  std::string again = "x,y,z,yaw\n";
  for (const io::RobotPose& p : poses) {
    for (const double v : {p.x, p.y, p.z}) FUZZ_CHECK(std::abs(v) <= app::kMaxWorldCoordinate);
    for (const double v : {p.x, p.y, p.z, p.yaw}) {
      FUZZ_CHECK(std::isfinite(v));
      char buffer[32];
      again.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
      again += ',';
    }
    again.back() = '\n';
  }
  const std::vector<io::RobotPose> back = io::parsePosesCsv(again, "again.csv");
  FUZZ_CHECK(back.size() == poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    FUZZ_CHECK(back[i].x == poses[i].x && back[i].y == poses[i].y && back[i].z == poses[i].z &&
               back[i].yaw == poses[i].yaw);
  }
  return 0;
}
