// Building and removing the physics of a subtree: the whole scene when the world is made, a
// spawned subtree later, and a subtree taken out of the scene.

#include <algorithm>

#include "ode_convert.h"
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

void World::Impl::moveSubtree(Node& top) {
  // each static geometry's place relative to its node (a mesh's box sits on the mesh's
  // centre), then the nodes' new poses, then the geometries there; ground stays as made, and
  // what bodies carry goes with the bodies
  struct Static {
    const Node* node;
    dGeomID geom;
    core::Pose offset;
    core::Aabb box;  // where it was, then where it is too
  };
  std::vector<Static> statics;
  scene::traverse(top, [&](Node& n, const scene::TraversalState&) {
    const auto g = geom_of.find(n.handle());
    if (g == geom_of.end() || dGeomGetBody(g->second) != nullptr) return;
    const int kind = dGeomGetClass(g->second);
    if (kind == dPlaneClass || kind == dHeightfieldClass) return;
    const dReal* p = dGeomGetPosition(g->second);
    dQuaternion q;
    dGeomGetQuaternion(g->second, q);
    statics.push_back({&n, g->second, n.world.inverse() * core::Pose{{p[0], p[1], p[2]}, {q[0], q[1], q[2], q[3]}},
                       aabbOf(g->second)});
  }, {top.world, top.world_scale, nullptr}, scene::Templates::Skip);
  scene::updateTransforms(top);
  // the broad phase's tree of fixed shapes is made again (once, at the next step)
  if (!statics.empty()) shapes_changed = true;
  for (auto& s : statics) {
    const core::Pose at = s.node->world * s.offset;
    dGeomSetPosition(s.geom, at.position.x, at.position.y, at.position.z);
    const dQuaternion q = {at.rotation.w, at.rotation.x, at.rotation.y, at.rotation.z};
    dGeomSetQuaternion(s.geom, q);
    s.box.add(aabbOf(s.geom));
  }
  // a sleeping body that lay on (or against) a moved shape, or where one went, wakes
  constexpr double kNear = 0.01;  // m
  for (dGeomID g : shapes) {
    const dBodyID b = dGeomGetBody(g);
    if (b == nullptr || dBodyIsEnabled(b)) continue;
    const core::Aabb box = aabbOf(g);
    for (const auto& s : statics) {
      if (box.lo.x <= s.box.hi.x + kNear && box.hi.x >= s.box.lo.x - kNear && box.lo.y <= s.box.hi.y + kNear &&
          box.hi.y >= s.box.lo.y - kNear && box.lo.z <= s.box.hi.z + kNear && box.hi.z >= s.box.lo.z - kNear) {
        dBodyEnable(b);
        break;
      }
    }
  }
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
