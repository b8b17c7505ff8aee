// The outputs of one run of a tool, written whole or not at all. Each output is written to a
// temporary file beside it (so that the final rename stays within one file system), created as
// soon as the output is named: that is also the check that its folder takes a new file, before any
// work. commit() renames them all into place once every step has succeeded; until then nothing a
// user can see has changed, and on an exception, or on SIGINT, SIGTERM or SIGHUP, the temporaries
// are removed and the tool exits (status 130, 143 or 129 on a signal: io/temporary_files.h).
//
// An output is refused, with one line naming it, when its path is empty, names something other
// than a regular file (a directory, /dev/null), or is the same file as an input or as another
// output of the run: by filesystem identity (device and inode) where both exist, by the
// normalised path (symbolic links resolved) otherwise.
#pragma once

#include "io/temporary_files.h"

#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace revolve::io {

// A stream into an output's temporary that checks every write: the first failure (a full disk,
// a file-size limit) throws std::runtime_error "<output>: write failed: <cause>" at once, so a
// long job stops instead of writing on into an error.
class OutputStream {
 public:
  OutputStream(std::FILE* file, std::string output) : file_(file), output_(std::move(output)) {}
  void write(const void* data, std::size_t bytes);
  void write(std::string_view text) { write(text.data(), text.size()); }
  void print(const char* format, ...) __attribute__((format(printf, 2, 3)));
  std::FILE* file() const { return file_; }
  [[noreturn]] void fail(int error) const;

 private:
  std::FILE* file_;
  std::string output_;
};

class OutputSet {
 public:
  OutputSet();
  ~OutputSet();  // an uncommitted set removes its temporaries
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // An input of the run (`what`: "the scene file", ...), which no output may be. Files that do
  // not exist are ignored (reading them fails anyway).
  void addInput(std::string_view what, const std::string& path);

  // Adds an output named by `option` ("-o", "--stats"; "" outside a command line) and creates its
  // temporary; std::runtime_error naming the path, the option and the rule when it is refused.
  // Outputs are refused against the inputs added so far and against each other.
  void add(std::string_view option, const std::string& path);

  // The output's temporary as a stream (opened on first use, buffered); errors throw at once.
  // Every output is written through its stream: no writer opens a temporary by name, so that no
  // library's unchecked writes (OpenImageIO's PNG writer ignores a full disk) can leave a short file.
  OutputStream& stream(const std::string& path);
  // Writes the output through `write`, then closes it and checks that every byte was written.
  void write(const std::string& path, const std::function<void(std::FILE*)>& write);

  // Closes every stream and verifies it (a failed flush or close, or a temporary whose size is not
  // the stream's length, throws, naming its output), then renames every temporary over its output,
  // signals held off meanwhile. If a rename fails, the outputs already renamed are put back as they
  // were (from hard links made beforehand) and std::runtime_error names it.
  void commit();

 private:
  struct Output;
  Output& find(const std::string& path) const;
  void close(Output& output);

  std::vector<std::unique_ptr<Output>> outputs_;
  struct Input {
    std::string what, path;
  };
  std::vector<Input> inputs_;
  bool committed_ = false;
};

// Writes `path` alone, whole or not at all: an OutputSet of one output, committed at once.
void writeFileAtomically(const std::string& path, const std::function<void(std::FILE*)>& write);

}  // namespace revolve::io
