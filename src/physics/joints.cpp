// Joints: one ODE joint per Joint node (between the Body above it and the Body below it, or
// that Body and the world), motors that follow the joint's fields every step, and the fixed
// joints that attach() makes.

#include <algorithm>
#include <cmath>

#include "world_impl.h"

namespace gdpn::physics {

using core::Vec3;
using scene::JointControl;
using scene::JointKind;
using scene::Node;
using F = scene::field::Joint;

namespace {

/// How ODE drives the motors of a joint kind.
struct Motors {
  void (*set)(dJointID, int, dReal) = nullptr;  // ODE's setter of the kind's parameters; null: no motors
  bool two_axes = false;                        // a motor on axis 2 too
};

Motors motorsOf(JointKind kind) {
  switch (kind) {
    case JointKind::Hinge: return {dJointSetHingeParam, false};
    case JointKind::Slider: return {dJointSetSliderParam, false};
    case JointKind::Universal: return {dJointSetUniversalParam, true};
    case JointKind::Hinge2: return {dJointSetHinge2Param, true};
    case JointKind::Ball:
    case JointKind::Fixed: return {};
  }
  return {};
}

/// The kind's word in the model file.
const char* kindName(JointKind kind) {
  switch (kind) {
    case JointKind::Hinge: return "hinge";
    case JointKind::Slider: return "slider";
    case JointKind::Ball: return "ball";
    case JointKind::Universal: return "universal";
    case JointKind::Hinge2: return "hinge2";
    case JointKind::Fixed: return "fixed";
  }
  return "?";
}

/// The field's location, or the node's when the field was left at its default.
core::SourceLoc at(const Node& n, F field) { return n.fieldLoc(field).line > 0 ? n.fieldLoc(field) : n.loc; }

}  // namespace

std::optional<core::Diagnostic> World::Impl::axesProblem(const Node& n, JointKind kind) {
  // ODE normalises the axes it is given: a zero one (or a cross product of parallel ones)
  // stops the process there, so they are refused before ODE sees them
  const bool one = kind == JointKind::Hinge || kind == JointKind::Slider || kind == JointKind::Universal ||
                   kind == JointKind::Hinge2;
  const bool two = kind == JointKind::Universal || kind == JointKind::Hinge2;
  const Vec3 a1 = n.vec3(F::Axis1), a2 = n.vec3(F::Axis2);
  const std::string joint = std::string(kindName(kind)) + " joint '" + n.path() + "'";
  constexpr double kTiny = 1e-9;  // shorter than this, or closer to parallel (sine), is degenerate
  if (one && a1.length() < kTiny) {
    return core::Diagnostic{core::Severity::Error, at(n, F::Axis1),
                            joint + " has a zero axis1: it needs a direction, such as [0, 0, 1]"};
  }
  if (two && a2.length() < kTiny) {
    return core::Diagnostic{core::Severity::Error, at(n, F::Axis2),
                            joint + " has a zero axis2: it needs a direction, such as [1, 0, 0]"};
  }
  if (two && a1.normalized().cross(a2.normalized()).length() < kTiny) {
    return core::Diagnostic{core::Severity::Error, at(n, F::Axis2),
                            joint + " has axis2 parallel to axis1: its two axes need different directions"};
  }
  return std::nullopt;
}

bool World::Impl::addJoint(Node& n, Body* parent_body, core::Diagnostics& diags) {
  // the first Body below the joint (Transforms may place it), not inside another Body
  Body* child_body = nullptr;
  std::vector<Node*> todo;
  for (auto it = n.children().rbegin(); it != n.children().rend(); ++it) todo.push_back(it->get());
  while (!todo.empty() && !child_body) {
    Node* c = todo.back();
    todo.pop_back();
    if (c->is_template) continue;  // not simulated: nothing to join
    if (c->kind() == scene::NodeKind::Body) {
      if (const auto b = body_of.find(c->handle()); b != body_of.end()) child_body = &bodies[b->second];
    } else {
      for (auto it = c->children().rbegin(); it != c->children().rend(); ++it) todo.push_back(it->get());
    }
  }
  if (!child_body) {
    diags.error(n.loc, "joint '" + n.path() + "' joins no bodies: it needs a Body among its children (joined to "
                       "the Body above it, or to the world)");
    return false;
  }
  const auto kind = n.choice<JointKind>(F::Kind);
  if (auto bad = axesProblem(n, kind)) {
    diags.error(bad->loc, bad->message);
    return false;
  }
  dJointID j = makeJoint(n, kind, child_body->id, parent_body ? parent_body->id : nullptr);
  joints.push_back({&n, j, kind, n.choice<JointControl>(F::Control), nullptr, {}, {}});
  joint_of[n.handle()] = joints.size() - 1;
  return true;
}

dJointID World::Impl::makeJoint(const Node& n, JointKind kind, dBodyID child, dBodyID parent) {
  // made, attached, then placed where the node is now: anchor, axes and limits
  dJointID j = nullptr;
  switch (kind) {
    case JointKind::Hinge: j = dJointCreateHinge(world, nullptr); break;
    case JointKind::Slider: j = dJointCreateSlider(world, nullptr); break;
    case JointKind::Ball: j = dJointCreateBall(world, nullptr); break;
    case JointKind::Universal: j = dJointCreateUniversal(world, nullptr); break;
    case JointKind::Hinge2: j = dJointCreateHinge2(world, nullptr); break;
    case JointKind::Fixed: j = dJointCreateFixed(world, nullptr); break;
  }
  dJointAttach(j, child, parent);
  const Vec3 anchor = n.world.apply(n.vec3(F::Anchor));
  const Vec3 a1 = n.world.rotation.rotate(n.vec3(F::Axis1)).normalized();
  const Vec3 a2 = n.world.rotation.rotate(n.vec3(F::Axis2)).normalized();
  const bool angular = kind != JointKind::Slider;
  auto limit = [&](F field) {
    const double v = n.number(field);
    return std::abs(v) >= kHuge ? (v < 0 ? -dInfinity : dInfinity) : (angular ? core::radians(v) : v);
  };
  switch (kind) {
    case JointKind::Hinge:
      dJointSetHingeAnchor(j, anchor.x, anchor.y, anchor.z);
      dJointSetHingeAxis(j, a1.x, a1.y, a1.z);
      dJointSetHingeParam(j, dParamHiStop, limit(F::Hi1));
      dJointSetHingeParam(j, dParamLoStop, limit(F::Lo1));
      break;
    case JointKind::Slider:
      dJointSetSliderAxis(j, a1.x, a1.y, a1.z);
      dJointSetSliderParam(j, dParamHiStop, limit(F::Hi1));
      dJointSetSliderParam(j, dParamLoStop, limit(F::Lo1));
      break;
    case JointKind::Ball: dJointSetBallAnchor(j, anchor.x, anchor.y, anchor.z); break;
    case JointKind::Universal:
      dJointSetUniversalAnchor(j, anchor.x, anchor.y, anchor.z);
      dJointSetUniversalAxis1(j, a1.x, a1.y, a1.z);
      dJointSetUniversalAxis2(j, a2.x, a2.y, a2.z);
      dJointSetUniversalParam(j, dParamHiStop, limit(F::Hi1));
      dJointSetUniversalParam(j, dParamLoStop, limit(F::Lo1));
      dJointSetUniversalParam(j, dParamHiStop2, limit(F::Hi2));
      dJointSetUniversalParam(j, dParamLoStop2, limit(F::Lo2));
      break;
    case JointKind::Hinge2: {
      dJointSetHinge2Anchor(j, anchor.x, anchor.y, anchor.z);
      const dReal ax1[3] = {a1.x, a1.y, a1.z}, ax2[3] = {a2.x, a2.y, a2.z};
      dJointSetHinge2Axes(j, ax1, ax2);
      dJointSetHinge2Param(j, dParamHiStop, limit(F::Hi1));
      dJointSetHinge2Param(j, dParamLoStop, limit(F::Lo1));
      break;
    }
    case JointKind::Fixed: dJointSetFixed(j); break;
  }
  return j;
}

std::string World::Impl::refreshJoint(const Node& n) {
  const auto it = joint_of.find(n.handle());
  if (it == joint_of.end()) return {};
  Joint& jt = joints[it->second];
  jt.control = n.choice<JointControl>(F::Control);
  const auto kind = n.choice<JointKind>(F::Kind);
  if (kind == jt.kind) return {};
  if (auto bad = axesProblem(n, kind)) return bad->message;
  // a joint of another kind: made again between the same bodies, where they are now
  dBodyID child = dJointGetBody(jt.id, 0), parent = dJointGetBody(jt.id, 1);
  dJointDestroy(jt.id);
  jt.id = makeJoint(n, kind, child, parent);
  if (jt.feedback) dJointSetFeedback(jt.id, jt.feedback.get());
  jt.kind = kind;
  if (child) dBodyEnable(child);
  if (parent) dBodyEnable(parent);
  return {};
}

double World::Impl::position(const Joint& j, int axis) {
  switch (j.kind) {
    case JointKind::Hinge: return dJointGetHingeAngle(j.id);
    case JointKind::Slider: return dJointGetSliderPosition(j.id);
    case JointKind::Universal: return axis == 1 ? dJointGetUniversalAngle1(j.id) : dJointGetUniversalAngle2(j.id);
    case JointKind::Hinge2: return axis == 1 ? dJointGetHinge2Angle1(j.id) : 0.0;
    case JointKind::Ball:
    case JointKind::Fixed: return 0.0;
  }
  return 0.0;
}

void World::Impl::driveMotors() {
  for (const auto& jt : joints) {
    if (!jt.id) continue;
    const Node& n = *jt.node;
    const bool angular = jt.kind != JointKind::Slider;
    double vel1 = angular ? core::radians(n.number(F::Vel1)) : n.number(F::Vel1);
    if (jt.control == JointControl::Position) {
      // a proportional servo: the speed closes the error in servo_time, capped at |vel1|
      const double target = angular ? core::radians(n.number(F::Target1)) : n.number(F::Target1);
      const double speed = (target - position(jt, 1)) / n.number(F::ServoTime);
      vel1 = vel1 == 0 ? speed : std::clamp(speed, -std::abs(vel1), std::abs(vel1));
    }
    const double fmax1 = n.number(F::Fmax1);
    const double vel2 = core::radians(n.number(F::Vel2)), fmax2 = n.number(F::Fmax2);
    // a motor on axis 1 (hinge, slider, universal, hinge2), and on axis 2 (universal, hinge2)
    const Motors motors = motorsOf(jt.kind);
    if (motors.set) {
      motors.set(jt.id, dParamVel, vel1);
      motors.set(jt.id, dParamFMax, fmax1);
      if (motors.two_axes) {
        motors.set(jt.id, dParamVel2, vel2);
        motors.set(jt.id, dParamFMax2, fmax2);
      }
    }
    if (fmax1 > 0 || fmax2 > 0) {
      // a motor that works wakes what it moves
      for (int k = 0; k < 2; ++k) {
        if (dBodyID b = dJointGetBody(jt.id, k)) dBodyEnable(b);
      }
    }
  }
}

double World::jointPosition(const scene::Node& joint, int axis) const {
  return Impl::position(impl_->joints[impl_->joint_of.at(joint.handle())], axis);
}

double World::jointRate(const scene::Node& joint, int axis) const {
  const auto& j = impl_->joints[impl_->joint_of.at(joint.handle())];
  switch (j.kind) {
    case JointKind::Hinge: return dJointGetHingeAngleRate(j.id);
    case JointKind::Slider: return dJointGetSliderPositionRate(j.id);
    case JointKind::Universal:
      return axis == 1 ? dJointGetUniversalAngle1Rate(j.id) : dJointGetUniversalAngle2Rate(j.id);
    case JointKind::Hinge2: return axis == 1 ? dJointGetHinge2Angle1Rate(j.id) : dJointGetHinge2Angle2Rate(j.id);
    case JointKind::Ball:
    case JointKind::Fixed: return 0.0;
  }
  return 0.0;
}

bool World::attach(const scene::Node& a, const scene::Node& b) {
  auto* ba = impl_->owner(a);
  auto* bb = impl_->owner(b);
  if (!ba || !bb || ba == bb) return false;
  const auto key = std::minmax(ba->id, bb->id);
  if (impl_->attached.count(key)) return false;
  dJointID j = dJointCreateFixed(impl_->world, nullptr);
  dJointAttach(j, ba->id, bb->id);
  dJointSetFixed(j);
  dBodyEnable(ba->id);
  dBodyEnable(bb->id);
  impl_->attached[key] = j;
  return true;
}

bool World::detach(const scene::Node& a, const scene::Node& b) {
  auto* ba = impl_->owner(a);
  auto* bb = impl_->owner(b);
  if (!ba || !bb) return false;
  auto it = impl_->attached.find(std::minmax(ba->id, bb->id));
  if (it == impl_->attached.end()) return false;
  dJointDestroy(it->second);
  impl_->attached.erase(it);
  dBodyEnable(ba->id);
  dBodyEnable(bb->id);
  return true;
}

}  // namespace gdpn::physics
