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

std::string readTextFile(const std::string& path, std::uint64_t maxBytes, std::string_view kind) {
  // O_NONBLOCK: opening a FIFO without a writer would otherwise wait for one; it is refused below.
  const Descriptor file(open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC));
  if (file.get() < 0) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  struct stat status {};
  if (fstat(file.get(), &status) != 0) throw InputError(path, 0, std::string("cannot read: ") + std::strerror(errno));
  if (!S_ISREG(status.st_mode)) throw InputError(path, 0, "is " + fileKindOf(status.st_mode) + ", not a regular file");
  const auto tooLarge = [&](const std::string& size) {
    return InputError(path, 0, size + " is too large: " + std::string(kind) + " is read up to " + byteCount(maxBytes));
  };
  if (std::uint64_t(status.st_size) > maxBytes) throw tooLarge("its " + byteCount(std::uint64_t(status.st_size)));
  std::string text(std::size_t(status.st_size), '\0');
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
    if (text.size() + std::size_t(got) > maxBytes) throw tooLarge("growing while read, it");
    text.append(chunk, std::size_t(got));
  }
  return text;
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
