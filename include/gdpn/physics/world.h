#pragma once
/// \file
/// Rigid-body physics for a scene, through ODE (whose types never leave src/physics).
/// The tree decides the dynamics: a shape under a Body is part of that body; any other shape
/// is static; a Joint joins the Body above it to the Body below it, or that Body to the world.
/// Materials give contacts their friction and bounce; a Conveyor makes its sibling shapes
/// move what touches them (a contact surface velocity, not a force field).

#include <memory>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/core/math.h"
#include "gdpn/scene/node.h"

namespace gdpn::physics {

/// The farthest a body may be from the origin, m, and the fastest it may move, m/s (or turn,
/// rad/s); a body beyond either, or one whose placement or velocity is no longer finite, is a
/// physics fault (World::fault).
inline constexpr double kMaxDistance = 1e12;
inline constexpr double kMaxSpeed = 1e12;
/// The largest force (N) or torque (N m) a script may apply, each component.
inline constexpr double kMaxForce = 1e18;

/// The physics of one scene. It reads joint motor fields (vel1, fmax1, ...) and conveyor
/// speeds every step, so a script that sets them drives the joint or the belt; what else it
/// keeps of a node it reads again when told through fieldChanged(). It writes each moving
/// body's placement back into the scene (Node::dynamic_pose, Node::world).
class World {
 public:
  /// Builds bodies, geometry, joints, conveyors and contacts from `scene` (which must outlive
  /// the world). Problems (a joint with no body, a missing mesh file) go to `diags` at the
  /// node's location; then null. `seed` seeds ODE's own generator (constraint order).
  static std::unique_ptr<World> create(scene::Scene& scene, const std::string& model_dir, std::uint64_t seed,
                                       core::Diagnostics& diags);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Advances by `dt` seconds in the World node's sub-steps, then updates the scene. After a
  /// fault (see fault()) it does nothing: the scene keeps the last good placements.
  void step(double dt);

  /// Why the physics cannot go on, empty while all is well: a body whose position, rotation
  /// or velocity went non-finite or beyond kMaxDistance or kMaxSpeed in a sub-step (named by
  /// its path, with what went wrong), or an error ODE reported.
  [[nodiscard]] const std::string& fault() const;

  /// Tells the world that fields of `node` were assigned; the scripting layer calls it after
  /// every assignment of a field. Returns why the world cannot follow (a joint's new kind
  /// with a zero axis, or two parallel axes: the joint stays as it was), empty when it can.
  /// The world reads again what it keeps of that node:
  /// - a Joint's `kind` and `control` (a new kind makes the joint again between the same
  ///   bodies, where they are now: its positions count from there);
  /// - a Region's or RangeFinder's `scope`, and its volume (`shape`, `size`, `radius`,
  ///   `height`, `length`; a changed volume gets a new geometry);
  /// - a Transform's placement: the poses below it, and with them the sensors and the shapes
  ///   no body carries, follow (a script turning a knob); bodies keep the poses the physics
  ///   gives them;
  /// - a Conveyor's `direction` and `radius` (its `speed` is read at every contact anyway);
  /// - a Material's `friction` and `bounce`, for the shapes it colours.
  /// Motor fields (vel1, fmax1, vel2, fmax2, target1, servo_time) are read every step and need
  /// no call. Everything else holds as built: a body's mass and damping, a shape's size, a
  /// joint's anchor, axes and limits, the World settings. Nodes of other kinds, and nodes
  /// this world does not hold, are ignored.
  [[nodiscard]] std::string fieldChanged(const scene::Node& node);

  /// True when `node` is a Body this world moves.
  [[nodiscard]] bool isBody(const scene::Node& node) const;
  /// A body's linear velocity, m/s (world frame).
  [[nodiscard]] core::Vec3 velocity(const scene::Node& body) const;
  /// The velocity of the world point `at` (m) moving with the body `body` belongs to, m/s.
  [[nodiscard]] core::Vec3 pointVelocity(const scene::Node& body, core::Vec3 at) const;
  /// The mass of the body `body` belongs to, kg.
  [[nodiscard]] double mass(const scene::Node& body) const;
  /// A body's angular velocity, rad/s (world frame).
  [[nodiscard]] core::Vec3 angularVelocity(const scene::Node& body) const;
  /// Sets a body's linear velocity, m/s. The vectors given to this and the three below must
  /// be finite and within kMaxSpeed or kMaxForce (the scripting layer refuses others).
  void setVelocity(const scene::Node& body, core::Vec3 v);
  /// A force (N, world frame) applied at the centre of mass in every step until changed.
  void setForce(const scene::Node& body, core::Vec3 force);
  /// A force (N, world frame) applied in the next step only.
  void addForce(const scene::Node& body, core::Vec3 force);
  /// A torque (N m, world frame) applied in every step until changed.
  void setTorque(const scene::Node& body, core::Vec3 torque);
  /// True while the body is awake (auto-disable puts resting bodies to sleep).
  [[nodiscard]] bool awake(const scene::Node& body) const;
  /// Wakes a body.
  void wake(const scene::Node& body);

  /// A joint's position on axis 1 or 2: radians (hinge, universal, hinge2) or metres (slider).
  [[nodiscard]] double jointPosition(const scene::Node& joint, int axis = 1) const;
  /// Its rate on axis 1 or 2: rad/s or m/s.
  [[nodiscard]] double jointRate(const scene::Node& joint, int axis = 1) const;

  /// Joins two bodies (or a body and the body of a node inside another) with a fixed joint
  /// made now, as they are. False when either is no body or they are already attached.
  bool attach(const scene::Node& a, const scene::Node& b);
  /// Breaks the fixed joint made by attach(). False when there is none.
  bool detach(const scene::Node& a, const scene::Node& b);

  /// Adds the bodies, shapes and joints of the subtree at `top`, a node just put into the
  /// scene (spawned). False, with diagnostics, when it cannot be built.
  bool add(scene::Node& top, core::Diagnostics& diags);
  /// Takes the bodies, shapes and joints of the subtree at `top` out of the physics; the
  /// scene nodes are the caller's to delete afterwards.
  void remove(const scene::Node& top);

  /// What a Region or RangeFinder feels, computed from the scene as it is now.
  struct Feel {
    std::vector<scene::NodeHandle> items;  ///< Region: the bodies (or static shapes) inside, by path
    double distance = 0;                   ///< RangeFinder: metres to the first hit (its length when none)
    scene::NodeHandle hit = 0;             ///< RangeFinder: the body or shape hit (0 when none)
  };
  /// Evaluates every Region and RangeFinder of the scene; `out` gets one entry per sensor node
  /// (by handle). Cost grows with the pairs that overlap, not with sensors times bodies.
  void sense(std::vector<std::pair<scene::NodeHandle, Feel>>& out);

  /// Distances along rays from `from` (world, m) in each direction of `dirs` (unit, world), as
  /// far as `length` m, seeing what `sensor`'s `scope` lets it see: `distance[i]` is the
  /// first hit's distance (`length` where nothing is hit), `hit[i]` the body or static shape
  /// hit (0: none). One query of the shapes near the fan, then a ray test per ray and shape.
  void castRays(const scene::Node& sensor, scene::Scope scope, core::Vec3 from, const std::vector<core::Vec3>& dirs,
                double length, std::vector<double>& distance, std::vector<scene::NodeHandle>& hit);

  /// What touches a watched body: the body (or static shape) on the other side and the sum,
  /// over the contact points, of the normal force it exerts there, N, averaged over the last
  /// step's sub-steps.
  struct Touch {
    scene::NodeHandle other = 0;  ///< the body or static shape touching
    double normal_force = 0;      ///< N
  };
  /// Keeps the contact forces on the body that `node` belongs to from now on (a Contact
  /// sensor's body); false when it belongs to no body of this world.
  bool watchContacts(const scene::Node& node);
  /// What touched the body of `node` in the last step (watched with watchContacts), in the
  /// order of the others' paths.
  [[nodiscard]] std::vector<Touch> touches(const scene::Node& node) const;
  /// Keeps the force and torque of Joint node `joint` from now on; false when it is no joint
  /// of this world.
  bool watchJoint(const scene::Node& joint);
  /// The force (N) and torque (N m, about the world point `at`) that watched joint `joint`
  /// applies to the body below it, world frame, averaged over the last step's sub-steps.
  void jointWrench(const scene::Node& joint, core::Vec3 at, core::Vec3& force, core::Vec3& torque) const;

  /// A point where two shapes touch.
  struct Contact {
    core::Vec3 position;  ///< world frame, m
    core::Vec3 normal;    ///< unit, world frame: the way the first shape is pushed
    double depth = 0;     ///< how far they overlap, m
  };
  /// Keeps the contact points of every sub-step from now on (`on`), or no longer. Off at
  /// first: a world nobody looks at pays nothing for them.
  void recordContacts(bool on);
  /// The contact points of the last sub-step while recording (empty otherwise).
  [[nodiscard]] const std::vector<Contact>& contacts() const;

  /// Number of bodies, and of those awake.
  [[nodiscard]] std::size_t bodyCount() const;
  [[nodiscard]] std::size_t awakeCount() const;

 private:
  struct Impl;
  explicit World(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// Assigns field `i` of `node` from outside the model file (a script, a Modbus write): the
/// value, written in `unit` where the field is an angle, is converted to the stored unit,
/// checked by the field's own rules (as the model file is), set, and told to `world` (null:
/// none). Returns "" or why not, the field then as it was: the field's rule (with a note when
/// the angle was given in radians), or what the world cannot follow.
std::string assignField(scene::Node& node, std::size_t i, scene::FieldValue value, scene::AngleUnit unit, World* world);

}  // namespace gdpn::physics
