// Building and removing the physics of a subtree: the whole scene when the world is made, a
// spawned subtree later, and a subtree taken out of the scene.

#include <algorithm>

#include "world_impl.h"

namespace gdpn::physics {

using scene::Node;
using scene::NodeKind;

bool World::Impl::addSubtree(Node& top, core::Diagnostics& diags) {
  scene::updateTransforms(top);
  // bodies first: joints need both ends
  bool ok = buildBodies(top, diags);
  // a geometry per shape with the material in effect, and the sensors
  std::vector<std::pair<Node*, Body*>> pending_joints;
  scene::TraversalState state{top.world, top.world_scale, scene::materialAt(top)};
  scene::traverse(top, [&](Node& n, const scene::TraversalState& st) {
    ok = addGeom(n, st, model_dir, diags) && ok;
    if (n.kind() == NodeKind::Joint) pending_joints.emplace_back(&n, n.parent() ? owner(*n.parent()) : nullptr);
    addSensor(n);
  }, state, scene::Templates::Skip);
  // then the joints
  for (const auto& [node, parent] : pending_joints) ok = addJoint(*node, parent, diags) && ok;
  return ok;
}

void World::Impl::removeSubtree(const Node& top) {
  scene::traverse(const_cast<Node&>(top), [&](Node& n, const scene::TraversalState&) {
    const auto h = n.handle();
    // its geometry, as a shape or as a sensor
    if (auto g = geom_of.find(h); g != geom_of.end()) {
      shapes.erase(std::find(shapes.begin(), shapes.end(), g->second));
      shapes_changed = true;
      dGeomDestroy(g->second);
      geom_of.erase(g);
    }
    for (auto it = sensors.begin(); it != sensors.end();) {
      if (it->node == &n) {
        dGeomDestroy(it->geom);
        it = sensors.erase(it);
        retagSensors();
      } else {
        ++it;
      }
    }
    // its joint
    if (auto j = joint_of.find(h); j != joint_of.end()) {
      dJointDestroy(joints[j->second].id);
      joints[j->second].id = nullptr;
      joint_of.erase(j);
    }
    // its body, and what attach() joined to it
    if (auto b = body_of.find(h); b != body_of.end()) {
      Body& body = bodies[b->second];
      for (auto it = attached.begin(); it != attached.end();) {
        if (it->first.first == body.id || it->first.second == body.id) {
          dJointDestroy(it->second);
          it = attached.erase(it);
        } else {
          ++it;
        }
      }
      dBodyDestroy(body.id);
      body.id = nullptr;
      body_of.erase(b);
    }
  });
}

}  // namespace gdpn::physics
