// Sensing: a geometry for each Region and RangeFinder, never in contacts, placed where its
// node is at each pass and met with the shapes whose boxes it overlaps.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ode_convert.h"
#include "world_impl.h"

namespace gdpn::physics {
namespace {

using core::Vec3;
using scene::Node;
using scene::NodeKind;

/// What a sensor node is made as: its volume and what it feels.
struct SensorSpec {
  Primitive volume;                         // None: no geometry (a time sensor, or no sensor)
  scene::Scope scope = scene::Scope::World;
  bool bodies_only = false;                 // a Region that reports no static shapes
};

Primitive rayPrimitive(double length) {
  Primitive p;
  p.form = Form::Ray;
  p.length = length;
  return p;
}

SensorSpec sensorSpec(const Node& n) {
  switch (n.kind()) {
    case NodeKind::RangeFinder:
      return {rayPrimitive(n.number(scene::field::RangeFinder::Length)),
              n.choice<scene::Scope>(scene::field::RangeFinder::Scope)};
    case NodeKind::Region: {
      using F = scene::field::Region;
      const Vec3 e = scene::shapeExtent(n), s = n.world_scale;
      const auto scope = n.choice<scene::Scope>(F::Scope);
      const bool bodies = n.choice<scene::RegionReport>(F::Report) == scene::RegionReport::Bodies;
      switch (n.choice<scene::RegionShape>(F::Shape)) {
        case scene::RegionShape::Box: return {boxPrimitive(e, s), scope, bodies};
        case scene::RegionShape::Sphere: return {spherePrimitive(e, s), scope, bodies};
        case scene::RegionShape::Cylinder: return {cylinderPrimitive(e, s, false), scope, bodies};
        case scene::RegionShape::Cone: {
          Primitive cone = cylinderPrimitive(e, s, false);
          cone.form = Form::Cone;
          return {cone, scope, bodies};
        }
        case scene::RegionShape::Ray: return {rayPrimitive(n.number(F::Length)), scope, bodies};
      }
      return {};
    }
    // other sensors need no geometry; the rest are no sensors
    case NodeKind::Group:
    case NodeKind::Transform:
    case NodeKind::Material:
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
    case NodeKind::Joint:
    case NodeKind::Conveyor:
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

/// Sides of the pyramid a cone is sensed as: its base a regular polygon inscribed in the
/// cone's base circle (the slanted faces lie within 0.2% of the radius inside the cone).
constexpr int kConeSides = 48;

/// A cone of base radius `r` and height `h` (m) along z, base at -h/2, apex at +h/2, as
/// ODE's convex geometry reads it: a pyramid of kConeSides slanted faces and the base.
std::unique_ptr<Convex> conePolyhedron(double r, double h) {
  auto c = std::make_unique<Convex>();
  const double half = h / 2;
  // the apex, then the base's corners counterclockwise seen from above
  c->points = {0, 0, half};
  for (int i = 0; i < kConeSides; ++i) {
    const double a = 2 * std::numbers::pi * i / kConeSides;
    c->points.insert(c->points.end(), {r * std::cos(a), r * std::sin(a), -half});
  }
  // each slanted face through the apex and one edge of the base, its normal outward: the
  // edge lies at `inner` from the axis, so the face is u * h + z * inner = inner * h / 2
  // along the direction u of the edge's middle
  const double inner = r * std::cos(std::numbers::pi / kConeSides);
  const double length = std::hypot(h, inner);
  for (int i = 0; i < kConeSides; ++i) {
    const double mid = 2 * std::numbers::pi * (i + 0.5) / kConeSides;
    c->planes.insert(c->planes.end(), {h * std::cos(mid) / length, h * std::sin(mid) / length, inner / length,
                                       inner * half / length});
    const auto next = static_cast<unsigned>((i + 1) % kConeSides + 1);
    c->polygons.insert(c->polygons.end(), {3U, 0U, static_cast<unsigned>(i + 1), next});
  }
  // the base, facing down: its corners clockwise seen from above
  c->planes.insert(c->planes.end(), {0, 0, -1, half});
  c->polygons.push_back(kConeSides);
  for (int i = kConeSides; i >= 1; --i) c->polygons.push_back(static_cast<unsigned>(i));
  return c;
}

/// A sensor's geometry in `space`; a volume's sizes are taken as at least 1e-9 m. A cone
/// gets its polyhedron in `convex` (which the geometry reads as long as it lives).
dGeomID sensorGeom(dSpaceID space, const Primitive& v, std::unique_ptr<Convex>& convex) {
  constexpr double kLeast = 1e-9;
  convex.reset();
  switch (v.form) {
    case Form::Box:
      return dCreateBox(space, std::max(v.box.x, kLeast), std::max(v.box.y, kLeast), std::max(v.box.z, kLeast));
    case Form::Sphere: return dCreateSphere(space, std::max(v.radius, kLeast));
    case Form::Cylinder: return dCreateCylinder(space, std::max(v.radius, kLeast), std::max(v.height, kLeast));
    case Form::Cone: {
      convex = conePolyhedron(std::max(v.radius, kLeast), std::max(v.height, kLeast));
      return dCreateConvex(space, convex->planes.data(), static_cast<unsigned>(convex->planes.size() / 4),
                           convex->points.data(), static_cast<unsigned>(convex->points.size() / 3),
                           convex->polygons.data());
    }
    case Form::Ray: return dCreateRay(space, v.length);
    case Form::None:
    case Form::Mesh:
    case Form::Plane:
    case Form::Terrain: return nullptr;
  }
  return nullptr;
}

}  // namespace

void World::Impl::addSensor(Node& n) {
  const SensorSpec spec = sensorSpec(n);
  if (spec.volume.form == Form::None) return;
  std::unique_ptr<Convex> convex;
  dGeomID geom = sensorGeom(space, spec.volume, convex);
  sensors.push_back({&n, geom, spec.scope, spec.bodies_only, spec.volume, std::move(convex)});
  retagSensors();
}

void World::Impl::refreshSensor(const Node& n) {
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    Sensor& sensor = sensors[i];
    if (sensor.node != &n) continue;
    const SensorSpec spec = sensorSpec(n);
    sensor.scope = spec.scope;
    sensor.bodies_only = spec.bodies_only;
    if (spec.volume == sensor.volume) continue;
    // a new shape or size: a new geometry in the same place in the list
    dGeomDestroy(sensor.geom);
    sensor.geom = sensorGeom(space, spec.volume, sensor.convex);
    sensor.volume = spec.volume;
    dGeomSetData(sensor.geom, reinterpret_cast<void*>(kSensorTag | i));
  }
}

void World::Impl::retagSensors() {
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    dGeomSetData(sensors[i].geom, reinterpret_cast<void*>(kSensorTag | i));
  }
}

bool World::Impl::inScope(const Sensor& sensor, const Node& shape) {
  if (sensor.scope == scene::Scope::World) return true;
  const Node* parent = sensor.node->parent();
  for (const Node* n = &shape; n; n = n->parent()) {
    if (sensor.scope == scene::Scope::Parent && n == parent) return true;
    if (sensor.scope == scene::Scope::Siblings && n->parent() == parent) return n != sensor.node;
  }
  return false;
}

const Node* World::Impl::reported(const Node& shape) const {
  const Body* b = owner(shape);
  return b ? b->node : &shape;
}

void World::Impl::feel(std::size_t index, dGeomID other) {
  const Sensor& sensor = sensors[index];
  const Surface s = surfaceOf(other, *this);
  if (!s.node || !inScope(sensor, *s.node)) return;
  dContactGeom c;
  if (dCollide(sensor.geom, other, 1, &c, sizeof(dContactGeom)) == 0) return;
  Felt& f = felt[index];
  if (sensor.ray()) {
    if (c.depth < f.distance) {
      f.distance = c.depth;
      f.hit = reported(*s.node);
    }
  } else if (!sensor.bodies_only || owner(*s.node)) {
    f.items.push_back(reported(*s.node));
  }
}

void World::Impl::sense(std::vector<std::pair<scene::NodeHandle, Feel>>& out) {
  out.clear();
  felt.assign(sensors.size(), Felt{});
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    const Sensor& sensor = sensors[i];
    const Node& n = *sensor.node;
    // sensors follow the nodes they sit in (a body moves them)
    if (sensor.ray()) {
      const Vec3 from = n.world.position, dir = n.world.rotation.rotate({1, 0, 0});
      dGeomRaySet(sensor.geom, from.x, from.y, from.z, dir.x, dir.y, dir.z);
      felt[i].distance = dGeomRayGetLength(sensor.geom);
    } else {
      dGeomSetPosition(sensor.geom, n.world.position.x, n.world.position.y, n.world.position.z);
      const dQuaternion q = {n.world.rotation.w, n.world.rotation.x, n.world.rotation.y, n.world.rotation.z};
      dGeomSetQuaternion(sensor.geom, q);
    }
  }
  if (!sensors.empty()) {
    // one sweep over the moving shapes' boxes and the sensors' finds the sensor-to-body
    // pairs; each sensor looks up the fixed shapes in their tree
    refreshMoving();
    const std::size_t m = moving.size();
    sense_boxes.assign(moving_boxes.begin(), moving_boxes.end());
    for (const auto& sensor : sensors) sense_boxes.push_back(aabbOf(sensor.geom));
    sense_sweep.pairs(sense_boxes, [&](std::size_t i, std::size_t j) {
      if ((i < m) == (j < m)) return;  // two shapes, or two sensors
      feel(std::max(i, j) - m, moving[std::min(i, j)]);
    });
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      fixed_tree.query(sense_boxes[m + i], [&](std::size_t k) { feel(i, fixed[k]); });
      for (dGeomID g : endless) feel(i, g);
    }
  }
  // what each felt: a ray its nearest hit; a volume what lies in it, once each, by path
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    const Node& n = *sensors[i].node;
    Felt& f = felt[i];
    Feel feel;
    if (sensors[i].ray()) {
      feel.distance = f.distance;
      feel.hit = f.hit ? f.hit->handle() : 0;
      // a static shape still stops the ray of a Region that reports bodies only
      const bool reports = f.hit && (!sensors[i].bodies_only || owner(*f.hit));
      if (n.kind() == NodeKind::Region && reports) feel.items.push_back(f.hit->handle());
    } else {
      std::sort(f.items.begin(), f.items.end(), [](const Node* a, const Node* b) { return a->path() < b->path(); });
      f.items.erase(std::unique(f.items.begin(), f.items.end()), f.items.end());
      for (const Node* item : f.items) feel.items.push_back(item->handle());
    }
    out.emplace_back(n.handle(), std::move(feel));
  }
}

void World::sense(std::vector<std::pair<scene::NodeHandle, Feel>>& out) { impl_->sense(out); }

void World::castRays(const Node& sensor, scene::Scope scope, Vec3 from, const std::vector<Vec3>& dirs, double length,
                     std::vector<double>& distance, std::vector<scene::NodeHandle>& hit) {
  Impl& m = *impl_;
  distance.assign(dirs.size(), length);
  hit.assign(dirs.size(), 0);
  if (dirs.empty() || !(length > 0)) return;
  // the shapes whose boxes meet the box around every ray, and in the sensor's scope
  const Vec3 reach{length, length, length};
  const core::Aabb fan{from - reach, from + reach};
  const Impl::Sensor as{const_cast<Node*>(&sensor), nullptr, scope, false, rayPrimitive(length), nullptr};
  std::vector<dGeomID> near;
  auto consider = [&](dGeomID g) {
    const Surface s = Impl::surfaceOf(g, m);
    if (s.node && Impl::inScope(as, *s.node)) near.push_back(g);
  };
  m.refreshShapes();
  m.refreshMoving();
  for (std::size_t i = 0; i < m.moving.size(); ++i) {
    if (core::overlaps(m.moving_boxes[i], fan)) consider(m.moving[i]);
  }
  m.fixed_tree.query(fan, [&](std::size_t k) { consider(m.fixed[k]); });
  for (dGeomID g : m.endless) consider(g);
  if (near.empty()) return;
  dGeomID ray = dCreateRay(nullptr, length);
  std::vector<core::Aabb> boxes;
  boxes.reserve(near.size());
  for (dGeomID g : near) boxes.push_back(aabbOf(g));
  for (std::size_t r = 0; r < dirs.size(); ++r) {
    const Vec3 d = dirs[r];
    dGeomRaySet(ray, from.x, from.y, from.z, d.x, d.y, d.z);
    dGeomRaySetLength(ray, length);
    const Vec3 to = from + d * length;
    const core::Aabb span{{std::min(from.x, to.x), std::min(from.y, to.y), std::min(from.z, to.z)},
                          {std::max(from.x, to.x), std::max(from.y, to.y), std::max(from.z, to.z)}};
    for (std::size_t k = 0; k < near.size(); ++k) {
      if (!core::overlaps(boxes[k], span)) continue;
      dContactGeom c;
      if (dCollide(ray, near[k], 1, &c, sizeof(dContactGeom)) == 0 || !(c.depth < distance[r])) continue;
      distance[r] = c.depth;
      hit[r] = m.reported(*Impl::surfaceOf(near[k], m).node)->handle();
    }
  }
  dGeomDestroy(ray);
}

}  // namespace gdpn::physics
