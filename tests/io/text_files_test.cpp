// The CSV readers and writers of platform/io: every rule of text_files.h has a test, and every error
// message is checked for what the rule says it must name: the file, the line, the field and the
// offending text. Expected numbers are reasoned from the decimal text and IEEE rounding, not taken
// from the code under test.
#include "io/text_files.h"

#include "scratch_directory.h"
#include "support/test_seeds.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace revolve::io {
namespace {

using revolve::testing::readWholeFile;
using revolve::testing::ScratchDirectory;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

constexpr float kInf = std::numeric_limits<float>::infinity();

// The message of the InputError that `parse` must throw.
template <class Parse>
std::string inputError(Parse&& parse) {
  try {
    parse();
  } catch (const InputError& error) {
    return error.what();
  } catch (const std::exception& error) {
    ADD_FAILURE() << "threw something other than InputError: " << error.what();
    return {};
  }
  ADD_FAILURE() << "input was accepted";
  return {};
}

std::string profileError(const std::string& text) {
  return inputError([&] { parseProfileCsv(text, "p.csv"); });
}
std::string raysError(const std::string& text) {
  return inputError([&] { parseRaysCsv(text, "r.csv"); });
}

std::vector<double> radii(const ProfileFile& file) {
  std::vector<double> r;
  for (const Point2& p : file.points) r.push_back(p.r);
  return r;
}
std::vector<double> heights(const ProfileFile& file) {
  std::vector<double> z;
  for (const Point2& p : file.points) z.push_back(p.z);
  return z;
}
std::array<float, 8> fieldsOf(const Ray& ray) {
  return {ray.origin.x,    ray.origin.y,    ray.origin.z, ray.direction.x,
          ray.direction.y, ray.direction.z, ray.tnear,    ray.tfar};
}

// ---------------------------------------------------------------------------------------------
// Profile CSV

TEST(ProfileCsv, HeaderIsOptional) {
  const ProfileFile with = parseProfileCsv("r,z\n1,2\n3,4\n", "p.csv");
  const ProfileFile without = parseProfileCsv("1,2\n3,4\n", "p.csv");
  EXPECT_THAT(radii(with), ::testing::ElementsAre(1.0, 3.0));
  EXPECT_THAT(heights(with), ::testing::ElementsAre(2.0, 4.0));
  EXPECT_THAT(radii(without), ::testing::ElementsAre(1.0, 3.0));
  EXPECT_THAT(heights(without), ::testing::ElementsAre(2.0, 4.0));
  // Line numbers count the header: the points sit on lines 2 and 3, or 1 and 2 without it.
  EXPECT_THAT(with.lines, ::testing::ElementsAre(2u, 3u));
  EXPECT_THAT(without.lines, ::testing::ElementsAre(1u, 2u));
}

TEST(ProfileCsv, LastLineNeedsNoNewline) {
  EXPECT_THAT(radii(parseProfileCsv("1,2\n3,4", "p.csv")), ::testing::ElementsAre(1.0, 3.0));
}

TEST(ProfileCsv, WrongHeaderIsNamedWithTheExpectedOne) {
  EXPECT_THAT(profileError("x,y\n1,2\n"), AllOf(StartsWith("p.csv:1: "), HasSubstr("x,y"), HasSubstr("\"r,z\"")));
  // The header names the columns in order: swapped names are wrong, not a synonym.
  EXPECT_THAT(profileError("z,r\n1,2\n"), AllOf(StartsWith("p.csv:1: "), HasSubstr("z,r")));
}

TEST(ProfileCsv, HeaderIsOnlyAcceptedAsTheFirstLine) {
  // On line 2 "r" is a value that is not a number.
  EXPECT_THAT(profileError("1,2\nr,z\n"), AllOf(StartsWith("p.csv:2: "), HasSubstr("r = \"r\" is not a number")));
}

TEST(ProfileCsv, WrongColumnCountNamesExpectedAndFound) {
  EXPECT_THAT(profileError("1,2\n1,2,3\n"),
              AllOf(StartsWith("p.csv:2: "), HasSubstr("expected 2"), HasSubstr("found 3")));
  EXPECT_THAT(profileError("r,z\n5\n"), AllOf(StartsWith("p.csv:2: "), HasSubstr("expected 2"), HasSubstr("found 1")));
}

TEST(ProfileCsv, NonNumberNamesFieldAndText) {
  EXPECT_THAT(profileError("r,z\n1,abc\n"), AllOf(StartsWith("p.csv:2: "), HasSubstr("z = \"abc\" is not a number")));
  EXPECT_THAT(profileError("1,2\none,2\n"), AllOf(StartsWith("p.csv:2: "), HasSubstr("r = \"one\" is not a number")));
}

TEST(ProfileCsv, TrailingGarbageIsNotANumber) {
  // A prefix that parses is not enough: the whole field must be the number.
  EXPECT_THAT(profileError("1,2x\n"), AllOf(StartsWith("p.csv:1: "), HasSubstr("z = \"2x\" is not a number")));
  EXPECT_THAT(profileError("1,2\n3 4,5\n"), AllOf(StartsWith("p.csv:2: "), HasSubstr("r = \"3 4\" is not a number")));
  EXPECT_THAT(profileError("1,2\n1e,5\n"), AllOf(StartsWith("p.csv:2: "), HasSubstr("r = \"1e\" is not a number")));
}

TEST(ProfileCsv, EmptyFieldIsNotANumber) {
  EXPECT_THAT(profileError("1,2\n3,\n"), AllOf(StartsWith("p.csv:2: "), HasSubstr("z = \"\" is not a number")));
  EXPECT_THAT(profileError("1,2\n,3\n"), AllOf(StartsWith("p.csv:2: "), HasSubstr("r = \"\" is not a number")));
}

TEST(ProfileCsv, NonFiniteValuesPassTheSyntaxCheck) {
  // The reader checks syntax only; the Profile constructor rejects non-finite points with their
  // index, which revolve-trace maps back to the line (tested in revolve_trace_cli_test).
  const ProfileFile file = parseProfileCsv("nan,1\n2,inf\n", "p.csv");
  ASSERT_EQ(file.points.size(), 2u);
  EXPECT_TRUE(std::isnan(file.points[0].r));
  EXPECT_EQ(file.points[1].z, std::numeric_limits<double>::infinity());
}

TEST(ProfileCsv, BlankLinesAreSkippedButCounted) {
  // Lines: 1 empty, 2 spaces, 3 point, 4 tab, 5 point, 6 empty.
  const ProfileFile file = parseProfileCsv("\n  \n1,2\n\t\n3,4\n\n", "p.csv");
  EXPECT_THAT(radii(file), ::testing::ElementsAre(1.0, 3.0));
  EXPECT_THAT(file.lines, ::testing::ElementsAre(3u, 5u));
  // A header may follow blank lines: it is the first non-blank line.
  EXPECT_THAT(parseProfileCsv("\nr,z\n1,2\n", "p.csv").lines, ::testing::ElementsAre(3u));
  // Errors name the physical line.
  EXPECT_THAT(profileError("1,2\n\n\nx,2\n"), StartsWith("p.csv:4: "));
}

TEST(ProfileCsv, CrlfLineEndingsAreAccepted) {
  const ProfileFile file = parseProfileCsv("r,z\r\n1,2\r\n\r\n3,4\r\n", "p.csv");
  EXPECT_THAT(radii(file), ::testing::ElementsAre(1.0, 3.0));
  EXPECT_THAT(heights(file), ::testing::ElementsAre(2.0, 4.0));
  EXPECT_THAT(file.lines, ::testing::ElementsAre(2u, 4u));
  // The carriage return is not part of the last field, so it is not quoted in messages either.
  EXPECT_THAT(profileError("1,2\r\n3,x\r\n"),
              AllOf(StartsWith("p.csv:2: "), HasSubstr("z = \"x\""), Not(HasSubstr("\r"))));
}

TEST(ProfileCsv, LeadingPlusIsAccepted) {
  const ProfileFile file = parseProfileCsv("+1,+2.5\n+0,-3\n", "p.csv");
  EXPECT_THAT(radii(file), ::testing::ElementsAre(1.0, 0.0));
  EXPECT_THAT(heights(file), ::testing::ElementsAre(2.5, -3.0));
  // One sign only: "+-1" and "++1" are not numbers, nor is a lone "+".
  EXPECT_THAT(profileError("1,2\n+-1,2\n"), HasSubstr("r = \"+-1\" is not a number"));
  EXPECT_THAT(profileError("1,2\n++1,2\n"), HasSubstr("r = \"++1\" is not a number"));
  EXPECT_THAT(profileError("1,2\n1,+\n"), HasSubstr("z = \"+\" is not a number"));
}

TEST(ProfileCsv, ValuesAreReadAsDoubles) {
  // Compared with double literals: the compiler rounds the same decimal text to nearest.
  const ProfileFile file = parseProfileCsv("0.1,1e-300\n2.5e300,-0.30000000000000004\n", "p.csv");
  EXPECT_THAT(radii(file), ::testing::ElementsAre(0.1, 2.5e300));
  EXPECT_THAT(heights(file), ::testing::ElementsAre(1e-300, -0.30000000000000004));
}

TEST(ProfileCsv, EmptyFileHasNoPoints) {
  // Line 0: the problem is the file as a whole, not any one line.
  EXPECT_THAT(profileError(""), AllOf(StartsWith("p.csv: "), HasSubstr("no profile points")));
  EXPECT_THAT(profileError("\n \r\n\n"), AllOf(StartsWith("p.csv: "), HasSubstr("no profile points")));
}

TEST(ProfileCsv, HeaderAloneHasNoPoints) {
  EXPECT_THAT(profileError("r,z\n"), AllOf(StartsWith("p.csv: "), HasSubstr("no profile points")));
}

TEST(ProfileCsv, BinaryGarbageGivesOneShortPrintableLine) {
  // revolve-trace prints the message as its one line of stderr: a control character or a whole
  // binary line copied into it would break that line or flood the terminal.
  std::string garbage = "\x01\x02\x7f\x1b[2J\r\v\f";
  for (int i = 0; i < 5000; ++i) garbage += static_cast<char>(0x80 + i % 128);
  const std::string message = profileError(garbage + "\n1,2\n");
  EXPECT_THAT(message, StartsWith("p.csv:1: "));
  EXPECT_LT(message.size(), 200u);
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    EXPECT_TRUE(byte >= 0x20 && byte < 0x7f) << "unprintable byte " << int(byte) << " in: " << message;
  }
}

TEST(ProfileCsv, MissingFileIsNamedWithTheCause) {
  const ScratchDirectory directory;
  const std::string path = directory / "absent.csv";
  EXPECT_THAT(inputError([&] { readProfileCsv(path); }),
              AllOf(StartsWith(path + ": "), HasSubstr("No such file or directory")));
}

TEST(ProfileCsv, ReadsTheFileItIsGiven) {
  const ScratchDirectory directory;
  const std::string path = directory.write("p.csv", "r,z\r\n0,0\n1,0.5\n");
  const ProfileFile file = readProfileCsv(path);
  EXPECT_THAT(radii(file), ::testing::ElementsAre(0.0, 1.0));
  // Messages from a file read from disk carry its path, as given.
  EXPECT_THAT(inputError([&] { readProfileCsv(directory.write("bad.csv", "1,2\n3,y\n")); }),
              StartsWith(directory / "bad.csv" + ":2: "));
}

// A directory opens like a file but cannot be read; the readers must say so rather than see an
// empty file (which for rays is valid: zero rays).
TEST(ReadTextFile, DirectoryIsAnError) {
  const ScratchDirectory directory;
  EXPECT_THAT(inputError([&] { readTextFile(directory.path().string(), kMaxCsvFileBytes, "a CSV file"); }),
              StartsWith(directory.path().string() + ": "));
}

// ---------------------------------------------------------------------------------------------
// Rays CSV

constexpr const char* kRayHeader = "ox,oy,oz,dx,dy,dz,tnear,tfar";
// The field names of the documented header, in column order.
const std::array<std::string, 8> kRayFields = {"ox", "oy", "oz", "dx", "dy", "dz", "tnear", "tfar"};

// A valid ray line with field `index` replaced by `text`.
std::string rayLineWith(std::size_t index, const std::string& text) {
  std::array<std::string, 8> fields = {"1", "2", "3", "4", "5", "6", "0.5", "7"};
  fields[index] = text;
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + fields[i];
  return line + "\n";
}

TEST(RaysCsv, HeaderIsOptional) {
  const std::string body = "1,2,3,4,5,6,0.5,7\n-1,-2,-3,0,0,1,0,inf\n";
  for (const std::string& text : {std::string(kRayHeader) + "\n" + body, body}) {
    const std::vector<Ray> rays = parseRaysCsv(text, "r.csv");
    ASSERT_EQ(rays.size(), 2u);
    EXPECT_THAT(fieldsOf(rays[0]), ::testing::ElementsAre(1, 2, 3, 4, 5, 6, 0.5f, 7));
    EXPECT_THAT(fieldsOf(rays[1]), ::testing::ElementsAre(-1, -2, -3, 0, 0, 1, 0, kInf));
  }
}

TEST(RaysCsv, WrongHeaderIsNamedWithTheExpectedOne) {
  EXPECT_THAT(raysError("ox,oy,oz,dx,dy,dz,tmin,tmax\n1,2,3,4,5,6,0,1\n"),
              AllOf(StartsWith("r.csv:1: "), HasSubstr("tmin"), HasSubstr(std::string("\"") + kRayHeader + "\"")));
  // The profile's header is not the rays' header.
  EXPECT_THAT(raysError("r,z\n"), StartsWith("r.csv:1: "));
}

TEST(RaysCsv, WrongColumnCountNamesExpectedAndFound) {
  EXPECT_THAT(raysError("1,2,3,4,5,6,0\n"),
              AllOf(StartsWith("r.csv:1: "), HasSubstr("expected 8"), HasSubstr(kRayHeader), HasSubstr("found 7")));
  EXPECT_THAT(raysError("1,2,3,4,5,6,0,1\n1,2,3,4,5,6,0,1,2\n"),
              AllOf(StartsWith("r.csv:2: "), HasSubstr("expected 8"), HasSubstr("found 9")));
}

TEST(RaysCsv, NonNumberNamesItsField) {
  for (std::size_t i = 0; i < kRayFields.size(); ++i) {
    SCOPED_TRACE(kRayFields[i]);
    EXPECT_THAT(raysError("1,0,0,1,0,0,0,1\n" + rayLineWith(i, "abc")),
                AllOf(StartsWith("r.csv:2: "), HasSubstr(kRayFields[i] + " = \"abc\" is not a number")));
  }
}

TEST(RaysCsv, TrailingGarbageIsNotANumber) {
  // "1.5f" is a C float literal, not a CSV number.
  EXPECT_THAT(raysError(rayLineWith(2, "1.5f")), HasSubstr("oz = \"1.5f\" is not a number"));
  EXPECT_THAT(raysError(rayLineWith(6, "0.5.1")), HasSubstr("tnear = \"0.5.1\" is not a number"));
}

TEST(RaysCsv, EmptyFieldIsNotANumber) {
  EXPECT_THAT(raysError("1,0,0,1,0,0,0,1\n" + rayLineWith(4, "")),
              AllOf(StartsWith("r.csv:2: "), HasSubstr("dy = \"\" is not a number")));
  EXPECT_THAT(raysError("1,0,0,1,0,0,0,\n"), HasSubstr("tfar = \"\" is not a number"));
}

TEST(RaysCsv, NanIsRejectedInEveryField) {
  for (std::size_t i = 0; i < kRayFields.size(); ++i) {
    SCOPED_TRACE(kRayFields[i]);
    EXPECT_THAT(raysError(rayLineWith(i, "nan")),
                AllOf(StartsWith("r.csv:1: "), HasSubstr(kRayFields[i] + " = \"nan\" is not finite")));
  }
}

TEST(RaysCsv, InfinityIsRejectedExceptAsTfar) {
  for (std::size_t i = 0; i + 1 < kRayFields.size(); ++i) {
    SCOPED_TRACE(kRayFields[i]);
    EXPECT_THAT(raysError(rayLineWith(i, "inf")), HasSubstr(kRayFields[i] + " = \"inf\" is not finite"));
    EXPECT_THAT(raysError(rayLineWith(i, "-inf")), HasSubstr(kRayFields[i] + " = \"-inf\" is not finite"));
  }
  // tfar may be +inf ("no limit"), never -inf.
  EXPECT_THAT(raysError(rayLineWith(7, "-inf")), HasSubstr("tfar = \"-inf\" is not finite"));
}

TEST(RaysCsv, TfarMayBeInfinite) {
  for (const char* text : {"inf", "+inf", "infinity"}) {
    SCOPED_TRACE(text);
    const std::vector<Ray> rays = parseRaysCsv(rayLineWith(7, text), "r.csv");
    ASSERT_EQ(rays.size(), 1u);
    EXPECT_EQ(rays[0].tfar, kInf);
  }
}

TEST(RaysCsv, ZeroDirectionIsRejected) {
  EXPECT_THAT(raysError("1,2,3,4,5,6,0,1\n\n1,2,3,0,0,0,0,1\n"),
              AllOf(StartsWith("r.csv:3: "), HasSubstr("direction"), HasSubstr("zero")));
  // -0 is zero too.
  EXPECT_THAT(raysError("1,2,3,-0,0,-0,0,1\n"), HasSubstr("zero"));
}

TEST(RaysCsv, TinyDirectionIsNotZero) {
  // 1e-45 rounds to the smallest subnormal float 2^-149 (1.4013e-45), which is not zero.
  const std::vector<Ray> rays = parseRaysCsv("0,0,0,0,1e-45,0,0,1\n", "r.csv");
  ASSERT_EQ(rays.size(), 1u);
  EXPECT_EQ(rays[0].direction.y, 0x1p-149f);
}

TEST(RaysCsv, NegativeTnearIsRejected) {
  EXPECT_THAT(raysError(rayLineWith(6, "-1")),
              AllOf(StartsWith("r.csv:1: "), HasSubstr("tnear = \"-1\""), HasSubstr("negative")));
  // -0 equals 0, which 0 <= tnear allows.
  EXPECT_EQ(parseRaysCsv(rayLineWith(6, "-0"), "r.csv").at(0).tnear, 0.0f);
}

TEST(RaysCsv, TnearAboveTfarIsRejected) {
  EXPECT_THAT(raysError("0,0,0,1,0,0,2,1\n"),
              AllOf(StartsWith("r.csv:1: "), HasSubstr("tnear = \"2\""), HasSubstr("tfar = \"1\"")));
  // tnear == tfar is an interval of one point, allowed by tnear <= tfar.
  EXPECT_EQ(parseRaysCsv("0,0,0,1,0,0,3,3\n", "r.csv").size(), 1u);
  // Compared after rounding to float: 1.00000001 is within half an ulp (2^-24) of 1, so both read
  // as 1.0f and the interval [1, 1] is valid.
  EXPECT_EQ(parseRaysCsv("0,0,0,1,0,0,1.00000001,1\n", "r.csv").size(), 1u);
}

TEST(RaysCsv, BlankLinesAreSkippedAndCrlfAccepted) {
  const std::string text =
      std::string("\r\n") + kRayHeader + "\r\n\r\n  \r\n1,2,3,4,5,6,0,1\r\n\t\r\n0,0,0,1,0,0,0,inf\r\n";
  const std::vector<Ray> rays = parseRaysCsv(text, "r.csv");
  ASSERT_EQ(rays.size(), 2u);
  EXPECT_THAT(fieldsOf(rays[0]), ::testing::ElementsAre(1, 2, 3, 4, 5, 6, 0, 1));
  EXPECT_EQ(rays[1].tfar, kInf);  // the "\r" is not part of "inf"
  // Blanks on lines 1, 3, 4 and 6, header on 2, rays on 5 and 7: a bad line appended is line 8.
  EXPECT_THAT(raysError(text + "1,2,3,4,5,6,0,x\r\n"), StartsWith("r.csv:8: "));
}

TEST(RaysCsv, LeadingPlusIsAccepted) {
  const std::vector<Ray> rays = parseRaysCsv("+1,+2,+3,+4,-5,+6,+0.5,+7\n", "r.csv");
  ASSERT_EQ(rays.size(), 1u);
  EXPECT_THAT(fieldsOf(rays[0]), ::testing::ElementsAre(1, 2, 3, 4, -5, 6, 0.5f, 7));
  EXPECT_THAT(raysError("1,0,0,1,0,0,0,1\n" + rayLineWith(0, "+-1")),
              AllOf(StartsWith("r.csv:2: "), HasSubstr("ox = \"+-1\" is not a number")));
}

TEST(RaysCsv, ValuesAreRoundedOnceToFloat) {
  // 0.1 and 1e-3 as float literals: the compiler rounds the decimal to the nearest float.
  EXPECT_EQ(parseRaysCsv(rayLineWith(0, "0.1"), "r.csv").at(0).origin.x, 0.1f);
  EXPECT_EQ(parseRaysCsv(rayLineWith(6, "1e-3"), "r.csv").at(0).tnear, 1e-3f);
  // 1.0000000596046448 lies just above 1 + 2^-24 = 1.000000059604644775..., the midpoint between
  // the floats 1 and 1 + 2^-23. Rounded once it is 1 + 2^-23 (0x1.000002p0f). Through double it
  // would first become the midpoint exactly (the excess 2.5e-17 is below half a double ulp,
  // 1.1e-16) and then tie to even: 1.0f. So this value tells single from double rounding.
  constexpr const char* kJustAboveMidpoint = "1.0000000596046448";
  EXPECT_EQ(parseRaysCsv(rayLineWith(1, kJustAboveMidpoint), "r.csv").at(0).origin.y, 0x1.000002p0f);
  ASSERT_EQ(static_cast<float>(std::strtod(kJustAboveMidpoint, nullptr)), 1.0f)
      << "the example no longer separates single from double rounding";
}

TEST(RaysCsv, ValuesBeyondFloatRangeRoundAsIeeeSays) {
  // Read "as 32-bit floats": a decimal below half the smallest subnormal (2^-150 ~ 7e-46) rounds
  // to zero, one between subnormals rounds to the nearest (1e-40 lies between 2^-133 multiples),
  // and one beyond FLT_MAX + half an ulp rounds to infinity, which only tfar may be.
  const std::vector<Ray> rays = parseRaysCsv("0,0,1e-50,1,1e-40,0,0,1e39\n", "r.csv");
  ASSERT_EQ(rays.size(), 1u);
  EXPECT_EQ(rays[0].origin.z, 0.0f);
  EXPECT_EQ(rays[0].direction.y, 1e-40f);
  EXPECT_EQ(rays[0].tfar, kInf);
  EXPECT_THAT(raysError("1e39,0,0,1,0,0,0,1\n"),
              AllOf(StartsWith("r.csv:1: "), HasSubstr("ox = \"1e39\""), HasSubstr("not finite")));
  EXPECT_THAT(raysError("0,0,0,-1e39,0,0,0,1\n"), HasSubstr("not finite"));
}

TEST(ProfileCsv, ValuesBeyondDoubleRangeRoundAsIeeeSays) {
  // 1e400 rounds to infinity (left for Profile to reject, naming the point), 1e-400 to zero.
  const ProfileFile profile = parseProfileCsv("1e400,0\n1e-400,1\n", "p.csv");
  ASSERT_EQ(profile.points.size(), 2u);
  EXPECT_EQ(profile.points[0].r, std::numeric_limits<double>::infinity());
  EXPECT_EQ(profile.points[1].r, 0.0);
}

TEST(RaysCsv, EmptyFileIsNoRays) {
  // Unlike a profile, a rays file may be empty: the output then has no ray lines.
  EXPECT_TRUE(parseRaysCsv("", "r.csv").empty());
  EXPECT_TRUE(parseRaysCsv(std::string(kRayHeader) + "\n\n", "r.csv").empty());
}

TEST(RaysCsv, MissingFileIsNamedWithTheCause) {
  const ScratchDirectory directory;
  // A path through a regular file: open fails with ENOTDIR, not ENOENT.
  const std::string path = directory.write("plain", "") + "/r.csv";
  EXPECT_THAT(inputError([&] { readRaysCsv(path); }), AllOf(StartsWith(path + ": "), HasSubstr("Not a directory")));
}

// ---------------------------------------------------------------------------------------------
// writeFileAtomically

TEST(WriteFileAtomically, WritesTheFileAndLeavesNoTemporary) {
  const ScratchDirectory directory;
  const std::string target = directory / "out.csv";
  writeFileAtomically(target, [](std::FILE* out) { std::fputs("first\n", out); });
  EXPECT_EQ(readWholeFile(target), "first\n");
  writeFileAtomically(target, [](std::FILE* out) { std::fputs("second\n", out); });
  EXPECT_EQ(readWholeFile(target), "second\n");
  EXPECT_THAT(directory.entries(), ::testing::ElementsAre("out.csv"));
}

TEST(WriteFileAtomically, ThrowingWriterLeavesTargetUntouched) {
  const ScratchDirectory directory;
  const std::string target = directory.write("out.csv", "old contents\n");
  // More than a stdio buffer, so that some of it reaches the temporary file before the throw.
  const auto writer = [](std::FILE* out) {
    for (int i = 0; i < 100000; ++i) std::fputs("new contents\n", out);
    throw std::logic_error("writer failed");
  };
  try {
    writeFileAtomically(target, writer);
    ADD_FAILURE() << "the writer's exception was swallowed";
  } catch (const std::logic_error& error) {
    EXPECT_STREQ(error.what(), "writer failed");  // propagated as is
  }
  EXPECT_EQ(readWholeFile(target), "old contents\n");
  EXPECT_THAT(directory.entries(), ::testing::ElementsAre("out.csv"));
}

TEST(WriteFileAtomically, ThrowingWriterCreatesNothing) {
  const ScratchDirectory directory;
  EXPECT_THROW(writeFileAtomically(directory / "out.csv", [](std::FILE*) { throw std::runtime_error("no"); }),
               std::runtime_error);
  EXPECT_TRUE(directory.entries().empty());
}

TEST(WriteFileAtomically, StreamErrorLeavesTargetUntouched) {
  const ScratchDirectory directory;
  const std::string target = directory.write("out.csv", "old contents\n");
  // Reading from the write-only stream sets its error indicator, as a failed write would.
  const auto writer = [](std::FILE* out) {
    std::fputs("partial", out);
    std::fgetc(out);
  };
  EXPECT_THAT(
      [&] {
        try {
          writeFileAtomically(target, writer);
        } catch (const std::runtime_error& error) {
          return std::string(error.what());
        }
        return std::string("accepted");
      }(),
      AllOf(StartsWith(target + ": "), HasSubstr("write failed")));
  EXPECT_EQ(readWholeFile(target), "old contents\n");
  EXPECT_THAT(directory.entries(), ::testing::ElementsAre("out.csv"));
}

TEST(WriteFileAtomically, MissingDirectoryIsAnErrorNamingTheTarget) {
  const ScratchDirectory directory;
  const std::string target = directory / "no/such/dir/out.csv";
  try {
    writeFileAtomically(target, [](std::FILE* out) { std::fputs("x", out); });
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& error) {
    EXPECT_THAT(error.what(), AllOf(StartsWith(target + ": "), HasSubstr("No such file or directory")));
  }
  EXPECT_TRUE(directory.entries().empty());
}

TEST(WriteFileAtomically, TargetThatIsADirectoryIsNotReplacedAndNoTemporaryRemains) {
  const ScratchDirectory directory;
  const std::string target = directory / "out.csv";
  std::filesystem::create_directory(target);
  // rename(2) cannot put a file in the place of a directory (EISDIR).
  EXPECT_THROW(writeFileAtomically(target, [](std::FILE* out) { std::fputs("x", out); }), std::runtime_error);
  EXPECT_TRUE(std::filesystem::is_directory(target));
  EXPECT_THAT(directory.entries(), ::testing::ElementsAre("out.csv"));
}

// Sets the process umask for the scope of a test and restores it.
class ScopedUmask {
 public:
  explicit ScopedUmask(mode_t mask) : previous_(umask(mask)) {}
  ~ScopedUmask() { umask(previous_); }

 private:
  mode_t previous_;
};

TEST(WriteFileAtomically, PermissionsAreThoseOfAPlainCreate) {
  // open(O_CREAT, 0666) gives 0666 & ~umask; mkstemp alone would give 0600 whatever the umask.
  for (const mode_t mask : {mode_t{022}, mode_t{027}, mode_t{0}, mode_t{077}}) {
    SCOPED_TRACE("umask " + std::to_string(mask));
    const ScopedUmask scoped(mask);
    const ScratchDirectory directory;
    const std::string target = directory / "out.csv";
    writeFileAtomically(target, [](std::FILE* out) { std::fputs("x", out); });
    struct stat status {};
    ASSERT_EQ(stat(target.c_str(), &status), 0);
    EXPECT_EQ(status.st_mode & 07777, 0666 & ~mask);
  }
}

// ---------------------------------------------------------------------------------------------
// writeHitsCsv

Hit hitWith(float t, Vec3 normal, float u, float v) {
  Hit hit{};
  hit.t = t;
  hit.normal = normal;
  hit.u = u;
  hit.v = v;
  return hit;
}

TEST(HitsCsv, HeaderMissLineAndHitLineInInputOrder) {
  const ScratchDirectory directory;
  const std::string path = directory / "h.csv";
  writeHitsCsv(path, {std::nullopt, hitWith(4.0f, {-1, 0, 0}, 0.5f, 0.25f), std::nullopt});
  EXPECT_EQ(readWholeFile(path),
            "hit,t,nx,ny,nz,u,v\n"
            "0,inf,0,0,0,0,0\n"
            "1,4,-1,0,0,0.5,0.25\n"
            "0,inf,0,0,0,0,0\n");
}

TEST(HitsCsv, NoRaysIsTheHeaderAlone) {
  const ScratchDirectory directory;
  writeHitsCsv(directory / "h.csv", {});
  EXPECT_EQ(readWholeFile(directory / "h.csv"), "hit,t,nx,ny,nz,u,v\n");
}

TEST(HitsCsv, NumbersHaveNineSignificantDigits) {
  const ScratchDirectory directory;
  const std::string path = directory / "h.csv";
  // Exact values of the floats, rounded by hand to 9 significant digits (%.9g):
  //   0.1f        = 13421773 * 2^-27 = 0.100000001490116...  -> 0.100000001
  //   1/3.f       = 11184811 * 2^-25 = 0.333333343267440...  -> 0.333333343
  //   123456789.f = 123456792 (spacing 8 above 2^26)         -> 123456792
  //   1e-10f      = 1.00000001335e-10                        -> 1.00000001e-10 (%g: exponent < -4)
  //   FLT_MAX     = 3.4028234664e38                          -> 3.40282347e+38
  //   0.6f        = 10066330 * 2^-24 = 0.600000023841857...  -> 0.600000024
  writeHitsCsv(path, {hitWith(0.1f, {1.0f / 3.0f, -0.6f, 1e-10f}, 123456789.0f, 0.0f),
                      hitWith(std::numeric_limits<float>::max(), {0, 0, 1}, 0.75f, 1.0f)});
  EXPECT_EQ(readWholeFile(path),
            "hit,t,nx,ny,nz,u,v\n"
            "1,0.100000001,0.333333343,-0.600000024,1.00000001e-10,123456792,0\n"
            "1,3.40282347e+38,0,0,1,0.75,1\n");
}

TEST(HitsCsv, NineDigitsReadBackToTheSameFloat) {
  // FLT_DECIMAL_DIG = 9: any float printed with 9 significant digits reads back exactly. Checked
  // on random finite bit patterns, across all exponents.
  for (const std::uint64_t seed : revolve::testing::testSeeds({1, 2})) {
    SCOPED_TRACE(revolve::testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    std::vector<float> values;
    while (values.size() < 6 * 2000) {
      const float value = std::bit_cast<float>(static_cast<std::uint32_t>(random()));
      if (std::isfinite(value)) values.push_back(value);
    }
    std::vector<std::optional<Hit>> hits;
    for (std::size_t i = 0; i < values.size(); i += 6) {
      hits.push_back(hitWith(values[i], {values[i + 1], values[i + 2], values[i + 3]}, values[i + 4], values[i + 5]));
    }
    const ScratchDirectory directory;
    writeHitsCsv(directory / "h.csv", hits);
    std::istringstream in(readWholeFile(directory / "h.csv"));
    std::string line;
    std::getline(in, line);
    std::size_t next = 0;
    while (std::getline(in, line)) {
      ASSERT_TRUE(line.starts_with("1,")) << line;
      std::istringstream fields(line.substr(2));
      for (std::string field; std::getline(fields, field, ',');) {
        ASSERT_LT(next, values.size());
        float read = 0;
        const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), read);
        ASSERT_TRUE(error == std::errc() && end == field.data() + field.size()) << field;
        EXPECT_EQ(std::bit_cast<std::uint32_t>(read), std::bit_cast<std::uint32_t>(values[next]))
            << field << " was written for " << values[next];
        ++next;
      }
    }
    EXPECT_EQ(next, values.size());
  }
}

}  // namespace
}  // namespace revolve::io

namespace revolve::io {
namespace {

using revolve::testing::readWholeFile;
using revolve::testing::ScratchDirectory;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::exception& error) {
    return error.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

// ---------------------------------------------------------------------------------------------
// readTextFile: regular files only, within a limit; lines within a limit.

TEST(ReadTextFile, OnlyARegularFileIsReadAndNothingElseBlocksOrGrows) {
  const ScratchDirectory directory;
  const std::string fifo = directory / "pipe";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // A FIFO with no writer would block an ordinary open; it is refused at once instead.
  EXPECT_EQ(errorOf([&] { readTextFile(fifo, kMaxCsvFileBytes, "a CSV file"); }),
            fifo + ": is a FIFO (named pipe), not a regular file");
  EXPECT_EQ(errorOf([&] { readTextFile("/dev/zero", kMaxCsvFileBytes, "a CSV file"); }),
            "/dev/zero: is a character device, not a regular file");
  EXPECT_EQ(errorOf([&] { readTextFile(directory.path().string(), kMaxCsvFileBytes, "a CSV file"); }),
            directory.path().string() + ": is a directory, not a regular file");
}

TEST(ReadTextFile, AFileOverItsLimitIsRefusedBeforeItIsRead) {
  const ScratchDirectory directory;
  const std::string exact = directory.write("exact.csv", std::string(100, 'x'));
  EXPECT_EQ(readTextFile(exact, 100, "a test file"), std::string(100, 'x'));
  const std::string over = directory.write("over.csv", std::string(101, 'x'));
  EXPECT_EQ(errorOf([&] { readTextFile(over, 100, "a test file"); }),
            over + ": its 101 bytes is too large: a test file is read up to 100 bytes");
  // Sparse: a terabyte that takes no disk, refused from its size alone.
  const std::string huge = directory.write("huge.csv", "");
  ASSERT_EQ(truncate(huge.c_str(), off_t{1} << 40), 0);
  EXPECT_THAT(errorOf([&] { readTextFile(huge, kMaxCsvFileBytes, "a CSV file"); }),
              AllOf(StartsWith(huge + ": its 1.1 TB"), HasSubstr("is too large: a CSV file is read up to 256 MiB")));
}

TEST(CsvLines, ALineOverTheLimitIsAnErrorNamingItsNumberBeforeItIsSplit) {
  const std::string header = "ox,oy,oz,dx,dy,dz,tnear,tfar\n";
  EXPECT_EQ(errorOf([&] { parseRaysCsv(header + std::string(kMaxCsvLineBytes + 1, ','), "r.csv"); }),
            "r.csv:2: the line is 4097 bytes long; a line of these files holds at most 4096");
  // At the limit the line is read (and judged by its fields).
  EXPECT_THAT(errorOf([&] { parseRaysCsv(header + std::string(kMaxCsvLineBytes, ','), "r.csv"); }),
              HasSubstr("r.csv:2: expected 8"));
  EXPECT_THAT(errorOf([&] { parseProfileCsv(std::string(5000, '7'), "p.csv"); }),
              StartsWith("p.csv:1: the line is 5000 bytes long"));
}

TEST(RaysCsv, CoordinatesBeyondTwoToTheSixtyAreRefusedWithTheLimit) {
  // 2^60 = 1.152921504606846976e18; Embree asserts |x| <= 1.844e18.
  EXPECT_EQ(parseRaysCsv("1.15e18,0,0,1,0,0,0,inf\n", "r.csv").size(), 1u);
  EXPECT_EQ(
      errorOf([&] { parseRaysCsv("1.16e18,0,0,1,0,0,0,inf\n", "r.csv"); }),
      "r.csv:1: ox = \"1.16e18\" is beyond +-2^60 (1.15e18), the largest coordinate revolve traces and Embree accepts");
  EXPECT_THAT(errorOf([&] { parseRaysCsv("0,0,0,1,0,-2e18,0,inf\n", "r.csv"); }),
              StartsWith("r.csv:1: dz = \"-2e18\" is beyond +-2^60"));
}

// ---------------------------------------------------------------------------------------------
// OutputSet: the outputs of one run, whole and together or not at all.

TEST(OutputSet, NothingIsVisibleBeforeCommitAndEverythingAfter) {
  const ScratchDirectory directory;
  const std::string a = directory.write("a.txt", "old a"), b = directory / "b.txt";
  OutputSet outputs;
  outputs.add("--a", a);
  outputs.add("--b", b);
  outputs.stream(a).write("new a");
  outputs.write(b, [](std::FILE* out) { std::fputs("new b", out); });
  EXPECT_EQ(readWholeFile(a), "old a");
  EXPECT_FALSE(std::filesystem::exists(b));
  EXPECT_EQ(directory.entries().size(), 3u) << "a.txt and the two temporaries";
  outputs.commit();
  EXPECT_EQ(readWholeFile(a), "new a");
  EXPECT_EQ(readWholeFile(b), "new b");
  EXPECT_EQ(directory.entries(), (std::set<std::string>{"a.txt", "b.txt"}));
}

TEST(OutputSet, AnUncommittedSetLeavesEveryOutputAsItWas) {
  const ScratchDirectory directory;
  const std::string a = directory.write("a.txt", "old a"), b = directory / "b.txt";
  {
    OutputSet outputs;
    outputs.add("--a", a);
    outputs.add("--b", b);
    outputs.stream(a).write(std::string(1 << 21, 'x'));  // beyond the stream's buffer: bytes on disk
  }
  EXPECT_EQ(readWholeFile(a), "old a");
  EXPECT_EQ(directory.entries(), std::set<std::string>{"a.txt"});
}

TEST(OutputSet, RefusesEmptyNamesNonFilesInputsAndRepeatsByIdentity) {
  const ScratchDirectory directory;
  const std::string scene = directory.write("scene.json", "{}");
  std::filesystem::create_hard_link(scene, directory / "hard.json");
  std::filesystem::create_symlink("scene.json", directory / "soft.json");
  std::filesystem::create_directory(directory / "folder");
  OutputSet outputs;
  outputs.addInput("the scene file", scene);
  outputs.addInput("a missing file", directory / "absent.csv");  // ignored: it is no file
  EXPECT_EQ(errorOf([&] { outputs.add("-o", ""); }), "-o: the file name is empty");
  EXPECT_EQ(errorOf([&] { outputs.add("-o", directory / "folder"); }),
            directory / "folder" +
                ": -o names a directory, not a regular file (an output is written beside it and renamed into place)");
  EXPECT_THAT(errorOf([&] { outputs.add("-o", "/dev/null"); }), StartsWith("/dev/null: -o names a character device"));
  for (const std::string& same :
       {scene, directory / "hard.json", directory / "soft.json", directory / "folder/../scene.json"}) {
    EXPECT_EQ(
        errorOf([&] { outputs.add("--stats", same); }),
        same + ": --stats names the same file as the scene file (an input); an output may not overwrite an input");
  }
  outputs.add("-o", directory / "out.png");
  EXPECT_EQ(errorOf([&] { outputs.add("--stats", directory / "./out.png"); }),
            directory / "./out.png" + ": --stats names the same file as -o (" + directory / "out.png" +
                "); each output needs a file of its own");
  outputs.add("--csv", directory / "absent.csv");
}

// When a rename fails part-way (here the second output's path became a directory meanwhile), the
// output already renamed is put back as it was, and no temporary or backup remains.
TEST(OutputSet, AFailedRenamePutsBackTheOutputsAlreadyReplaced) {
  const ScratchDirectory directory;
  const std::string a = directory.write("a.txt", "old a"), c = directory / "c.txt", b = directory / "b.txt";
  OutputSet outputs;
  outputs.add("--a", a);
  outputs.add("--c", c);
  outputs.add("--b", b);
  outputs.stream(a).write("new a");
  outputs.stream(c).write("new c");
  outputs.stream(b).write("new b");
  std::filesystem::create_directory(b);
  std::filesystem::create_directory(b + "/inside");  // rename(2) replaces only an empty directory
  EXPECT_THAT(errorOf([&] { outputs.commit(); }),
              AllOf(StartsWith(b + ": cannot replace: "), HasSubstr("(the outputs written before it were put back)")));
  EXPECT_EQ(readWholeFile(a), "old a");
  EXPECT_FALSE(std::filesystem::exists(c));
  EXPECT_EQ(directory.entries(), (std::set<std::string>{"a.txt", "b.txt"}));
}

// A temporary that does not hold what its stream wrote (here shortened behind the stream's back, as
// by a writer that ignores a failed write of its own) is refused before any rename.
TEST(OutputSet, ATemporaryShorterThanItsStreamIsAFailedWriteAndNothingIsReplaced) {
  const ScratchDirectory directory;
  const std::string image = directory.write("image.png", "an existing image");
  OutputSet outputs;
  outputs.add("-o", image);
  outputs.stream(image).write("a new image of 32 bytes, written");
  std::fflush(outputs.stream(image).file());
  std::string temporary;
  for (const std::string& name : directory.entries()) {
    if (name.rfind("image.png.tmp-", 0) == 0) temporary = directory / name;
  }
  ASSERT_FALSE(temporary.empty());
  std::filesystem::resize_file(temporary, 4);
  EXPECT_EQ(errorOf([&] { outputs.commit(); }), image + ": write failed: the file holds 4 of the 32 bytes written");
  EXPECT_EQ(readWholeFile(image), "an existing image");
}

// An injected writer on a full device: /dev/full fails every write with ENOSPC.
TEST(OutputStream, AFullDiskIsOneErrorNamingTheOutputAtTheFirstFailedWrite) {
  std::FILE* full = std::fopen("/dev/full", "w");
  ASSERT_NE(full, nullptr);
  std::setvbuf(full, nullptr, _IONBF, 0);
  OutputStream out(full, "scan.pcd");
  EXPECT_EQ(errorOf([&] { out.write("a point"); }), "scan.pcd: write failed: No space left on device");
  EXPECT_EQ(errorOf([&] { out.print("%d", 42); }), "scan.pcd: write failed: No space left on device");
  std::fclose(full);
}

}  // namespace
}  // namespace revolve::io
