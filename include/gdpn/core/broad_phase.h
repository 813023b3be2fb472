#pragma once
// Broad-phase collision search: which boxes may touch. Two structures, for the two kinds of
// things a plant holds: a bounding-volume tree over boxes that do not move (belts, walls,
// the ground), built once and queried in logarithmic time, and a sweep over the boxes of the
// moving bodies, kept sorted from one step to the next so that re-sorting costs about as much
// as the bodies moved. Neither allocates once it has reached its size.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gdpn/core/math.h"

namespace gdpn::core {

/// True when the closed boxes `a` and `b` share a point.
inline bool overlaps(const Aabb& a, const Aabb& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

/// A bounding-volume tree over boxes that stay where they are. Items are the indices of the
/// boxes given to build(); a query reports them in an order fixed by the build.
class AabbTree {
 public:
  /// Builds the tree over `boxes` (finite ones), replacing what was there.
  void build(const std::vector<Aabb>& boxes);
  /// Calls `visit(index)` for every box that overlaps `box`.
  template <class Visit>
  void query(const Aabb& box, Visit&& visit) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (!overlaps(n.box, box)) continue;
      if (n.count > 0) {
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
          if (overlaps(boxes_[i], box)) visit(static_cast<std::size_t>(items_[i]));
        }
      } else {
        stack[top++] = n.first + 1;  // the right child
        stack[top++] = n.first;      // the left child, visited first
      }
    }
  }
  /// How many boxes the tree holds.
  [[nodiscard]] std::size_t size() const { return items_.size(); }

 private:
  struct Node {
    Aabb box;
    std::uint32_t first = 0;  // a leaf: its first item; an inner node: its left child (right = +1)
    std::uint32_t count = 0;  // items in a leaf; 0 for an inner node
  };
  void split(std::uint32_t self, std::uint32_t first, std::uint32_t count, int depth);
  std::vector<Node> nodes_;
  std::vector<Aabb> boxes_;          // in leaf order
  std::vector<std::uint32_t> items_; // the index each box was given under, in leaf order
};

/// Overlapping pairs among boxes that move, found by sorting them along x and sweeping. The
/// order is kept between calls: boxes that moved a little re-sort in about linear time.
class SweepAndPrune {
 public:
  /// Calls `visit(i, j)` once for every pair of overlapping boxes among `boxes` (i != j;
  /// indices into `boxes`). The number of boxes may change between calls.
  template <class Visit>
  void pairs(const std::vector<Aabb>& boxes, Visit&& visit) {
    sort(boxes);
    for (std::size_t a = 0; a < order_.size(); ++a) {
      const Aabb& ba = boxes[order_[a]];
      for (std::size_t b = a + 1; b < order_.size(); ++b) {
        const Aabb& bb = boxes[order_[b]];
        if (bb.lo.x > ba.hi.x) break;
        if (ba.lo.y <= bb.hi.y && bb.lo.y <= ba.hi.y && ba.lo.z <= bb.hi.z && bb.lo.z <= ba.hi.z) {
          visit(static_cast<std::size_t>(order_[a]), static_cast<std::size_t>(order_[b]));
        }
      }
    }
  }

 private:
  void sort(const std::vector<Aabb>& boxes);
  std::vector<std::uint32_t> order_;  // indices into the boxes, by their low x
};

}  // namespace gdpn::core
