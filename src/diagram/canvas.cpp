#include "gdpn/diagram/canvas.h"

namespace gdpn::diagram {

// DejaVu Sans' advance is about 0.6 em for lower case and digits
constexpr double kAverageAdvance = 0.6;

double Canvas::textWidth(std::string_view text, double size) const {
  return kAverageAdvance * size * static_cast<double>(codePoints(text));
}

std::size_t codePoints(std::string_view text) {
  std::size_t n = 0;
  for (const char c : text) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80 ? 1 : 0;
  return n;
}

}  // namespace gdpn::diagram
