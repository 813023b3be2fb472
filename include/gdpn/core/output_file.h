#pragma once
/// \file
/// Output files that never destroy the old one: written beside the target, renamed into place
/// only when complete.

#include <fstream>
#include <functional>
#include <ostream>
#include <string>

namespace gdpn::core {

/// A file being written. `open` makes a temporary file `<dir>/.<name>.tmp-XXXXXX` in the
/// target's folder; callers write to `stream()` (or let another program write to `tempPath()`);
/// `commit` checks the write, flushes it to disk and renames it over the target. A file not
/// committed is removed when the object dies, so a failed write leaves the old file as it was
/// and no stray temporary file.
///
/// A target that exists and is not a regular file (/dev/stdout, a pipe, /dev/full) cannot be
/// replaced: it is written directly, and `commit` reports whether every byte went out.
class OutputFile {
 public:
  /// An output for `path`; nothing is created before `open`.
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Creates the temporary file (or opens a non-regular target). False with `why` on failure.
  [[nodiscard]] bool open(std::string& why);
  /// The stream to write to (open only after a successful `open`).
  [[nodiscard]] std::ostream& stream() { return stream_; }
  /// The path being written now: the temporary file, or the target itself when it is not a
  /// regular file. For a program that writes the file itself (the stream is closed first).
  [[nodiscard]] const std::string& tempPath() const { return temp_; }
  /// True when the target is not a regular file and is written in place.
  [[nodiscard]] bool direct() const { return direct_; }
  /// The target path.
  [[nodiscard]] const std::string& path() const { return path_; }
  /// Closes the stream without writing; the file at `tempPath()` stays for another writer.
  void closeStream();
  /// Checks that every byte was written, syncs the file to disk and renames it over the
  /// target. False with `why` (and the temporary file removed) on failure.
  [[nodiscard]] bool commit(std::string& why);
  /// Removes the temporary file; the target is left as it was.
  void discard();

 private:
  std::string path_;
  std::string temp_;
  std::ofstream stream_;
  bool direct_ = false;   // the target is not a regular file: written in place
  bool pending_ = false;  // a temporary file exists and is ours to remove
};

/// Writes `text` to `path` through an OutputFile. False with `why` on failure (the old file
/// unchanged).
[[nodiscard]] bool writeOutput(const std::string& path, const std::string& text, std::string& why);

/// The same with what `write` writes to the stream it is given (text made as it goes out).
[[nodiscard]] bool writeOutput(const std::string& path, const std::function<void(std::ostream&)>& write, std::string& why);

/// True when `a` and `b` name the same file: one existing file, or one path once links, `.`
/// and `..` are resolved (for files not yet made).
[[nodiscard]] bool sameFile(const std::string& a, const std::string& b);

}  // namespace gdpn::core
