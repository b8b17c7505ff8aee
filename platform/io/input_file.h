// Reading the tools' input files within limits: only a regular file is read (a FIFO, a device
// such as /dev/zero or /dev/urandom, a directory or a socket is refused by name before any byte is
// read, so nothing can hang or grow without end), and no file larger than the limit of its kind.
// Errors are InputErrors: one line naming the file (and the line, where there is one).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include <sys/types.h>

namespace revolve::io {

// "file:line: problem", or "file: problem" for a problem with the whole file (line 0).
class InputError : public std::runtime_error {
 public:
  InputError(std::string_view file, std::size_t line, const std::string& problem);
};

// JSON files (scenes, sensors): 64 MiB, a hundred times the largest bundled scene (3,000
// objects in 0.46 MB), because the parsed tree takes about ten times its text.
inline constexpr std::uint64_t kMaxJsonFileBytes = std::uint64_t{1} << 26;
// CSV files (profiles, rays, poses): 256 MiB, about 6 million rays or 10 hours of poses at 100 Hz.
inline constexpr std::uint64_t kMaxCsvFileBytes = std::uint64_t{1} << 28;
// One CSV line: 4 KiB. The longest a format needs is a ray's 8 numbers, a few hundred bytes even
// with every digit a double can carry; a longer line is not one of these files.
inline constexpr std::size_t kMaxCsvLineBytes = 4096;

// The whole contents of the regular file at `path`, if it holds at most `maxBytes`; InputError
// otherwise (missing, unreadable, not a regular file, too large: "its 80 MB is too large: `kind`
// is read up to 64 MiB", kind such as "a JSON file").
std::string readTextFile(const std::string& path, std::uint64_t maxBytes, std::string_view kind);

// The texts of the files a reader opens, by path as opened: kept as it reads them (so that a scene
// or sensor can be rebuilt elsewhere from what it read), or supplied beforehand so that nothing is
// read from disk at all.
struct FileTexts {
  std::map<std::string, std::string> texts;
  bool readFiles = true;  // false: a path not among `texts` is an InputError; no file is opened

  // The text of `path`: the one kept, else the file read as readTextFile reads it (and kept). A kept
  // text is held to the same size limit.
  const std::string& text(const std::string& path, std::uint64_t maxBytes, std::string_view kind);
};

// The lines of the regular file at `path`, read a block at a time, so that memory stays bounded
// however large the file (a bulk object table of a million profiles is gigabytes of text): the same
// lines, numbering and limits as csv::Lines gives for a whole text (a line longer than
// kMaxCsvLineBytes is an InputError naming its number), and the file held to `maxBytes` as
// readTextFile holds it.
class FileLines {
 public:
  FileLines(const std::string& path, std::uint64_t maxBytes, std::string_view kind);
  ~FileLines();
  FileLines(const FileLines&) = delete;
  FileLines& operator=(const FileLines&) = delete;

  // The next line without its '\n', valid until the next call; nullopt after the last.
  std::optional<std::string_view> next();
  std::size_t number() const { return number_; }

 private:
  bool fill();  // reads another block after the unread bytes; false at the end of the file

  std::string path_, kind_;
  std::uint64_t maxBytes_ = 0, bytesRead_ = 0;
  int fd_ = -1;
  std::string buffer_;
  std::size_t begin_ = 0, end_ = 0;  // the unread bytes of buffer_
  bool atEnd_ = false;
  std::size_t number_ = 0;
};

// What a path that is not a regular file names, for messages: "a directory", "a FIFO (named
// pipe)", "a character device", "a block device", "a socket", else "not a plain file".
std::string fileKindOf(mode_t mode);

// Bytes as a short human figure for messages ("64 MiB", "1.5 GB").
std::string byteCount(std::uint64_t bytes);

}  // namespace revolve::io
