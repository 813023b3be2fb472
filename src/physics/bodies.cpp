// Bodies: one ODE body per Body node, its mass from its own shapes, and what the World
// tells and takes of a body (velocity, forces, sleep).

#include "gdpn/core/assert.h"
#include "ode_convert.h"
#include "world_impl.h"

namespace gdpn::physics {
namespace {

using core::Pose;
using core::Vec3;
using scene::Node;
using scene::NodeKind;

template <class B>
B& need(B* b) {
  GDPN_ASSERT(b != nullptr, "the node belongs to a body of this world");
  return *b;
}

}  // namespace

World::Impl::Body* World::Impl::owner(const Node& node) {
  for (const Node* n = &node; n; n = n->parent()) {
    auto it = body_of.find(n->handle());
    if (it != body_of.end()) return &bodies[it->second];
  }
  return nullptr;
}

bool World::Impl::buildBodies(Node& node, core::Diagnostics& diags) {
  // bodies below a body are made before its mass is summed, so its shapes know their owner
  if (node.is_template) return true;  // copied by spawning, not simulated
  const bool body = node.kind() == NodeKind::Body;
  if (body) {
    dBodyID id = dBodyCreate(world);
    bodies.push_back({&node, id, {}, {}, {}, {}, false, {}});
    body_of[node.handle()] = bodies.size() - 1;
  }
  bool ok = true;
  for (const auto& c : node.children()) ok = buildBodies(*c, diags) && ok;
  if (body) ok = finishBody(bodies[body_of[node.handle()]], diags) && ok;
  return ok;
}

bool World::Impl::finishBody(Body& body, core::Diagnostics& diags) {
  Node& node = *body.node;
  using F = scene::field::Body;
  const double density = node.number(F::Density);
  const double total = node.number(F::Mass);
  dMass m;
  dMassSetZero(&m);
  const Pose inv = node.world.inverse();
  bool unread_mesh = false;  // reported when its geometry is made
  scene::traverse(node, [&](Node& n, const scene::TraversalState&) {
    const Primitive p = shapePrimitive(n);
    if (p.form == Form::None || owner(n) != &body) return;
    dMass sm;
    switch (p.form) {
      case Form::Box:
        if (p.box.x <= 0 || p.box.y <= 0 || p.box.z <= 0) return;
        dMassSetBox(&sm, density, p.box.x, p.box.y, p.box.z);
        break;
      case Form::Sphere:
        if (p.radius <= 0) return;
        dMassSetSphere(&sm, density, p.radius);
        break;
      case Form::Cylinder:
        if (p.radius <= 0 || p.height <= 0) return;
        dMassSetCylinder(&sm, density, 3, p.radius, p.height);
        break;
      case Form::Mesh: {
        // a mesh weighs as its bounding box (open meshes have no volume of their own); a
        // mesh that cannot be read is reported when its geometry is made
        core::Diagnostics later;
        const MeshGeometry* mesh = meshOf(n, model_dir, later);
        if (mesh == nullptr) {
          unread_mesh = true;
          return;
        }
        const Vec3 size = mesh->box.hi - mesh->box.lo;
        if (size.x <= 0 || size.y <= 0 || size.z <= 0) return;
        dMassSetBox(&sm, density, size.x, size.y, size.z);
        const Vec3 c = (mesh->box.lo + mesh->box.hi) * 0.5;
        dMassTranslate(&sm, c.x, c.y, c.z);
        break;
      }
      // ground has no mass (and cannot be part of a body: see addGeom)
      case Form::None:
      case Form::Cone:  // only a Region's volume, never a shape (shapePrimitive)
      case Form::Ray:
      case Form::Plane:
      case Form::Terrain: return;
    }
    const Pose local = inv * n.world;  // the shape in the body node's frame
    dMatrix3 r;
    rotationMatrix(local.rotation, r);
    dMassRotate(&sm, r);
    dMassTranslate(&sm, local.position.x, local.position.y, local.position.z);
    dMassAdd(&m, &sm);
  });
  if (m.mass <= 0 && total <= 0 && !unread_mesh) {
    // ODE cannot move a body that weighs nothing (its mass check fails)
    const auto& at = node.fieldLoc(F::Mass).line > 0      ? node.fieldLoc(F::Mass)
                     : node.fieldLoc(F::Density).line > 0 ? node.fieldLoc(F::Density)
                                                          : node.loc;
    diags.error(at, "body '" + node.path() + "' weighs nothing: its mass is 0 and " +
                        (density > 0 ? "it has no shapes of its own with a volume" : "its density is 0") +
                        "; give it a mass above 0, or shapes and a density above 0");
    return false;
  }
  if (m.mass <= 0) dMassSetSphereTotal(&m, total > 0 ? total : 1.0, 0.05);
  if (total > 0) dMassAdjust(&m, total);
  body.com = {m.c[0], m.c[1], m.c[2]};
  dMassTranslate(&m, -m.c[0], -m.c[1], -m.c[2]);
  dBodySetMass(body.id, &m);
  setPose(body.id, {node.world.apply(body.com), node.world.rotation});
  const double ld = node.number(F::LinearDamping), ad = node.number(F::AngularDamping);
  if (ld > 0) dBodySetLinearDamping(body.id, ld);
  if (ad > 0) dBodySetAngularDamping(body.id, ad);
  node.dynamic_pose = node.world;
  return true;
}

bool World::isBody(const scene::Node& node) const { return impl_->body_of.count(node.handle()) > 0; }

core::Vec3 World::velocity(const scene::Node& body) const { return v3(dBodyGetLinearVel(need(impl_->owner(body)).id)); }
core::Vec3 World::pointVelocity(const scene::Node& body, core::Vec3 at) const {
  dVector3 v;
  dBodyGetPointVel(need(impl_->owner(body)).id, at.x, at.y, at.z, v);
  return v3(v);
}
double World::mass(const scene::Node& body) const {
  dMass m;
  dBodyGetMass(need(impl_->owner(body)).id, &m);
  return m.mass;
}
core::Vec3 World::angularVelocity(const scene::Node& body) const {
  return v3(dBodyGetAngularVel(need(impl_->owner(body)).id));
}
void World::setVelocity(const scene::Node& body, core::Vec3 v) {
  auto& b = need(impl_->owner(body));
  dBodyEnable(b.id);
  dBodySetLinearVel(b.id, v.x, v.y, v.z);
}
void World::setForce(const scene::Node& body, core::Vec3 force) {
  auto& b = need(impl_->owner(body));
  dBodyEnable(b.id);
  b.force = force;
}
void World::addForce(const scene::Node& body, core::Vec3 force) {
  auto& b = need(impl_->owner(body));
  dBodyEnable(b.id);
  b.pending = b.pending + force;
}
void World::setTorque(const scene::Node& body, core::Vec3 torque) {
  auto& b = need(impl_->owner(body));
  dBodyEnable(b.id);
  b.torque = torque;
}
bool World::awake(const scene::Node& body) const { return dBodyIsEnabled(need(impl_->owner(body)).id) != 0; }
void World::wake(const scene::Node& body) { dBodyEnable(need(impl_->owner(body)).id); }

std::size_t World::bodyCount() const { return impl_->body_of.size(); }
std::size_t World::awakeCount() const {
  std::size_t n = 0;
  for (const auto& b : impl_->bodies) n += b.id && dBodyIsEnabled(b.id) ? 1u : 0u;
  return n;
}

}  // namespace gdpn::physics
