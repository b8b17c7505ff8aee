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

// The rows of a CSV file from its lines (Lines over a whole text, or FileLines over a file read a
// block at a time): blank lines skipped; a first line equal to `header` skipped, and a first line
// that starts with a non-number reported as a wrong header; every other line split into fields and
// required to hold `columns` of them. Errors are InputErrors naming the file and line.
template <class LineSource>
class Rows {
 public:
  Rows(LineSource& lines, std::string_view file, std::string_view header, std::size_t columns)
      : lines_(lines), file_(file), header_(header), columns_(columns) {}

  // The next row's fields (valid until the next call), or nullptr after the last.
  const std::vector<std::string_view>* next();
  std::size_t line() const { return lines_.number(); }

 private:
  LineSource& lines_;
  std::string_view file_, header_;
  std::size_t columns_;
  bool first_ = true;
  std::vector<std::string_view> fields_;
};

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

template <class LineSource>
const std::vector<std::string_view>* Rows<LineSource>::next() {
  while (const std::optional<std::string_view> raw = lines_.next()) {
    const std::string_view line = trim(*raw);
    if (line.empty()) continue;
    fields_ = splitFields(line);
    if (first_) {
      first_ = false;
      if (!parseNumber<double>(fields_[0])) {
        std::string joined;
        for (std::size_t i = 0; i < fields_.size(); ++i) {
          if (i > 0) joined += ',';
          joined += fields_[i];
        }
        if (joined == header_) continue;
        throw InputError(file_, lines_.number(),
                         "header " + quote(line) + " is not the expected \"" + std::string(header_) + "\"");
      }
    }
    if (fields_.size() != columns_) {
      throw InputError(file_, lines_.number(),
                       "expected " + std::to_string(columns_) + " comma-separated values (" + std::string(header_) +
                           "), found " + std::to_string(fields_.size()));
    }
    return &fields_;
  }
  return nullptr;
}

}  // namespace revolve::io::csv
