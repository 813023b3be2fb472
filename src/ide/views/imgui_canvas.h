#pragma once
// A diagram::Canvas that draws into a Dear ImGui draw list: the net view's pictures are made
// by the same painter as `gdpn render --net`. Private to the ide module.

#include "gdpn/diagram/canvas.h"

struct ImDrawList;
struct ImFont;

namespace gdpn::ide {

/// Draws onto `list` inside the rectangle at window pixel (`x`, `y`) of `width` x `height`
/// pixels, clipped to it; text in `font` (ImGui's default when null).
class ImGuiCanvas final : public diagram::Canvas {
 public:
  ImGuiCanvas(ImDrawList* list, float x, float y, int width, int height, ImFont* font);
  [[nodiscard]] int width() const override { return width_; }
  [[nodiscard]] int height() const override { return height_; }
  void clear(diagram::Rgba colour) override;
  void fillCircle(diagram::Point centre, double radius, diagram::Rgba colour) override;
  void strokeCircle(diagram::Point centre, double radius, double line_width, diagram::Rgba colour) override;
  void fillRect(const diagram::Box& box, diagram::Rgba colour) override;
  void strokeRect(const diagram::Box& box, double line_width, diagram::Rgba colour) override;
  void polyline(std::span<const diagram::Point> points, double line_width, diagram::Rgba colour,
                bool dashed) override;
  void fillPolygon(std::span<const diagram::Point> points, diagram::Rgba colour) override;
  void text(diagram::Point anchor, std::string_view text, double size, diagram::HAlign h, diagram::VAlign v,
            diagram::Rgba colour) override;
  [[nodiscard]] double textWidth(std::string_view text, double size) const override;

 private:
  ImDrawList* list_;
  float x_, y_;
  int width_, height_;
  ImFont* font_;
};

}  // namespace gdpn::ide
