// "1 ring", "16 rings": a count and its noun, singular for one, for the tools' summary lines.
#pragma once

#include <cstddef>
#include <string>

namespace revolve::app {

inline std::string counted(std::size_t n, const std::string& singular, const std::string& plural = "") {
  return std::to_string(n) + " " + (n == 1 ? singular : plural.empty() ? singular + "s" : plural);
}

}  // namespace revolve::app
