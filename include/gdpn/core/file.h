#pragma once
/// \file
/// Reading input files, with problems reported as diagnostics. Every input (model, input
/// events, PNML, mesh, elevation) is read only from a regular file no larger than
/// maxInputBytes(), so that `/dev/zero`, a FIFO or a gigabyte of garbage is refused at once.

#include <cstdint>
#include <optional>
#include <string>

#include "gdpn/core/diagnostics.h"

namespace gdpn::core {

/// The largest input file gdpn reads, in bytes (256 MiB unless set).
std::uintmax_t maxInputBytes();
/// Sets the largest input file gdpn reads, in bytes (tests lower it); returns the one before.
std::uintmax_t setMaxInputBytes(std::uintmax_t bytes);

/// Lowers (or raises) maxInputBytes() while it lives, then puts the one before back.
class InputLimit {
 public:
  /// Sets the limit to `bytes`.
  explicit InputLimit(std::uintmax_t bytes) : before_(setMaxInputBytes(bytes)) {}
  InputLimit(const InputLimit&) = delete;
  InputLimit& operator=(const InputLimit&) = delete;
  ~InputLimit() { setMaxInputBytes(before_); }

 private:
  std::uintmax_t before_;
};

/// The size in bytes of the regular file at `path` when it is one of at most maxInputBytes();
/// otherwise nullopt and `why` says what it is instead ("no such file", "is a FIFO, not a
/// regular file", "is 300 MiB; gdpn reads input files of at most 256 MiB").
std::optional<std::uintmax_t> inputFileSize(const std::string& path, std::string& why);

/// The whole file at `path`; a missing, unreadable, non-regular or too large path gives a
/// diagnostic and nullopt.
std::optional<std::string> readFile(const std::string& path, Diagnostics& diags);

/// True when `text` is valid UTF-8 without control characters (tab, line feed and carriage
/// return allowed); otherwise reports the first offending place (in `file`).
bool checkUtf8(const std::string& text, const std::string& file, Diagnostics& diags);

}  // namespace gdpn::core
