#pragma once
/// \file
/// A uniform grid over a layout's items, so that a viewport asks only for what it shows: a
/// query costs about the number of items in the cells it touches, not the size of the page.

#include <cstdint>
#include <optional>
#include <vector>

#include "gdpn/diagram/layout.h"

namespace gdpn::diagram {

/// Which items of a NetLayout overlap a box (layout units).
class SpatialIndex {
 public:
  /// An index over every item of `layout` (which must outlive the index and stay unchanged).
  /// `cell` is the grid's pitch, layout units (> 0).
  explicit SpatialIndex(const NetLayout& layout, double cell = 4 * kEditorUnit);

  /// The items whose boxes overlap `view` (layout units), each once, in a fixed order: arcs
  /// first, then instances, transitions and places, each by index (the order they are drawn). Not safe to call from two threads at once.
  [[nodiscard]] std::vector<ItemRef> query(const Box& view) const;

  /// The items whose boxes lie wholly inside `band` (layout units), in query()'s order: what a
  /// rubber band selects.
  [[nodiscard]] std::vector<ItemRef> within(const Box& band) const;
  /// The item under `p` (layout units), for clicks: a place within its circle, a transition
  /// or instance within its box grown by `tolerance`, an arc within `tolerance` of its
  /// polyline (layout units). Places and transitions win over instances, and those over arcs;
  /// nullopt over empty paper.
  [[nodiscard]] std::optional<ItemRef> pick(Point p, double tolerance) const;

 private:
  const NetLayout* layout_;
  double cell_;
  Point origin_;                          // the grid's top-left corner, layout units
  int columns_ = 0, rows_ = 0;
  std::vector<std::uint32_t> starts_;     // per cell: where its items start in items_ (rows_*columns_ + 1)
  std::vector<ItemRef> items_;            // items by cell
  mutable std::vector<std::uint32_t> stamp_;  // per item (by flat number): the query that last took it
  mutable std::uint32_t query_ = 0;
  std::vector<std::uint32_t> offsets_;    // flat number of each kind's first item

  [[nodiscard]] std::uint32_t flat(ItemRef r) const { return offsets_[static_cast<std::size_t>(r.kind)] + r.index; }
};

}  // namespace gdpn::diagram
