// Where and when a benchmark ran, for the JSON every subcommand writes: the machine (CPU model,
// hardware threads), the date and the command line, so that each figure can be traced to its run.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace revolve::bench {

std::string cpuModel();  // /proc/cpuinfo's model name, or "unknown"
std::string today();     // YYYY-MM-DD, UTC
double loadAverage();    // the machine's 1-minute load average (/proc/loadavg), -1 if unknown
// {"command", "date", "machine": {"cpu", "threads", "load_before"}, "embree"}: the head of the JSON
// outputs, taken when the run starts; a shared machine's load says how far to trust its times.
nlohmann::ordered_json runInfo(const std::string& commandLine);
// Adds machine.load_after when the run is done.
void finishRunInfo(nlohmann::ordered_json& info);

// `document` written to `path` through a temporary file renamed into place.
void writeJsonFile(const std::string& path, const nlohmann::ordered_json& document);

}  // namespace revolve::bench
