#pragma once
/// \file
/// A small anti-aliased software rasteriser: draws into an RGBA buffer in memory, text
/// through stb_truetype, and saves the picture as PNG. No OpenGL, no window.

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "gdpn/diagram/canvas.h"

namespace gdpn::diagram {

/// Debian's DejaVu Sans (package fonts-dejavu-core), the font of net pictures.
inline constexpr const char* kDefaultFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// A picture in memory: `width` x `height` pixels, 4 bytes per pixel (RGBA, straight alpha),
/// top row first. Each pixel's coverage by a shape is computed from its distance to the
/// shape's outline (one-pixel-wide anti-aliasing); colours blend "source over".
class RasterCanvas final : public Canvas {
 public:
  /// A canvas of `width` x `height` pixels (each 1 to 16384) using the TrueType font at
  /// `font_path`; null with `why` when the size is out of range or the font cannot be read.
  static std::unique_ptr<RasterCanvas> create(int width, int height, const std::string& font_path, std::string& why);
  ~RasterCanvas() override;

  [[nodiscard]] int width() const override { return width_; }
  [[nodiscard]] int height() const override { return height_; }
  void clear(Rgba colour) override;
  void fillCircle(Point centre, double radius, Rgba colour) override;
  void strokeCircle(Point centre, double radius, double line_width, Rgba colour) override;
  void fillRect(const Box& box, Rgba colour) override;
  void strokeRect(const Box& box, double line_width, Rgba colour) override;
  void polyline(std::span<const Point> points, double line_width, Rgba colour, bool dashed) override;
  void fillPolygon(std::span<const Point> points, Rgba colour) override;
  void text(Point anchor, std::string_view text, double size, HAlign h, VAlign v, Rgba colour) override;
  [[nodiscard]] double textWidth(std::string_view text, double size) const override;

  /// The pixels: RGBA, top row first.
  [[nodiscard]] const std::vector<std::uint8_t>& rgba() const { return pixels_; }
  /// The pixel at column `x`, row `y` (both in range).
  [[nodiscard]] Rgba at(int x, int y) const;
  /// Writes the picture as PNG (RGB) to `path`, beside the old file and then renamed over
  /// it; false with `why` on failure, the old file then unchanged.
  [[nodiscard]] bool writePng(const std::string& path, std::string& why) const;

 private:
  struct Font;
  struct Glyph {
    int x0 = 0, y0 = 0, w = 0, h = 0;  // offset from the pen and size, pixels
    std::vector<std::uint8_t> alpha;   // coverage, w * h
  };
  RasterCanvas(int width, int height, std::unique_ptr<Font> font);
  void blend(int x, int y, Rgba colour, double coverage);
  void segments(std::span<const std::pair<Point, Point>> pieces, double line_width, Rgba colour);
  const Glyph& glyph(std::uint32_t code_point, double size, int subpixel) const;

  int width_, height_;
  std::vector<std::uint8_t> pixels_;
  std::unique_ptr<Font> font_;
  std::vector<float> coverage_;  // scratch: a polyline's coverage over its box
  mutable std::unordered_map<std::uint64_t, Glyph> glyphs_;  // by code point, size and subpixel shift
};

}  // namespace gdpn::diagram
