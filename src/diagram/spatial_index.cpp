#include "gdpn/diagram/spatial_index.h"

#include <algorithm>
#include <cmath>

namespace gdpn::diagram {
namespace {

// every item of the layout, in drawing order: arcs under instances under transitions and places
template <typename F>
void forEachItem(const NetLayout& l, F&& f) {
  for (std::uint32_t i = 0; i < l.arcs.size(); ++i) f(ItemRef{ItemKind::Arc, i});
  for (std::uint32_t i = 0; i < l.instances.size(); ++i) f(ItemRef{ItemKind::Instance, i});
  for (std::uint32_t i = 0; i < l.transitions.size(); ++i) f(ItemRef{ItemKind::Transition, i});
  for (std::uint32_t i = 0; i < l.places.size(); ++i) f(ItemRef{ItemKind::Place, i});
}

int drawOrder(ItemKind k) {
  switch (k) {
    case ItemKind::Arc: return 0;
    case ItemKind::Instance: return 1;
    case ItemKind::Transition: return 2;
    case ItemKind::Place: return 3;
  }
  return 0;
}

}  // namespace

SpatialIndex::SpatialIndex(const NetLayout& layout, double cell) : layout_(&layout), cell_(std::max(cell, 1.0)) {
  const Box& b = layout.bounds;
  origin_ = b.min;
  columns_ = std::max(1, static_cast<int>(std::ceil(b.width() / cell_)) + 1);
  rows_ = std::max(1, static_cast<int>(std::ceil(b.height() / cell_)) + 1);
  offsets_ = {0, 0, 0, 0};
  offsets_[static_cast<int>(ItemKind::Transition)] = static_cast<std::uint32_t>(layout.places.size());
  offsets_[static_cast<int>(ItemKind::Instance)] = offsets_[1] + static_cast<std::uint32_t>(layout.transitions.size());
  offsets_[static_cast<int>(ItemKind::Arc)] = offsets_[2] + static_cast<std::uint32_t>(layout.instances.size());
  stamp_.assign(offsets_[3] + layout.arcs.size(), 0);
  // the cells an item's box covers
  auto cells = [&](const Box& box, auto&& visit) {
    const int x0 = std::clamp(static_cast<int>(std::floor((box.min.x - origin_.x) / cell_)), 0, columns_ - 1);
    const int x1 = std::clamp(static_cast<int>(std::floor((box.max.x - origin_.x) / cell_)), 0, columns_ - 1);
    const int y0 = std::clamp(static_cast<int>(std::floor((box.min.y - origin_.y) / cell_)), 0, rows_ - 1);
    const int y1 = std::clamp(static_cast<int>(std::floor((box.max.y - origin_.y) / cell_)), 0, rows_ - 1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) visit(static_cast<std::size_t>(y) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(x));
  };
  // two passes: count per cell, then fill (a compact array of arrays)
  starts_.assign(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_) + 1, 0);
  forEachItem(layout, [&](ItemRef r) { cells(layout.boxOf(r), [&](std::size_t c) { ++starts_[c + 1]; }); });
  for (std::size_t c = 1; c < starts_.size(); ++c) starts_[c] += starts_[c - 1];
  items_.resize(starts_.back());
  std::vector<std::uint32_t> fill(starts_.begin(), starts_.end() - 1);
  forEachItem(layout, [&](ItemRef r) { cells(layout.boxOf(r), [&](std::size_t c) { items_[fill[c]++] = r; }); });
}

std::vector<ItemRef> SpatialIndex::query(const Box& view) const {
  std::vector<ItemRef> out;
  if (++query_ == 0) {  // the stamps wrapped around: start them afresh
    std::fill(stamp_.begin(), stamp_.end(), 0);
    query_ = 1;
  }
  const auto col = [&](double x) { return static_cast<int>(std::floor((x - origin_.x) / cell_)); };
  const auto row = [&](double y) { return static_cast<int>(std::floor((y - origin_.y) / cell_)); };
  const int x0 = std::max(col(view.min.x), 0), x1 = std::min(col(view.max.x), columns_ - 1);
  const int y0 = std::max(row(view.min.y), 0), y1 = std::min(row(view.max.y), rows_ - 1);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const auto c = static_cast<std::size_t>(y) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(x);
      for (std::uint32_t k = starts_[c]; k < starts_[c + 1]; ++k) {
        const ItemRef r = items_[k];
        auto& s = stamp_[flat(r)];
        if (s == query_ || !layout_->boxOf(r).overlaps(view)) continue;
        s = query_;
        out.push_back(r);
      }
    }
  }
  std::sort(out.begin(), out.end(), [](ItemRef a, ItemRef b) {
    return drawOrder(a.kind) != drawOrder(b.kind) ? drawOrder(a.kind) < drawOrder(b.kind) : a.index < b.index;
  });
  return out;
}

std::vector<ItemRef> SpatialIndex::within(const Box& band) const {
  auto out = query(band);
  std::erase_if(out, [&](ItemRef r) {
    const Box& b = layout_->boxOf(r);
    return b.min.x < band.min.x || b.min.y < band.min.y || b.max.x > band.max.x || b.max.y > band.max.y;
  });
  return out;
}

std::optional<ItemRef> SpatialIndex::pick(Point p, double tolerance) const {
  const Box near = Box::around(p, tolerance, tolerance);
  const auto items = query(near);
  // drawn last is on top: walk the drawing order backwards
  for (auto it = items.rbegin(); it != items.rend(); ++it) {
    const ItemRef r = *it;
    switch (r.kind) {
      case ItemKind::Place: {
        const Point c = layout_->places[r.index].centre;
        if (std::hypot(p.x - c.x, p.y - c.y) <= kPlaceRadius + tolerance) return r;
        break;
      }
      case ItemKind::Transition:
      case ItemKind::Instance: return r;  // the box overlaps the grown point: a hit
      case ItemKind::Arc: {
        const auto& pts = layout_->arcs[r.index].points;
        for (std::size_t i = 1; i < pts.size(); ++i)
          if (distanceToSegment(p, pts[i - 1], pts[i]) <= tolerance) return r;
        break;
      }
    }
  }
  return std::nullopt;
}

}  // namespace gdpn::diagram
