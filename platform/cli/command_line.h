// What every tool's main() shares: CLI11 parsing that keeps the README's promise for errors (one
// line on stderr, "tool: problem (see --help)", and exit status 1, never CLI11's two lines and
// status 105), validators whose messages state the rule broken with the value as written, and the
// guard that turns any failure of the work into one line and status 1.
#pragma once

#include "io/curve_tolerance.h"
#include "io/temporary_files.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <new>
#include <optional>
#include <string>
#include <system_error>

namespace revolve::app {

// An error message on one line: a library's newlines (OpenImageIO's, CLI11's) become "; ".
inline std::string oneLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  for (std::size_t at; (at = text.find_first_of("\r\n")) != std::string::npos;) text.replace(at, 1, "; ");
  return text;
}

// Parses the command line; nullopt to go on, or the status to exit with (0 after --help).
inline std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv, const char* tool) {
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::fprintf(stderr, "%s: %s (see --help)\n", tool, oneLine(error.what()).c_str());
    return 1;
  }
}

// A file name: an empty value (-o "") is an error, never taken as "not given".
inline const CLI::Validator kNonEmpty(
    [](std::string& value) {
      return value.empty() ? std::string("the value is empty; a file name is needed") : std::string();
    },
    "FILE");

// A whole number of type T in [lo, hi], written in decimal. The message names what is wrong with
// the text as given: not a number, a number but not a whole one, or out of range. The text is
// replaced by its canonical decimal, so that CLI11's conversion (which reads a leading 0 as octal)
// sees the number this validator judged.
template <class T>
CLI::Validator wholeNumberIn(T lo, T hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        std::string_view digits(text);
        if (digits.size() > 1 && digits.front() == '+') digits.remove_prefix(1);
        T value{};
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
        if (end == digits.data() + digits.size() && error == std::errc()) {
          if (value < lo || value > hi) return text + " is out of range: it must lie in " + range;
          text = std::to_string(value);
          return {};
        }
        double number = 0;
        const auto [numberEnd, numberError] = std::from_chars(digits.data(), digits.data() + digits.size(), number);
        if (!digits.empty() && numberEnd == digits.data() + digits.size()) {
          if (numberError == std::errc() && std::isfinite(number) && number != std::floor(number)) {
            return text + " is not a whole number";
          }
          return text + " is out of range: it must be a whole number in " + range;
        }
        return "\"" + text.substr(0, 40) + "\" is not a number";
      },
      "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

// --tolerance into `target`: "pixel" where `pixelAllowed`, or a number held to the rule
// (io/curve_tolerance.h); a refused value (an empty one too) is CLI11's error naming it.
inline CLI::Option* addToleranceOption(CLI::App& app, std::optional<io::CurveTolerance>& target, bool pixelAllowed,
                                       const std::string& help) {
  return app
      .add_option_function<std::string>(
          "--tolerance",
          [&target, pixelAllowed](const std::string& text) { target = io::parseCurveTolerance(text, pixelAllowed); },
          help)
      ->check(CLI::Validator(
          [pixelAllowed](std::string& text) {
            return io::parseCurveTolerance(text, pixelAllowed) ? std::string()
                                                               : io::toleranceTextFault(text, pixelAllowed);
          },
          pixelAllowed ? "pixel|T" : "T"))
      ->type_name(pixelAllowed ? "TEXT" : "FLOAT");
}

// Runs a tool's work after its command line is parsed: any exception becomes one line "tool:
// message" and status 1; running out of memory names what the tool was working on (`subject`,
// its main input). Installs the handler that removes temporaries on SIGINT / SIGTERM / SIGHUP.
template <class Work>
int runTool(const char* tool, const std::string& subject, Work&& work) {
  io::removeTemporariesOnSignals();
  try {
    work();
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "%s: %s: out of memory (more than this machine could give)\n", tool, subject.c_str());
    return 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: %s\n", tool, oneLine(error.what()).c_str());
    return 1;
  }
  return 0;
}

}  // namespace revolve::app
