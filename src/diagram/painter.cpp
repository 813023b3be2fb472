#include "gdpn/diagram/painter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace gdpn::diagram {
namespace {

// sizes in layout units, scaled by the zoom when drawn
constexpr double kLabelSize = 11.0;     // names
constexpr double kLabelGap = 3.0;       // between a shape and its name
constexpr double kLineWidth = 1.2;      // arcs
constexpr double kOutlineWidth = 1.6;   // places, instance boxes
constexpr double kArrowLength = 9.0;
constexpr double kArrowHalfWidth = 4.0;
constexpr double kInhibitorRadius = 3.5;
constexpr double kDotRadius = 3.2;
constexpr double kNameRoom = 18.0;      // names under places and above transitions
// pixels: a place drawn smaller than this radius makes the picture coarse (squares, hairlines)
constexpr double kCoarseRadiusPx = 2.5;

Rgba kindColour(net::SlotKind kind) {
  switch (kind) {
    case net::SlotKind::Control: return colours::kControl;
    case net::SlotKind::Node: return colours::kNode;
    case net::SlotKind::Sensor: return colours::kSensor;
    case net::SlotKind::Value: return colours::kValue;
    case net::SlotKind::Continuous: return colours::kContinuous;
  }
  return colours::kControl;
}

Rgba activityColour(Activity a) {
  switch (a) {
    case Activity::Idle: return colours::kIdle;
    case Activity::Enabled: return colours::kEnabled;
    case Activity::Waiting: return colours::kIdle;
    case Activity::HeldBack: return colours::kHeldBack;
    case Activity::Occurring: return colours::kOccurring;
  }
  return colours::kIdle;
}

Point unit(Point d) {
  const double len = std::hypot(d.x, d.y);
  return len > 1e-12 ? d * (1.0 / len) : Point{1, 0};
}

// the point `share` of the way along a polyline, and the direction there
std::pair<Point, Point> pointAlong(const std::vector<Point>& pts, double share) {
  double total = 0;
  for (std::size_t i = 1; i < pts.size(); ++i) total += std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
  double left = total * share;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const Point d = pts[i] - pts[i - 1];
    const double len = std::hypot(d.x, d.y);
    if (left <= len && len > 0) return {pts[i - 1] + d * (left / len), unit(d)};
    left -= len;
  }
  return {pts.front(), Point{1, 0}};
}

// cuts `length` off the end of a polyline (it keeps at least its first point and one more)
void trimEnd(std::vector<Point>& pts, double length) {
  while (pts.size() >= 2) {
    const Point a = pts[pts.size() - 2], b = pts.back();
    const double seg = std::hypot(b.x - a.x, b.y - a.y);
    if (seg > length) {
      pts.back() = b + (a - b) * (length / seg);
      return;
    }
    length -= seg;
    pts.pop_back();
  }
  pts.push_back(pts.front());
}

// where `count` token dots sit in a place of radius r (offsets from its centre)
std::vector<Point> dotPattern(std::int64_t count, double r) {
  const double s = 0.42 * r;
  switch (count) {
    case 1: return {{0, 0}};
    case 2: return {{-s, 0}, {s, 0}};
    case 3: return {{-s, s * 0.6}, {s, s * 0.6}, {0, -s * 0.8}};
    case 4: return {{-s, -s}, {s, -s}, {-s, s}, {s, s}};
    default: return {{-s, -s}, {s, -s}, {-s, s}, {s, s}, {0, 0}};
  }
}

// a piece of text waiting for the label pass: where it may stand, first choice first
struct Label {
  std::string text;
  double size = 0;
  HAlign h = HAlign::Centre;
  VAlign v = VAlign::Middle;
  Rgba colour;
  std::vector<Point> anchors;  // candidates; names have one
};

// the box `text` covers at `anchor`, pixels
Box labelBox(const Canvas& c, const Label& l, Point anchor) {
  const double w = c.textWidth(l.text, l.size), h = 1.17 * l.size;
  const double x = l.h == HAlign::Left ? anchor.x : l.h == HAlign::Centre ? anchor.x - w / 2 : anchor.x - w;
  const double y = l.v == VAlign::Top ? anchor.y : l.v == VAlign::Middle ? anchor.y - 0.5 * h : anchor.y - h;
  return {{x - 1, y}, {x + w + 1, y + h}};
}

}  // namespace

double labelPx(const Viewport& v) {
  double font = std::min(kLabelSize * v.zoom, kMaxFontPx);
  if (font >= kReadableFromPx) font = std::max(font, std::min(v.min_label_px, kMaxFontPx));
  return font >= kMinFontPx ? font : 0.0;
}

namespace {

class Painter {
 public:
  Painter(const NetLayout& l, const NetState* s, const Viewport& v, Canvas& c) : l_(l), s_(s), v_(v), c_(c) {
    font_ = labelPx(v);
    labels_ = font_ > 0;
    coarse_ = kPlaceRadius * v.zoom < kCoarseRadiusPx;
  }

  void arc(const ArcLayout& a) {
    std::vector<Point> pts;
    for (const Point& p : a.points) pts.push_back(v_.toScreen(p));
    if (pts.size() < 2) return;
    std::optional<bool> holds;
    if (s_ != nullptr && a.spec_index < s_->arcs.size()) holds = s_->arcs[a.spec_index];
    const Rgba colour = !holds ? colours::kIdle : *holds ? colours::kEnabled : colours::kArcOff;
    if (coarse_) {
      // zoomed far out: a hairline, no head (a head would be larger than the places it joins)
      c_.polyline(pts, 1.0, colour, false);
      return;
    }
    const double w = std::max(kLineWidth * v_.zoom, 1.0);
    // the end: an arrowhead (normal), a small circle (inhibitor) or nothing (test)
    const Point end = pts.back();
    if (a.kind == net::ArcKind::Normal) {
      // the line stops inside the head; the head points along the last stretch of its length
      const double len = std::max(kArrowLength * v_.zoom, 6.0), half = std::max(kArrowHalfWidth * v_.zoom, 3.0);
      trimEnd(pts, len);
      const Point dir = unit(end - pts.back());
      const Point base = end - dir * len, side{-dir.y * half, dir.x * half};
      pts.push_back(end - dir * (len * 0.8));
      const std::array<Point, 3> head{end, base + side, base - side};
      c_.fillPolygon(head, colour);
    } else if (a.kind == net::ArcKind::Inhibitor) {
      const double r = std::max(kInhibitorRadius * v_.zoom, 2.5);
      trimEnd(pts, 2 * r);
      const Point dir = unit(end - pts.back());
      c_.strokeCircle(end - dir * r, r, w, colour);
    }
    const Point dir = unit(end - pts[pts.size() - 2]);
    c_.polyline(pts, w, colour, a.kind == net::ArcKind::Test);
    if (!labels_) return;
    // the weight where the spec puts it, else beside the line: at its middle, else a third of
    // the way from either end
    if (!a.inscription.empty()) {
      Label l{a.inscription, std::max(font_ * 0.9, kMinFontPx), HAlign::Centre, VAlign::Middle, colours::kInscription, {}};
      const double gap = l.size * 0.75;
      if (a.label_at) {
        l.anchors.push_back(v_.toScreen(*a.label_at));
      } else {
        for (const double share : {0.5, 0.35, 0.65, 0.2, 0.8}) {
          const auto [at, d] = pointAlong(pts, share);
          const Point normal{d.y, -d.x};
          l.anchors.push_back(at + normal * gap);
          l.anchors.push_back(at - normal * gap);
        }
      }
      pending_.push_back(std::move(l));
    }
    // the reference's name where the arc meets an instance box
    if (!a.link.empty()) {
      const bool to_box = a.to.kind == ItemKind::Instance;
      const Point s = v_.toScreen(to_box ? a.points.back() : a.points.front());
      const bool left = (to_box ? dir.x : -unit(pts[1] - pts[0]).x) > 0;
      Label l{a.link, std::max(font_ * 0.85, kMinFontPx), left ? HAlign::Right : HAlign::Left, VAlign::Bottom,
              colours::kInstanceLine, {}};
      l.anchors = {{s.x + (left ? -3.0 : 3.0), s.y - 2}, {s.x + (left ? -3.0 : 3.0), s.y + 2 + 1.17 * l.size}};
      pending_.push_back(std::move(l));
    }
  }

  /// Draws the names where they belong, then each weight and link name at its first free place.
  void finish() {
    for (const auto& [l, at] : names_) {
      c_.fillRect(labelBox(c_, l, at), kPatch);
      c_.text(at, l.text, l.size, l.h, l.v, l.colour);
    }
    for (const auto& l : pending_) {
      // the first place that covers nothing, else the one that covers least
      Point best = l.anchors.front();
      double least = 1e300;
      for (const Point& at : l.anchors) {
        // a few pixels apart, so that an inscription never reads as part of a name
        Box b = labelBox(c_, l, at);
        b.min = b.min - Point{4, 2};
        b.max = b.max + Point{4, 2};
        double covered = 0;
        for (const Box& o : taken_) {
          if (!o.overlaps(b)) continue;
          covered += (std::min(b.max.x, o.max.x) - std::max(b.min.x, o.min.x)) * (std::min(b.max.y, o.max.y) - std::max(b.min.y, o.min.y));
        }
        if (covered < least) {
          least = covered;
          best = at;
        }
        if (covered == 0) break;
      }
      const Box b = labelBox(c_, l, best);
      taken_.push_back(b);
      c_.fillRect(b, kPatch);
      c_.text(best, l.text, l.size, l.h, l.v, l.colour);
    }
  }

  void instance(const InstanceLayout& i) {
    const Box b{v_.toScreen(i.box.min), v_.toScreen(i.box.max)};
    c_.fillRect(b, colours::kInstanceFill);
    c_.strokeRect(b, std::max(kOutlineWidth * v_.zoom, 1.0), colours::kInstanceLine);
    taken_.push_back(b);
    if (!labels_) return;
    const Point c = v_.toScreen(i.centre);
    c_.text({c.x, c.y - 1}, i.name, font_, HAlign::Centre, VAlign::Bottom, colours::kOutline);
    c_.text({c.x, c.y + 1}, ": " + i.type, font_ * 0.9, HAlign::Centre, VAlign::Top, colours::kInstanceLine);
  }

  void transition(std::size_t k) {
    const NodeLayout& t = l_.transitions[k];
    const Activity a = s_ != nullptr && k < s_->transitions.size() ? s_->transitions[k] : Activity::Idle;
    const Box b{v_.toScreen(t.box.min), v_.toScreen(t.box.max)};
    if (t.fluid) {
      flow(k, t, a, b);
      return;
    }
    // a bar at least a pixel and a half wide, so that it shows when zoomed out
    const double grow = std::max(0.0, (1.5 - b.width()) / 2);
    const Box bar{{b.min.x - grow, b.min.y}, {b.max.x + grow, b.max.y}};
    c_.fillRect(bar, activityColour(a));
    // its marking suffices but it is not (yet) able to start: outlined in the enabled colour
    if (!coarse_ && (a == Activity::HeldBack || a == Activity::Waiting)) {
      const double w = std::max(kOutlineWidth * v_.zoom, 1.0);
      c_.strokeRect(bar, w, colours::kEnabled);
    }
    taken_.push_back(b);
    if (labels_) name({(b.min.x + b.max.x) / 2, b.min.y - kLabelGap * v_.zoom}, t.name, VAlign::Bottom);
    // its condition (the tag): under the bar, else beside it, where it covers least
    if (labels_ && !t.tag.empty()) {
      Label l{t.tag, std::max(font_ * 0.85, kMinFontPx), HAlign::Centre, VAlign::Top, colours::kInscription, {}};
      const double below = b.max.y + 1.5 * kLabelGap * v_.zoom + (s_ != nullptr ? font_ : 0.0);
      l.anchors = {{(b.min.x + b.max.x) / 2, below}, {(b.min.x + b.max.x) / 2, b.min.y - kLabelGap * v_.zoom - 1.2 * font_}};
      pending_.push_back(std::move(l));
    }
    // with servers, how many of its occurrences run, under the bar
    const std::uint32_t n = s_ != nullptr && k < s_->occurrences.size() ? s_->occurrences[k] : 0;
    if (labels_ && n > 1) {
      const Point at{(b.min.x + b.max.x) / 2, b.max.y + 0.5 * kLabelGap * v_.zoom};
      const Label count{"\u00d7" + std::to_string(n), font_ * 0.9, HAlign::Centre, VAlign::Top, activityColour(a), {at}};
      c_.text(at, count.text, count.size, count.h, count.v, count.colour);
      taken_.push_back(labelBox(c_, count, at));
    }
  }

  void place(std::size_t k) {
    const NodeLayout& p = l_.places[k];
    const Point c = v_.toScreen(p.centre);
    const double r = kPlaceRadius * v_.zoom;
    if (coarse_) {
      // zoomed far out: a square the place's size (a pixel at least), in its tokens' colour
      // when it holds any, so that the marking still shows
      Rgba colour = colours::kOutline;
      if (p.fluid && amountOf(k, *p.fluid).first > 0) colour = colours::kContinuous;
      if (s_ != nullptr && k < s_->places.size()) {
        for (const auto& slot : s_->places[k]) {
          if (slot.count > 0) {
            colour = kindColour(slot.kind);
            break;
          }
        }
      }
      const double half = std::max(r, 0.75);
      c_.fillRect(Box::around(c, half, half), colour);
      return;
    }
    c_.fillCircle(c, r, colours::kBackground);
    c_.strokeCircle(c, r, std::max(kOutlineWidth * v_.zoom, 1.0), colours::kOutline);
    if (p.fluid) level(k, *p.fluid, c, r);
    else if (s_ != nullptr && k < s_->places.size()) tokens(s_->places[k], c, r);
    taken_.push_back(Box::around(c, r, r));
    if (labels_) name({c.x, c.y + r + kLabelGap * v_.zoom}, p.name, VAlign::Top);
    if (labels_ && !p.tag.empty()) {
      // the port or fusion tag: above and beside the place, where it covers least
      Label l{p.tag, std::max(font_ * 0.85, kMinFontPx), HAlign::Left, VAlign::Bottom, colours::kInstanceLine, {}};
      const double d = r * 0.75;
      l.anchors = {{c.x + d, c.y - d}, {c.x + r + 3, c.y + l.size / 2}, {c.x + d, c.y + d + l.size}};
      pending_.push_back(std::move(l));
    }
  }

 private:
  // a continuous place's amount and capacity: the run's, else the spec's
  [[nodiscard]] std::pair<double, double> amountOf(std::size_t k, const FluidLook& look) const {
    if (s_ != nullptr && k < s_->amounts.size() && s_->amounts[k]) {
      return {*s_->amounts[k], k < s_->capacities.size() ? s_->capacities[k] : net::kNoBound};
    }
    return {look.amount, look.capacity.value_or(net::kNoBound)};
  }

  // a continuous place (hybrid nets): a double circle, filled from the bottom up to its level
  // (amount over capacity), its amount and unit written inside, else beside it
  void level(std::size_t k, const FluidLook& look, Point c, double r) {
    const double ri = kInnerCircle * r;
    const auto [amount, capacity] = amountOf(k, look);
    if (std::isfinite(capacity) && capacity > 0 && amount > 0) {
      const double f = std::clamp(amount / capacity, 0.0, 1.0);
      if (f >= 1.0) {
        c_.fillCircle(c, ri, colours::kContinuous);
      } else {
        // the segment of the inner disc below the level line: convex, an arc and its chord
        const double start = std::asin(std::clamp(1.0 - 2.0 * f, -1.0, 1.0));  // from the centre, y down
        constexpr int kSteps = 32;
        std::vector<Point> seg;
        for (int i = 0; i <= kSteps; ++i) {
          const double th = start + (std::numbers::pi - 2 * start) * i / kSteps;
          seg.push_back({c.x + ri * std::cos(th), c.y + ri * std::sin(th)});
        }
        c_.fillPolygon(seg, colours::kContinuous);
      }
    }
    c_.strokeCircle(c, ri, std::max(kOutlineWidth * 0.75 * v_.zoom, 1.0), colours::kOutline);
    if (!labels_) return;
    const std::string text = amountText(amount, look.unit);
    // inside the inner circle, as large as names where it fits there at 4/5 of their size;
    // else across the inner outline, on a patch, down to 7/10; else beside the place
    const double wide = c_.textWidth(text, font_);
    const auto fit = [&](double room) { return wide > room ? font_ * room / wide : font_; };
    double size = fit(1.85 * ri);
    if (size < std::max(kMinFontPx, 0.8 * font_)) size = fit(1.6 * r);
    if (size >= std::max(kMinFontPx, 0.7 * font_)) {
      Label l{text, size, HAlign::Centre, VAlign::Middle, colours::kOutline, {c}};
      const Box box = labelBox(c_, l, c);
      c_.fillRect({{box.min.x + 1, box.min.y + 0.1 * size}, {box.max.x - 1, box.max.y - 0.1 * size}}, kAmountPatch);
      c_.text(c, text, size, HAlign::Centre, VAlign::Middle, colours::kOutline);
      return;
    }
    // beside it, where it covers least
    Label l{text, std::max(font_ * 0.9, kMinFontPx), HAlign::Left, VAlign::Middle, colours::kOutline, {}};
    l.anchors = {{c.x + r + 3, c.y}, {c.x - r - 3 - c_.textWidth(text, l.size), c.y}, {c.x + 0.7 * r, c.y - r - l.size}};
    pending_.push_back(std::move(l));
  }

  // a continuous transition (hybrid nets): a hollow box with a double border, in the enabled
  // colour while it flows, its rate beside it
  void flow(std::size_t k, const NodeLayout& t, Activity a, const Box& b) {
    const Rgba colour = activityColour(a);
    taken_.push_back(b);
    if (coarse_ || b.width() < 6.0) {
      c_.fillRect(b, colour);
    } else {
      const double w = std::max(kOutlineWidth * 0.75 * v_.zoom, 1.0);
      const double inset = std::max(0.22 * b.width(), 2.0 * w + 1.0);
      c_.fillRect(b, colours::kBackground);
      c_.strokeRect(b, w, colour);
      c_.strokeRect({{b.min.x + inset, b.min.y + inset}, {b.max.x - inset, b.max.y - inset}}, w, colour);
    }
    if (!labels_) return;
    name({(b.min.x + b.max.x) / 2, b.min.y - kLabelGap * v_.zoom}, t.name, VAlign::Bottom);
    const double rate = s_ != nullptr && k < s_->flow_rates.size() && s_->flow_rates[k] ? *s_->flow_rates[k] : 0.0;
    if (rate == 0.0) return;
    const std::string& unit = t.fluid->unit;
    const std::string text = rateText(rate, unit);
    Label l{text, std::max(font_ * 0.9, kMinFontPx), HAlign::Left, VAlign::Middle, colours::kEnabled, {}};
    const double mid = (b.min.y + b.max.y) / 2, gap = 3.0 + kLabelGap * v_.zoom;
    // under the box first: its arcs mostly leave by its sides
    l.anchors = {{(b.min.x + b.max.x) / 2 - c_.textWidth(text, l.size) / 2, b.max.y + gap + l.size / 2},
                 {b.max.x + gap, mid},
                 {b.min.x - gap - c_.textWidth(text, l.size), mid}};
    pending_.push_back(std::move(l));
  }

  // a construct's name: drawn in the label pass, over the arcs, on a white patch
  void name(Point at, const std::string& text, VAlign v) {
    Label l{text, font_, HAlign::Centre, v, colours::kOutline, {at}};
    taken_.push_back(labelBox(c_, l, at));
    names_.emplace_back(std::move(l), at);
  }

  void tokens(const std::vector<SlotMarking>& slots, Point c, double r) {
    // tokens per kind: control, node, sensor, value (SlotKind's order)
    constexpr std::size_t kKinds = 4;
    std::array<std::int64_t, kKinds> per_kind{0, 0, 0, 0};
    for (const auto& s : slots) per_kind[static_cast<std::size_t>(s.kind)] += s.count;
    const std::int64_t total = per_kind[0] + per_kind[1] + per_kind[2] + per_kind[3];
    if (total == 0) return;
    if (total <= kMaxDots) {
      // dots: control tokens first, then node tokens, sensor variables and values
      const auto offsets = dotPattern(total, r);
      const double dot = std::max(kDotRadius * v_.zoom, 1.0);
      std::size_t i = 0;
      for (std::size_t kind = 0; kind < kKinds; ++kind)
        for (std::int64_t n = 0; n < per_kind[kind]; ++n)
          c_.fillCircle(c + offsets[i++], dot, kindColour(static_cast<net::SlotKind>(kind)));
      return;
    }
    // numbers, one line per kind present, in the kind's colour
    std::vector<std::pair<std::string, Rgba>> lines;
    for (std::size_t kind = 0; kind < kKinds; ++kind)
      if (per_kind[kind] > 0) lines.emplace_back(std::to_string(per_kind[kind]), kindColour(static_cast<net::SlotKind>(kind)));
    const double size = std::min(1.6 * r / static_cast<double>(lines.size()), kMaxFontPx);
    if (size < kMinFontPx * 0.75) {
      c_.fillCircle(c, std::max(r * 0.4, 1.0), lines.front().second);  // too small to read: one dot says "marked"
      return;
    }
    const double top = c.y - size * static_cast<double>(lines.size()) / 2;
    for (std::size_t i = 0; i < lines.size(); ++i)
      c_.text({c.x, top + size * (static_cast<double>(i) + 0.5)}, lines[i].first, size, HAlign::Centre, VAlign::Middle,
              lines[i].second);
  }

  const NetLayout& l_;
  const NetState* s_;
  const Viewport& v_;
  Canvas& c_;
  double font_ = kLabelSize;
  bool labels_ = true;
  bool coarse_ = false;  // places under kCoarseRadiusPx: squares and hairlines, no heads or labels
  std::vector<std::pair<Label, Point>> names_;  // names, where they stand
  std::vector<Label> pending_;                  // weights and link names, placed last
  std::vector<Box> taken_;                      // what labels should not cover: shapes and placed labels, pixels
  static constexpr Rgba kPatch{255, 255, 255, 200};
  static constexpr Rgba kAmountPatch{255, 255, 255, 150};  // under an amount, over its level
};

}  // namespace

Box drawnBounds(const NetLayout& layout) {
  Box b = layout.bounds;
  b.min = b.min - Point{kNameRoom, kNameRoom};
  b.max = b.max + Point{kNameRoom, kNameRoom};
  // names wider than their shapes
  for (const auto& p : layout.places) {
    const double half = 0.6 * kLabelSize * static_cast<double>(codePoints(p.name)) / 2;
    b.add({p.centre.x - half, p.centre.y});
    b.add({p.centre.x + half, p.centre.y});
  }
  for (const auto& t : layout.transitions) {
    const double half = 0.6 * kLabelSize * static_cast<double>(codePoints(t.name)) / 2;
    b.add({t.centre.x - half, t.centre.y});
    b.add({t.centre.x + half, t.centre.y});
  }
  return b;
}

Viewport fitViewport(const NetLayout& layout, int width, int height, double margin, double max_zoom) {
  const Box b = drawnBounds(layout);
  const double w = std::max(b.width(), 1.0), h = std::max(b.height(), 1.0);
  const double zoom = std::min({(width - 2 * margin) / w, (height - 2 * margin) / h, max_zoom});
  Viewport v;
  v.zoom = std::max(zoom, 1e-6);
  // centred: the drawing's middle at the canvas' middle
  const Point mid{(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2};
  v.origin = mid - Point{width / 2.0, height / 2.0} * (1.0 / v.zoom);
  return v;
}

std::size_t paintNet(const NetLayout& layout, const SpatialIndex& index, const NetState* state, const Viewport& view,
                     Canvas& canvas) {
  canvas.clear(colours::kBackground);
  // what the viewport shows, grown by the room names and arrowheads take beyond the shapes
  Box visible = view.visible(canvas.width(), canvas.height());
  const double room = kNameRoom + kMaxFontPx / view.zoom * 4;
  visible.min = visible.min - Point{room, room};
  visible.max = visible.max + Point{room, room};
  const auto items = index.query(visible);
  Painter painter(layout, state, view, canvas);
  for (const ItemRef r : items) {
    switch (r.kind) {
      case ItemKind::Arc: painter.arc(layout.arcs[r.index]); break;
      case ItemKind::Instance: painter.instance(layout.instances[r.index]); break;
      case ItemKind::Transition: painter.transition(r.index); break;
      case ItemKind::Place: painter.place(r.index); break;
    }
  }
  painter.finish();
  return items.size();
}

}  // namespace gdpn::diagram
