#pragma once
/// \file
/// Running a piece of gdpn's own Python (the HTML report's plots, the sweeps) in the embedded
/// interpreter: text in, text out, so that no Python type crosses into the rest of gdpn.

#include <optional>
#include <string>

namespace gdpn::script {

/// Runs `source` (Python, named `filename` in tracebacks) as a fresh module and calls its
/// function `function` with the string `argument`; returns what it returns, as text. Starts the
/// interpreter when it is not running. Nullopt with `error` (the exception and its traceback)
/// when the source or the call raises.
std::optional<std::string> callPython(const std::string& source, const std::string& filename,
                                      const std::string& function, const std::string& argument,
                                      std::string& error);

}  // namespace gdpn::script
