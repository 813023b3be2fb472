#pragma once
/// \file
/// Reading input files, with problems reported as diagnostics.

#include <optional>
#include <string>

#include "gdpn/core/diagnostics.h"

namespace gdpn::core {

/// The whole file at `path`; a missing, unreadable or folder path gives a diagnostic and nullopt.
std::optional<std::string> readFile(const std::string& path, Diagnostics& diags);

/// True when `text` is valid UTF-8 without control characters (tab, line feed and carriage
/// return allowed); otherwise reports the first offending place (in `file`).
bool checkUtf8(const std::string& text, const std::string& file, Diagnostics& diags);

}  // namespace gdpn::core
