#pragma once
/// \file
/// Actions: traversals of the tree that keep a state stack (placement, scale, material) and
/// dispatch on node type. Transforms place their children; a Material colours the shapes
/// after it among its siblings (and below them).

#include <functional>

#include "gdpn/core/math.h"
#include "gdpn/scene/node.h"

namespace gdpn::scene {

/// What a traversal carries down the tree.
struct TraversalState {
  core::Pose pose;                  ///< world placement of the current frame
  core::Vec3 scale{1, 1, 1};        ///< accumulated scale
  const Node* material = nullptr;   ///< the Material in effect, or null
};

/// Whether a traversal visits templates (Node::is_template) and their subtrees.
enum class Templates : bool {
  Visit,  ///< every node: editing, finding, deleting
  Skip,   ///< what is simulated, sensed and drawn: templates and what is below them left out
};

/// Visits `node` and its subtree in order, calling `visit(node, state)` with the state in
/// effect at each node. Group-like nodes push the state for their children and pop it after.
/// With Templates::Skip a template (`node` itself included) is not visited, nor its subtree.
void traverse(Node& node, const std::function<void(Node&, const TraversalState&)>& visit,
              TraversalState state = {}, Templates templates = Templates::Visit);

/// True when `node` or a node above it is a template (Node::is_template).
[[nodiscard]] bool inTemplate(const Node& node);

/// The Material in effect at `node`: the nearest one before it among its siblings, or before
/// an ancestor among the ancestor's siblings, that is no template; null when none is.
const Node* materialAt(const Node& node);

/// The Conveyor that drives the shapes among `parent`'s children: the last of its children
/// that is a Conveyor and no template; null when none is. The physics moves what touches
/// those shapes along it, and the renderer draws its arrows on them. Constant time in the
/// children but for template Conveyors.
const Node* drivingConveyor(const Node& parent);

/// Sets Node::world and Node::world_scale of every node below `root` (itself included), `root`
/// placed in its parent's frame as that stands (the parent's own placement included).
void updateTransforms(Node& root);

/// The size of a primitive volume in its own frame, centred on its origin, in metres along
/// x, y, z, before any scale: a Cube's edges; a Sphere's diameter three times; a Cylinder's
/// or Cone's diameter, diameter and height. A Region's volume by its `shape` the same way
/// (a ray has none). Zero for every other node. The physics, the renderer and picking all
/// take a shape's size from here.
core::Vec3 shapeExtent(const Node& node);

/// The box a shape takes up in its own frame, before scale (empty for planes and meshes not
/// yet loaded).
core::Aabb shapeBounds(const Node& shape);

/// The world box around every shape in `node`'s subtree (from the last updateTransforms()),
/// templates left out unless `node` is one.
core::Aabb boundingBox(const Node& node);

/// What a ray hit.
struct Pick {
  Node* shape = nullptr;  ///< the shape hit first, or null
  double distance = -1;   ///< metres along the ray
};

/// The first shape below `root` that `ray` hits (by its bounding box; exact for unrotated
/// boxes, conservative otherwise), from the last updateTransforms(); templates are not drawn,
/// so not hit.
Pick pick(Node& root, const core::Ray& ray);

}  // namespace gdpn::scene
