// The World façade: making the ODE world from the scene's settings, stepping it, writing
// the bodies' placements back into the scene, and hearing of fields a script changed.

#include "gdpn/physics/world.h"

#include "ode_convert.h"
#include "world_impl.h"

namespace gdpn::physics {
namespace {

using core::Pose;
using core::Vec3;
using scene::Node;
using scene::NodeKind;

void initOde() {
  static const bool done = [] {
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
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

void World::Impl::step(double dt) {
  const double h = dt / substeps;
  driveMotors();
  for (int k = 0; k < substeps; ++k) {
    for (auto& b : bodies) {
      if (!b.id) continue;
      const Vec3 f = b.force + b.pending;
      if (f.x != 0 || f.y != 0 || f.z != 0) dBodyAddForce(b.id, f.x, f.y, f.z);
      if (b.torque.x != 0 || b.torque.y != 0 || b.torque.z != 0) dBodyAddTorque(b.id, b.torque.x, b.torque.y, b.torque.z);
    }
    collide();
    dWorldQuickStep(world, h);
    dJointGroupEmpty(contacts);
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
  });
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
  if (!impl->addSubtree(scene.root(), diags)) return nullptr;
  return std::unique_ptr<World>(new World(std::move(impl)));
}

void World::step(double dt) { impl_->step(dt); }

void World::fieldChanged(const scene::Node& node) {
  switch (node.kind()) {
    // what the world keeps of a node, read again
    case NodeKind::Joint: impl_->refreshJoint(node); return;
    case NodeKind::Region:
    case NodeKind::RangeFinder: impl_->refreshSensor(node); return;
    case NodeKind::Material:
    case NodeKind::Conveyor: impl_->refreshSurfaces(node); return;
    // the rest holds as built, or is read every step
    case NodeKind::Group:
    case NodeKind::Transform:
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
    case NodeKind::TimeSensor: return;
  }
}

bool World::add(scene::Node& top, core::Diagnostics& diags) { return impl_->addSubtree(top, diags); }
void World::remove(const scene::Node& top) { impl_->removeSubtree(top); }

}  // namespace gdpn::physics
