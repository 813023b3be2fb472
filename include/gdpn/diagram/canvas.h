#pragma once
/// \file
/// What the net view draws on: an abstract canvas in screen pixels (x right, y down, the
/// top-left pixel's corner at 0, 0). The CLI draws on an SVG or a raster canvas; the IDE
/// draws through an adapter onto Dear ImGui's draw lists.

#include <cstdint>
#include <span>
#include <string_view>

#include "gdpn/diagram/geometry.h"

namespace gdpn::diagram {

/// A colour with straight (not premultiplied) alpha, 0-255 per channel.
struct Rgba {
  std::uint8_t r = 0;    ///< red
  std::uint8_t g = 0;    ///< green
  std::uint8_t b = 0;    ///< blue
  std::uint8_t a = 255;  ///< opacity: 0 transparent, 255 opaque
  friend bool operator==(const Rgba&, const Rgba&) = default;
};

/// Where text stands horizontally relative to its anchor.
enum class HAlign : std::uint8_t { Left, Centre, Right };
/// Where text stands vertically relative to its anchor.
enum class VAlign : std::uint8_t {
  Top,     ///< the anchor is at the top of the text
  Middle,  ///< the anchor is at the middle of the text's capitals
  Bottom,  ///< the anchor is at the bottom of the text (below descenders)
};

/// A surface to draw on, in pixels. Shapes are anti-aliased where the canvas can. Each call
/// maps to one ImDrawList call in the IDE's adapter (AddCircleFilled, AddCircle, AddRectFilled,
/// AddRect, AddPolyline, AddConvexPolyFilled, AddText with the font size), offset by the view's
/// top-left corner.
class Canvas {
 public:
  virtual ~Canvas() = default;

  /// Width of the surface, pixels.
  [[nodiscard]] virtual int width() const = 0;
  /// Height of the surface, pixels.
  [[nodiscard]] virtual int height() const = 0;
  /// Fills the whole surface with `colour`.
  virtual void clear(Rgba colour) = 0;
  /// A filled disc of `radius` pixels about `centre`.
  virtual void fillCircle(Point centre, double radius, Rgba colour) = 0;
  /// A circle's outline `line_width` pixels wide, centred on the circle of `radius` pixels.
  virtual void strokeCircle(Point centre, double radius, double line_width, Rgba colour) = 0;
  /// A filled rectangle (pixels).
  virtual void fillRect(const Box& box, Rgba colour) = 0;
  /// A rectangle's outline `line_width` pixels wide, centred on the box's edges.
  virtual void strokeRect(const Box& box, double line_width, Rgba colour) = 0;
  /// An open polyline `line_width` pixels wide through `points` (pixels); dashed when `dashed`.
  virtual void polyline(std::span<const Point> points, double line_width, Rgba colour, bool dashed) = 0;
  /// A filled convex polygon (an arrowhead), `points` in pixels, either winding.
  virtual void fillPolygon(std::span<const Point> points, Rgba colour) = 0;
  /// UTF-8 `text` of `size` pixels (the font's em) at `anchor`, aligned as asked.
  virtual void text(Point anchor, std::string_view text, double size, HAlign h, VAlign v, Rgba colour) = 0;
  /// The advance width of `text` at `size` pixels, pixels. The default estimates it from
  /// DejaVu Sans' average advance; canvases with a real font measure it.
  [[nodiscard]] virtual double textWidth(std::string_view text, double size) const;
};

/// Code points in UTF-8 `text`, a bad byte counting as one (for width estimates).
[[nodiscard]] std::size_t codePoints(std::string_view text);

}  // namespace gdpn::diagram
