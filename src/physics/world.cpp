// The scene's rigid-body physics through ODE. Everything ODE stays in this file.

#include "gdpn/physics/world.h"

#include <ode/ode.h>

#include <algorithm>
#include <deque>
#include <cmath>
#include <filesystem>
#include <map>
#include <unordered_map>

#include "gdpn/core/assert.h"
#include "gdpn/core/broad_phase.h"
#include "gdpn/scene/actions.h"
#include "gdpn/scene/mesh.h"
#include "gdpn/scene/terrain.h"

namespace gdpn::physics {
namespace {

using core::Pose;
using core::Quat;
using core::Vec3;
using scene::Node;

/// The convex hull of `points` (x y z each) as ODE's convex geometry wants it: planes
/// (a b c d with unit normals, outward), the hull's points, and polygons (3 i j k per face).
/// Incremental: each point outside the hull so far replaces the faces it sees. Empty when
/// the points are flat.
void convexHull(const std::vector<double>& points, std::vector<double>& planes, std::vector<double>& out_points,
                std::vector<unsigned>& polygons) {
  const std::size_t n = points.size() / 3;
  auto P = [&](std::size_t i) { return Vec3{points[3 * i], points[3 * i + 1], points[3 * i + 2]}; };
  if (n < 4) return;
  core::Aabb box;
  for (std::size_t i = 0; i < n; ++i) box.add(P(i));
  const Vec3 extent = box.hi - box.lo;
  const double eps = 1e-9 * std::max({extent.x, extent.y, extent.z, 1e-12});
  // a first tetrahedron: two far points, the farthest from their line, the farthest from their plane
  std::size_t a = 0, b = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (P(i).x < P(a).x) a = i;
    if (P(i).x > P(b).x) b = i;
  }
  if ((P(b) - P(a)).length() <= eps) {
    for (std::size_t i = 0; i < n; ++i) {
      if ((P(i) - P(a)).length() > (P(b) - P(a)).length()) b = i;
    }
  }
  std::size_t c = a, d = a;
  double best = eps;
  for (std::size_t i = 0; i < n; ++i) {
    const double dist = (P(i) - P(a)).cross(P(b) - P(a)).length();
    if (dist > best) best = dist, c = i;
  }
  if (c == a) return;
  Vec3 normal = (P(b) - P(a)).cross(P(c) - P(a)).normalized();
  best = eps;
  for (std::size_t i = 0; i < n; ++i) {
    const double dist = std::abs(normal.dot(P(i) - P(a)));
    if (dist > best) best = dist, d = i;
  }
  if (d == a) return;
  struct Face {
    std::size_t v[3];
    Vec3 normal;
    double offset;
    bool alive = true;
  };
  std::vector<Face> faces;
  const Vec3 inside = (P(a) + P(b) + P(c) + P(d)) * 0.25;
  auto add = [&](std::size_t i, std::size_t j, std::size_t k) {
    Face f{{i, j, k}, (P(j) - P(i)).cross(P(k) - P(i)).normalized(), 0.0};
    if (f.normal.dot(inside - P(i)) > 0) {  // face the outside
      std::swap(f.v[1], f.v[2]);
      f.normal = -f.normal;
    }
    f.offset = f.normal.dot(P(f.v[0]));
    faces.push_back(f);
  };
  add(a, b, c), add(a, b, d), add(a, c, d), add(b, c, d);
  for (std::size_t p = 0; p < n; ++p) {
    const Vec3 x = P(p);
    std::vector<std::size_t> seen;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (faces[f].alive && faces[f].normal.dot(x) - faces[f].offset > eps) seen.push_back(f);
    }
    if (seen.empty()) continue;
    // the horizon: edges of seen faces whose reverse is not an edge of another seen face
    std::map<std::pair<std::size_t, std::size_t>, int> edges;
    for (auto f : seen) {
      for (int e = 0; e < 3; ++e) edges[{faces[f].v[e], faces[f].v[(e + 1) % 3]}] += 1;
      faces[f].alive = false;
    }
    for (const auto& [edge, count] : edges) {
      if (edges.count({edge.second, edge.first}) != 0) continue;
      Face f{{edge.first, edge.second, p}, (P(edge.second) - P(edge.first)).cross(x - P(edge.first)).normalized(), 0.0};
      f.offset = f.normal.dot(P(edge.first));
      faces.push_back(f);
    }
  }
  std::map<std::size_t, unsigned> index;
  for (const auto& f : faces) {
    if (!f.alive) continue;
    planes.insert(planes.end(), {f.normal.x, f.normal.y, f.normal.z, f.offset});
    polygons.push_back(3);
    for (auto v : f.v) {
      auto [it, added] = index.emplace(v, static_cast<unsigned>(index.size()));
      if (added) out_points.insert(out_points.end(), {P(v).x, P(v).y, P(v).z});
      polygons.push_back(it->second);
    }
  }
}

constexpr double kHuge = 1e299;  // field values beyond this mean "no limit"

void initOde() {
  static const bool done = [] {
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    return true;
  }();
  (void)done;
}

void setPose(dBodyID b, const Pose& p) {
  dBodySetPosition(b, p.position.x, p.position.y, p.position.z);
  const dQuaternion q = {p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z};
  dBodySetQuaternion(b, q);
}

Pose bodyPose(dBodyID b) {
  const dReal* p = dBodyGetPosition(b);
  const dReal* q = dBodyGetQuaternion(b);
  return {{p[0], p[1], p[2]}, {q[0], q[1], q[2], q[3]}};
}

void rotationMatrix(const Quat& q, dMatrix3 r) {
  const dQuaternion dq = {q.w, q.x, q.y, q.z};
  dRfromQ(r, dq);
}

Vec3 v3(const dReal* v) { return {v[0], v[1], v[2]}; }

/// What a geometry brings to a contact.
struct Surface {
  double friction = 0.8;
  double bounce = 0.0;
  double conveyor_speed = 0.0;  // m/s, 0 when not a conveyor (as built; see conveyor_node)
  const Node* conveyor_node = nullptr;  // the Conveyor: its speed is read at each contact
  Vec3 conveyor_dir;            // in the frame of the geometry's body (world frame if static)
  bool conveyor = false;
  const Node* node = nullptr;   // the shape
};

}  // namespace

struct World::Impl {
  struct Body {
    Node* node;
    dBodyID id;
    Vec3 com;                // centre of mass in the node's frame (the ODE body's origin)
    Vec3 force, torque;      // applied every step
    Vec3 pending;            // applied in the next step only
  };
  struct Joint {
    Node* node;
    dJointID id;
    std::string kind;
    int vel1, fmax1, vel2, fmax2;  // field indices
    int control, target1, servo_time;
  };

  scene::Scene& scene;
  dWorldID world = nullptr;
  dSpaceID space = nullptr;  // holds every geometry; never collided (see the broad phase below)
  dJointGroupID contacts = nullptr;
  int substeps = 1;
  std::deque<Body> bodies;  // stable addresses; a removed body keeps its place with id null
  std::unordered_map<scene::NodeHandle, std::size_t> body_of;  // Body node -> index
  std::vector<Joint> joints;
  std::unordered_map<scene::NodeHandle, std::size_t> joint_of;
  std::vector<Surface> surfaces;  // per geometry, by dGeomGetData index
  std::unordered_map<scene::NodeHandle, dGeomID> geom_of;  // shape node -> its geometry
  struct Sensor {
    Node* node;
    dGeomID geom;     // never in contacts
    bool ray;         // a ray: RangeFinder, or a Region of shape ray
  };
  std::vector<Sensor> sensors;
  std::deque<std::vector<double>> heightfields;     // the heights ODE reads (it keeps pointers)
  std::vector<dHeightfieldDataID> heightfield_data;
  /// A Mesh node's geometry as ODE reads it (ODE keeps pointers into these arrays).
  struct MeshGeometry {
    std::vector<double> points;        // scaled vertices, x y z
    std::vector<dTriIndex> indices;    // three per triangle
    core::Aabb box;                    // around the points
    std::vector<double> planes;        // convex hull: a b c d per face
    std::vector<double> hull_points;   // its vertices
    std::vector<unsigned> polygons;    // 3 i j k per face
  };
  std::unordered_map<scene::NodeHandle, MeshGeometry> meshes;
  std::vector<dTriMeshDataID> trimesh_data;
  // geometry data: surfaces are 1..n; a sensor's data has this bit set over its index
  static constexpr std::uintptr_t kSensorTag = std::uintptr_t{1} << 62;
  std::string model_dir;
  std::map<std::pair<dBodyID, dBodyID>, dJointID> attached;

  // ---- broad phase ----
  // Shapes on bodies are swept against each other and looked up in a tree of the shapes
  // without one, which never move; planes and other endless shapes meet everything.
  std::vector<dGeomID> shapes;     // every shape's geometry, in the order made
  bool shapes_changed = true;      // the lists and the tree below are to be remade
  std::vector<dGeomID> moving;     // shapes on bodies
  std::vector<dGeomID> fixed;      // shapes on no body, bounded: in fixed_tree
  std::vector<dGeomID> endless;    // shapes on no body whose box is unbounded
  std::vector<core::Aabb> moving_boxes;
  core::AabbTree fixed_tree;
  core::SweepAndPrune sweep;
  std::vector<core::Aabb> sense_boxes;  // the moving shapes', then the sensors'
  core::SweepAndPrune sense_sweep;

  explicit Impl(scene::Scene& s) : scene(s) {}
  ~Impl() {
    for (auto& [pair, j] : attached) dJointDestroy(j);
    if (space) dSpaceDestroy(space);
    space = nullptr;
    for (auto d : heightfield_data) dGeomHeightfieldDataDestroy(d);
    for (auto d : trimesh_data) dGeomTriMeshDataDestroy(d);
    if (contacts) dJointGroupDestroy(contacts);
    if (space) dSpaceDestroy(space);
    if (world) dWorldDestroy(world);
  }

  // ---- building ----

  /// The Body that owns `node` (itself, or the nearest Body above it), or null.
  Body* owner(const Node& node) {
    for (const Node* n = &node; n; n = n->parent()) {
      auto it = body_of.find(n->handle());
      if (it != body_of.end()) return &bodies[it->second];
    }
    return nullptr;
  }
  const Body* owner(const Node& node) const { return const_cast<Impl*>(this)->owner(node); }

  struct Pending {
    Node* node;
    Body* parent;  // the body above the joint, or null (the world)
  };

  /// The Material in effect at `node`: the last one among the earlier siblings of it or of
  /// any of its ancestors, nearest first.
  static const Node* materialAt(const Node& node) {
    for (const Node* n = &node; n->parent(); n = n->parent()) {
      for (const Node* sib = n->prev(); sib; sib = sib->prev()) {
        if (sib->type().name == "Material") return sib;
      }
    }
    return nullptr;
  }

  /// Builds everything in the subtree at `top`: bodies first (joints need both ends), then
  /// one geometry per shape with the material in effect, then the joints.
  bool addSubtree(Node& top, core::Diagnostics& diags) {
    scene::updateTransforms(top);
    bool ok = true;
    buildBodies(top);
    std::vector<std::pair<Node*, Body*>> pending_joints;
    scene::TraversalState state{top.world, top.world_scale, materialAt(top)};
    scene::traverse(top, [&](Node& n, const scene::TraversalState& st) {
      if (n.type().category == scene::Category::Shape) ok = addGeom(n, st, model_dir, diags) && ok;
      if (n.type().name == "Joint") pending_joints.emplace_back(&n, n.parent() ? owner(*n.parent()) : nullptr);
      if (n.type().category == scene::Category::Sensor) addSensor(n);
    }, state);
    for (const auto& [node, parent] : pending_joints) ok = addJoint(*node, parent, diags) && ok;
    return ok;
  }

  void buildBodies(Node& node) {
    if (node.type().name == "Body") {
      dBodyID id = dBodyCreate(world);
      bodies.push_back({&node, id, {}, {}, {}, {}});
      body_of[node.handle()] = bodies.size() - 1;
    }
    for (const auto& c : node.children()) buildBodies(*c);
    if (node.type().name == "Body") finishBody(bodies[body_of[node.handle()]]);
  }

  void addSensor(Node& n) {
    const auto& t = n.type().name;
    dGeomID g = nullptr;
    bool ray = false;
    if (t == "RangeFinder") {
      g = dCreateRay(space, n.number("length"));
      ray = true;
    } else if (t == "Region") {
      const std::string shape = n.text("shape");
      const Vec3 s = n.world_scale;
      if (shape == "box") {
        const Vec3 size = n.vec3("size").times(s);
        g = dCreateBox(space, std::max(size.x, 1e-9), std::max(size.y, 1e-9), std::max(size.z, 1e-9));
      } else if (shape == "sphere") {
        g = dCreateSphere(space, std::max(n.number("radius") * std::max({s.x, s.y, s.z}), 1e-9));
      } else if (shape == "cylinder" || shape == "cone") {
        const double r = n.number("radius") * std::max(s.x, s.y) * (shape == "cone" ? 0.5 : 1.0);
        g = dCreateCylinder(space, std::max(r, 1e-9), std::max(n.number("height") * s.z, 1e-9));
      } else {
        g = dCreateRay(space, n.number("length"));
        ray = true;
      }
    } else {
      return;  // time sensors need no geometry
    }
    sensors.push_back({&n, g, ray});
    retagSensors();
  }

  /// Each sensor geometry's data: the tag and its index in `sensors`.
  void retagSensors() {
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      dGeomSetData(sensors[i].geom, reinterpret_cast<void*>(kSensorTag | i));
    }
  }

  /// True when shape `shape` is in the scope of `sensor`.
  static bool inScope(const Node& sensor, const Node& shape) {
    const std::string scope = sensor.text("scope");
    if (scope == "world") return true;
    const Node* parent = sensor.parent();
    for (const Node* n = &shape; n; n = n->parent()) {
      if (scope == "parent" && n == parent) return true;
      if (scope == "siblings" && n->parent() == parent) return n != &sensor;
    }
    return false;
  }

  /// The node an overlap reports: the body a shape belongs to, or the static shape itself.
  const Node* reported(const Node& shape) const {
    const Body* b = owner(shape);
    return b ? b->node : &shape;
  }

  /// What each sensor felt in one sensing pass.
  struct Felt {
    std::vector<const Node*> items;
    double distance;
    const Node* hit;
  };

  /// Sensor `index` and shape `other`, whose boxes overlap: what the sensor feels of it.
  void feel(std::size_t index, dGeomID other) {
    const Sensor& sensor = sensors[index];
    const Surface s = surfaceOf(other, *this);
    if (!s.node || !inScope(*sensor.node, *s.node)) return;
    dContactGeom c;
    if (dCollide(sensor.geom, other, 1, &c, sizeof(dContactGeom)) == 0) return;
    Felt& f = felt[index];
    if (sensor.ray) {
      if (c.depth < f.distance) {
        f.distance = c.depth;
        f.hit = reported(*s.node);
      }
    } else {
      f.items.push_back(reported(*s.node));
    }
  }

  std::vector<Felt> felt;

  /// Each sensor is placed where its node is, then meets the shapes its box overlaps.
  void sense(std::vector<std::pair<scene::NodeHandle, Feel>>& out) {
    out.clear();
    felt.assign(sensors.size(), Felt{});
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      const Sensor& sensor = sensors[i];
      const Node& n = *sensor.node;
      // sensors follow the nodes they sit in (a body moves them)
      if (sensor.ray) {
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
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      const Node& n = *sensors[i].node;
      Felt& f = felt[i];
      Feel feel;
      if (sensors[i].ray) {
        feel.distance = f.distance;
        feel.hit = f.hit ? f.hit->handle() : 0;
        if (n.type().name == "Region" && f.hit) feel.items.push_back(f.hit->handle());
      } else {
        std::sort(f.items.begin(), f.items.end(), [](const Node* a, const Node* b) { return a->path() < b->path(); });
        f.items.erase(std::unique(f.items.begin(), f.items.end()), f.items.end());
        for (const Node* item : f.items) feel.items.push_back(item->handle());
      }
      out.emplace_back(n.handle(), std::move(feel));
    }
  }

  void removeSubtree(const Node& top) {
    scene::traverse(const_cast<Node&>(top), [&](Node& n, const scene::TraversalState&) {
      const auto h = n.handle();
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
      if (auto j = joint_of.find(h); j != joint_of.end()) {
        dJointDestroy(joints[j->second].id);
        joints[j->second].id = nullptr;
        joint_of.erase(j);
      }
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

  /// The geometry of Mesh node `n` (its file read, its part chosen, scaled), made once.
  const MeshGeometry* meshOf(Node& n, const std::string& dir, core::Diagnostics& diags) {
    if (auto it = meshes.find(n.handle()); it != meshes.end()) return &it->second;
    const std::string file = n.text("file");
    const auto at = n.field_locs[static_cast<std::size_t>(n.type().fieldIndex("file"))];
    const auto path = (std::filesystem::path(dir) / file).string();
    std::string why;
    auto data = file.empty() ? nullptr : scene::loadMesh(path, why);
    if (!data) {
      diags.error(at.line > 0 ? at : n.loc, "cannot read the mesh file '" + file + "': " + (file.empty() ? "no file given" : why));
      return nullptr;
    }
    const auto part = n.number("part");
    if (part >= static_cast<double>(data->parts.size())) {
      const auto ploc = n.field_locs[static_cast<std::size_t>(n.type().fieldIndex("part"))];
      diags.error(ploc.line > 0 ? ploc : n.loc, "the mesh file '" + file + "' has " + std::to_string(data->parts.size()) +
                                                    " parts: 'part' must be below that, or -1 for all");
      return nullptr;
    }
    MeshGeometry geo;
    const Vec3 s = n.vec3("scale").times(n.world_scale);
    for (std::size_t i = 0; i < data->parts.size(); ++i) {
      if (part >= 0 && static_cast<std::size_t>(part) != i) continue;
      const auto& p = data->parts[i];
      const auto base = static_cast<dTriIndex>(geo.points.size() / 3);
      for (std::size_t k = 0; k + 2 < p.positions.size(); k += 3) {
        const Vec3 v = Vec3{p.positions[k], p.positions[k + 1], p.positions[k + 2]}.times(s);
        geo.points.insert(geo.points.end(), {v.x, v.y, v.z});
        geo.box.add(v);
      }
      for (auto idx : p.indices) geo.indices.push_back(base + static_cast<dTriIndex>(idx));
    }
    convexHull(geo.points, geo.planes, geo.hull_points, geo.polygons);
    return &(meshes[n.handle()] = std::move(geo));
  }

  /// Mass from the body's own shapes (not those of bodies below it), centre of mass at the
  /// ODE body's origin.
  void finishBody(Body& body) {
    Node& node = *body.node;
    const double density = node.number("density");
    const double total = node.number("mass");
    dMass m;
    dMassSetZero(&m);
    const Pose inv = node.world.inverse();
    scene::traverse(node, [&](Node& n, const scene::TraversalState&) {
      if (n.type().category != scene::Category::Shape || owner(n) != &body) return;
      const Vec3 s = n.world_scale;
      dMass sm;
      const auto& t = n.type().name;
      if (t == "Cube") {
        const Vec3 size = n.vec3("size").times(s);
        if (size.x <= 0 || size.y <= 0 || size.z <= 0) return;
        dMassSetBox(&sm, density, size.x, size.y, size.z);
      } else if (t == "Sphere") {
        const double r = n.number("radius") * std::max({s.x, s.y, s.z});
        if (r <= 0) return;
        dMassSetSphere(&sm, density, r);
      } else if (t == "Cylinder" || t == "Cone") {
        const double r = n.number("radius") * std::max(s.x, s.y) * (t == "Cone" ? 0.5 : 1.0);
        const double h = n.number("height") * s.z;
        if (r <= 0 || h <= 0) return;
        dMassSetCylinder(&sm, density, 3, r, h);
      } else if (t == "Mesh") {
        // a mesh weighs as its bounding box (open meshes have no volume of their own); a
        // mesh that cannot be read is reported when its geometry is made
        core::Diagnostics later;
        const MeshGeometry* mesh = meshOf(n, model_dir, later);
        if (mesh == nullptr) return;
        const Vec3 size = mesh->box.hi - mesh->box.lo;
        if (size.x <= 0 || size.y <= 0 || size.z <= 0) return;
        dMassSetBox(&sm, density, size.x, size.y, size.z);
        const Vec3 c = (mesh->box.lo + mesh->box.hi) * 0.5;
        dMassTranslate(&sm, c.x, c.y, c.z);
      } else {
        return;
      }
      const Pose local = inv * n.world;  // the shape in the body node's frame
      dMatrix3 r;
      rotationMatrix(local.rotation, r);
      dMassRotate(&sm, r);
      dMassTranslate(&sm, local.position.x, local.position.y, local.position.z);
      dMassAdd(&m, &sm);
    });
    if (m.mass <= 0) dMassSetSphereTotal(&m, total > 0 ? total : 1.0, 0.05);
    if (total > 0) dMassAdjust(&m, total);
    body.com = {m.c[0], m.c[1], m.c[2]};
    dMassTranslate(&m, -m.c[0], -m.c[1], -m.c[2]);
    dBodySetMass(body.id, &m);
    setPose(body.id, {node.world.apply(body.com), node.world.rotation});
    const double ld = node.number("linear_damping"), ad = node.number("angular_damping");
    if (ld > 0) dBodySetLinearDamping(body.id, ld);
    if (ad > 0) dBodySetAngularDamping(body.id, ad);
    node.dynamic_pose = node.world;
  }

  bool addGeom(Node& n, const scene::TraversalState& st, const std::string& dir, core::Diagnostics& diags) {
    const auto& t = n.type().name;
    const Vec3 s = n.world_scale;
    Body* body = owner(n);
    dGeomID g = nullptr;
    Pose geom_pose = n.world;  // where the geometry goes (a mesh's box sits on the mesh's centre)
    if (t == "Cube") {
      const Vec3 size = n.vec3("size").times(s);
      if (size.x <= 0 || size.y <= 0 || size.z <= 0) return true;
      g = dCreateBox(space, size.x, size.y, size.z);
    } else if (t == "Sphere") {
      const double r = n.number("radius") * std::max({s.x, s.y, s.z});
      if (r <= 0) return true;
      g = dCreateSphere(space, r);
    } else if (t == "Cylinder" || t == "Cone") {
      // ODE has no cone: a cone collides as a cylinder of its height and half its radius
      const double r = n.number("radius") * std::max(s.x, s.y) * (t == "Cone" ? 0.5 : 1.0);
      const double h = n.number("height") * s.z;
      if (r <= 0 || h <= 0) return true;
      g = dCreateCylinder(space, r, h);
    } else if (t == "Plane") {
      if (body) {
        diags.error(n.loc, "a Plane is endless ground and cannot be part of the Body '" + body->node->path() + "'");
        return false;
      }
      const Vec3 normal = n.world.rotation.rotate(n.vec3("normal")).normalized();
      g = dCreatePlane(space, normal.x, normal.y, normal.z, normal.dot(n.world.position));
    } else if (t == "Terrain") {
      if (body) {
        diags.error(n.loc, "a Terrain is ground and cannot be part of the Body '" + body->node->path() + "'");
        return false;
      }
      const std::string file = n.text("file");
      const auto at = n.field_locs[static_cast<std::size_t>(n.type().fieldIndex("file"))];
      const auto path = (std::filesystem::path(dir) / file).string();
      std::string why;
      auto grid = scene::loadHeightGrid(path, why);
      if (!grid) {
        diags.error(at.line > 0 ? at : n.loc, "cannot read the elevation file '" + file + "': " + why);
        return false;
      }
      // ODE's heightfield is Y-up: x along width, z along depth (rows), heights along +y.
      // Turned a quarter about x, its depth runs towards -y, so row 0 (north) lands at +y.
      heightfields.push_back(std::move(grid->height));
      dHeightfieldDataID data = dGeomHeightfieldDataCreate();
      dGeomHeightfieldDataBuildDouble(data, heightfields.back().data(), 0, n.number("width") * s.x,
                                      n.number("depth") * s.y, grid->nx, grid->ny, n.number("height_scale") * s.z,
                                      0.0, 1.0, 0);
      heightfield_data.push_back(data);
      g = dCreateHeightfield(space, data, 1);
      const Pose pose = n.world * Pose{{}, Quat::axisAngle({1, 0, 0}, M_PI / 2)};
      const dQuaternion q = {pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z};
      dGeomSetPosition(g, pose.position.x, pose.position.y, pose.position.z);
      dGeomSetQuaternion(g, q);
    } else if (t == "Mesh") {
      const auto mesh = meshOf(n, dir, diags);
      if (!mesh) return false;
      const std::string& kind = n.text("collision");
      if (kind == "box" || mesh->points.size() < 12 || (kind == "convex" && mesh->planes.empty())) {
        const Vec3 size = mesh->box.hi - mesh->box.lo;
        if (size.x <= 0 || size.y <= 0 || size.z <= 0) return true;
        g = dCreateBox(space, size.x, size.y, size.z);
        geom_pose = n.world * Pose{(mesh->box.lo + mesh->box.hi) * 0.5, {}};
      } else if (kind == "convex") {
        g = dCreateConvex(space, mesh->planes.data(), static_cast<unsigned>(mesh->planes.size() / 4),
                          mesh->hull_points.data(), static_cast<unsigned>(mesh->hull_points.size() / 3),
                          mesh->polygons.data());
      } else {
        dTriMeshDataID data = dGeomTriMeshDataCreate();
        dGeomTriMeshDataBuildDouble(data, mesh->points.data(), 3 * sizeof(double),
                                    static_cast<int>(mesh->points.size() / 3), mesh->indices.data(),
                                    static_cast<int>(mesh->indices.size()), 3 * sizeof(dTriIndex));
        dGeomTriMeshDataPreprocess2(data, 1U << dTRIDATAPREPROCESS_BUILD_FACE_ANGLES, nullptr);
        trimesh_data.push_back(data);
        g = dCreateTriMesh(space, data, nullptr, nullptr, nullptr);
      }
    } else {
      return true;
    }
    // what the geometry brings to contacts: the material in effect, a conveyor beside it
    Surface surface;
    surface.node = &n;
    if (st.material) {
      surface.friction = st.material->number("friction");
      surface.bounce = st.material->number("bounce");
    }
    if (n.parent()) {
      for (const auto& sib : n.parent()->children()) {
        if (sib->type().name != "Conveyor") continue;
        surface.conveyor = true;
        surface.conveyor_speed = sib->number("speed");
        surface.conveyor_node = sib.get();
        const Vec3 dir_world = sib->world.rotation.rotate(sib->vec3("direction")).normalized();
        surface.conveyor_dir = body ? bodyPose(body->id).rotation.conjugate().rotate(dir_world) : dir_world;
      }
    }
    surfaces.push_back(surface);
    dGeomSetData(g, reinterpret_cast<void*>(surfaces.size()));  // 1-based: 0 means none
    geom_of[n.handle()] = g;
    shapes.push_back(g);
    shapes_changed = true;
    if (t == "Plane" || t == "Terrain") return true;
    const Pose& at = geom_pose;
    const dQuaternion q = {at.rotation.w, at.rotation.x, at.rotation.y, at.rotation.z};
    if (body) {
      dGeomSetBody(g, body->id);
      dGeomSetOffsetWorldPosition(g, at.position.x, at.position.y, at.position.z);
      dGeomSetOffsetWorldQuaternion(g, q);
    } else {
      dGeomSetPosition(g, at.position.x, at.position.y, at.position.z);
      dGeomSetQuaternion(g, q);
    }
    return true;
  }

  bool addJoint(Node& n, Body* parent_body, core::Diagnostics& diags) {
    // the first Body below the joint (Transforms may place it), not inside another Body
    Body* child_body = nullptr;
    std::vector<Node*> todo;
    for (auto it = n.children().rbegin(); it != n.children().rend(); ++it) todo.push_back(it->get());
    while (!todo.empty() && !child_body) {
      Node* c = todo.back();
      todo.pop_back();
      if (c->type().name == "Body") {
        child_body = &bodies[body_of[c->handle()]];
      } else {
        for (auto it = c->children().rbegin(); it != c->children().rend(); ++it) todo.push_back(it->get());
      }
    }
    if (!child_body) {
      diags.error(n.loc, "joint '" + n.path() + "' joins no bodies: it needs a Body among its children (joined to "
                         "the Body above it, or to the world)");
      return false;
    }
    const std::string kind = n.text("kind");
    dJointID j = nullptr;
    if (kind == "hinge") j = dJointCreateHinge(world, nullptr);
    else if (kind == "slider") j = dJointCreateSlider(world, nullptr);
    else if (kind == "ball") j = dJointCreateBall(world, nullptr);
    else if (kind == "universal") j = dJointCreateUniversal(world, nullptr);
    else if (kind == "hinge2") j = dJointCreateHinge2(world, nullptr);
    else j = dJointCreateFixed(world, nullptr);
    dJointAttach(j, child_body->id, parent_body ? parent_body->id : nullptr);
    const Vec3 anchor = n.world.apply(n.vec3("anchor"));
    const Vec3 a1 = n.world.rotation.rotate(n.vec3("axis1")).normalized();
    const Vec3 a2 = n.world.rotation.rotate(n.vec3("axis2")).normalized();
    const bool angular = kind != "slider";
    auto limit = [&](const char* field) {
      const double v = n.number(field);
      return std::abs(v) >= kHuge ? (v < 0 ? -dInfinity : dInfinity) : (angular ? core::radians(v) : v);
    };
    if (kind == "hinge") {
      dJointSetHingeAnchor(j, anchor.x, anchor.y, anchor.z);
      dJointSetHingeAxis(j, a1.x, a1.y, a1.z);
      dJointSetHingeParam(j, dParamHiStop, limit("hi1"));
      dJointSetHingeParam(j, dParamLoStop, limit("lo1"));
    } else if (kind == "slider") {
      dJointSetSliderAxis(j, a1.x, a1.y, a1.z);
      dJointSetSliderParam(j, dParamHiStop, limit("hi1"));
      dJointSetSliderParam(j, dParamLoStop, limit("lo1"));
    } else if (kind == "ball") {
      dJointSetBallAnchor(j, anchor.x, anchor.y, anchor.z);
    } else if (kind == "universal") {
      dJointSetUniversalAnchor(j, anchor.x, anchor.y, anchor.z);
      dJointSetUniversalAxis1(j, a1.x, a1.y, a1.z);
      dJointSetUniversalAxis2(j, a2.x, a2.y, a2.z);
      dJointSetUniversalParam(j, dParamHiStop, limit("hi1"));
      dJointSetUniversalParam(j, dParamLoStop, limit("lo1"));
      dJointSetUniversalParam(j, dParamHiStop2, limit("hi2"));
      dJointSetUniversalParam(j, dParamLoStop2, limit("lo2"));
    } else if (kind == "hinge2") {
      dJointSetHinge2Anchor(j, anchor.x, anchor.y, anchor.z);
      const dReal ax1[3] = {a1.x, a1.y, a1.z}, ax2[3] = {a2.x, a2.y, a2.z};
      dJointSetHinge2Axes(j, ax1, ax2);
      dJointSetHinge2Param(j, dParamHiStop, limit("hi1"));
      dJointSetHinge2Param(j, dParamLoStop, limit("lo1"));
    } else {
      dJointSetFixed(j);
    }
    const auto& type = n.type();
    joints.push_back({&n, j, kind, type.fieldIndex("vel1"), type.fieldIndex("fmax1"), type.fieldIndex("vel2"),
                      type.fieldIndex("fmax2"), type.fieldIndex("control"), type.fieldIndex("target1"),
                      type.fieldIndex("servo_time")});
    joint_of[n.handle()] = joints.size() - 1;
    return true;
  }

  // ---- stepping ----

  static double value(const Node& n, int field) { return std::get<double>(n.value(static_cast<std::size_t>(field))); }

  /// Where joint `j` stands on `axis` (1 or 2): radians, or metres for a slider.
  static double position(const Joint& j, int axis) {
    if (j.kind == "hinge") return dJointGetHingeAngle(j.id);
    if (j.kind == "slider") return dJointGetSliderPosition(j.id);
    if (j.kind == "universal") return axis == 1 ? dJointGetUniversalAngle1(j.id) : dJointGetUniversalAngle2(j.id);
    if (j.kind == "hinge2") return axis == 1 ? dJointGetHinge2Angle1(j.id) : 0.0;
    return 0.0;
  }

  /// Motors follow the joint nodes' fields (a script may have set them).
  void driveMotors() {
    for (const auto& jt : joints) {
      if (!jt.id) continue;
      const Node& n = *jt.node;
      const bool angular = jt.kind != "slider";
      double vel1 = angular ? core::radians(value(n, jt.vel1)) : value(n, jt.vel1);
      if (std::get<std::string>(n.value(static_cast<std::size_t>(jt.control))) == "position") {
        // a proportional servo: the speed closes the error in servo_time, capped at |vel1|
        const double target = angular ? core::radians(value(n, jt.target1)) : value(n, jt.target1);
        const double speed = (target - position(jt, 1)) / value(n, jt.servo_time);
        vel1 = vel1 == 0 ? speed : std::clamp(speed, -std::abs(vel1), std::abs(vel1));
      }
      const double fmax1 = value(n, jt.fmax1);
      const double vel2 = core::radians(value(n, jt.vel2)), fmax2 = value(n, jt.fmax2);
      if (jt.kind == "hinge") {
        dJointSetHingeParam(jt.id, dParamVel, vel1);
        dJointSetHingeParam(jt.id, dParamFMax, fmax1);
      } else if (jt.kind == "slider") {
        dJointSetSliderParam(jt.id, dParamVel, vel1);
        dJointSetSliderParam(jt.id, dParamFMax, fmax1);
      } else if (jt.kind == "universal") {
        dJointSetUniversalParam(jt.id, dParamVel, vel1);
        dJointSetUniversalParam(jt.id, dParamFMax, fmax1);
        dJointSetUniversalParam(jt.id, dParamVel2, vel2);
        dJointSetUniversalParam(jt.id, dParamFMax2, fmax2);
      } else if (jt.kind == "hinge2") {
        dJointSetHinge2Param(jt.id, dParamVel, vel1);
        dJointSetHinge2Param(jt.id, dParamFMax, fmax1);
        dJointSetHinge2Param(jt.id, dParamVel2, vel2);
        dJointSetHinge2Param(jt.id, dParamFMax2, fmax2);
      }
      if (fmax1 > 0 || fmax2 > 0) {
        // a motor that works wakes what it moves
        for (int k = 0; k < 2; ++k) {
          if (dBodyID b = dJointGetBody(jt.id, k)) dBodyEnable(b);
        }
      }
    }
  }

  static Surface surfaceOf(dGeomID g, const Impl& self) {
    const auto i = reinterpret_cast<std::size_t>(dGeomGetData(g));
    return i == 0 || (i & kSensorTag) ? Surface{} : self.surfaces[i - 1];
  }

  /// A running belt wakes a sleeping body lying on it (a script may have just started it).
  bool beltWakes(dGeomID belt, dBodyID other) const {
    if (other == nullptr || dBodyIsEnabled(other)) return false;
    const auto i = reinterpret_cast<std::size_t>(dGeomGetData(belt));
    if (i == 0 || (i & kSensorTag) != 0) return false;
    const Surface& s = surfaces[i - 1];
    if (!s.conveyor || s.conveyor_node == nullptr || s.conveyor_node->number("speed") == 0.0) return false;
    dBodyEnable(other);
    return true;
  }

  static void nearCallback(void* data, dGeomID o1, dGeomID o2) {
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
    if (belt1 || belt2) {
      const Surface& belt = belt1 ? s1 : s2;
      const dBodyID belt_body = belt1 ? b1 : b2;
      dir = belt_body ? bodyPose(belt_body).rotation.rotate(belt.conveyor_dir) : belt.conveyor_dir;
      // the speed now: a script may start and stop a belt
      const double speed = belt.conveyor_node ? belt.conveyor_node->number("speed") : belt.conveyor_speed;
      motion = belt1 ? -speed : speed;
    }
    for (int i = 0; i < n; ++i) {
      dSurfaceParameters& sp = contact[i].surface;
      sp.mode = dContactBounce | dContactApprox1;
      const double mu = std::sqrt(s1.friction * s2.friction);
      sp.mu = mu > 1e6 ? dInfinity : mu;
      sp.bounce = std::max(s1.bounce, s2.bounce);
      sp.bounce_vel = 0.01;
      if (belt1 || belt2) {
        sp.mode |= dContactFDir1 | dContactMotion1;
        contact[i].fdir1[0] = dir.x;
        contact[i].fdir1[1] = dir.y;
        contact[i].fdir1[2] = dir.z;
        sp.motion1 = motion;
      }
      dJointID c = dJointCreateContact(self.world, self.contacts, &contact[i]);
      dJointAttach(c, b1, b2);
    }
  }

  static core::Aabb aabbOf(dGeomID g) {
    dReal a[6];
    dGeomGetAABB(g, a);
    return {{a[0], a[2], a[4]}, {a[1], a[3], a[5]}};
  }

  /// Sorts the shapes into moving, fixed and endless, and rebuilds the fixed shapes' tree,
  /// when shapes have come or gone since the last time.
  void refreshShapes() {
    if (!shapes_changed) return;
    moving.clear();
    fixed.clear();
    endless.clear();
    std::vector<core::Aabb> boxes;
    for (dGeomID g : shapes) {
      if (dGeomGetBody(g)) {
        moving.push_back(g);
        continue;
      }
      const core::Aabb box = aabbOf(g);
      const double bounds[6] = {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z};
      if (std::all_of(bounds, bounds + 6, [](double v) { return std::isfinite(v) && std::abs(v) < 1e12; })) {
        fixed.push_back(g);
        boxes.push_back(box);
      } else {
        endless.push_back(g);
      }
    }
    fixed_tree.build(boxes);
    shapes_changed = false;
  }

  /// The moving shapes' boxes where their bodies are now.
  void refreshMoving() {
    refreshShapes();
    moving_boxes.resize(moving.size());
    for (std::size_t i = 0; i < moving.size(); ++i) moving_boxes[i] = aabbOf(moving[i]);
  }

  /// Contacts for every pair of shapes whose boxes overlap, at least one of them moving.
  void collide() {
    refreshMoving();
    sweep.pairs(moving_boxes, [&](std::size_t i, std::size_t j) {
      if (dGeomGetBody(moving[i]) != dGeomGetBody(moving[j])) nearCallback(this, moving[i], moving[j]);
    });
    for (std::size_t i = 0; i < moving.size(); ++i) {
      fixed_tree.query(moving_boxes[i], [&](std::size_t k) { nearCallback(this, moving[i], fixed[k]); });
      for (dGeomID g : endless) nearCallback(this, moving[i], g);
    }
  }

  void step(double dt) {
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

  /// Moving bodies tell the scene where they are; sleeping ones have not moved.
  void writeBack() {
    for (auto& b : bodies) {
      if (!b.id || (!dBodyIsEnabled(b.id) && b.node->dynamic_pose)) continue;
      const Pose p = bodyPose(b.id);
      b.node->dynamic_pose = Pose{p.position - p.rotation.rotate(b.com), p.rotation};
      scene::updateTransforms(*b.node);
    }
  }
};

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
    if (!settings && n.type().name == "World") settings = &n;
  });
  Vec3 g{0, 0, -9.81};
  double erp = 0.2, cfm = 1e-5;
  bool auto_disable = true;
  int iterations = 40;
  if (settings) {
    iterations = static_cast<int>(settings->number("iterations"));
    g = settings->vec3("gravity");
    erp = settings->number("erp");
    cfm = settings->number("cfm");
    impl->substeps = static_cast<int>(settings->number("substeps"));
    auto_disable = settings->flag("auto_disable");
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

bool World::isBody(const scene::Node& node) const { return impl_->body_of.count(node.handle()) > 0; }

namespace {
template <class B>
B& need(B* b) {
  GDPN_ASSERT(b != nullptr, "the node belongs to a body of this world");
  return *b;
}
}  // namespace

core::Vec3 World::velocity(const scene::Node& body) const { return v3(dBodyGetLinearVel(need(impl_->owner(body)).id)); }
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

double World::jointPosition(const scene::Node& joint, int axis) const {
  return Impl::position(impl_->joints[impl_->joint_of.at(joint.handle())], axis);
}

double World::jointRate(const scene::Node& joint, int axis) const {
  const auto& j = impl_->joints[impl_->joint_of.at(joint.handle())];
  if (j.kind == "hinge") return dJointGetHingeAngleRate(j.id);
  if (j.kind == "slider") return dJointGetSliderPositionRate(j.id);
  if (j.kind == "universal") return axis == 1 ? dJointGetUniversalAngle1Rate(j.id) : dJointGetUniversalAngle2Rate(j.id);
  if (j.kind == "hinge2") return axis == 1 ? dJointGetHinge2Angle1Rate(j.id) : dJointGetHinge2Angle2Rate(j.id);
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

bool World::add(scene::Node& top, core::Diagnostics& diags) { return impl_->addSubtree(top, diags); }
void World::sense(std::vector<std::pair<scene::NodeHandle, Feel>>& out) { impl_->sense(out); }
void World::remove(const scene::Node& top) { impl_->removeSubtree(top); }

std::size_t World::bodyCount() const { return impl_->body_of.size(); }
std::size_t World::awakeCount() const {
  std::size_t n = 0;
  for (const auto& b : impl_->bodies) n += b.id && dBodyIsEnabled(b.id) ? 1u : 0u;
  return n;
}

}  // namespace gdpn::physics
