#include "gdpn/core/broad_phase.h"

#include <algorithm>
#include <numeric>

namespace gdpn::core {

namespace {
constexpr std::uint32_t kLeafSize = 4;

double centre(const Aabb& b, int axis) {
  switch (axis) {
    case 0: return b.lo.x + b.hi.x;
    case 1: return b.lo.y + b.hi.y;
    default: return b.lo.z + b.hi.z;
  }
}
}  // namespace

void AabbTree::build(const std::vector<Aabb>& boxes) {
  nodes_.clear();
  boxes_ = boxes;
  items_.resize(boxes.size());
  std::iota(items_.begin(), items_.end(), 0u);
  if (boxes.empty()) return;
  nodes_.reserve(2 * boxes.size() / kLeafSize + 2);
  nodes_.emplace_back();
  split(0, 0, static_cast<std::uint32_t>(boxes.size()), 0);
}

/// Makes node `self` over items [first, first + count): a leaf when few, else an inner node
/// whose two children (side by side) split the items at the median along the longest axis of
/// their centres.
void AabbTree::split(std::uint32_t self, std::uint32_t first, std::uint32_t count, int depth) {
  Aabb all, centres;
  for (std::uint32_t i = first; i < first + count; ++i) {
    all.add(boxes_[i]);
    centres.add((boxes_[i].lo + boxes_[i].hi) * 0.5);
  }
  nodes_[self].box = all;
  if (count <= kLeafSize || depth >= 48) {
    nodes_[self].first = first;
    nodes_[self].count = count;
    return;
  }
  const Vec3 extent = centres.hi - centres.lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  // order this range by centre along the axis, ties by index, so that a build is the same
  // every time; boxes and items move together
  std::vector<std::uint32_t> perm(count);
  std::iota(perm.begin(), perm.end(), first);
  std::sort(perm.begin(), perm.end(), [&](std::uint32_t a, std::uint32_t b) {
    const double ca = centre(boxes_[a], axis), cb = centre(boxes_[b], axis);
    return ca != cb ? ca < cb : items_[a] < items_[b];
  });
  std::vector<Aabb> boxes(count);
  std::vector<std::uint32_t> items(count);
  for (std::uint32_t k = 0; k < count; ++k) {
    boxes[k] = boxes_[perm[k]];
    items[k] = items_[perm[k]];
  }
  std::copy(boxes.begin(), boxes.end(), boxes_.begin() + first);
  std::copy(items.begin(), items.end(), items_.begin() + first);
  const auto left = static_cast<std::uint32_t>(nodes_.size());
  nodes_[self].first = left;
  nodes_[self].count = 0;
  nodes_.emplace_back();
  nodes_.emplace_back();
  const std::uint32_t half = count / 2;
  split(left, first, half, depth + 1);
  split(left + 1, first + half, count - half, depth + 1);
}

void SweepAndPrune::sort(const std::vector<Aabb>& boxes) {
  const auto n = static_cast<std::uint32_t>(boxes.size());
  auto before = [&](std::uint32_t a, std::uint32_t b) {
    return boxes[a].lo.x != boxes[b].lo.x ? boxes[a].lo.x < boxes[b].lo.x : a < b;
  };
  if (order_.size() != n) {
    // the set changed: sort afresh
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0u);
    std::sort(order_.begin(), order_.end(), before);
    return;
  }
  // insertion sort: boxes move little between steps, so this is about linear
  for (std::size_t i = 1; i < order_.size(); ++i) {
    const std::uint32_t item = order_[i];
    std::size_t j = i;
    while (j > 0 && before(item, order_[j - 1])) {
      order_[j] = order_[j - 1];
      --j;
    }
    order_[j] = item;
  }
}

}  // namespace gdpn::core
