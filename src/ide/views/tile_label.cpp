// The palette tile's name in lines that fit (tile_label.h).

#include "gdpn/ide/tile_label.h"

#include <algorithm>

namespace gdpn::ide {

namespace {

/// The longest prefix of `text` (one character at least) that `fits` with `suffix` after it.
std::size_t widestPrefix(std::string_view text, std::string_view suffix, float width,
                         const std::function<float(std::string_view)>& measure) {
  std::size_t n = 1;
  while (n < text.size() && measure(std::string(text.substr(0, n + 1)) + std::string(suffix)) <= width) ++n;
  return n;
}

}  // namespace

std::vector<std::string> tileLabel(std::string_view name, float width,
                                   const std::function<float(std::string_view)>& measure, std::size_t max_lines) {
  max_lines = std::max<std::size_t>(max_lines, 1);
  std::vector<std::string> lines;
  std::string_view rest = name;
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
    for (std::size_t space = rest.find(' '); space != std::string_view::npos; space = rest.find(' ', space + 1)) {
      if (measure(rest.substr(0, space)) > width) break;
      cut = space;
    }
    if (cut != std::string_view::npos) {
      lines.emplace_back(rest.substr(0, cut));
      rest.remove_prefix(cut + 1);
    } else {
      const std::size_t n = widestPrefix(rest, "-", width, measure);
      lines.push_back(std::string(rest.substr(0, n)) + (n < rest.size() ? "-" : ""));
      rest.remove_prefix(n);
    }
  }
  return lines;
}

}  // namespace gdpn::ide
