// Where and when a benchmark ran, for the JSON every subcommand writes: the machine (CPU model,
// hardware threads), the date and the command line, so that each figure can be traced to its run.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace revolve::bench {

std::string cpuModel();  // /proc/cpuinfo's model name, or "unknown"
std::string today();     // YYYY-MM-DD, UTC
// {"command", "date", "machine": {"cpu", "threads"}, "embree"}: the head of every JSON output.
nlohmann::ordered_json runInfo(const std::string& commandLine);

// `document` written to `path` through a temporary file renamed into place.
void writeJsonFile(const std::string& path, const nlohmann::ordered_json& document);

}  // namespace revolve::bench
