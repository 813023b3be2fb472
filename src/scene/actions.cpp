#include "gdpn/scene/actions.h"

#include <array>

#include "gdpn/scene/fields.h"

namespace gdpn::scene {

void traverse(Node& node, const std::function<void(Node&, const TraversalState&)>& visit, TraversalState state,
              Templates templates) {
  if (templates == Templates::Skip && node.is_template) return;
  // a body the physics moves is where the physics says, whatever its parents say
  if (node.dynamic_pose) state.pose = *node.dynamic_pose;
  visit(node, state);
  if (node.children().empty()) return;
  // the node's own placement holds for its children; a Material among them holds for the
  // siblings after it
  TraversalState inner = state;
  inner.pose = node.frameIn(state.pose, state.scale);
  inner.scale = state.scale.times(node.localScale());
  for (const auto& child : node.children()) {
    const bool skipped = templates == Templates::Skip && child->is_template;
    if (child->kind() == NodeKind::Material && !skipped) inner.material = child.get();
    traverse(*child, visit, inner, templates);
  }
}

bool inTemplate(const Node& node) {
  for (const Node* n = &node; n != nullptr; n = n->parent()) {
    if (n->is_template) return true;
  }
  return false;
}

const Node* materialAt(const Node& node) {
  for (const Node* n = &node; n->parent(); n = n->parent()) {
    // a Material marked as a template colours nothing: the one before it, then
    for (const Node* sib = n->previous(NodeKind::Material); sib != nullptr; sib = sib->previous(NodeKind::Material)) {
      if (!sib->is_template) return sib;
    }
  }
  return nullptr;
}

const Node* drivingConveyor(const Node& parent) {
  // a Conveyor marked as a template moves nothing: the one before it, then
  const Node* conveyor = parent.lastChild(NodeKind::Conveyor);
  while (conveyor != nullptr && conveyor->is_template) conveyor = conveyor->previous(NodeKind::Conveyor);
  return conveyor;
}

void updateTransforms(Node& root) {
  traverse(root, [](Node& n, const TraversalState& st) {
    n.world = st.pose;
    n.world_scale = st.scale;
  }, {root.parent() ? root.parent()->framePose() : core::Pose{},
      root.parent() ? root.parent()->world_scale.times(root.parent()->localScale()) : core::Vec3{1, 1, 1}, nullptr});
}

namespace {

/// A ball's or a round prism's extent from its radius and height (m).
core::Vec3 round(double radius, double height) { return {2 * radius, 2 * radius, height}; }

}  // namespace

core::Vec3 shapeExtent(const Node& node) {
  switch (node.kind()) {
    case NodeKind::Cube: return node.vec3(field::Cube::Size);
    case NodeKind::Sphere: {
      const double d = 2 * node.number(field::Sphere::Radius);
      return {d, d, d};
    }
    case NodeKind::Cylinder: return round(node.number(field::Cylinder::Radius), node.number(field::Cylinder::Height));
    case NodeKind::Cone: return round(node.number(field::Cone::Radius), node.number(field::Cone::Height));
    case NodeKind::Region: {
      const double r = node.number(field::Region::Radius), h = node.number(field::Region::Height);
      switch (node.choice<RegionShape>(field::Region::Shape)) {
        case RegionShape::Box: return node.vec3(field::Region::Size);
        case RegionShape::Sphere: return {2 * r, 2 * r, 2 * r};
        case RegionShape::Cylinder:
        case RegionShape::Cone: return round(r, h);
        case RegionShape::Ray: return {};
      }
      return {};
    }
    case NodeKind::Group:
    case NodeKind::Transform:
    case NodeKind::Material:
    case NodeKind::Light:
    case NodeKind::Camera:
    case NodeKind::Fog:
    case NodeKind::Plane:
    case NodeKind::Mesh:
    case NodeKind::Terrain:
    case NodeKind::World:
    case NodeKind::Body:
    case NodeKind::Joint:
    case NodeKind::Conveyor:
    case NodeKind::GradientField:
    case NodeKind::RangeFinder:
    case NodeKind::GradientSensor:
    case NodeKind::KeyboardSensor:
    case NodeKind::MouseSensor:
    case NodeKind::ColorCamera:
    case NodeKind::DepthCamera:
    case NodeKind::LaserScan:
    case NodeKind::Imu:
    case NodeKind::Gps:
    case NodeKind::Contact:
    case NodeKind::ForceTorque:
    case NodeKind::TimeSensor: return {};
  }
  return {};
}

core::Aabb shapeBounds(const Node& shape) {
  core::Aabb box;
  // planes, meshes and terrain have no extent of their own here
  const NodeKind k = shape.kind();
  if (k != NodeKind::Cube && k != NodeKind::Sphere && k != NodeKind::Cylinder && k != NodeKind::Cone) return box;
  const core::Vec3 h = shapeExtent(shape) * 0.5;
  box.add(-h);
  box.add(h);
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
  }, {node.world, node.world_scale, nullptr}, node.is_template ? Templates::Visit : Templates::Skip);
  return box;
}

Pick pick(Node& root, const core::Ray& ray) {
  Pick best;
  traverse(root, [&](Node& n, const TraversalState&) {
    if (n.type().category != Category::Shape) return;
    const double d = core::intersect(ray, worldBounds(n));
    if (d >= 0 && (!best.shape || d < best.distance)) best = {&n, d};
  }, {root.world, root.world_scale, nullptr}, Templates::Skip);
  return best;
}

}  // namespace gdpn::scene
