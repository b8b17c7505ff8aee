// Number formatting for error messages: the shortest text that reads back to the same value.
#pragma once

#include <charconv>
#include <string>

namespace revolve::detail {

inline std::string formatNumber(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace revolve::detail
