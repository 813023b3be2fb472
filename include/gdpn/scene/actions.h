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

/// Visits `node` and its subtree in order, calling `visit(node, state)` with the state in
/// effect at each node. Group-like nodes push the state for their children and pop it after.
void traverse(Node& node, const std::function<void(Node&, const TraversalState&)>& visit,
              TraversalState state = {});

/// Sets Node::world and Node::world_scale of every node below `root` (itself included).
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

/// The world box around every shape in `node`'s subtree (from the last updateTransforms()).
core::Aabb boundingBox(const Node& node);

/// What a ray hit.
struct Pick {
  Node* shape = nullptr;  ///< the shape hit first, or null
  double distance = -1;   ///< metres along the ray
};

/// The first shape below `root` that `ray` hits (by its bounding box; exact for unrotated
/// boxes, conservative otherwise), from the last updateTransforms().
Pick pick(Node& root, const core::Ray& ray);

}  // namespace gdpn::scene
