#pragma once
/// \file
/// Plane geometry of net pictures: points and axis-aligned boxes, in whatever frame the
/// caller says (layout units or screen pixels).

#include <algorithm>
#include <cmath>

namespace gdpn::diagram {

/// A point or a vector in the plane (x right, y down).
struct Point {
  double x = 0.0;  ///< right
  double y = 0.0;  ///< down
  friend Point operator+(Point a, Point b) { return {a.x + b.x, a.y + b.y}; }
  friend Point operator-(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
  friend Point operator*(Point a, double s) { return {a.x * s, a.y * s}; }
  friend bool operator==(const Point&, const Point&) = default;
};

/// An axis-aligned box: `min` is the top-left corner, `max` the bottom-right one.
struct Box {
  Point min;  ///< top-left corner
  Point max;  ///< bottom-right corner
  /// The box of `centre` grown by `half_w` and `half_h` on each side.
  static Box around(Point centre, double half_w, double half_h) {
    return {{centre.x - half_w, centre.y - half_h}, {centre.x + half_w, centre.y + half_h}};
  }
  /// Width along x.
  [[nodiscard]] double width() const { return max.x - min.x; }
  /// Height along y.
  [[nodiscard]] double height() const { return max.y - min.y; }
  /// True when the two boxes share any point (touching counts).
  [[nodiscard]] bool overlaps(const Box& o) const {
    return min.x <= o.max.x && o.min.x <= max.x && min.y <= o.max.y && o.min.y <= max.y;
  }
  /// Grows the box to hold `p`.
  void add(Point p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y)};
  }
  friend bool operator==(const Box&, const Box&) = default;
};

/// The point of the segment from `a` to `b` nearest `p` (`a` for a segment of no length).
inline Point nearestOnSegment(Point p, Point a, Point b) {
  const Point ab = b - a, ap = p - a;
  const double len2 = ab.x * ab.x + ab.y * ab.y;
  const double t = len2 > 0 ? std::clamp((ap.x * ab.x + ap.y * ab.y) / len2, 0.0, 1.0) : 0.0;
  return a + ab * t;
}

/// The distance from `p` to the segment from `a` to `b`, in the points' unit.
inline double distanceToSegment(Point p, Point a, Point b) {
  const Point q = nearestOnSegment(p, a, b);
  return std::hypot(p.x - q.x, p.y - q.y);
}

}  // namespace gdpn::diagram
