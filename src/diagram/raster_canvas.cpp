#include "gdpn/diagram/raster_canvas.h"

#include <stb/stb_image_write.h>
#include <stb/stb_truetype.h>

#include <algorithm>
#include <cmath>

#include "gdpn/core/file.h"
#include "gdpn/core/output_file.h"

namespace gdpn::diagram {
namespace {

constexpr int kMaxSide = 16384;  // pixels
constexpr int kSubpixels = 4;    // horizontal glyph positions per pixel

double clamp01(double v) { return v < 0 ? 0 : v > 1 ? 1 : v; }

// the next code point of UTF-8 `s` from `i` (a bad byte reads as U+FFFD)
std::uint32_t nextCodePoint(std::string_view s, std::size_t& i) {
  const auto c = static_cast<unsigned char>(s[i++]);
  int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
  if (c >= 0x80 && extra == 0) return 0xFFFD;
  std::uint32_t cp = extra == 0 ? c : c & (0x3Fu >> extra);
  for (; extra > 0; --extra) {
    if (i >= s.size() || (static_cast<unsigned char>(s[i]) & 0xC0) != 0x80) return 0xFFFD;
    cp = (cp << 6) | (static_cast<unsigned char>(s[i++]) & 0x3Fu);
  }
  return cp;
}

}  // namespace

struct RasterCanvas::Font {
  std::string data;  // the TrueType file
  stbtt_fontinfo info{};
  int ascent = 0, descent = 0;  // font units
};

std::unique_ptr<RasterCanvas> RasterCanvas::create(int width, int height, const std::string& font_path, std::string& why) {
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
    why = "a picture must be 1 to " + std::to_string(kMaxSide) + " pixels on each side";
    return nullptr;
  }
  auto font = std::make_unique<Font>();
  core::Diagnostics diags;
  if (auto data = core::readFile(font_path, diags)) font->data = std::move(*data);
  // the font info points into the data, which stays in place from here on
  const auto* bytes = reinterpret_cast<const unsigned char*>(font->data.data());
  if (font->data.empty() || stbtt_InitFont(&font->info, bytes, stbtt_GetFontOffsetForIndex(bytes, 0)) == 0) {
    why = font_path + ": cannot read the font (Debian's package fonts-dejavu-core has it)";
    return nullptr;
  }
  int gap = 0;
  stbtt_GetFontVMetrics(&font->info, &font->ascent, &font->descent, &gap);
  return std::unique_ptr<RasterCanvas>(new RasterCanvas(width, height, std::move(font)));
}

RasterCanvas::RasterCanvas(int width, int height, std::unique_ptr<Font> font)
    : width_(width), height_(height),
      pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 255),
      font_(std::move(font)) {}

RasterCanvas::~RasterCanvas() = default;

Rgba RasterCanvas::at(int x, int y) const {
  const auto i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) * 4;
  return {pixels_[i], pixels_[i + 1], pixels_[i + 2], pixels_[i + 3]};
}

void RasterCanvas::blend(int x, int y, Rgba c, double coverage) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_ || coverage <= 0) return;
  const double a = coverage * c.a / 255.0;
  auto* p = &pixels_[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) * 4];
  auto mix = [a](std::uint8_t dst, std::uint8_t src) {
    return static_cast<std::uint8_t>(std::lround(dst + (src - dst) * a));
  };
  p[0] = mix(p[0], c.r);
  p[1] = mix(p[1], c.g);
  p[2] = mix(p[2], c.b);
  p[3] = static_cast<std::uint8_t>(std::lround(p[3] + (255 - p[3]) * a));
}

void RasterCanvas::clear(Rgba c) {
  for (std::size_t i = 0; i < pixels_.size(); i += 4) {
    pixels_[i] = c.r;
    pixels_[i + 1] = c.g;
    pixels_[i + 2] = c.b;
    pixels_[i + 3] = c.a;
  }
}

// the pixels within `margin` of a box, clipped to the canvas, visited by their centres
template <typename F>
void forPixels(const Box& b, double margin, int width, int height, F&& f) {
  const int x0 = std::max(0, static_cast<int>(std::floor(b.min.x - margin)));
  const int x1 = std::min(width - 1, static_cast<int>(std::ceil(b.max.x + margin)));
  const int y0 = std::max(0, static_cast<int>(std::floor(b.min.y - margin)));
  const int y1 = std::min(height - 1, static_cast<int>(std::ceil(b.max.y + margin)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) f(x, y, Point{x + 0.5, y + 0.5});
}

void RasterCanvas::fillCircle(Point c, double r, Rgba colour) {
  forPixels(Box::around(c, r, r), 1, width_, height_, [&](int x, int y, Point p) {
    blend(x, y, colour, clamp01(r + 0.5 - std::hypot(p.x - c.x, p.y - c.y)));
  });
}

void RasterCanvas::strokeCircle(Point c, double r, double w, Rgba colour) {
  // lines thinner than a pixel are drawn a pixel wide and fainter
  const double ww = std::max(w, 1.0), fade = w / ww;
  forPixels(Box::around(c, r + ww, r + ww), 1, width_, height_, [&](int x, int y, Point p) {
    blend(x, y, colour, fade * clamp01(ww / 2 + 0.5 - std::abs(std::hypot(p.x - c.x, p.y - c.y) - r)));
  });
}

void RasterCanvas::fillRect(const Box& b, Rgba colour) {
  // exact coverage: the share of each pixel's square inside the box
  forPixels(b, 1, width_, height_, [&](int x, int y, Point) {
    const double cx = clamp01(std::min(b.max.x, x + 1.0) - std::max(b.min.x, static_cast<double>(x)));
    const double cy = clamp01(std::min(b.max.y, y + 1.0) - std::max(b.min.y, static_cast<double>(y)));
    blend(x, y, colour, cx * cy);
  });
}

void RasterCanvas::strokeRect(const Box& b, double w, Rgba colour) {
  const double h = w / 2;
  fillRect({{b.min.x - h, b.min.y - h}, {b.max.x + h, b.min.y + h}}, colour);
  fillRect({{b.min.x - h, b.max.y - h}, {b.max.x + h, b.max.y + h}}, colour);
  fillRect({{b.min.x - h, b.min.y + h}, {b.min.x + h, b.max.y - h}}, colour);
  fillRect({{b.max.x - h, b.min.y + h}, {b.max.x + h, b.max.y - h}}, colour);
}

void RasterCanvas::segments(std::span<const std::pair<Point, Point>> pieces, double w, Rgba colour) {
  if (pieces.empty()) return;
  const double ww = std::max(w, 1.0), fade = w / ww;
  // each pixel's coverage is the most any piece gives it, blended once: no darker dots where
  // pieces meet
  Box box{pieces[0].first, pieces[0].first};
  for (const auto& [a, b] : pieces) {
    box.add(a);
    box.add(b);
  }
  const int x0 = std::max(0, static_cast<int>(std::floor(box.min.x - ww - 1)));
  const int y0 = std::max(0, static_cast<int>(std::floor(box.min.y - ww - 1)));
  const int x1 = std::min(width_ - 1, static_cast<int>(std::ceil(box.max.x + ww + 1)));
  const int y1 = std::min(height_ - 1, static_cast<int>(std::ceil(box.max.y + ww + 1)));
  if (x1 < x0 || y1 < y0) return;
  const auto cols = static_cast<std::size_t>(x1 - x0 + 1);
  coverage_.assign(cols * static_cast<std::size_t>(y1 - y0 + 1), 0.0f);
  for (const auto& ends : pieces) {
    const Point a = ends.first, b = ends.second;  // not a structured binding: the lambda takes them
    Box piece{a, a};
    piece.add(b);
    forPixels(piece, ww, width_, height_, [&](int x, int y, Point p) {
      auto& c = coverage_[static_cast<std::size_t>(y - y0) * cols + static_cast<std::size_t>(x - x0)];
      c = std::max(c, static_cast<float>(clamp01(ww / 2 + 0.5 - distanceToSegment(p, a, b))));
    });
  }
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const float c = coverage_[static_cast<std::size_t>(y - y0) * cols + static_cast<std::size_t>(x - x0)];
      if (c > 0) blend(x, y, colour, fade * static_cast<double>(c));
    }
}

void RasterCanvas::polyline(std::span<const Point> points, double w, Rgba colour, bool dashed) {
  std::vector<std::pair<Point, Point>> pieces;
  if (!dashed) {
    for (std::size_t i = 1; i < points.size(); ++i) pieces.emplace_back(points[i - 1], points[i]);
    segments(pieces, w, colour);
    return;
  }
  // dashes 3 line widths long, gaps 2 wide, continued across bends
  const double on = 3 * std::max(w, 1.0), off = 2 * std::max(w, 1.0);
  double phase = 0;  // distance into the current dash-gap period
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Point a = points[i - 1], d = points[i] - a;
    const double len = std::hypot(d.x, d.y);
    double s = 0;
    while (s < len) {
      const bool in_dash = phase < on;
      const double step = std::min(len - s, in_dash ? on - phase : on + off - phase);
      if (in_dash) pieces.emplace_back(a + d * (s / len), a + d * ((s + step) / len));
      s += step;
      phase = std::fmod(phase + step, on + off);
    }
  }
  segments(pieces, w, colour);
}

void RasterCanvas::fillPolygon(std::span<const Point> points, Rgba colour) {
  if (points.size() < 3) return;
  // coverage from the signed distance to a convex outline: the largest distance outside any edge
  double area = 0;
  Box box{points[0], points[0]};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point a = points[i], b = points[(i + 1) % points.size()];
    area += a.x * b.y - b.x * a.y;
    box.add(a);
  }
  const double sign = area > 0 ? 1.0 : -1.0;
  forPixels(box, 1, width_, height_, [&](int x, int y, Point p) {
    double outside = -1e300;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Point a = points[i], b = points[(i + 1) % points.size()];
      const Point e = b - a;
      const double len = std::hypot(e.x, e.y);
      if (len < 1e-12) continue;
      // outward normal of edge a-b for this winding (y down)
      const Point n{sign * e.y / len, -sign * e.x / len};
      outside = std::max(outside, (p.x - a.x) * n.x + (p.y - a.y) * n.y);
    }
    blend(x, y, colour, clamp01(0.5 - outside));
  });
}

const RasterCanvas::Glyph& RasterCanvas::glyph(std::uint32_t cp, double size, int subpixel) const {
  const auto size_key = static_cast<std::uint64_t>(std::lround(size * 8));
  const std::uint64_t key = (static_cast<std::uint64_t>(cp) << 32) | (size_key << 4) | static_cast<std::uint64_t>(subpixel);
  auto it = glyphs_.find(key);
  if (it != glyphs_.end()) return it->second;
  Glyph g;
  const float scale = stbtt_ScaleForMappingEmToPixels(&font_->info, static_cast<float>(size));
  const float shift = static_cast<float>(subpixel) / kSubpixels;
  int x1 = 0, y1 = 0;
  stbtt_GetCodepointBitmapBoxSubpixel(&font_->info, static_cast<int>(cp), scale, scale, shift, 0, &g.x0, &g.y0, &x1, &y1);
  g.w = std::max(0, x1 - g.x0);
  g.h = std::max(0, y1 - g.y0);
  g.alpha.assign(static_cast<std::size_t>(g.w) * static_cast<std::size_t>(g.h), 0);
  if (g.w > 0 && g.h > 0) {
    stbtt_MakeCodepointBitmapSubpixel(&font_->info, g.alpha.data(), g.w, g.h, g.w, scale, scale, shift, 0,
                                      static_cast<int>(cp));
  }
  return glyphs_.emplace(key, std::move(g)).first->second;
}

double RasterCanvas::textWidth(std::string_view text, double size) const {
  const double scale = static_cast<double>(stbtt_ScaleForMappingEmToPixels(&font_->info, static_cast<float>(size)));
  double width = 0;
  std::uint32_t previous = 0;
  for (std::size_t i = 0; i < text.size();) {
    const std::uint32_t cp = nextCodePoint(text, i);
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&font_->info, static_cast<int>(cp), &advance, &bearing);
    if (previous != 0) width += scale * stbtt_GetCodepointKernAdvance(&font_->info, static_cast<int>(previous), static_cast<int>(cp));
    width += scale * advance;
    previous = cp;
  }
  return width;
}

void RasterCanvas::text(Point anchor, std::string_view text, double size, HAlign h, VAlign v, Rgba colour) {
  if (text.empty() || size <= 0) return;
  const double scale = static_cast<double>(stbtt_ScaleForMappingEmToPixels(&font_->info, static_cast<float>(size)));
  const double w = textWidth(text, size);
  double x = h == HAlign::Left ? anchor.x : h == HAlign::Centre ? anchor.x - w / 2 : anchor.x - w;
  // the baseline, on a whole pixel so that glyphs stay crisp (capitals are 0.73 em tall)
  const double baseline = v == VAlign::Top      ? anchor.y + font_->ascent * scale
                          : v == VAlign::Middle ? anchor.y + 0.365 * size
                                                : anchor.y + font_->descent * scale;
  const int base = static_cast<int>(std::lround(baseline));
  std::uint32_t previous = 0;
  for (std::size_t i = 0; i < text.size();) {
    const std::uint32_t cp = nextCodePoint(text, i);
    if (previous != 0) x += scale * stbtt_GetCodepointKernAdvance(&font_->info, static_cast<int>(previous), static_cast<int>(cp));
    const double pen = std::floor(x);
    const int sub = std::min(kSubpixels - 1, static_cast<int>((x - pen) * kSubpixels));
    const Glyph& g = glyph(cp, size, sub);
    for (int gy = 0; gy < g.h; ++gy)
      for (int gx = 0; gx < g.w; ++gx) {
        const auto a = g.alpha[static_cast<std::size_t>(gy) * static_cast<std::size_t>(g.w) + static_cast<std::size_t>(gx)];
        if (a != 0) blend(static_cast<int>(pen) + g.x0 + gx, base + g.y0 + gy, colour, a / 255.0);
      }
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&font_->info, static_cast<int>(cp), &advance, &bearing);
    x += scale * advance;
    previous = cp;
  }
}

bool RasterCanvas::writePng(const std::string& path, std::string& why) const {
  // RGB, encoded in memory, then written beside the old file and renamed over it
  std::vector<std::uint8_t> rgb;
  rgb.reserve(pixels_.size() / 4 * 3);
  for (std::size_t i = 0; i < pixels_.size(); i += 4) rgb.insert(rgb.end(), {pixels_[i], pixels_[i + 1], pixels_[i + 2]});
  std::string png;
  auto append = [](void* out, void* data, int size) {
    static_cast<std::string*>(out)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (stbi_write_png_to_func(append, &png, width_, height_, 3, rgb.data(), width_ * 3) == 0) {
    why = "cannot encode the picture as PNG";
    return false;
  }
  return core::writeOutput(path, png, why);
}

}  // namespace gdpn::diagram
