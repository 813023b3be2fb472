#include "gdpn/diagram/layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string_view>
#include <unordered_map>
#include <optional>

#include "detail/graphviz_layout.h"

namespace gdpn::diagram {
namespace {

// the width of an instance box: room for its longer line at the box's font (about 7 units a character)
double instanceWidth(const net::InstanceSpec& inst) {
  const auto chars = std::max(inst.name.size(), inst.type.size() + 2);
  return std::max(72.0, 7.0 * static_cast<double>(chars) + 20.0);
}

// the box of a node at `c`: `width` is an instance box's or a transition's width
Box boxOfNode(ItemKind kind, Point c, double width) {
  switch (kind) {
    case ItemKind::Place: return Box::around(c, kPlaceRadius, kPlaceRadius);
    case ItemKind::Transition: return Box::around(c, width / 2, kBarHeight / 2);
    case ItemKind::Instance: return Box::around(c, width / 2, kInstanceHeight / 2);
    case ItemKind::Arc: break;
  }
  return {c, c};
}

// the point where the ray from the centre of `item` toward `toward` leaves its outline
Point outlinePoint(const NetLayout& l, ItemRef item, Point toward) {
  const Box& b = l.boxOf(item);
  const Point c{(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2};
  const Point d = toward - c;
  const double len = std::hypot(d.x, d.y);
  if (len < 1e-9) return c;
  if (item.kind == ItemKind::Place) return c + d * (kPlaceRadius / len);
  const double hw = b.width() / 2, hh = b.height() / 2;
  const double sx = std::abs(d.x) > 1e-12 ? hw / std::abs(d.x) : 1e300;
  const double sy = std::abs(d.y) > 1e-12 ? hh / std::abs(d.y) : 1e300;
  return c + d * std::min(sx, sy);
}

Point centreOf(const NetLayout& l, ItemRef item) {
  const Box& b = l.boxOf(item);
  return {(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2};
}

// an arc's two ends resolved against the page: items and the link's reference
struct Ends {
  ItemRef from, to;
  std::string link;
};

/// The page's places, transitions and instances by name: an arc's ends found in constant time
/// (a page of 20,000 arcs would otherwise compare names 10^8 times).
class PageNames {
 public:
  explicit PageNames(const net::PageSpec& page) {
    names_.reserve(page.places.size() + page.transitions.size() + page.instances.size());
    for (std::size_t i = 0; i < page.places.size(); ++i) names_.emplace(page.places[i].name, ItemRef{ItemKind::Place, static_cast<std::uint32_t>(i)});
    for (std::size_t i = 0; i < page.transitions.size(); ++i)
      names_.emplace(page.transitions[i].name, ItemRef{ItemKind::Transition, static_cast<std::uint32_t>(i)});
    for (std::size_t i = 0; i < page.instances.size(); ++i)
      instances_.emplace(page.instances[i].name, ItemRef{ItemKind::Instance, static_cast<std::uint32_t>(i)});
  }

  /// The ends of `arc`; nullopt when one names nothing on the page.
  [[nodiscard]] std::optional<Ends> resolve(const net::ArcSpec& arc) const {
    std::string link;
    const auto find = [&](const std::string& name) -> std::optional<ItemRef> {
      if (const auto it = names_.find(name); it != names_.end()) return it->second;
      // a link `instance/reference` ends at the instance's box
      const auto slash = name.find('/');
      if (slash == std::string::npos) return std::nullopt;
      const auto it = instances_.find(std::string_view(name).substr(0, slash));
      if (it == instances_.end()) return std::nullopt;
      link = name.substr(slash + 1);
      return it->second;
    };
    const auto from = find(arc.from);
    const auto to = find(arc.to);
    if (!from || !to) return std::nullopt;
    return Ends{*from, *to, link};
  }

 private:
  std::unordered_map<std::string_view, ItemRef> names_, instances_;
};

bool allPositioned(const net::PageSpec& page) {
  return std::all_of(page.places.begin(), page.places.end(), [](const auto& p) { return p.position.has_value(); }) &&
         std::all_of(page.transitions.begin(), page.transitions.end(), [](const auto& t) { return t.position.has_value(); }) &&
         std::all_of(page.instances.begin(), page.instances.end(), [](const auto& i) { return i.position.has_value(); });
}

// an arc through its bend points: from its source's outline (toward the first bend) through
// each bend to its target's outline (from the last)
void routeVia(const NetLayout& l, ArcLayout& arc, const std::vector<net::EditorPos>& via) {
  arc.points.clear();
  arc.points.push_back(outlinePoint(l, arc.from, layoutPoint(via.front())));
  for (const auto& v : via) arc.points.push_back(layoutPoint(v));
  arc.points.push_back(outlinePoint(l, arc.to, layoutPoint(via.back())));
  arc.follows_via = true;
}

// straight arcs between positioned nodes, or through their bend points; an arc without bend
// points with a twin between the same two items (the other way, or again) bends off the
// straight line so that both stay visible
// routes the arcs (those `only` marks, when given) straight or through their bends; arcs
// between the same two items bend apart
void routeStraight(NetLayout& l, const net::PageSpec& page, const std::vector<char>* only = nullptr) {
  // arcs between the same two items, by the pair: how many, and how many routed so far
  // (an item in 32 bits: its kind in the top two, its index below: a page holds fewer than 2^30)
  const auto flat = [](ItemRef r) { return (static_cast<std::uint64_t>(r.kind) << 30) | r.index; };
  const auto keyOf = [&](const ArcLayout& arc) {
    const auto [lo, hi] = std::minmax(arc.from, arc.to);
    return flat(lo) << 32 | flat(hi);
  };
  std::unordered_map<std::uint64_t, std::pair<int, int>> twins;
  twins.reserve(l.arcs.size());
  const auto bent = [&](const ArcLayout& arc) { return !page.arcs[arc.spec_index].via.empty(); };
  for (const auto& arc : l.arcs) {
    if (!bent(arc)) ++twins[keyOf(arc)].first;
  }
  for (std::size_t k = 0; k < l.arcs.size(); ++k) {
    auto& arc = l.arcs[k];
    if (bent(arc)) {
      if (only == nullptr || (*only)[k] != 0) routeVia(l, arc, page.arcs[arc.spec_index].via);
      continue;
    }
    auto& [count, seen] = twins[keyOf(arc)];
    const int twin = seen++;
    if (only != nullptr && (*only)[k] == 0) continue;
    const Point a = centreOf(l, arc.from), b = centreOf(l, arc.to);
    if (count < 2) {
      arc.points = {outlinePoint(l, arc.from, b), outlinePoint(l, arc.to, a)};
      continue;
    }
    // each arc bends to its own left; two arcs the same way spread further apart
    const Point d = b - a;
    const double len = std::max(std::hypot(d.x, d.y), 1e-9);
    const Point left{d.y / len, -d.x / len};
    const Point bend = (a + b) * 0.5 + left * (12.0 * (1 + twin / 2));
    arc.points = {outlinePoint(l, arc.from, bend), bend, outlinePoint(l, arc.to, bend)};
  }
}

// a page too large for Graphviz: each node in the column of its breadth-first distance from
// the nodes no arc enters (then from the first node not yet reached), in spec order down it
void layoutInColumns(NetLayout& l) {
  const std::size_t places = l.places.size(), transitions = l.transitions.size();
  const std::size_t n = places + transitions + l.instances.size();
  auto flat = [&](ItemRef r) -> std::size_t {
    return r.kind == ItemKind::Place ? r.index : r.kind == ItemKind::Transition ? places + r.index : places + transitions + r.index;
  };
  std::vector<std::vector<std::size_t>> next(n);
  std::vector<bool> entered(n, false);
  for (const auto& a : l.arcs) {
    next[flat(a.from)].push_back(flat(a.to));
    entered[flat(a.to)] = true;
  }
  std::vector<std::int64_t> rank(n, -1);
  std::vector<std::size_t> queue;
  auto visit = [&](std::size_t start) {
    rank[start] = 0;
    queue.assign(1, start);
    for (std::size_t q = 0; q < queue.size(); ++q)
      for (std::size_t m : next[queue[q]])
        if (rank[m] < 0) {
          rank[m] = rank[queue[q]] + 1;
          queue.push_back(m);
        }
  };
  for (std::size_t i = 0; i < n; ++i)
    if (!entered[i] && rank[i] < 0) visit(i);
  for (std::size_t i = 0; i < n; ++i)
    if (rank[i] < 0) visit(i);
  std::vector<std::size_t> rows;
  auto centre = [&](std::size_t i) -> Point& {
    return i < places ? l.places[i].centre : i < places + transitions ? l.transitions[i - places].centre
                                                                      : l.instances[i - places - transitions].centre;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(rank[i]);
    if (rows.size() <= r) rows.resize(r + 1, 0);
    centre(i) = Point{kEditorUnit * (0.5 + 1.5 * static_cast<double>(r)), kEditorUnit * (0.5 + static_cast<double>(rows[r]++))};
  }
}

bool layoutWithGraphviz(NetLayout& l, const std::vector<double>& instance_widths, std::string& why) {
  std::vector<detail::GvNode> nodes;
  for (std::size_t i = 0; i < l.places.size(); ++i) nodes.push_back({2 * kPlaceRadius, 2 * kPlaceRadius, true});
  for (const auto& t : l.transitions) nodes.push_back({t.fluid ? kFlowWidth : kBarWidth, kBarHeight, false});
  for (double w : instance_widths) nodes.push_back({w, kInstanceHeight, false});
  auto index = [&](ItemRef r) -> std::size_t {
    switch (r.kind) {
      case ItemKind::Place: return r.index;
      case ItemKind::Transition: return l.places.size() + r.index;
      case ItemKind::Instance: return l.places.size() + l.transitions.size() + r.index;
      case ItemKind::Arc: break;
    }
    return 0;
  };
  // ranks far enough apart for the longest inscription to stand beside its arc
  std::vector<detail::GvEdge> edges;
  double gap = 54.0;
  for (const auto& arc : l.arcs) {
    edges.push_back({index(arc.from), index(arc.to)});
    gap = std::max(gap, 7.0 * static_cast<double>(arc.inscription.size()) + 24.0);
  }
  auto result = detail::dotLayout(nodes, edges, std::min(gap, 120.0), why);
  if (!result) return false;
  // a margin around the drawing, for the names under the places
  const Point margin{kEditorUnit / 2, kEditorUnit / 2};
  std::size_t k = 0;
  for (auto& p : l.places) p.centre = result->centres[k++] + margin;
  for (auto& t : l.transitions) t.centre = result->centres[k++] + margin;
  for (auto& i : l.instances) i.centre = result->centres[k++] + margin;
  for (std::size_t e = 0; e < l.arcs.size(); ++e) {
    l.arcs[e].points.clear();
    for (const Point& p : result->edges[e]) l.arcs[e].points.push_back(p + margin);
  }
  return true;
}

}  // namespace

const Box& NetLayout::boxOf(ItemRef item) const {
  switch (item.kind) {
    case ItemKind::Place: return places[item.index].box;
    case ItemKind::Transition: return transitions[item.index].box;
    case ItemKind::Instance: return instances[item.index].box;
    case ItemKind::Arc: return arcs[item.index].box;
  }
  return bounds;
}

namespace {

// the inscriptions the spec places (an offset from the middle of the arc), each arc's box (of
// those `only` marks, when given), then the bounds of everything
void placeLabelsAndBound(NetLayout& l, const net::PageSpec& page, const std::vector<char>* only) {
  for (std::size_t k = 0; k < l.arcs.size(); ++k) {
    if (only != nullptr && (*only)[k] == 0) continue;
    auto& arc = l.arcs[k];
    const auto& offset = page.arcs[arc.spec_index].label_at;
    arc.label_at.reset();
    if (offset && !arc.points.empty()) arc.label_at = middleOf(arc.points) + layoutPoint(*offset);
    arc.box = {arc.points.front(), arc.points.front()};
    for (const Point& p : arc.points) arc.box.add(p);
    if (arc.label_at) arc.box.add(*arc.label_at);
  }
  bool first = true;
  auto grow = [&](const Box& b) {
    if (first) l.bounds = b;
    l.bounds.add(b.min);
    l.bounds.add(b.max);
    first = false;
  };
  for (const auto& arc : l.arcs) grow(arc.box);
  for (const auto& p : l.places) grow(p.box);
  for (const auto& t : l.transitions) grow(t.box);
  for (const auto& i : l.instances) grow(i.box);
}

}  // namespace

NetLayout layoutPage(const net::PageSpec& page, core::Diagnostics& diags) {
  NetLayout l;
  l.page = page.name;
  // nodes, at their editor positions when they have them
  auto at = [](const std::optional<net::EditorPos>& p) {
    return p ? Point{(*p)[0] * kEditorUnit, (*p)[1] * kEditorUnit} : Point{};
  };
  for (const auto& p : page.places) {
    // the tags: a published place (a port of the page type), a fusion set's member
    const bool port = std::any_of(page.references.begin(), page.references.end(), [&](const auto& r) { return r.place == p.name; });
    std::string tag = port ? "port" : "";
    if (!p.fusion.empty()) tag += (tag.empty() ? "fusion " : ", fusion ") + p.fusion;
    l.places.push_back({p.name, at(p.position), {}, std::move(tag)});
    if (p.fluid) l.places.back().fluid = FluidLook{p.fluid->amount, p.fluid->capacity, p.fluid->unit};
  }
  // a transition's tag: its condition on its binding, in brackets as CPN tools write guards
  for (const auto& t : page.transitions) {
    l.transitions.push_back({t.name, at(t.position), {}, t.conditioned() ? "[" + t.when.text + "]" : std::string()});
    if (t.flow) l.transitions.back().fluid = FluidLook{0.0, std::nullopt, rateUnit(page, t.name)};
  }
  std::vector<double> widths;
  for (const auto& i : page.instances) {
    InstanceLayout box;
    box.name = i.name;
    box.centre = at(i.position);
    box.type = i.type;
    l.instances.push_back(std::move(box));
    widths.push_back(instanceWidth(i));
  }
  // arcs between constructs of this page (a dangling arc is the compiler's to report)
  const PageNames names(page);
  for (std::size_t k = 0; k < page.arcs.size(); ++k) {
    const auto& a = page.arcs[k];
    const auto ends = names.resolve(a);
    if (!ends) continue;
    ArcLayout arc;
    arc.spec_index = static_cast<std::uint32_t>(k);
    arc.from = ends->from;
    arc.to = ends->to;
    arc.link = ends->link;
    arc.kind = a.kind;
    arc.weight = 0;
    for (const auto& w : a.weights) arc.weight += w.value;
    if (a.weights.empty()) arc.weight = 1;
    arc.inscription = inscription(a.weights);
    if (a.amount) arc.inscription = *a.amount == 1.0 ? std::string() : amountText(*a.amount);
    // value inscriptions as written (a slot other than a0 named before its text)
    for (const auto& v : a.inscriptions) {
      arc.inscription += (arc.inscription.empty() ? "" : "+") +
                         (v.slot == net::kDefaultSlot ? v.text : net::slotName(v.slot) + ": " + v.text);
    }
    l.arcs.push_back(std::move(arc));
  }
  // positions: the spec's, or Graphviz's for a page with any construct lacking one
  std::string why;
  const std::size_t constructs = page.places.size() + page.transitions.size() + page.instances.size();
  const bool columns = !allPositioned(page) && constructs > kGraphvizLimit;
  if (columns) {
    diags.warning(page.loc, "page '" + page.name + "' has " + std::to_string(constructs) +
                                " constructs and some lack a position: laid out in columns (Graphviz lays out pages of up to " +
                                std::to_string(kGraphvizLimit) + ")");
    layoutInColumns(l);
  } else if (!allPositioned(page)) {
    l.from_graphviz = true;
    if (!layoutWithGraphviz(l, widths, why)) {
      diags.error(page.loc, "page '" + page.name + "': " + why);
      NetLayout empty;
      empty.page = page.name;
      empty.from_graphviz = true;
      return empty;
    }
  }
  for (auto& p : l.places) p.box = boxOfNode(ItemKind::Place, p.centre, 0);
  for (auto& t : l.transitions) t.box = boxOfNode(ItemKind::Transition, t.centre, t.fluid ? kFlowWidth : kBarWidth);
  for (std::size_t i = 0; i < l.instances.size(); ++i)
    l.instances[i].box = boxOfNode(ItemKind::Instance, l.instances[i].centre, widths[i]);
  // routes: straight or through the bend points; Graphviz's where it placed the nodes, but
  // through the bend points of an arc that has them
  if (!l.from_graphviz) {
    routeStraight(l, page);
  } else {
    for (auto& arc : l.arcs) {
      if (const auto& via = page.arcs[arc.spec_index].via; !via.empty()) routeVia(l, arc, via);
    }
  }
  placeLabelsAndBound(l, page, nullptr);
  return l;
}

void relayoutMoved(NetLayout& l, const net::PageSpec& page, const std::vector<ItemRef>& moved) {
  // the items moved: at the spec's positions, their boxes keeping their size
  std::vector<char> item_moved(l.places.size() + l.transitions.size() + l.instances.size(), 0);
  const auto flat = [&](ItemRef r) -> std::size_t {
    return r.kind == ItemKind::Place ? r.index : r.kind == ItemKind::Transition ? l.places.size() + r.index
                                                                               : l.places.size() + l.transitions.size() + r.index;
  };
  for (const ItemRef r : moved) {
    std::optional<net::EditorPos> at;
    NodeLayout* node = nullptr;
    switch (r.kind) {
      case ItemKind::Place: node = &l.places[r.index]; at = page.places[r.index].position; break;
      case ItemKind::Transition: node = &l.transitions[r.index]; at = page.transitions[r.index].position; break;
      case ItemKind::Instance: node = &l.instances[r.index]; at = page.instances[r.index].position; break;
      case ItemKind::Arc: break;
    }
    if (node == nullptr || !at) continue;
    const Point half{node->box.width() / 2, node->box.height() / 2};
    node->centre = layoutPoint(*at);
    node->box = {node->centre - half, node->centre + half};
    item_moved[flat(r)] = 1;
  }
  // the arcs that touch them (or whose bends moved with them), routed again
  std::vector<char> arc_moved(l.arcs.size(), 0);
  for (std::size_t k = 0; k < l.arcs.size(); ++k) arc_moved[k] = item_moved[flat(l.arcs[k].from)] | item_moved[flat(l.arcs[k].to)];
  routeStraight(l, page, &arc_moved);
  placeLabelsAndBound(l, page, &arc_moved);
}

std::string rateUnit(const net::PageSpec& page, const std::string& name) {
  const auto unitOf = [&](const std::string& place) -> const std::string* {
    for (const auto& p : page.places) {
      if (p.name == place && p.fluid && !p.fluid->unit.empty()) return &p.fluid->unit;
    }
    return nullptr;
  };
  for (const bool output : {true, false}) {
    for (const auto& a : page.arcs) {
      if (a.kind != net::ArcKind::Normal) continue;
      if ((output ? a.from : a.to) != name) continue;
      if (const auto* u = unitOf(output ? a.to : a.from)) return *u + "/s";
    }
  }
  return "/s";
}

std::string rateText(double rate, const std::string& unit) {
  return unit.starts_with("/") ? amountText(rate) + unit : amountText(rate, unit);
}

std::string amountText(double amount, const std::string& unit) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", amount == 0.0 ? 0.0 : amount);  // never "-0"
  return unit.empty() ? std::string(buf) : std::string(buf) + " " + unit;
}

std::string inscription(const std::vector<net::SlotCount>& weights) {
  if (weights.empty()) return "";
  if (weights.size() == 1 && weights[0].slot == net::kDefaultSlot)
    return weights[0].value == 1 ? "" : std::to_string(weights[0].value);
  // by slot; a run of three or more neighbours in one row with one weight reads "b0..b4"
  auto sorted = weights;
  std::sort(sorted.begin(), sorted.end(), [](const auto& x, const auto& y) { return x.slot < y.slot; });
  std::string out;
  for (std::size_t i = 0; i < sorted.size();) {
    std::size_t j = i;
    while (j + 1 < sorted.size() && sorted[j + 1].slot == sorted[j].slot + 1 && sorted[j + 1].slot / 8 == sorted[i].slot / 8 &&
           sorted[j + 1].value == sorted[i].value)
      ++j;
    if (j < i + 2) j = i;  // two neighbours read better apart: "a0+a1"
    out += out.empty() ? "" : "+";
    if (sorted[i].value != 1) out += std::to_string(sorted[i].value) + "\xc2\xb7";
    out += net::slotName(sorted[i].slot);
    if (j > i) out += ".." + net::slotName(sorted[j].slot);
    i = j + 1;
  }
  return out;
}

Point layoutPoint(const net::EditorPos& at) { return {at[0] * kEditorUnit, at[1] * kEditorUnit}; }

net::EditorPos editorPosition(Point p) {
  // quarters of an editor unit; + 0.0 turns -0 into 0
  const auto snap = [](double v) { return std::round(v / kEditorUnit * 4.0) / 4.0 + 0.0; };
  return {snap(p.x), snap(p.y)};
}

Point middleOf(const std::vector<Point>& points) {
  double length = 0;
  for (std::size_t i = 1; i < points.size(); ++i) length += std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
  // walk half the length along it
  double left = length / 2;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Point d = points[i] - points[i - 1];
    const double step = std::hypot(d.x, d.y);
    if (step > 0 && left <= step) return points[i - 1] + d * (left / step);
    left -= step;
  }
  return points.empty() ? Point{} : points.front();
}

net::EditorPos labelOffset(const ArcLayout& arc, Point p) {
  const Point d = arc.points.empty() ? p : p - middleOf(arc.points);
  return {d.x / kEditorUnit + 0.0, d.y / kEditorUnit + 0.0};
}

SegmentHit nearestSegment(const ArcLayout& arc, Point p) {
  const auto& pts = arc.points;
  if (pts.size() < 2) {
    const Point at = pts.empty() ? p : pts.front();
    return {0, at, std::hypot(p.x - at.x, p.y - at.y)};
  }
  SegmentHit best;
  best.distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Point at = nearestOnSegment(p, pts[i], pts[i + 1]);
    const double d = std::hypot(p.x - at.x, p.y - at.y);
    if (d < best.distance) best = {i, at, d};
  }
  return best;
}

std::optional<std::size_t> bendAt(const ArcLayout& arc, Point p, double tolerance) {
  if (!arc.follows_via) return std::nullopt;
  std::optional<std::size_t> best;
  double nearest = tolerance;
  // the bends are the points between the two ends
  for (std::size_t i = 1; i + 1 < arc.points.size(); ++i) {
    const double d = std::hypot(p.x - arc.points[i].x, p.y - arc.points[i].y);
    if (d <= nearest) {
      nearest = d;
      best = i - 1;
    }
  }
  return best;
}

PageView findView(const net::NetSpec& spec, const std::string& path, core::Diagnostics& diags,
                  const core::SourceLoc& where) {
  auto named = [](const std::vector<net::PageSpec>& pages, std::string_view name) -> const net::PageSpec* {
    for (const auto& p : pages)
      if (p.name == name) return &p;
    return nullptr;
  };
  // the first part names a page (or a page type); each further part an instance inside
  const auto slash = path.find('/');
  const std::string head = path.substr(0, slash);
  PageView view;
  if (head.empty() && !spec.pages.empty()) {
    view = {&spec.pages.front(), spec.pages.front().name};
  } else if (const auto* page = named(spec.pages, head)) {
    view = {page, head};
  } else if (const auto* type = named(spec.page_types, head)) {
    view = {type, ""};
  }
  for (std::size_t at = slash; view.page != nullptr && at != std::string::npos;) {
    const auto next = path.find('/', at + 1);
    const std::string inst = path.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1);
    const auto& list = view.page->instances;
    const auto it = std::find_if(list.begin(), list.end(), [&](const auto& i) { return i.name == inst; });
    const auto* type = it == list.end() ? nullptr : named(spec.page_types, it->type);
    if (type == nullptr) {
      diags.error(where, "'" + view.page->name + "' has no instance '" + inst + "' (in '" + path + "')");
      return {};
    }
    view = {type, view.prefix.empty() ? "" : view.prefix + "/" + inst};
    at = next;
  }
  if (view.page != nullptr) return view;
  std::string list;
  for (const auto& p : spec.pages) list += (list.empty() ? "" : ", ") + p.name;
  std::string types;
  for (const auto& p : spec.page_types) types += (types.empty() ? "" : ", ") + p.name;
  std::string message = path.empty() ? "the model has no page" : "no page or page type '" + head + "'";
  message += list.empty() ? "" : "; the pages are: " + list;
  message += types.empty() ? "" : "; the page types are: " + types;
  diags.error(where, message);
  return {};
}

}  // namespace gdpn::diagram
