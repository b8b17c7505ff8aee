#include "io/output_set.h"

#include "io/input_file.h"

#include <cerrno>
#include <cstdarg>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace revolve::io {
namespace {

struct Identity {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string normal;  // absolute, symbolic links resolved as far as the path exists
};

Identity identify(const std::string& path) {
  Identity identity;
  struct stat status {};
  if (stat(path.c_str(), &status) == 0)
    identity.exists = true, identity.device = status.st_dev, identity.inode = status.st_ino;
  std::error_code code;
  const std::filesystem::path absolute = std::filesystem::absolute(path, code);
  const std::filesystem::path normal = std::filesystem::weakly_canonical(absolute, code);
  identity.normal = (code ? absolute.lexically_normal() : normal).string();
  return identity;
}

bool sameFile(const Identity& a, const Identity& b) {
  if (a.exists && b.exists) return a.device == b.device && a.inode == b.inode;
  return !a.exists && !b.exists && a.normal == b.normal;
}

std::string named(std::string_view option) { return option.empty() ? std::string("the output") : std::string(option); }

}  // namespace

void OutputStream::fail(int error) const {
  throw std::runtime_error(output_ + ": write failed: " + std::strerror(error));
}

void OutputStream::write(const void* data, std::size_t bytes) {
  if (bytes > 0 && std::fwrite(data, 1, bytes, file_) != bytes) fail(errno);
}

void OutputStream::print(const char* format, ...) {
  std::va_list arguments;
  va_start(arguments, format);
  const int written = std::vfprintf(file_, format, arguments);
  va_end(arguments);
  if (written < 0) fail(errno);
}

struct OutputSet::Output {
  std::string option, path, temporary;
  Identity identity;
  int descriptor = -1;
  std::unique_ptr<OutputStream> stream;
  TemporaryRegistration registration;
};

OutputSet::OutputSet() = default;

OutputSet::~OutputSet() {
  if (committed_) return;
  for (const auto& output : outputs_) {
    if (output->stream) std::fclose(output->stream->file());
    if (output->descriptor >= 0) ::close(output->descriptor);
    unlink(output->temporary.c_str());
  }
}

void OutputSet::addInput(std::string_view what, const std::string& path) {
  if (!path.empty()) inputs_.push_back({std::string(what), path});
}

void OutputSet::add(std::string_view option, const std::string& path) {
  if (path.empty()) throw std::runtime_error(named(option) + ": the file name is empty");
  struct stat status {};
  if (stat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode)) {
    throw std::runtime_error(path + ": " + named(option) + " names " + fileKindOf(status.st_mode) +
                             ", not a regular file (an output is written beside it and renamed into place)");
  }
  auto output = std::make_unique<Output>();
  output->option = option;
  output->path = path;
  output->identity = identify(path);
  for (const Input& input : inputs_) {
    const Identity inputIdentity = identify(input.path);
    if (inputIdentity.exists && sameFile(output->identity, inputIdentity)) {
      throw std::runtime_error(path + ": " + named(option) + " names the same file as " + input.what +
                               " (an input); an output may not overwrite an input");
    }
  }
  for (const auto& other : outputs_) {
    if (sameFile(output->identity, other->identity)) {
      throw std::runtime_error(path + ": " + named(option) + " names the same file as " + named(other->option) + " (" +
                               other->path + "); each output needs a file of its own");
    }
  }
  const HeldSignals held;  // no window in which the temporary exists unregistered
  output->temporary = path + ".tmp-XXXXXX";
  output->descriptor = mkstemp(output->temporary.data());
  if (output->descriptor < 0) throw std::runtime_error(path + ": cannot create a file there: " + std::strerror(errno));
  output->registration = TemporaryRegistration(output->temporary);
  // mkstemp makes the file private (0600); give the result the permissions a plain create would.
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(output->descriptor, 0666 & ~mask);
  outputs_.push_back(std::move(output));
}

OutputSet::Output& OutputSet::find(const std::string& path) const {
  for (const auto& output : outputs_) {
    if (output->path == path) return *output;
  }
  throw std::logic_error(path + ": not an output of this run");
}

OutputStream& OutputSet::stream(const std::string& path) {
  Output& output = find(path);
  if (!output.stream) {
    if (output.descriptor < 0) output.descriptor = open(output.temporary.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    std::FILE* file = output.descriptor >= 0 ? fdopen(output.descriptor, "w") : nullptr;
    if (file == nullptr) throw std::runtime_error(path + ": cannot write: " + std::strerror(errno));
    output.descriptor = -1;  // the stream owns it now
    std::setvbuf(file, nullptr, _IOFBF, std::size_t{1} << 20);
    output.stream = std::make_unique<OutputStream>(file, path);
  }
  return *output.stream;
}

void OutputSet::write(const std::string& path, const std::function<void(std::FILE*)>& write) {
  OutputStream& out = stream(path);
  write(out.file());
  if (std::ferror(out.file())) {
    // The error indicator may be set by an operation that left no errno of its own.
    const int error = errno;
    out.fail(error != 0 ? error : EIO);
  }
  close(find(path));
}

void OutputSet::close(Output& output) {
  if (output.stream) {
    std::FILE* file = output.stream->file();
    errno = 0;
    const bool flushed = std::fflush(file) == 0 && !std::ferror(file);
    const int error = errno != 0 ? errno : EIO;
    // Every byte the stream (or a child handed its descriptor, as the plotter) wrote is in the
    // file: its size is the stream's position. A writer that ignored a failed write cannot pass.
    struct stat status {};
    const off_t length = flushed ? ftello(file) : -1;
    const bool whole = !flushed || (length >= 0 && fstat(fileno(file), &status) == 0 && status.st_size == length);
    const bool closed = std::fclose(file) == 0;
    const int closeError = errno;
    const OutputStream failed = *output.stream;
    output.stream.reset();
    if (!flushed) failed.fail(error);
    if (!whole) {
      throw std::runtime_error(output.path + ": write failed: the file holds " + std::to_string(status.st_size) +
                               " of the " + std::to_string(length) + " bytes written");
    }
    if (!closed) failed.fail(closeError);
  } else if (output.descriptor >= 0) {
    ::close(output.descriptor);
    output.descriptor = -1;
  }
}

void OutputSet::commit() {
  for (const auto& output : outputs_) close(*output);
  const HeldSignals held;
  // Hard links to the outputs being replaced, so that a failed rename can put back the ones done.
  std::vector<std::string> backups(outputs_.size());
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    if (!outputs_[i]->identity.exists) continue;
    std::string backup = outputs_[i]->path + ".old-XXXXXX";
    const int descriptor = mkstemp(backup.data());
    if (descriptor < 0) continue;  // no backup: that output cannot be put back
    ::close(descriptor);
    unlink(backup.c_str());
    if (link(outputs_[i]->path.c_str(), backup.c_str()) == 0) backups[i] = backup;
  }
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    if (std::rename(outputs_[i]->temporary.c_str(), outputs_[i]->path.c_str()) == 0) continue;
    const int error = errno;
    for (std::size_t j = 0; j < i; ++j) {
      if (!backups[j].empty()) {
        std::rename(backups[j].c_str(), outputs_[j]->path.c_str());
      } else if (!outputs_[j]->identity.exists) {
        unlink(outputs_[j]->path.c_str());
      }
    }
    for (std::size_t j = i; j < outputs_.size(); ++j) unlink(outputs_[j]->temporary.c_str());
    for (std::size_t j = i; j < outputs_.size(); ++j) {
      if (!backups[j].empty()) unlink(backups[j].c_str());
    }
    committed_ = true;  // nothing left to remove
    for (const auto& output : outputs_) output->registration = TemporaryRegistration();
    throw std::runtime_error(outputs_[i]->path + ": cannot replace: " + std::strerror(error) +
                             (i > 0 ? " (the outputs written before it were put back)" : ""));
  }
  for (const std::string& backup : backups) {
    if (!backup.empty()) unlink(backup.c_str());
  }
  for (const auto& output : outputs_) output->registration = TemporaryRegistration();
  committed_ = true;
}

void writeFileAtomically(const std::string& path, const std::function<void(std::FILE*)>& write) {
  OutputSet outputs;
  outputs.add("", path);
  outputs.write(path, write);
  outputs.commit();
}

}  // namespace revolve::io
