#pragma once
/// \file
/// Checking a script's Python syntax without running it (the IDE's script editor compiles
/// each script when it loses focus).

#include <optional>
#include <string>

namespace gdpn::script {

/// A syntax error in a script: where and what.
struct SyntaxProblem {
  int line = 0;         ///< 1-based line of the script's own text (0 when Python gave none)
  int column = 0;       ///< 1-based column (0 when Python gave none)
  std::string message;  ///< Python's words ("invalid syntax", "expected ':'")
};

/// Compiles `code` as Python (a statement block, or an expression when `expression`) without
/// running it; nullopt when it compiles, else the first syntax error. Starts the interpreter
/// when it is not running.
std::optional<SyntaxProblem> syntaxProblem(const std::string& code, bool expression);

/// Starts the embedded interpreter once (the engine and the syntax check share it).
void startInterpreter();

/// Has Python's tracebacks quote the lines of `text` for the file `file` rather than the file
/// on disk (the IDE runs a model as Save will write it, its scripts compiled at their lines in
/// that text); an empty `file` does nothing. Starts the interpreter when it is not running.
void quoteSourceAs(const std::string& file, const std::string& text);

}  // namespace gdpn::script
