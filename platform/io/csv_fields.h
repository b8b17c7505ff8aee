// Fields of CSV lines for the readers of platform/io: splitting, trimming, strict number parsing and
// quoting for messages. Internal to platform/io.
#pragma once

#include "io/input_file.h"

#include <charconv>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace revolve::io::csv {

// The lines of a file's text, split at '\n' and numbered from 1; a line longer than
// kMaxCsvLineBytes is an InputError naming its number, before anything splits it.
class Lines {
 public:
  Lines(std::string_view text, std::string_view file) : text_(text), file_(file) {}

  // The next line without its '\n', or nullopt after the last.
  std::optional<std::string_view> next() {
    if (text_.empty()) return std::nullopt;
    const std::size_t newline = text_.find('\n');
    const std::string_view line = text_.substr(0, newline);
    text_ = newline == std::string_view::npos ? std::string_view{} : text_.substr(newline + 1);
    ++number_;
    if (line.size() > kMaxCsvLineBytes) {
      throw InputError(file_, number_,
                       "the line is " + std::to_string(line.size()) +
                           " bytes long; a line of these files holds at most " + std::to_string(kMaxCsvLineBytes));
    }
    return line;
  }
  std::size_t number() const { return number_; }

 private:
  std::string_view text_, file_;
  std::size_t number_ = 0;
};

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

inline std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (std::size_t comma; (comma = line.find(',', start)) != std::string_view::npos; start = comma + 1) {
    fields.push_back(trim(line.substr(start, comma - start)));
  }
  fields.push_back(trim(line.substr(start)));
  return fields;
}

// Quoted for messages, shortened so that a binary line cannot flood the terminal.
inline std::string quote(std::string_view text) {
  std::string out = "\"";
  for (char c : text.substr(0, 40)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  return out + (text.size() > 40 ? "...\"" : "\"");
}

// A whole field as a number of type T, rounded once from its decimal text. A value beyond T's range
// rounds as IEEE says, to +-inf or (gradually) to zero: from_chars reports those as out of range
// without a value, so they are re-read with strtof / strtod, which round them correctly (the
// tools never change the C locale, so the decimal point is '.').
template <class T>
std::optional<T> parseNumber(std::string_view field) {
  if (field.size() > 1 && field.front() == '+' && field[1] != '-' && field[1] != '+') field.remove_prefix(1);
  if (field.empty()) return std::nullopt;
  T value{};
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (end != field.data() + field.size()) return std::nullopt;
  if (error == std::errc::result_out_of_range) {
    const std::string text(field);
    if constexpr (std::is_same_v<T, float>)
      return std::strtof(text.c_str(), nullptr);
    else
      return std::strtod(text.c_str(), nullptr);
  }
  if (error != std::errc()) return std::nullopt;
  return value;
}

}  // namespace revolve::io::csv
