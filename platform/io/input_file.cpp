#include "io/input_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace revolve::io {
namespace {

class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }
  int release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }

 private:
  int fd_;
};

}  // namespace

namespace {
// Built by appending: GCC 12 warns falsely (-Wrestrict) on a chain of string operator+.
std::string located(std::string_view file, std::size_t line, const std::string& problem) {
  std::string text(file);
  if (line > 0) {
    text += ':';
    text += std::to_string(line);
  }
  text += ": ";
  text += problem;
  return text;
}
}  // namespace

InputError::InputError(std::string_view file, std::size_t line, const std::string& problem)
    : std::runtime_error(located(file, line, problem)) {}

std::string byteCount(std::uint64_t bytes) {
  char text[48];
  if (bytes >= (std::uint64_t{1} << 20) && bytes < (std::uint64_t{1} << 30) && bytes % (std::uint64_t{1} << 20) == 0) {
    std::snprintf(text, sizeof text, "%llu MiB", static_cast<unsigned long long>(bytes >> 20));  // the limits
  } else if (bytes >= 1000000000000) {
    std::snprintf(text, sizeof text, "%.3g TB", double(bytes) * 1e-12);
  } else if (bytes >= 1000000000) {
    std::snprintf(text, sizeof text, "%.3g GB", double(bytes) * 1e-9);
  } else if (bytes >= 1000000) {
    std::snprintf(text, sizeof text, "%.3g MB", double(bytes) * 1e-6);
  } else {
    std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
  }
  return text;
}

std::string fileKindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a plain file";
}

namespace {

InputError tooLarge(std::string_view path, const std::string& size, std::string_view kind, std::uint64_t maxBytes) {
  return InputError(path, 0, size + " is too large: " + std::string(kind) + " is read up to " + byteCount(maxBytes));
}

// The open descriptor of `path` if it is a regular file of at most `maxBytes`; its size in `size`.
int openRegularFile(const std::string& path, std::uint64_t maxBytes, std::string_view kind, std::uint64_t& size) {
  // O_NONBLOCK: opening a FIFO without a writer would otherwise wait for one; it is refused below.
  Descriptor file(open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC));
  if (file.get() < 0) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  struct stat status {};
  if (fstat(file.get(), &status) != 0) throw InputError(path, 0, std::string("cannot read: ") + std::strerror(errno));
  if (!S_ISREG(status.st_mode)) throw InputError(path, 0, "is " + fileKindOf(status.st_mode) + ", not a regular file");
  if (std::uint64_t(status.st_size) > maxBytes)
    throw tooLarge(path, "its " + byteCount(std::uint64_t(status.st_size)), kind, maxBytes);
  size = std::uint64_t(status.st_size);
  return file.release();
}

}  // namespace

std::string readTextFile(const std::string& path, std::uint64_t maxBytes, std::string_view kind) {
  std::uint64_t size = 0;
  const Descriptor file(openRegularFile(path, maxBytes, kind, size));
  std::string text(std::size_t(size), '\0');
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t got = read(file.get(), text.data() + done, text.size() - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw InputError(path, 0, std::string("read error: ") + std::strerror(errno));
    if (got == 0) break;  // it shrank meanwhile
    done += std::size_t(got);
  }
  text.resize(done);
  // A file that grows while read (a log being written) is read to its end, never beyond the limit.
  char chunk[1 << 16];
  for (;;) {
    const ssize_t got = read(file.get(), chunk, sizeof chunk);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw InputError(path, 0, std::string("read error: ") + std::strerror(errno));
    if (got == 0) break;
    if (text.size() + std::size_t(got) > maxBytes) throw tooLarge(path, "growing while read, it", kind, maxBytes);
    text.append(chunk, std::size_t(got));
  }
  return text;
}

FileLines::FileLines(const std::string& path, std::uint64_t maxBytes, std::string_view kind)
    : path_(path), kind_(kind), maxBytes_(maxBytes) {
  std::uint64_t size = 0;
  fd_ = openRegularFile(path, maxBytes, kind, size);
  // Room for the longest line, its '\n' and a block to read beyond it.
  buffer_.resize(std::size_t{1} << 20);
}

FileLines::~FileLines() {
  if (fd_ >= 0) close(fd_);
}

bool FileLines::fill() {
  if (atEnd_) return false;
  if (begin_ > 0) {  // keep the unread bytes, at the front
    std::copy(buffer_.begin() + std::ptrdiff_t(begin_), buffer_.begin() + std::ptrdiff_t(end_), buffer_.begin());
    end_ -= begin_;
    begin_ = 0;
  }
  for (;;) {
    const ssize_t got = read(fd_, buffer_.data() + end_, buffer_.size() - end_);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw InputError(path_, 0, std::string("read error: ") + std::strerror(errno));
    if (got == 0) {
      atEnd_ = true;
      return false;
    }
    bytesRead_ += std::uint64_t(got);
    // A file that grows while read is read to its end, never beyond the limit.
    if (bytesRead_ > maxBytes_) throw tooLarge(path_, "growing while read, it", kind_, maxBytes_);
    end_ += std::size_t(got);
    return true;
  }
}

std::optional<std::string_view> FileLines::next() {
  for (;;) {
    const char* const start = buffer_.data() + begin_;
    const auto* const newline = static_cast<const char*>(std::memchr(start, '\n', end_ - begin_));
    const std::size_t length = newline != nullptr ? std::size_t(newline - start) : end_ - begin_;
    // The refusal csv::Lines makes, before more of an overlong line is read.
    if (length > kMaxCsvLineBytes) {
      throw InputError(path_, number_ + 1,
                       "the line is more than " + std::to_string(kMaxCsvLineBytes) +
                           " bytes long; a line of these files holds at most " + std::to_string(kMaxCsvLineBytes));
    }
    if (newline != nullptr) {
      begin_ += length + 1;
      ++number_;
      return std::string_view(start, length);
    }
    if (!fill()) {  // the end: a last line without its '\n', or nothing
      if (length == 0) return std::nullopt;
      begin_ = end_;
      ++number_;
      return std::string_view(buffer_.data() + end_ - length, length);
    }
  }
}

const std::string& FileTexts::text(const std::string& path, std::uint64_t maxBytes, std::string_view kind) {
  if (const auto kept = texts.find(path); kept != texts.end()) {
    if (kept->second.size() > maxBytes) {
      throw InputError(path, 0,
                       "its " + byteCount(kept->second.size()) + " is too large: " + std::string(kind) +
                           " is read up to " + byteCount(maxBytes));
    }
    return kept->second;
  }
  if (!readFiles) throw InputError(path, 0, "not among the files supplied with the text that names it");
  return texts.emplace(path, readTextFile(path, maxBytes, kind)).first->second;
}

}  // namespace revolve::io
