#pragma once
/// \file
/// Python source shown read-only with line numbers and highlighting (keywords, strings,
/// comments, numbers, builtins), for the contents view. highlightPython() needs no ImGui;
/// drawPython() draws inside an ImGui frame.

#include <string_view>
#include <vector>

namespace gdpn::ide {

/// What a piece of a line of Python is.
enum class PyToken : unsigned char { Text, Keyword, Builtin, String, Comment, Number };

/// One piece of a line: [begin, end) of the line, and what it is.
struct PySpan {
  std::size_t begin = 0;  ///< first byte
  std::size_t end = 0;    ///< one past the last byte
  PyToken kind = PyToken::Text;  ///< what it is
};

/// Splits one line of Python into pieces covering it. `in_string` carries an open
/// triple-quoted string ('"' or '\'', 0 when none) from one line to the next.
std::vector<PySpan> highlightPython(std::string_view line, char& in_string);

/// Draws `code` in the current ImGui window, one numbered line per source line, numbered from
/// `first_line` (the model file's line; 1 when unknown). Line `error_line` of the code (1 its
/// first; 0 for none) is marked as the one with a syntax error. Returns the number of lines.
int drawPython(std::string_view code, int first_line, int error_line = 0);

}  // namespace gdpn::ide
