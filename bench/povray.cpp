#include "povray.h"

#include <OpenImageIO/imagebuf.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace revolve::bench {
namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The last non-empty lines of POV-Ray's messages, for an error.
std::string tail(const std::string& text, int lines) {
  std::vector<std::string> kept;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) kept.push_back(line);
  }
  std::string out;
  for (std::size_t i = kept.size() > std::size_t(lines) ? kept.size() - lines : 0; i < kept.size(); ++i)
    out += " | " + kept[i];
  return out;
}

// Runs `argv` in `directory` with stdout and stderr appended to `log`; returns the exit status.
int runIn(const std::string& directory, std::vector<std::string> argv, const std::string& log) {
  std::vector<char*> pointers;
  for (std::string& arg : argv) pointers.push_back(arg.data());
  pointers.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawn_file_actions_addchdir_np(&actions, directory.c_str());
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, pointers[0], &actions, nullptr, pointers.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error("cannot run " + argv[0] + ": " + std::strerror(spawned));
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) throw std::runtime_error("waitpid failed for " + argv[0]);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// "  Trace Time:       0 hours  0 minutes  1 seconds (1.234 seconds)" -> 1.234
std::optional<double> timeStatistic(const std::string& stats, const std::string& name) {
  const std::regex line(name + R"(:[^(\n]*\(([0-9.]+) seconds\))");
  std::smatch match;
  if (!std::regex_search(stats, match, line)) return std::nullopt;
  return std::stod(match[1]);
}

std::uint64_t countStatistic(const std::string& stats, const std::string& pattern) {
  const std::regex line(pattern);
  std::smatch match;
  if (!std::regex_search(stats, match, line)) return 0;
  return std::stoull(match[1]);
}

}  // namespace

std::optional<std::string> findPovray() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::istringstream directories(path);
  for (std::string directory; std::getline(directories, directory, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(directory.empty() ? "." : directory) / "povray";
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return std::nullopt;
}

render::Image readImage(const std::string& path) {
  OIIO::ImageBuf buffer(path);
  if (!buffer.read(0, 0, true, OIIO::TypeDesc::FLOAT)) throw std::runtime_error(path + ": " + buffer.geterror());
  const OIIO::ImageSpec& spec = buffer.spec();
  if (spec.nchannels < 3)
    throw std::runtime_error(path + ": expected an RGB image, found " + std::to_string(spec.nchannels) + " channels");
  render::Image image;
  image.width = spec.width;
  image.height = spec.height;
  image.pixels.resize(3 * std::size_t(spec.width) * spec.height);
  const OIIO::ROI roi(spec.x, spec.x + spec.width, spec.y, spec.y + spec.height, 0, 1, 0, 3);
  if (!buffer.get_pixels(roi, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw std::runtime_error(path + ": " + buffer.geterror());
  return image;
}

PovrayRun runPovray(const std::string& povray, const PovrayRequest& request) {
  const std::string stats = "povray_stats.txt",
                    log = (std::filesystem::path(request.directory) / "povray_log.txt").string();
  const std::filesystem::path statsPath = std::filesystem::path(request.directory) / stats;
  const std::filesystem::path imagePath = std::filesystem::path(request.directory) / request.image;
  std::filesystem::remove(statsPath);
  std::filesystem::remove(imagePath);
  // -D: no display; -V: quiet; -A: one ray through each pixel centre; +FE: OpenEXR, linear;
  // +GS: statistics (a relative name: POV-Ray writes only below its working directory).
  const std::vector<std::string> argv = {povray,
                                         "-D",
                                         "-V",
                                         "+I" + request.scene,
                                         "+O" + request.image,
                                         "+FE",
                                         "+W" + std::to_string(request.width),
                                         "+H" + std::to_string(request.height),
                                         "-A",
                                         "+WT" + std::to_string(request.threads),
                                         "+GS" + stats,
                                         "File_Gamma=1.0",
                                         "Declare=Revolve_Depth=" + std::to_string(request.depth),
                                         "Declare=Revolve_Shadows=" + std::string(request.shadows ? "1" : "0")};
  const auto start = std::chrono::steady_clock::now();
  const int status = runIn(request.directory, argv, log);
  PovrayRun run;
  run.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status != 0) {
    throw std::runtime_error("povray failed on " + request.scene + " (exit status " + std::to_string(status) + ")" +
                             tail(readFile(log), 3));
  }
  const std::string text = readFile(statsPath.string());
  const std::optional<double> trace = timeStatistic(text, "Trace Time");
  if (!trace) throw std::runtime_error("povray wrote no Trace Time to " + statsPath.string() + tail(readFile(log), 3));
  run.traceSeconds = *trace;
  run.parseSeconds = timeStatistic(text, "Parse Time").value_or(0);
  run.boundingSeconds = timeStatistic(text, "Bounding Time").value_or(0);
  run.rays = countStatistic(text, R"(\nRays:\s+([0-9]+))");
  run.shadowRayTests = countStatistic(text, R"(Shadow Ray Tests:\s+([0-9]+))");
  run.latheTests = countStatistic(text, R"(\nLathe\s+([0-9]+))");
  run.image = readImage(imagePath.string());
  return run;
}

}  // namespace revolve::bench
