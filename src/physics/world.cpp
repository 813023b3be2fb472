// The World façade: making the ODE world from the scene's settings, stepping it, writing
// the bodies' placements back into the scene, and hearing of fields a script changed.

#include "gdpn/physics/world.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>

#include "ode_convert.h"
#include "world_impl.h"

namespace gdpn::physics {
namespace {

using core::Pose;
using core::Vec3;
using scene::Node;
using scene::NodeKind;

/// An error ODE reported, thrown out of its handler: ODE exits or aborts when an error or
/// debug handler returns, so the handler leaves by this instead, to the world's call.
struct OdeFault {
  std::string message;
};

/// ODE's message, its printf arguments formatted.
std::string odeText(const char* kind, int num, const char* msg, va_list ap) {
  char text[512];
  std::vsnprintf(text, sizeof text, msg, ap);
  return std::string(kind) + " " + std::to_string(num) + ": " + text;
}

// the last warning ODE gave (it repeats some in every step): kept quiet, told with a fault
thread_local std::string last_ode_message;

[[noreturn]] void throwOdeError(int num, const char* msg, va_list ap) {
  throw OdeFault{odeText("ODE error", num, msg, ap)};
}
[[noreturn]] void throwOdeDebug(int num, const char* msg, va_list ap) {
  throw OdeFault{odeText("ODE internal error", num, msg, ap)};
}
void keepOdeMessage(int num, const char* msg, va_list ap) { last_ode_message = odeText("ODE message", num, msg, ap); }

void initOde() {
  static const bool done = [] {
    dSetErrorHandler(throwOdeError);
    dSetDebugHandler(throwOdeDebug);
    dSetMessageHandler(keepOdeMessage);
    dInitODE2(0);
    dAllocateODEDataForThread(static_cast<unsigned>(dAllocateMaskAll));
    return true;
  }();
  (void)done;
}

}  // namespace

World::Impl::~Impl() {
  for (auto& [pair, j] : attached) dJointDestroy(j);
  if (space) dSpaceDestroy(space);
  space = nullptr;
  for (auto d : heightfield_data) dGeomHeightfieldDataDestroy(d);
  for (auto d : trimesh_data) dGeomTriMeshDataDestroy(d);
  if (contacts) dJointGroupDestroy(contacts);
  if (space) dSpaceDestroy(space);
  if (world) dWorldDestroy(world);
}

bool World::Impl::bodiesSane() {
  const auto bad = [](const dReal* v, int n, double bound) {
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += v[i] * v[i];
    return !std::isfinite(sum) || sum > bound * bound;
  };
  for (const auto& b : bodies) {
    if (!b.id) continue;
    const char* what = nullptr;
    const dReal* v = nullptr;
    if (bad(v = dBodyGetPosition(b.id), 3, kMaxDistance)) what = "its position";
    else if (bad(v = dBodyGetQuaternion(b.id), 4, 2.0)) what = "its rotation";
    else if (bad(v = dBodyGetLinearVel(b.id), 3, kMaxSpeed)) what = "its velocity";
    else if (bad(v = dBodyGetAngularVel(b.id), 3, kMaxSpeed)) what = "its angular velocity";
    if (!what) continue;
    char numbers[160];
    std::snprintf(numbers, sizeof numbers, "(%.6g, %.6g, %.6g)", v[0], v[1], v[2]);
    fault = "body '" + b.node->path() + "' ran away: " + what + " became " + numbers +
            ", not finite or beyond 1e12 (m, m/s, rad/s)";
    if (!last_ode_message.empty()) fault += " (last " + last_ode_message + ")";
    return false;
  }
  return true;
}

void World::Impl::step(double dt) {
  if (!fault.empty()) return;
  last_ode_message.clear();
  const double h = dt / substeps;
  driveMotors();
  for (Body* b : watched_bodies) b->sensed_substeps = 0;
  if (watching_joints) {
    for (auto& j : joints) j.force_sum = j.torque_sum = {};
  }
  for (int k = 0; k < substeps; ++k) {
    for (auto& b : bodies) {
      if (!b.id) continue;
      const Vec3 f = b.force + b.pending;
      if (f.x != 0 || f.y != 0 || f.z != 0) dBodyAddForce(b.id, f.x, f.y, f.z);
      if (b.torque.x != 0 || b.torque.y != 0 || b.torque.z != 0) dBodyAddTorque(b.id, b.torque.x, b.torque.y, b.torque.z);
    }
    touching.clear();
    collide();
    dWorldQuickStep(world, h);
    if (watching_contacts || watching_joints) gatherForces();
    dJointGroupEmpty(contacts);
    // a body that ran away stops the physics before ODE or the broad phase meet its numbers
    if (!bodiesSane()) return;
  }
  for (auto& b : bodies) b.pending = {};
  writeBack();
}

void World::Impl::writeBack() {
  for (auto& b : bodies) {
    if (!b.id || (!dBodyIsEnabled(b.id) && b.node->dynamic_pose)) continue;
    const Pose p = bodyPose(b.id);
    b.node->dynamic_pose = Pose{p.position - p.rotation.rotate(b.com), p.rotation};
    scene::updateTransforms(*b.node);
  }
}

World::World(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
World::~World() = default;

std::unique_ptr<World> World::create(scene::Scene& scene, const std::string& model_dir, std::uint64_t seed,
                                     core::Diagnostics& diags) {
  initOde();
  dRandSetSeed(static_cast<unsigned long>(seed));
  auto impl = std::make_unique<Impl>(scene);
  impl->world = dWorldCreate();
  impl->space = dSimpleSpaceCreate(nullptr);
  impl->contacts = dJointGroupCreate(0);
  // settings from the first World node, if any
  const Node* settings = nullptr;
  scene::traverse(scene.root(), [&](Node& n, const scene::TraversalState&) {
    if (!settings && n.kind() == NodeKind::World) settings = &n;
  }, {}, scene::Templates::Skip);
  Vec3 g{0, 0, -9.81};
  double erp = 0.2, cfm = 1e-5;
  bool auto_disable = true;
  int iterations = 40;
  if (settings) {
    using F = scene::field::World;
    iterations = static_cast<int>(settings->number(F::Iterations));
    g = settings->vec3(F::Gravity);
    erp = settings->number(F::Erp);
    cfm = settings->number(F::Cfm);
    impl->substeps = static_cast<int>(settings->number(F::Substeps));
    auto_disable = settings->flag(F::AutoDisable);
  }
  dWorldSetGravity(impl->world, g.x, g.y, g.z);
  dWorldSetERP(impl->world, erp);
  dWorldSetCFM(impl->world, cfm);
  dWorldSetQuickStepNumIterations(impl->world, iterations);
  dWorldSetAutoDisableFlag(impl->world, auto_disable ? 1 : 0);
  dWorldSetContactSurfaceLayer(impl->world, 0.001);
  impl->model_dir = model_dir;
  try {
    if (!impl->addSubtree(scene.root(), diags)) return nullptr;
  } catch (const OdeFault& e) {
    diags.error(scene.root().loc, "the physics cannot be built: " + e.message);
    return nullptr;
  }
  return std::unique_ptr<World>(new World(std::move(impl)));
}

void World::step(double dt) {
  try {
    impl_->step(dt);
  } catch (const OdeFault& e) {
    // what ODE was doing is left half done: the world steps no more
    impl_->fault = e.message;
  }
}

const std::string& World::fault() const { return impl_->fault; }

std::string World::fieldChanged(const scene::Node& node) {
  switch (node.kind()) {
    // what the world keeps of a node, read again
    case NodeKind::Joint: return impl_->refreshJoint(node);
    case NodeKind::Region:
    case NodeKind::RangeFinder: impl_->refreshSensor(node); return {};
    case NodeKind::Material:
    case NodeKind::Conveyor: impl_->refreshSurfaces(node); return {};
    case NodeKind::Transform: impl_->moveSubtree(const_cast<scene::Node&>(node)); return {};
    // the rest holds as built, or is read every step
    case NodeKind::Group:
    case NodeKind::Light:
    case NodeKind::Camera:
    case NodeKind::Fog:
    case NodeKind::Cube:
    case NodeKind::Sphere:
    case NodeKind::Cylinder:
    case NodeKind::Cone:
    case NodeKind::Plane:
    case NodeKind::Mesh:
    case NodeKind::Terrain:
    case NodeKind::World:
    case NodeKind::Body:
    case NodeKind::GradientField:
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

bool World::add(scene::Node& top, core::Diagnostics& diags) {
  try {
    return impl_->addSubtree(top, diags);
  } catch (const OdeFault& e) {
    diags.error(top.loc, "the physics of '" + top.path() + "' cannot be built: " + e.message);
    return false;
  }
}
void World::remove(const scene::Node& top) { impl_->removeSubtree(top); }

std::string assignField(scene::Node& node, std::size_t i, scene::FieldValue value, scene::AngleUnit unit, World* world) {
  if (auto why = scene::refusal(node, i, value, unit); !why.empty()) return why;
  value = scene::convertAngle(node, i, std::move(value), unit, true);
  scene::FieldValue before = node.value(i);
  node.setValue(i, std::move(value));
  // the physics keeps some fields of its own (a joint's kind and control, a sensor's scope);
  // what it cannot follow (a joint kind with a zero axis) is refused, the field as it was
  if (world != nullptr) {
    if (auto why = world->fieldChanged(node); !why.empty()) {
      node.setValue(i, std::move(before));
      return "'" + node.type().fields[i]->name + "': " + why;
    }
  }
  return "";
}

}  // namespace gdpn::physics
