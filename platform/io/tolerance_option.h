// --tolerance, as revolve-render and revolve-trace read it: one parser and one rule, so that both
// tools take and refuse the same values and say so the same way.
#pragma once

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

namespace revolve::app {

struct ToleranceOption {
  bool pixel = false;  // "pixel" (revolve-render): the camera's pixel footprint
  double value = 0;    // otherwise a distance in the profile's units, finite and > 0
};

// `text` as a tolerance: "pixel" where `pixelAllowed`, or a decimal number (an optional '+' first)
// that is finite and > 0 in double; nothing otherwise ("nan", "inf", "0", "-1", "1e-400", "", "abc").
inline std::optional<ToleranceOption> toleranceOption(std::string_view text, bool pixelAllowed) {
  if (pixelAllowed && text == "pixel") return ToleranceOption{true, 0};
  if (text.size() > 1 && text.front() == '+') text.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || end != text.data() + text.size() || error != std::errc() || !(value > 0 && value < HUGE_VAL)) {
    return std::nullopt;
  }
  return ToleranceOption{false, value};
}

// Why `text` is refused, as a sentence about the value as written (cut at 40 bytes, control bytes
// shown as '?'); the caller names the option.
inline std::string toleranceRefusal(std::string_view text, bool pixelAllowed) {
  std::string shown = "\"";
  for (const char c : text.substr(0, 40)) shown += (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) ? c : '?';
  shown += text.size() > 40 ? "...\"" : "\"";
  return shown +
         (pixelAllowed
              ? " is neither \"pixel\" nor a finite number > 0 (a distance in each profile's units)"
              : " is not a finite number > 0 (the polyline's largest distance from the curve, in the profile's units)");
}

}  // namespace revolve::app
