#include "gdpn/ide/python_text.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

namespace gdpn::ide {
namespace {

constexpr std::array<std::string_view, 35> kKeywords = {
    "False", "None",   "True",    "and",      "as",       "assert", "async", "await", "break",
    "class", "continue", "def",   "del",      "elif",     "else",   "except", "finally", "for",
    "from",  "global", "if",      "import",   "in",       "is",     "lambda", "nonlocal", "not",
    "or",    "pass",   "raise",   "return",   "try",      "while",  "with",  "yield"};
constexpr std::array<std::string_view, 16> kBuiltins = {"abs", "all",   "any", "float", "int",  "len",   "list",  "max",
                                                        "min", "print", "range", "round", "self", "set", "str", "sum"};

bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

bool contains(const auto& words, std::string_view w) { return std::find(words.begin(), words.end(), w) != words.end(); }

ImVec4 colourOf(PyToken kind) {
  switch (kind) {
    case PyToken::Text: return {0.86f, 0.86f, 0.86f, 1.0f};
    case PyToken::Keyword: return {0.80f, 0.55f, 0.95f, 1.0f};
    case PyToken::Builtin: return {0.45f, 0.75f, 0.95f, 1.0f};
    case PyToken::String: return {0.80f, 0.85f, 0.45f, 1.0f};
    case PyToken::Comment: return {0.50f, 0.58f, 0.50f, 1.0f};
    case PyToken::Number: return {0.95f, 0.65f, 0.40f, 1.0f};
  }
  return {1, 1, 1, 1};
}

/// The end of a string opened at `at` by `quote` (three of them when `triple`); npos when it
/// runs past the line.
std::size_t stringEnd(std::string_view line, std::size_t at, char quote, bool triple) {
  for (std::size_t i = at; i < line.size(); ++i) {
    if (line[i] == '\\') {
      ++i;
      continue;
    }
    if (line[i] != quote) continue;
    if (!triple) return i + 1;
    if (line.substr(i, 3) == std::string(3, quote)) return i + 3;
  }
  return std::string_view::npos;
}

}  // namespace

std::vector<PySpan> highlightPython(std::string_view line, char& in_string) {
  std::vector<PySpan> out;
  std::size_t i = 0;
  auto push = [&](std::size_t end, PyToken kind) {
    if (end > i) out.push_back({i, end, kind});
    i = end;
  };
  if (in_string != 0) {  // inside a triple-quoted string from an earlier line
    const auto end = stringEnd(line, 0, in_string, true);
    if (end == std::string_view::npos) {
      push(line.size(), PyToken::String);
      return out;
    }
    in_string = 0;
    push(end, PyToken::String);
  }
  while (i < line.size()) {
    const char c = line[i];
    if (c == '#') {
      push(line.size(), PyToken::Comment);
    } else if (c == '"' || c == '\'') {
      const bool triple = line.substr(i, 3) == std::string(3, c);
      const auto end = stringEnd(line, i + (triple ? 3 : 1), c, triple);
      if (end == std::string_view::npos) {
        if (triple) in_string = c;
        push(line.size(), PyToken::String);
      } else {
        push(end, PyToken::String);
      }
    } else if (std::isdigit(static_cast<unsigned char>(c)) != 0) {
      std::size_t end = i;
      while (end < line.size() && (isWordChar(line[end]) || line[end] == '.')) ++end;
      push(end, PyToken::Number);
    } else if (isWordChar(c)) {
      std::size_t end = i;
      while (end < line.size() && isWordChar(line[end])) ++end;
      const auto word = line.substr(i, end - i);
      push(end, contains(kKeywords, word) ? PyToken::Keyword : contains(kBuiltins, word) ? PyToken::Builtin : PyToken::Text);
    } else {
      std::size_t end = i + 1;
      while (end < line.size() && !isWordChar(line[end]) && line[end] != '#' && line[end] != '"' && line[end] != '\'') ++end;
      push(end, PyToken::Text);
    }
  }
  return out;
}

int drawPython(std::string_view code, int first_line, int error_line) {
  char in_string = 0;
  int n = 0;
  std::size_t start = 0;
  const int base = first_line > 0 ? first_line : 1;
  while (start <= code.size()) {
    const auto nl = code.find('\n', start);
    const auto line = code.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start);
    if (nl == std::string_view::npos && line.empty() && n > 0) break;  // no empty last line after a final newline
    if (n + 1 == error_line) {
      // the line Python could not read: a red band behind it and a red number
      const ImVec2 at = ImGui::GetCursorScreenPos();
      ImGui::GetWindowDrawList()->AddRectFilled(at, {at.x + ImGui::GetContentRegionAvail().x, at.y + ImGui::GetTextLineHeight()},
                                                IM_COL32(120, 30, 30, 255));
      ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%4d", base + n);
    } else {
      ImGui::TextDisabled("%4d", base + n);
    }
    float gap = 10.0f;  // between the number and the code, then none between pieces
    for (const auto& span : highlightPython(line, in_string)) {
      ImGui::SameLine(0.0f, gap);
      gap = 0.0f;
      const auto piece = line.substr(span.begin, span.end - span.begin);
      ImGui::TextColored(colourOf(span.kind), "%.*s", static_cast<int>(piece.size()), piece.data());
    }
    ++n;
    if (nl == std::string_view::npos) break;
    start = nl + 1;
  }
  return n;
}

}  // namespace gdpn::ide
