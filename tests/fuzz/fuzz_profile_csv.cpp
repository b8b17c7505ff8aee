// Fuzz target: a profile CSV as revolve-trace reads it. Parse, validate, build every method, trace.
// Expected: InputError or ProfileError with a one-line message, or a profile whose shapes keep
// every query promise (fuzz_checks.h). Anything else, or a sanitizer report, is a finding.
#include "fuzz_checks.h"
#include "io/text_files.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

using namespace revolve;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  io::ProfileFile file;
  try {
    file = io::parseProfileCsv(text, "fuzz.csv");
  } catch (const io::InputError& error) {
    fuzz::checkOneLineMessage(error.what());
    return 0;
  }
  // One line number a point, increasing, within the text.
  FUZZ_CHECK(file.lines.size() == file.points.size());
  FUZZ_CHECK(!file.points.empty());
  for (std::size_t i = 0; i < file.lines.size(); ++i) {
    FUZZ_CHECK(file.lines[i] >= 1 && file.lines[i] <= size);
    FUZZ_CHECK(i == 0 || file.lines[i] > file.lines[i - 1]);
  }

  std::optional<Profile> profile;
  try {
    profile.emplace(file.points);
  } catch (const ProfileError& error) {
    // revolve-trace maps the index to a line of the file: it must name a point of the input.
    FUZZ_CHECK(error.index() < file.points.size());
    fuzz::checkOneLineMessage(error.what());
    return 0;
  }
  for (const ProfileWarning& warning : profile->warnings()) {
    FUZZ_CHECK(warning.index < file.points.size());
    fuzz::checkOneLineMessage(warning.message);
  }
  std::mt19937_64 random = fuzz::generatorFor({data, size});
  fuzz::exerciseShapes(*profile, random);
  return 0;
}
