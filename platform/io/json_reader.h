// Strict, typed reading of JSON files for the file formats of platform/io (the scene file, the sensor
// file): every problem is one `Error` (an exception type constructed from a message) naming the
// file, the key path (`objects[12].profile`, `horizontal.samples`), the value and the rule it breaks,
// on one printable line. Unknown keys and repeated keys are errors, never silently ignored.
// Internal to platform/io's readers (it needs nlohmann-json, which revolve_io links privately).
#pragma once

#include <nlohmann/json.hpp>

#include "geometry/ray_limits.h"
#include "geometry/unit_vector.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace revolve::io::json {

// ordered_json keeps the file's order of keys, so indices and messages follow it.
using Json = nlohmann::ordered_json;

// Text from the file, made safe for a one-line message: control bytes become '?', and it is cut
// at 40 bytes so that a binary key cannot flood the terminal.
inline std::string printable(std::string_view text) {
  std::string out;
  for (const char c : text.substr(0, 40)) {
    const auto byte = static_cast<unsigned char>(c);
    out += (byte >= 0x20 && byte != 0x7f) ? c : '?';
  }
  if (text.size() > 40) out += "...";
  return out;
}
inline std::string quotedText(std::string_view text) {
  std::string out = "\"";  // built by appending: GCC 12 warns falsely (-Wrestrict) on "\"" + string
  out += printable(text);
  out += "\"";
  return out;
}

inline std::string child(const std::string& path, std::string_view key) {
  return path.empty() ? printable(key) : path + "." + printable(key);
}
inline std::string element(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

inline std::string joined(std::initializer_list<std::string_view> names) {
  std::string out;
  for (const std::string_view name : names) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

// A number as the file wrote it, as nearly as a parsed number can say: the shortest text that
// reads back to the same double (64.0000001 stays 64.0000001, never "64").
inline std::string numberText(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}
// A JSON number's text: whole numbers (which nlohmann keeps as integers) exactly.
inline std::string numberText(const Json& value) {
  if (value.is_number_unsigned()) return std::to_string(value.get<std::uint64_t>());
  if (value.is_number_integer()) return std::to_string(value.get<std::int64_t>());
  return numberText(value.get<double>());
}

using app::unitVector;

// Typed access to the JSON tree with key paths for messages.
template <class Error>
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw Error(file_ + ": " + (path.empty() ? "" : path + ": ") + problem);
  }

  const Json& object(const Json& value, const std::string& path,
                     std::initializer_list<std::string_view> allowed) const {
    if (!value.is_object()) fail(path, std::string("expected an object, found ") + value.type_name());
    for (const auto& [key, ignored] : value.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        fail(child(path, key), "unknown key; expected one of: " + joined(allowed));
      }
    }
    return value;
  }

  const Json& required(const Json& object, const std::string& path, const char* key) const {
    const auto found = object.find(key);
    if (found == object.end()) fail(path, std::string("missing key \"") + key + "\"");
    return *found;
  }
  const Json* optional(const Json& object, const char* key) const {
    const auto found = object.find(key);
    return found == object.end() ? nullptr : &*found;
  }

  const Json& array(const Json& value, const std::string& path) const {
    if (!value.is_array()) fail(path, std::string("expected an array, found ") + value.type_name());
    return value;
  }

  double number(const Json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, std::string("expected a number, found ") + value.type_name());
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(path, "the number is beyond double's range");
    return x;
  }
  double numberIn(const Json& value, const std::string& path, double lo, double hi, const char* rule) const {
    const double x = number(value, path);
    if (!(x >= lo && x <= hi)) fail(path, numberText(value) + " is out of range: " + rule);
    return x;
  }
  int integerIn(const Json& value, const std::string& path, int lo, int hi) const {
    const double x = number(value, path);
    if (x != std::floor(x)) fail(path, numberText(value) + " is not a whole number");
    if (!(x >= lo && x <= hi)) {
      fail(path, numberText(value) + " is out of range: must lie in [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "]");
    }
    return int(x);
  }
  // A whole number in [0, 2^64): JSON integers as nlohmann reads them, never via double.
  std::uint64_t unsignedInteger(const Json& value, const std::string& path) const {
    if (value.is_number_unsigned()) return value.get<std::uint64_t>();
    if (value.is_number_integer())
      fail(path, std::to_string(value.get<std::int64_t>()) + " is negative: expected a whole number >= 0");
    if (value.is_number()) fail(path, numberText(value) + " is not a whole number in [0, 2^64)");
    fail(path, std::string("expected a whole number, found ") + value.type_name());
  }
  std::string string(const Json& value, const std::string& path) const {
    if (!value.is_string()) fail(path, std::string("expected a string, found ") + value.type_name());
    return value.get<std::string>();
  }
  std::array<double, 3> vec3(const Json& value, const std::string& path) const {
    if (!value.is_array() || value.size() != 3) fail(path, "expected an array of 3 numbers [x, y, z]");
    return {number(value[0], element(path, 0)), number(value[1], element(path, 1)), number(value[2], element(path, 2))};
  }
  // A position in the world: each coordinate within +-kMaxWorldCoordinate (common/ray_limits.h).
  std::array<double, 3> position(const Json& value, const std::string& path) const {
    const std::array<double, 3> p = vec3(value, path);
    for (std::size_t i = 0; i < 3; ++i) {
      if (std::abs(p[i]) > app::kMaxWorldCoordinate) {
        fail(element(path, i), numberText(value[i]) + " is beyond the coordinate limit: " + app::kCoordinateLimitRule);
      }
    }
    return p;
  }
  // A direction: any finite vector but zero, returned as a unit vector (unitVector).
  std::array<double, 3> direction(const Json& value, const std::string& path) const {
    const std::array<double, 3> v = vec3(value, path);
    if (v[0] == 0 && v[1] == 0 && v[2] == 0) fail(path, "the vector is zero; a direction is needed");
    return unitVector(v);
  }

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

// Parses `text`; invalid JSON and a key repeated within one object (nlohmann would keep the last
// silently; a repeat is more likely a mistake) are errors through `in`, the repeat named by its
// key path (`camera.fov`, `objects[3].scale`).
template <class Error>
Json parse(std::string_view text, const Reader<Error>& in) {
  // The containers open at the parser's position: each one's key path, its keys so far (objects)
  // or elements so far (arrays), and the key whose value comes next.
  struct Open {
    std::string path;
    bool array = false;
    std::size_t elements = 0;
    std::string key;
    std::set<std::string> keys;
  };
  std::vector<Open> open;
  const auto nextPath = [&]() -> std::string {
    if (open.empty()) return "";
    const Open& parent = open.back();
    return parent.array ? element(parent.path, parent.elements) : child(parent.path, parent.key);
  };
  const auto valueDone = [&] {
    if (!open.empty() && open.back().array) ++open.back().elements;
  };
  const Json::parser_callback_t rejectRepeatedKeys = [&](int, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
      case Json::parse_event_t::array_start:
        open.push_back({nextPath(), event == Json::parse_event_t::array_start, 0, {}, {}});
        break;
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end:
        if (!open.empty()) open.pop_back();
        valueDone();
        break;
      case Json::parse_event_t::key:
        if (!open.empty()) {
          open.back().key = parsed.get<std::string>();
          if (!open.back().keys.insert(open.back().key).second) {
            in.fail(child(open.back().path, open.back().key),
                    "the key appears twice in its object; each key may appear once");
          }
        }
        break;
      case Json::parse_event_t::value:
        valueDone();
        break;
    }
    return true;
  };
  try {
    return Json::parse(text.begin(), text.end(), rejectRepeatedKeys);
  } catch (const Json::exception& error) {
    std::string message = error.what();
    const std::size_t bracket = message.find("] ");
    if (message.rfind("[json.exception.", 0) == 0 && bracket != std::string::npos)
      message = message.substr(bracket + 2);
    std::string safe;
    for (const char c : message.substr(0, 300)) safe += (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) ? c : '?';
    in.fail("", "not valid JSON: " + safe);
  }
}

}  // namespace revolve::io::json
