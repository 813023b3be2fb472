// The palette tile's name in lines that fit (tile_label.h).

#include "gdpn/ide/tile_label.h"

#include <algorithm>

namespace gdpn::ide {

namespace {

/// The bytes of the UTF-8 character that starts at `text[i]` (1 for a stray byte).
std::size_t characterAt(std::string_view text, std::size_t i) {
  std::size_t n = 1;
  while (i + n < text.size() && (static_cast<unsigned char>(text[i + n]) & 0xC0U) == 0x80U) ++n;
  return n;
}

/// The longest prefix of `text`, whole characters and one at least, that fits `width` with
/// `suffix` after it.
std::size_t widestPrefix(std::string_view text, std::string_view suffix, float width,
                         const std::function<float(std::string_view)>& measure) {
  std::size_t n = characterAt(text, 0);
  while (n < text.size()) {
    const std::size_t next = n + characterAt(text, n);
    if (measure(std::string(text.substr(0, next)) + std::string(suffix)) > width) break;
    n = next;
  }
  return n;
}

}  // namespace

std::vector<std::string> tileLabel(std::string_view name, float width,
                                   const std::function<float(std::string_view)>& measure, std::size_t max_lines) {
  max_lines = std::max<std::size_t>(max_lines, 1);
  std::vector<std::string> lines;
  std::string_view rest = name;
  while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  while (!rest.empty()) {
    if (lines.size() + 1 == max_lines) {
      // the last line: what is left, cut with ".." when it does not fit
      if (measure(rest) <= width) {
        lines.emplace_back(rest);
      } else {
        std::string head(rest.substr(0, widestPrefix(rest, "..", width, measure)));
        while (head.size() > 1 && head.back() == ' ') head.pop_back();
        lines.push_back(head + "..");
      }
      break;
    }
    if (measure(rest) <= width) {
      lines.emplace_back(rest);
      break;
    }
    // the most words that fit; else the widest piece of the first word, with a hyphen
    std::size_t cut = std::string_view::npos;
    for (std::size_t space = rest.find(' ', 1); space != std::string_view::npos; space = rest.find(' ', space + 1)) {
      if (measure(rest.substr(0, space)) > width) break;
      cut = space;
    }
    if (cut != std::string_view::npos) {
      std::string_view line = rest.substr(0, cut);
      while (line.back() == ' ') line.remove_suffix(1);  // cut >= 1: the line starts with no space
      lines.emplace_back(line);
      rest.remove_prefix(cut + 1);
      while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    } else {
      const std::size_t n = widestPrefix(rest, "-", width, measure);
      lines.push_back(std::string(rest.substr(0, n)) + (n < rest.size() ? "-" : ""));
      rest.remove_prefix(n);
    }
  }
  return lines;
}

}  // namespace gdpn::ide
