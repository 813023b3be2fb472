#include "gdpn/scene/actions.h"

#include <array>

namespace gdpn::scene {

void traverse(Node& node, const std::function<void(Node&, const TraversalState&)>& visit, TraversalState state) {
  // a body the physics moves is where the physics says, whatever its parents say
  if (node.dynamic_pose) state.pose = *node.dynamic_pose;
  visit(node, state);
  if (node.children().empty()) return;
  // the node's own placement holds for its children; a Material among them holds for the
  // siblings after it
  TraversalState inner = state;
  const core::Vec3 s = node.localScale();
  core::Pose local = node.dynamic_pose ? core::Pose{} : node.localPose();
  local.position = local.position.times(state.scale);
  inner.pose = state.pose * local;
  inner.scale = state.scale.times(s);
  for (const auto& child : node.children()) {
    if (child->type().name == "Material") inner.material = child.get();
    traverse(*child, visit, inner);
  }
}

void updateTransforms(Node& root) {
  traverse(root, [](Node& n, const TraversalState& st) {
    n.world = st.pose;
    n.world_scale = st.scale;
  }, {root.parent() ? root.parent()->world : core::Pose{},
      root.parent() ? root.parent()->world_scale : core::Vec3{1, 1, 1}, nullptr});
}

core::Aabb shapeBounds(const Node& shape) {
  core::Aabb box;
  const auto& name = shape.type().name;
  if (name == "Cube") {
    const core::Vec3 h = shape.vec3("size") * 0.5;
    box.add(-h);
    box.add(h);
  } else if (name == "Sphere") {
    const double r = shape.number("radius");
    box.add(core::Vec3{-r, -r, -r});
    box.add(core::Vec3{r, r, r});
  } else if (name == "Cylinder" || name == "Cone") {
    const double r = shape.number("radius"), h = shape.number("height") / 2;
    box.add(core::Vec3{-r, -r, -h});
    box.add(core::Vec3{r, r, h});
  }
  return box;
}

namespace {

core::Aabb worldBounds(const Node& shape) {
  core::Aabb local = shapeBounds(shape);
  if (local.empty()) return local;
  local.lo = local.lo.times(shape.world_scale);
  local.hi = local.hi.times(shape.world_scale);
  core::Aabb fixed;  // a negative scale swaps corners
  fixed.add(local.lo);
  fixed.add(local.hi);
  return fixed.transformed(shape.world);
}

}  // namespace

core::Aabb boundingBox(const Node& node) {
  core::Aabb box;
  traverse(const_cast<Node&>(node), [&](Node& n, const TraversalState&) {
    if (n.type().category == Category::Shape) box.add(worldBounds(n));
  }, {node.world, node.world_scale, nullptr});
  return box;
}

Pick pick(Node& root, const core::Ray& ray) {
  Pick best;
  traverse(root, [&](Node& n, const TraversalState&) {
    if (n.type().category != Category::Shape) return;
    const double d = core::intersect(ray, worldBounds(n));
    if (d >= 0 && (!best.shape || d < best.distance)) best = {&n, d};
  }, {root.world, root.world_scale, nullptr});
  return best;
}

}  // namespace gdpn::scene
