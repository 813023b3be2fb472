#pragma once
/// \file
/// The state behind physics::World, shared by the files of src/physics; each adds one part:
/// bodies and mass (bodies.cpp), the geometry of shapes (geometry.cpp), joints and motors
/// (joints.cpp), contacts, surfaces and conveyors (contacts.cpp), the pairs of shapes that
/// may touch (broad_phase.cpp), sensing (sensing.cpp), building and removing the physics of
/// a subtree (subtree.cpp), the façade and stepping (world.cpp). Private to src/physics: no
/// other module includes it, and it makes no promises. ODE's types stay behind it.

#include <ode/ode.h>

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "gdpn/core/broad_phase.h"
#include "gdpn/physics/world.h"
#include "gdpn/scene/actions.h"
#include "gdpn/scene/fields.h"

namespace gdpn::physics {

/// Field values beyond this mean "no limit".
inline constexpr double kHuge = 1e299;

/// The primitive ODE makes for a shape or for a sensor's volume, scale applied.
struct Primitive {
  /// What ODE makes.
  enum class Form : std::uint8_t { None, Box, Sphere, Cylinder, Cone, Ray, Mesh, Plane, Terrain };
  Form form = Form::None;  ///< None: nothing to make
  core::Vec3 box;          ///< Box: edge lengths, m
  double radius = 0;       ///< Sphere, Cylinder: m; Cone: of its base, m
  double height = 0;       ///< Cylinder, Cone: m, along z (a cone's base at -height/2, its apex at +height/2)
  double length = 0;       ///< Ray: m, along +x
  /// Same form and sizes.
  bool operator==(const Primitive&) const = default;
};
/// What ODE makes for a primitive (Primitive::Form).
using Form = Primitive::Form;

/// A convex polyhedron as ODE's convex geometry reads it (ODE keeps pointers into these).
struct Convex {
  std::vector<double> planes;      ///< a b c d per face: unit outward normal, offset (m)
  std::vector<double> points;      ///< x y z per vertex, m
  std::vector<unsigned> polygons;  ///< per face: its vertex count, then its vertices
};

/// A box of `extent` (scene::shapeExtent, m) with each edge scaled by `scale`.
Primitive boxPrimitive(core::Vec3 extent, core::Vec3 scale);
/// A sphere of diameter extent.x (m), its radius scaled by the largest factor of `scale`.
Primitive spherePrimitive(core::Vec3 extent, core::Vec3 scale);
/// A cylinder of diameter extent.x and height extent.z (m): its radius scaled by the larger
/// of scale.x and scale.y, its height by scale.z. ODE has no cone: a `cone` collides as a
/// cylinder of its height and half its radius.
Primitive cylinderPrimitive(core::Vec3 extent, core::Vec3 scale, bool cone);
/// What shape node `n` collides and weighs as: a Cube, Sphere, Cylinder or Cone sized by
/// scene::shapeExtent and scaled by n.world_scale; a Mesh, Plane or Terrain by its form only
/// (their sizes come from their files); None for every other kind.
Primitive shapePrimitive(const scene::Node& n);

/// What a geometry brings to a contact.
struct Surface {
  double friction = 0.8;                  ///< the Material's, or the default
  double bounce = 0.0;                    ///< restitution, 0 to 1
  const scene::Node* material = nullptr;  ///< the Material in effect, or null
  const scene::Node* conveyor_node = nullptr;  ///< the Conveyor beside the shape: its speed is read at each contact
  core::Vec3 conveyor_dir;                ///< belt direction, unit, in the frame of the geometry's body (world frame if static)
  core::Vec3 conveyor_field;              ///< the Conveyor's `direction` as conveyor_dir was made from
  core::Pose conveyor_frame;              ///< the Conveyor's frame in the frame of the geometry's body (the world's if static): where a curved belt's axis is
  bool conveyor = false;                  ///< a Conveyor is beside the shape
  const scene::Node* node = nullptr;      ///< the shape
};

struct World::Impl {
  /// A Body node and its ODE body.
  struct Body {
    scene::Node* node;
    dBodyID id;           ///< null once removed
    core::Vec3 com;       ///< centre of mass in the node's frame (the ODE body's origin), m
    core::Vec3 force, torque;  ///< applied every step: N, N m (world frame)
    core::Vec3 pending;   ///< applied in the next step only, N
    bool watched = false; ///< a Contact sensor reads what touches it (World::watchContacts)
    /// While watched: the body or static shape on the other side of each contact of this
    /// step, and the sum of its normal forces over the sub-steps, N.
    std::vector<std::pair<scene::NodeHandle, double>> touches;
    bool stepped = false;     ///< While watched: awake through this sub-step (its contacts bore forces)
    int sensed_substeps = 0;  ///< While watched: this step's sub-steps it was stepped in
    int touch_substeps = 1;   ///< While watched: the sub-steps `touches` sums over
  };
  /// A Joint node and its ODE joint, with the Enum fields read every step, cached.
  struct Joint {
    scene::Node* node;
    dJointID id;                  ///< null once removed
    scene::JointKind kind;        ///< what `id` was made as
    scene::JointControl control;  ///< what the motor on axis 1 follows
    /// While watched (World::watchJoint): what ODE writes back, and the sums over this step's
    /// sub-steps of the force (N) and torque about the child's centre of mass (N m) on the
    /// child body.
    std::unique_ptr<dJointFeedback> feedback;
    core::Vec3 force_sum, torque_sum;
  };
  /// A contact joint of this sub-step with a watched body on one side.
  struct WatchedContact {
    Body* body;                ///< the watched body
    scene::NodeHandle other;   ///< the body or static shape on the other side
    dJointFeedback* feedback;  ///< in `contact_feedback`
    core::Vec3 normal;         ///< the contact's normal, unit
    bool first;                ///< the watched body is ODE's body 1 of the joint
  };
  /// A Region or RangeFinder and its geometry, never in contacts.
  struct Sensor {
    scene::Node* node;
    dGeomID geom;
    scene::Scope scope;  ///< what it feels
    bool bodies_only;    ///< a Region that reports no static shapes
    Primitive volume;    ///< what `geom` was made as
    std::unique_ptr<Convex> convex;  ///< a cone's polyhedron, which `geom` reads; null for the others
    /// A ray: a RangeFinder, or a Region of shape ray.
    [[nodiscard]] bool ray() const { return volume.form == Primitive::Form::Ray; }
  };
  /// A Mesh node's geometry as ODE reads it (ODE keeps pointers into these arrays).
  struct MeshGeometry {
    std::vector<double> points;        ///< scaled vertices, x y z, m
    std::vector<dTriIndex> indices;    ///< three per triangle
    core::Aabb box;                    ///< around the points
    std::vector<double> planes;        ///< convex hull: a b c d per face
    std::vector<double> hull_points;   ///< its vertices
    std::vector<unsigned> polygons;    ///< 3 i j k per face
  };
  /// What each sensor felt in one sensing pass.
  struct Felt {
    std::vector<const scene::Node*> items;
    double distance;
    const scene::Node* hit;
  };

  scene::Scene& scene;
  dWorldID world = nullptr;
  dSpaceID space = nullptr;  // holds every geometry; never collided (see the broad phase below)
  dJointGroupID contacts = nullptr;
  bool record_contacts = false;          ///< keep the contact points of each sub-step (World::recordContacts)
  std::vector<World::Contact> touching;  ///< those of the last sub-step, while recording
  bool watching_contacts = false;        ///< some body is watched (World::watchContacts)
  std::vector<Body*> watched_bodies;     ///< those bodies (in `bodies`, whose addresses stay)
  std::deque<dJointFeedback> contact_feedback;  ///< this sub-step's, for watched contacts (stable addresses)
  std::vector<WatchedContact> watched_contacts;  ///< this sub-step's
  bool watching_joints = false;          ///< some joint is watched (World::watchJoint)
  int substeps = 1;
  std::deque<Body> bodies;  // stable addresses; a removed body keeps its place with id null
  std::unordered_map<scene::NodeHandle, std::size_t> body_of;  // Body node -> index
  std::vector<Joint> joints;
  std::unordered_map<scene::NodeHandle, std::size_t> joint_of;
  std::vector<Surface> surfaces;  // per geometry, by dGeomGetData index
  std::unordered_map<scene::NodeHandle, dGeomID> geom_of;  // shape node -> its geometry
  std::vector<Sensor> sensors;
  std::vector<Felt> felt;  // by sensor, in sense()
  std::deque<std::vector<double>> heightfields;     // the heights ODE reads (it keeps pointers)
  std::vector<dHeightfieldDataID> heightfield_data;
  std::unordered_map<scene::NodeHandle, MeshGeometry> meshes;
  std::vector<dTriMeshDataID> trimesh_data;
  // geometry data: surfaces are 1..n; a sensor's data has this bit set over its index
  static constexpr std::uintptr_t kSensorTag = std::uintptr_t{1} << 62;
  std::string model_dir;
  std::map<std::pair<dBodyID, dBodyID>, dJointID> attached;
  std::string fault;  // why the physics stopped (World::fault); empty while all is well

  // the broad phase: shapes on bodies are swept against each other and looked up in a tree
  // of the shapes without one, which never move; planes and other endless shapes meet
  // everything
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
  ~Impl();

  // subtree.cpp: building and removing
  /// The Material in effect at `node`: the last one among the earlier siblings of it or of
  /// any of its ancestors, nearest first; null when none.
  /// Builds everything in the subtree at `top`: bodies first (joints need both ends), then
  /// one geometry per shape with the material in effect, and the sensors, then the joints.
  bool addSubtree(scene::Node& top, core::Diagnostics& diags);
  /// Takes the bodies, geometries, sensors and joints of the subtree at `top` out.
  void removeSubtree(const scene::Node& top);
  /// The subtree at `top` was moved (a Transform's placement assigned): its world poses made
  /// again, and the geometries of its shapes that no body carries moved with them.
  void moveSubtree(scene::Node& top);

  // bodies.cpp
  /// The Body that owns `node` (itself, or the nearest Body above it), or null.
  Body* owner(const scene::Node& node);
  const Body* owner(const scene::Node& node) const { return const_cast<Impl*>(this)->owner(node); }
  /// An ODE body for every Body node in the subtree at `node`, each with its mass. False,
  /// with diagnostics, when a body weighs nothing.
  bool buildBodies(scene::Node& node, core::Diagnostics& diags);
  /// A body's mass from its own shapes (not those of bodies below it), its centre of mass at
  /// the ODE body's origin; its placement and damping. False, with a diagnostic at its `mass`
  /// (or `density`, or the node), when its mass is 0 and its shapes weigh nothing.
  bool finishBody(Body& body, core::Diagnostics& diags);

  // geometry.cpp
  /// The geometry of Mesh node `n` (its file read from `dir`, its part chosen, scaled), made
  /// once; null, with diagnostics, when the file cannot be read.
  const MeshGeometry* meshOf(scene::Node& n, const std::string& dir, core::Diagnostics& diags);
  /// The heightfield of Terrain node `n`, placed; null, with diagnostics, when its file
  /// cannot be read.
  dGeomID terrainGeom(scene::Node& n, const std::string& dir, core::Diagnostics& diags);
  /// The geometry of shape `n` (nothing for other nodes, or shapes of no size), on its body
  /// or fixed, with its surface. False, with diagnostics, when it cannot be made.
  bool addGeom(scene::Node& n, const scene::TraversalState& st, const std::string& dir, core::Diagnostics& diags);

  // joints.cpp
  /// The joint of Joint node `n` between `parent_body` (null: the world) and the first Body
  /// below it. False, with diagnostics, when there is no such Body.
  bool addJoint(scene::Node& n, Body* parent_body, core::Diagnostics& diags);
  /// A joint of `kind` between `child` and `parent` (null: the world), placed where node `n`
  /// is now: its anchor, axes and limits.
  dJointID makeJoint(const scene::Node& n, scene::JointKind kind, dBodyID child, dBodyID parent);
  /// Where joint `j` stands on `axis` (1 or 2): radians, or metres for a slider.
  static double position(const Joint& j, int axis);
  /// Sets every joint's motors from its node's fields (a script may have set them).
  void driveMotors();
  /// Why joint node `n` cannot be a joint of `kind` (ODE would normalise a zero vector): a
  /// zero axis1 (every kind with an axis), a zero axis2 or one parallel to axis1 (universal,
  /// hinge2); located at the field. Nullopt when it can.
  static std::optional<core::Diagnostic> axesProblem(const scene::Node& n, scene::JointKind kind);
  /// Reads a Joint node's kind and control again (World::fieldChanged); why it cannot take
  /// the new kind (the joint then stays as it was), or empty.
  std::string refreshJoint(const scene::Node& n);

  // contacts.cpp
  /// What shape `n`, on `body` (null: static), brings to contacts: the material in effect in
  /// `st`, a conveyor among its siblings.
  Surface surfaceFor(const scene::Node& n, const scene::TraversalState& st, const Body* body) const;
  /// A Conveyor's belt direction, unit, in the frame of `body` (the world's when null).
  static core::Vec3 conveyorDirection(const scene::Node& conveyor, const Body* body);
  /// A Conveyor's frame in the frame of `body` (the world's when null).
  static core::Pose conveyorFrame(const scene::Node& conveyor, const Body* body);
  /// Reads again what the surfaces take from Material or Conveyor `n` (World::fieldChanged).
  void refreshSurfaces(const scene::Node& n);
  /// The surface of geometry `g` (the default one for a sensor or an unknown geometry).
  static Surface surfaceOf(dGeomID g, const Impl& self);
  /// True when `belt` is a running belt and wakes `other`, a sleeping body lying on it (a
  /// script may have just started the belt).
  bool beltWakes(dGeomID belt, dBodyID other) const;
  /// The contact joints between two shapes that may touch (`data`: the Impl).
  static void nearCallback(void* data, dGeomID o1, dGeomID o2);
  /// Asks ODE for the forces of contact joint `c` (at `g`, between `o1` and `o2`) where a
  /// watched body is on either side.
  void watchContact(dJointID c, const dContactGeom& g, dGeomID o1, dGeomID o2);
  /// Adds what the watched contacts and joints of the sub-step just taken bore to their sums.
  void gatherForces();

  // broad_phase.cpp
  /// Sorts the shapes into moving, fixed and endless, and rebuilds the fixed shapes' tree,
  /// when shapes have come or gone since the last time.
  void refreshShapes();
  /// The moving shapes' boxes where their bodies are now.
  void refreshMoving();
  /// Contacts for every pair of shapes whose boxes overlap, at least one of them moving.
  void collide();

  // sensing.cpp
  /// The geometry of Region or RangeFinder `n` (nothing for other nodes).
  void addSensor(scene::Node& n);
  /// Each sensor geometry's data: the tag and its index in `sensors`.
  void retagSensors();
  /// True when `shape` is in the scope of `sensor`.
  static bool inScope(const Sensor& sensor, const scene::Node& shape);
  /// The node an overlap reports: the body a shape belongs to, or the static shape itself.
  const scene::Node* reported(const scene::Node& shape) const;
  /// Sensor `index` and shape `other`, whose boxes overlap: what the sensor feels of it.
  void feel(std::size_t index, dGeomID other);
  /// Places each sensor where its node is, then meets it with the shapes its box overlaps.
  void sense(std::vector<std::pair<scene::NodeHandle, Feel>>& out);
  /// Reads a sensor node's scope and volume again (World::fieldChanged).
  void refreshSensor(const scene::Node& n);

  // world.cpp: stepping
  /// Advances `dt` seconds: motors, then per sub-step forces, contacts and ODE's step.
  void step(double dt);
  /// Moving bodies tell the scene where they are; sleeping ones have not moved.
  void writeBack();
  /// False, with `fault` set, when a body's position, rotation or velocity is no longer
  /// finite or beyond kMaxDistance or kMaxSpeed.
  bool bodiesSane();
};

}  // namespace gdpn::physics
