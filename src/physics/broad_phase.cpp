// The broad phase: which pairs of shapes may touch. Shapes on bodies are swept against each
// other and looked up in a tree of the shapes on no body, which never move; planes and other
// endless shapes meet every moving shape.

#include <algorithm>
#include <cmath>

#include "ode_convert.h"
#include "world_impl.h"

namespace gdpn::physics {

void World::Impl::refreshShapes() {
  if (!shapes_changed) return;
  moving.clear();
  fixed.clear();
  endless.clear();
  std::vector<core::Aabb> boxes;
  for (dGeomID g : shapes) {
    if (dGeomGetBody(g)) {
      moving.push_back(g);
      continue;
    }
    const core::Aabb box = aabbOf(g);
    const double bounds[6] = {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z};
    if (std::all_of(bounds, bounds + 6, [](double v) { return std::isfinite(v) && std::abs(v) < 1e12; })) {
      fixed.push_back(g);
      boxes.push_back(box);
    } else {
      endless.push_back(g);
    }
  }
  fixed_tree.build(boxes);
  shapes_changed = false;
}

void World::Impl::refreshMoving() {
  refreshShapes();
  moving_boxes.resize(moving.size());
  for (std::size_t i = 0; i < moving.size(); ++i) moving_boxes[i] = aabbOf(moving[i]);
}

void World::Impl::collide() {
  refreshMoving();
  sweep.pairs(moving_boxes, [&](std::size_t i, std::size_t j) {
    if (dGeomGetBody(moving[i]) != dGeomGetBody(moving[j])) nearCallback(this, moving[i], moving[j]);
  });
  for (std::size_t i = 0; i < moving.size(); ++i) {
    fixed_tree.query(moving_boxes[i], [&](std::size_t k) { nearCallback(this, moving[i], fixed[k]); });
    for (dGeomID g : endless) nearCallback(this, moving[i], g);
  }
}

}  // namespace gdpn::physics
