// Contacts: what each shape brings to a contact (its material's friction and bounce, the
// belt of a conveyor beside it), and the contact joints made where two shapes touch.

#include <algorithm>
#include <cmath>

#include "ode_convert.h"
#include "world_impl.h"

namespace gdpn::physics {

using core::Vec3;
using scene::Node;
using scene::NodeKind;

Surface World::Impl::surfaceFor(const Node& n, const scene::TraversalState& st, const Body* body) const {
  Surface surface;
  surface.node = &n;
  // the material in effect
  surface.material = st.material;
  if (st.material) {
    surface.friction = st.material->number(scene::field::Material::Friction);
    surface.bounce = st.material->number(scene::field::Material::Bounce);
  }
  // a conveyor among the shape's siblings (the last one, if several)
  if (const Node* conveyor = n.parent() ? scene::drivingConveyor(*n.parent()) : nullptr) {
    surface.conveyor = true;
    surface.conveyor_node = conveyor;
    surface.conveyor_field = conveyor->vec3(scene::field::Conveyor::Direction);
    surface.conveyor_dir = conveyorDirection(*conveyor, body);
    surface.conveyor_frame = conveyorFrame(*conveyor, body);
  }
  return surface;
}

core::Pose World::Impl::conveyorFrame(const Node& conveyor, const Body* body) {
  return body ? bodyPose(body->id).inverse() * conveyor.world : conveyor.world;
}

Vec3 World::Impl::conveyorDirection(const Node& conveyor, const Body* body) {
  // the belt's direction in the world, then in the frame of the body that carries the belt
  const Vec3 dir_world = conveyor.world.rotation.rotate(conveyor.vec3(scene::field::Conveyor::Direction)).normalized();
  return body ? bodyPose(body->id).rotation.conjugate().rotate(dir_world) : dir_world;
}

void World::Impl::refreshSurfaces(const Node& n) {
  // the surfaces of the shapes there are now that take something from `n`
  for (dGeomID g : shapes) {
    Surface& s = surfaces[reinterpret_cast<std::size_t>(dGeomGetData(g)) - 1];
    if (s.material == &n) {
      s.friction = n.number(scene::field::Material::Friction);
      s.bounce = n.number(scene::field::Material::Bounce);
    }
    // a belt turned: its direction made again (a belt's speed is read at each contact)
    if (s.conveyor_node == &n && n.vec3(scene::field::Conveyor::Direction) != s.conveyor_field) {
      s.conveyor_field = n.vec3(scene::field::Conveyor::Direction);
      s.conveyor_dir = conveyorDirection(n, owner(*s.node));
    }
    if (s.conveyor_node == &n) s.conveyor_frame = conveyorFrame(n, owner(*s.node));
  }
}

Surface World::Impl::surfaceOf(dGeomID g, const Impl& self) {
  const auto i = reinterpret_cast<std::size_t>(dGeomGetData(g));
  return i == 0 || (i & kSensorTag) ? Surface{} : self.surfaces[i - 1];
}

bool World::Impl::beltWakes(dGeomID belt, dBodyID other) const {
  if (other == nullptr || dBodyIsEnabled(other)) return false;
  const auto i = reinterpret_cast<std::size_t>(dGeomGetData(belt));
  if (i == 0 || (i & kSensorTag) != 0) return false;
  const Surface& s = surfaces[i - 1];
  if (!s.conveyor || s.conveyor_node->number(scene::field::Conveyor::Speed) == 0.0) return false;
  dBodyEnable(other);
  return true;
}

void World::Impl::nearCallback(void* data, dGeomID o1, dGeomID o2) {
  auto& self = *static_cast<Impl*>(data);
  // sensors never get here: the broad phase pairs shapes only (sense() pairs the sensors)
  dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
  // nothing to do between static shapes, or where everything involved sleeps
  const bool awake1 = b1 && dBodyIsEnabled(b1), awake2 = b2 && dBodyIsEnabled(b2);
  if (!awake1 && !awake2 && !self.beltWakes(o1, b2) && !self.beltWakes(o2, b1)) return;
  if (b1 && b2 && dAreConnectedExcluding(b1, b2, dJointTypeContact)) return;
  constexpr int kMax = 8;
  dContact contact[kMax];
  const int n = dCollide(o1, o2, kMax, &contact[0].geom, sizeof(dContact));
  if (n == 0) return;
  const Surface s1 = surfaceOf(o1, self), s2 = surfaceOf(o2, self);
  // a conveyor's belt velocity, seen from body 1 relative to body 2
  const bool belt1 = s1.conveyor, belt2 = !belt1 && s2.conveyor;
  Vec3 dir;
  double motion = 0;
  double spin = 0;  // a curved belt's rate about its axis, rad/s
  Vec3 up, centre;  // a curved belt's axis: its direction and a point on it
  if (belt1 || belt2) {
    const Surface& belt = belt1 ? s1 : s2;
    const dBodyID belt_body = belt1 ? b1 : b2;
    dir = belt_body ? bodyPose(belt_body).rotation.rotate(belt.conveyor_dir) : belt.conveyor_dir;
    // the speed now: a script may start and stop a belt
    const double speed = belt.conveyor_node->number(scene::field::Conveyor::Speed);
    motion = belt1 ? -speed : speed;
    // a curved belt turns at its speed over its radius about an axis that far to its left
    const double radius = belt.conveyor_node->number(scene::field::Conveyor::Radius);
    if (radius != 0.0) {
      spin = speed / radius;
      const core::Pose frame = belt_body ? bodyPose(belt_body) * belt.conveyor_frame : belt.conveyor_frame;
      up = frame.rotation.rotate(Vec3{0, 0, 1});
      centre = frame.position + up.cross(dir) * radius;
    }
  }
  for (int i = 0; i < n; ++i) {
    dSurfaceParameters& sp = contact[i].surface;
    sp.mode = dContactBounce | dContactApprox1;
    const double mu = std::sqrt(s1.friction * s2.friction);
    sp.mu = mu > 1e6 ? dInfinity : mu;
    sp.bounce = std::max(s1.bounce, s2.bounce);
    sp.bounce_vel = 0.01;
    if (belt1 || belt2) {
      Vec3 along = dir;
      double m = motion;
      if (spin != 0.0) {
        // a curved belt: its velocity at the contact point, spin x (point - centre)
        const Vec3 p{contact[i].geom.pos[0], contact[i].geom.pos[1], contact[i].geom.pos[2]};
        const Vec3 v = (up * spin).cross(p - centre);
        const double speed = v.length();
        along = speed > 0 ? v * (1.0 / speed) : v;
        m = belt1 ? -speed : speed;
      }
      sp.mode |= dContactFDir1 | dContactMotion1;
      contact[i].fdir1[0] = along.x;
      contact[i].fdir1[1] = along.y;
      contact[i].fdir1[2] = along.z;
      sp.motion1 = m;
    }
    dJointID c = dJointCreateContact(self.world, self.contacts, &contact[i]);
    dJointAttach(c, b1, b2);
    if (self.watching_contacts) self.watchContact(c, contact[i].geom, o1, o2);
    if (self.record_contacts) {
      const dContactGeom& g = contact[i].geom;
      self.touching.push_back({Vec3{g.pos[0], g.pos[1], g.pos[2]}, Vec3{g.normal[0], g.normal[1], g.normal[2]}, g.depth});
    }
  }
}

void World::Impl::watchContact(dJointID c, const dContactGeom& g, dGeomID o1, dGeomID o2) {
  // each side whose body is watched sees the other side's body, or the static shape; where
  // both are watched, both read the joint's one feedback (ODE keeps one per joint)
  dJointFeedback* fb = nullptr;
  for (int side = 0; side < 2; ++side) {
    const dGeomID mine = side == 0 ? o1 : o2, theirs = side == 0 ? o2 : o1;
    const Surface s = surfaceOf(mine, *this), t = surfaceOf(theirs, *this);
    if (!s.node || !t.node) continue;
    Body* body = owner(*s.node);
    if (!body || !body->watched) continue;
    if (fb == nullptr) {
      fb = &contact_feedback.emplace_back();
      dJointSetFeedback(c, fb);
    }
    watched_contacts.push_back({body, reported(*t.node)->handle(), fb, Vec3{g.normal[0], g.normal[1], g.normal[2]}, side == 0});
  }
}

void World::Impl::gatherForces() {
  // a watched body's touches are summed over the sub-steps its island was stepped in (awake
  // after the step: ODE wakes an island when one of its bodies is awake, and steps no island
  // it has just put to sleep); one asleep for a whole step keeps what it read before, so that
  // a Contact sensor lets its body and what rests on it sleep
  for (Body* b : watched_bodies) {
    b->stepped = b->id && dBodyIsEnabled(b->id);
    if (!b->stepped) continue;
    if (b->sensed_substeps++ == 0) b->touches.clear();
    b->touch_substeps = b->sensed_substeps;
  }
  for (const auto& w : watched_contacts) {
    if (!w.body->stepped) continue;
    const dReal* f = w.first ? w.feedback->f1 : w.feedback->f2;
    const double normal = std::abs(f[0] * w.normal.x + f[1] * w.normal.y + f[2] * w.normal.z);
    auto& t = w.body->touches;
    auto at = std::find_if(t.begin(), t.end(), [&](const auto& p) { return p.first == w.other; });
    if (at == t.end()) {
      t.emplace_back(w.other, normal);
    } else {
      at->second += normal;
    }
  }
  watched_contacts.clear();
  contact_feedback.clear();
  if (!watching_joints) return;
  for (auto& j : joints) {
    if (!j.feedback || !j.id) continue;
    j.force_sum = j.force_sum + Vec3{j.feedback->f1[0], j.feedback->f1[1], j.feedback->f1[2]};
    j.torque_sum = j.torque_sum + Vec3{j.feedback->t1[0], j.feedback->t1[1], j.feedback->t1[2]};
  }
}

}  // namespace gdpn::physics

namespace gdpn::physics {

bool World::watchContacts(const Node& node) {
  Impl::Body* body = impl_->owner(node);
  if (!body || !body->id) return false;
  if (!body->watched) impl_->watched_bodies.push_back(body);
  body->watched = true;
  impl_->watching_contacts = true;
  return true;
}

std::vector<World::Touch> World::touches(const Node& node) const {
  std::vector<Touch> out;
  const Impl::Body* body = impl_->owner(node);
  if (!body) return out;
  const double n = body->touch_substeps;
  for (const auto& [other, sum] : body->touches) {
    if (impl_->scene.resolve(other)) out.push_back({other, sum / n});
  }
  std::sort(out.begin(), out.end(), [&](const Touch& a, const Touch& b) {
    return impl_->scene.resolve(a.other)->path() < impl_->scene.resolve(b.other)->path();
  });
  return out;
}

bool World::watchJoint(const Node& joint) {
  const auto it = impl_->joint_of.find(joint.handle());
  if (it == impl_->joint_of.end()) return false;
  auto& j = impl_->joints[it->second];
  if (!j.feedback) j.feedback = std::make_unique<dJointFeedback>();
  if (j.id) dJointSetFeedback(j.id, j.feedback.get());
  impl_->watching_joints = true;
  return true;
}

void World::jointWrench(const Node& joint, Vec3 at, Vec3& force, Vec3& torque) const {
  force = torque = {};
  const auto it = impl_->joint_of.find(joint.handle());
  if (it == impl_->joint_of.end()) return;
  const auto& j = impl_->joints[it->second];
  if (!j.feedback || !j.id) return;
  const double n = impl_->substeps;
  force = j.force_sum * (1.0 / n);
  // ODE's torque is about the child's centre of mass: moved to `at`
  const dBodyID child = dJointGetBody(j.id, 0);
  const Vec3 cm = child ? bodyPose(child).position : at;
  torque = j.torque_sum * (1.0 / n) + (cm - at).cross(force);
}

void World::recordContacts(bool on) {
  impl_->record_contacts = on;
  if (!on) impl_->touching.clear();
}

const std::vector<World::Contact>& World::contacts() const { return impl_->touching; }

}  // namespace gdpn::physics
