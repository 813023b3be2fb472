#pragma once
/// \file
/// Source locations and the diagnostics list that every loader fills.

#include <cstdint>
#include <iosfwd>
#include <set>
#include <string>
#include <vector>

namespace gdpn::core {

/// A position in a source file. Lines and columns count from 1; 0 means "unknown".
struct SourceLoc {
  std::string file;  ///< path as the user gave it
  int line = 0;      ///< 1-based line, 0 when unknown
  int column = 0;    ///< 1-based column, 0 when unknown

  /// "file:line:col", or less when line or column are unknown.
  [[nodiscard]] std::string str() const;
  friend bool operator==(const SourceLoc&, const SourceLoc&) = default;
};

/// How bad a diagnostic is.
enum class Severity : std::uint8_t { Note, Warning, Error };

/// One message about the input, in GCC's form when printed.
struct Diagnostic {
  Severity severity = Severity::Error;  ///< error, warning or note
  SourceLoc loc;                        ///< where the problem is
  std::string message;                  ///< what is wrong, without a trailing period

  /// "file:line:col: error: message".
  [[nodiscard]] std::string str() const;
};

/// An ordered list of diagnostics. Loaders append to it and carry on where they can. A
/// diagnostic said before (the same severity, place and words: a page type's mistake met again
/// in its next instance) is said once, its notes with it.
class Diagnostics {
 public:
  /// Appends an error at `loc`.
  void error(SourceLoc loc, std::string message);
  /// Appends a warning at `loc`.
  void warning(SourceLoc loc, std::string message);
  /// Appends a note at `loc` (it explains the diagnostic before it).
  void note(SourceLoc loc, std::string message);
  /// Appends every diagnostic of `other`, in order.
  void append(const Diagnostics& other);

  /// True when at least one error was reported.
  [[nodiscard]] bool hasErrors() const { return errors_ > 0; }
  /// Number of errors reported.
  [[nodiscard]] std::size_t errorCount() const { return errors_; }
  /// All diagnostics in the order they were reported.
  [[nodiscard]] const std::vector<Diagnostic>& all() const { return list_; }
  /// Writes every diagnostic, one per line.
  void print(std::ostream& out) const;
  /// Every diagnostic joined by newlines.
  [[nodiscard]] std::string str() const;

 private:
  /// Appends `d` unless it was said before (then its notes are left out too).
  void add(Diagnostic d);
  std::vector<Diagnostic> list_;
  std::set<std::string> said_;   // each error's and warning's text, to say it once
  bool repeating_ = false;       // the last error or warning was said before: its notes go too
  std::size_t errors_ = 0;
};

}  // namespace gdpn::core
