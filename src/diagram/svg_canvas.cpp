#include "gdpn/diagram/svg_canvas.h"

#include <cstdio>

#include "gdpn/core/text.h"

namespace gdpn::diagram {
namespace {

std::string num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", v);
  std::string s = text;
  // 12.50 -> 12.5, 12.00 -> 12: shorter files, still one spelling per number
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

// fill="#rrggbb" with fill-opacity when not opaque (or the same for stroke)
std::string paint(const char* what, Rgba c) {
  std::string s = std::string(" ") + what + "=\"" + svgColour(c) + "\"";
  if (c.a != 255) s += std::string(" ") + what + "-opacity=\"" + num(c.a / 255.0) + "\"";
  return s;
}

}  // namespace

std::string svgColour(Rgba c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
  return text;
}

SvgCanvas::SvgCanvas(int width, int height) : width_(width), height_(height) {}

void SvgCanvas::clear(Rgba colour) {
  body_.clear();
  body_ += "<rect x=\"0\" y=\"0\" width=\"" + num(width_) + "\" height=\"" + num(height_) + "\"" + paint("fill", colour) + "/>\n";
}

void SvgCanvas::fillCircle(Point c, double r, Rgba colour) {
  body_ += "<circle cx=\"" + num(c.x) + "\" cy=\"" + num(c.y) + "\" r=\"" + num(r) + "\"" + paint("fill", colour) + "/>\n";
}

void SvgCanvas::strokeCircle(Point c, double r, double w, Rgba colour) {
  body_ += "<circle cx=\"" + num(c.x) + "\" cy=\"" + num(c.y) + "\" r=\"" + num(r) + "\" fill=\"none\"" +
           paint("stroke", colour) + " stroke-width=\"" + num(w) + "\"/>\n";
}

void SvgCanvas::fillRect(const Box& b, Rgba colour) {
  body_ += "<rect x=\"" + num(b.min.x) + "\" y=\"" + num(b.min.y) + "\" width=\"" + num(b.width()) + "\" height=\"" +
           num(b.height()) + "\"" + paint("fill", colour) + "/>\n";
}

void SvgCanvas::strokeRect(const Box& b, double w, Rgba colour) {
  body_ += "<rect x=\"" + num(b.min.x) + "\" y=\"" + num(b.min.y) + "\" width=\"" + num(b.width()) + "\" height=\"" +
           num(b.height()) + "\" fill=\"none\"" + paint("stroke", colour) + " stroke-width=\"" + num(w) + "\"/>\n";
}

void SvgCanvas::polyline(std::span<const Point> points, double w, Rgba colour, bool dashed) {
  std::string list;
  for (const Point& p : points) list += (list.empty() ? "" : " ") + num(p.x) + "," + num(p.y);
  body_ += "<polyline points=\"" + list + "\" fill=\"none\"" + paint("stroke", colour) + " stroke-width=\"" + num(w) +
           "\"" + (dashed ? " stroke-dasharray=\"" + num(3 * w) + " " + num(2 * w) + "\"" : "") + "/>\n";
}

void SvgCanvas::fillPolygon(std::span<const Point> points, Rgba colour) {
  std::string list;
  for (const Point& p : points) list += (list.empty() ? "" : " ") + num(p.x) + "," + num(p.y);
  body_ += "<polygon points=\"" + list + "\"" + paint("fill", colour) + "/>\n";
}

void SvgCanvas::text(Point anchor, std::string_view text, double size, HAlign h, VAlign v, Rgba colour) {
  const char* anchor_name = h == HAlign::Left ? "start" : h == HAlign::Centre ? "middle" : "end";
  // the baseline from the anchor: DejaVu Sans' ascent is 0.93 em, descent 0.24 em, capitals 0.73 em
  const double dy = v == VAlign::Top ? 0.93 * size : v == VAlign::Middle ? 0.365 * size : -0.24 * size;
  body_ += "<text x=\"" + num(anchor.x) + "\" y=\"" + num(anchor.y + dy) + "\" font-size=\"" + num(size) +
           "\" text-anchor=\"" + anchor_name + "\"" + paint("fill", colour) + ">" + core::xmlEscape(text) + "</text>\n";
}

std::string SvgCanvas::svg() const {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
         num(width_) + "\" height=\"" + num(height_) + "\" viewBox=\"0 0 " + num(width_) + " " + num(height_) +
         "\" font-family=\"DejaVu Sans, sans-serif\">\n" + body_ + "</svg>\n";
}

}  // namespace gdpn::diagram
