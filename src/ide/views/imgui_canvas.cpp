#include "imgui_canvas.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

namespace gdpn::ide {
namespace {

ImU32 colourOf(diagram::Rgba c) { return IM_COL32(c.r, c.g, c.b, c.a); }

/// Segments of a circle of `radius` pixels: smooth at any zoom, cheap when small.
int segmentsFor(double radius) { return std::clamp(static_cast<int>(radius * 0.8), 12, 64); }

}  // namespace

ImGuiCanvas::ImGuiCanvas(ImDrawList* list, float x, float y, int width, int height, ImFont* font)
    : list_(list), x_(x), y_(y), width_(width), height_(height), font_(font ? font : ImGui::GetFont()) {}

void ImGuiCanvas::clear(diagram::Rgba colour) {
  list_->AddRectFilled({x_, y_}, {x_ + static_cast<float>(width_), y_ + static_cast<float>(height_)}, colourOf(colour));
}

void ImGuiCanvas::fillCircle(diagram::Point c, double radius, diagram::Rgba colour) {
  list_->AddCircleFilled({x_ + static_cast<float>(c.x), y_ + static_cast<float>(c.y)}, static_cast<float>(radius),
                         colourOf(colour), segmentsFor(radius));
}

void ImGuiCanvas::strokeCircle(diagram::Point c, double radius, double line_width, diagram::Rgba colour) {
  list_->AddCircle({x_ + static_cast<float>(c.x), y_ + static_cast<float>(c.y)}, static_cast<float>(radius),
                   colourOf(colour), segmentsFor(radius), static_cast<float>(line_width));
}

void ImGuiCanvas::fillRect(const diagram::Box& b, diagram::Rgba colour) {
  list_->AddRectFilled({x_ + static_cast<float>(b.min.x), y_ + static_cast<float>(b.min.y)},
                       {x_ + static_cast<float>(b.max.x), y_ + static_cast<float>(b.max.y)}, colourOf(colour));
}

void ImGuiCanvas::strokeRect(const diagram::Box& b, double line_width, diagram::Rgba colour) {
  list_->AddRect({x_ + static_cast<float>(b.min.x), y_ + static_cast<float>(b.min.y)},
                 {x_ + static_cast<float>(b.max.x), y_ + static_cast<float>(b.max.y)}, colourOf(colour), 0.0f, 0,
                 static_cast<float>(line_width));
}

void ImGuiCanvas::polyline(std::span<const diagram::Point> points, double line_width, diagram::Rgba colour,
                           bool dashed) {
  if (points.size() < 2) return;
  const ImU32 col = colourOf(colour);
  const auto w = static_cast<float>(line_width);
  if (!dashed) {
    std::vector<ImVec2> screen;
    screen.reserve(points.size());
    for (const auto& p : points) screen.push_back({x_ + static_cast<float>(p.x), y_ + static_cast<float>(p.y)});
    list_->AddPolyline(screen.data(), static_cast<int>(screen.size()), col, 0, w);
    return;
  }
  // dashes of 6 pixels with gaps of 4, continuing across the polyline's bends
  constexpr double kDash = 6.0, kGap = 4.0;
  double phase = 0.0;  // distance into the current dash-and-gap period
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const diagram::Point a = points[i], b = points[i + 1];
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    double at = 0.0;
    while (at < length) {
      const bool on = phase < kDash;
      const double step = std::min(length - at, on ? kDash - phase : kDash + kGap - phase);
      if (on) {
        const double t0 = at / length, t1 = (at + step) / length;
        list_->AddLine({x_ + static_cast<float>(a.x + (b.x - a.x) * t0), y_ + static_cast<float>(a.y + (b.y - a.y) * t0)},
                       {x_ + static_cast<float>(a.x + (b.x - a.x) * t1), y_ + static_cast<float>(a.y + (b.y - a.y) * t1)},
                       col, w);
      }
      at += step;
      phase = std::fmod(phase + step, kDash + kGap);
    }
  }
}

void ImGuiCanvas::fillPolygon(std::span<const diagram::Point> points, diagram::Rgba colour) {
  if (points.size() < 3) return;
  std::vector<ImVec2> screen;
  screen.reserve(points.size());
  for (const auto& p : points) screen.push_back({x_ + static_cast<float>(p.x), y_ + static_cast<float>(p.y)});
  // ImGui fills convex polygons wound either way
  list_->AddConvexPolyFilled(screen.data(), static_cast<int>(screen.size()), colourOf(colour));
}

void ImGuiCanvas::text(diagram::Point anchor, std::string_view text, double size, diagram::HAlign h,
                       diagram::VAlign v, diagram::Rgba colour) {
  if (text.empty()) return;
  const auto px = static_cast<float>(size);
  const ImVec2 extent = font_->CalcTextSizeA(px, FLT_MAX, 0.0f, text.data(), text.data() + text.size());
  float x = x_ + static_cast<float>(anchor.x);
  float y = y_ + static_cast<float>(anchor.y);
  if (h == diagram::HAlign::Centre) x -= extent.x * 0.5f;
  if (h == diagram::HAlign::Right) x -= extent.x;
  // ImGui places text by its line's top; capitals' middle sits about 0.55 of the size down
  if (v == diagram::VAlign::Middle) y -= px * 0.55f;
  if (v == diagram::VAlign::Bottom) y -= extent.y;
  list_->AddText(font_, px, {x, y}, colourOf(colour), text.data(), text.data() + text.size());
}

double ImGuiCanvas::textWidth(std::string_view text, double size) const {
  return static_cast<double>(
      font_->CalcTextSizeA(static_cast<float>(size), FLT_MAX, 0.0f, text.data(), text.data() + text.size()).x);
}

}  // namespace gdpn::ide
