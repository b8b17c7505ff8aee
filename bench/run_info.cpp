#include "run_info.h"

#include "io/text_files.h"
#include "shape/query_kernels.h"

#include <revolve/embree_api.h>

#include <ctime>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace revolve::bench {

std::string cpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  }
  return "unknown";
}

std::string today() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d", std::gmtime(&now));
  return text;
}

double loadAverage() {
  std::ifstream file("/proc/loadavg");
  double load = -1;
  file >> load;
  return file ? load : -1;
}

nlohmann::ordered_json runInfo(const std::string& commandLine) {
  nlohmann::ordered_json info;
  info["command"] = commandLine;
  info["date"] = today();
  info["machine"] = {
      {"cpu", cpuModel()}, {"threads", std::thread::hardware_concurrency()}, {"load_before", loadAverage()}};
  info["embree"] = RTC_VERSION_STRING;
  info["revolve_isa"] = detail::isaName(detail::chosenIsa());  // revolve-bench --isa, else the best
  return info;
}

void finishRunInfo(nlohmann::ordered_json& info) { info["machine"]["load_after"] = loadAverage(); }

void writeJsonFile(const std::string& path, const nlohmann::ordered_json& document) {
  const std::string text = document.dump(1) + "\n";
  io::writeFileAtomically(path, [&](std::FILE* file) {
    if (std::fwrite(text.data(), 1, text.size(), file) != text.size()) throw std::runtime_error("short write");
  });
}

}  // namespace revolve::bench
