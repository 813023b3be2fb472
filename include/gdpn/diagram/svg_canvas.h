#pragma once
/// \file
/// A canvas that writes SVG 1.1 text: one element per shape, numbers with two decimals, so
/// the same drawing gives the same bytes.

#include <string>

#include "gdpn/diagram/canvas.h"

namespace gdpn::diagram {

/// Collects SVG elements; `svg()` gives the whole document.
class SvgCanvas final : public Canvas {
 public:
  /// A canvas of `width` x `height` pixels (SVG user units).
  SvgCanvas(int width, int height);

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

  /// The SVG document drawn so far.
  [[nodiscard]] std::string svg() const;

 private:
  int width_, height_;
  std::string body_;
};

/// `colour` as SVG writes it: "#rrggbb" (the alpha goes in an opacity attribute).
[[nodiscard]] std::string svgColour(Rgba colour);

}  // namespace gdpn::diagram
