// The built-in node types, each described once. Units: metres, kilograms, seconds, degrees
// for angles in files (the physics converts). World frame: right-handed, Z up.

#include "gdpn/scene/fields.h"
#include "gdpn/scene/types.h"

namespace gdpn::scene {
namespace {

using V3 = std::array<double, 3>;
using V4 = std::array<double, 4>;

/// A number's bounds unless its field says otherwise (a script setting a motor's speed to
/// 1e300 is refused at the assignment, naming the field, rather than ending the run a step
/// later with a body run away).
constexpr double kHuge = kPlantLimit;

/// The description of field `id`: its id binds the description to the enum in fields.h.
template <FieldId F>
FieldDesc f(F id, std::string name, FieldKind kind, FieldValue initial, std::string unit, std::string doc,
            double min = -kHuge, double max = kHuge) {
  FieldDesc d;
  d.owner = field::ownerOf(id);
  d.index = static_cast<std::uint8_t>(id);
  d.name = std::move(name);
  d.kind = kind;
  d.initial = std::move(initial);
  d.unit = std::move(unit);
  d.doc = std::move(doc);
  d.min = min;
  d.max = max;
  return d;
}

/// An Enum field: its words in the order of the matching enum in fields.h.
template <FieldId F>
FieldDesc choice(F id, std::string name, std::vector<std::string> choices, std::string doc) {
  FieldDesc d;
  d.owner = field::ownerOf(id);
  d.index = static_cast<std::uint8_t>(id);
  d.name = std::move(name);
  d.kind = FieldKind::Enum;
  d.initial = choices.front();
  d.choices = std::move(choices);
  d.doc = std::move(doc);
  return d;
}

NodeType type(NodeKind kind, std::string name, Category category, bool children, std::string doc,
              std::vector<FieldDesc> own) {
  NodeType t;
  t.kind = kind;
  t.name = std::move(name);
  t.category = category;
  t.has_children = children;
  t.doc = std::move(doc);
  t.own = std::move(own);
  return t;
}

constexpr double kInf = 1e300;

/// `d` for a length or another amount that must be above 0 (0 itself refused: a Cube of size 0
/// on one axis, a sphere of radius 0).
FieldDesc positive(FieldDesc d) {
  d.min = 0;
  d.min_open = true;
  return d;
}

/// `d`, a field of a Joint's axis 1, in `unit` (a hinge's: deg, deg/s, N m), and in
/// `slider_unit` in a slider (m, m/s, N): its unit follows the joint's `kind`.
FieldDesc axis1(FieldDesc d, std::string slider_unit) {
  d.unit_follows = "kind";
  d.units_by_choice = {{"slider", std::move(slider_unit)}};
  return d;
}

/// The noise a sensor may add to each number it reads (ids `noise`, then bias and resolution
/// after it, in `unit`), drawn from its own stream of the model's generator.
template <FieldId F>
std::vector<FieldDesc> noise(F id, const std::string& unit) {
  const auto next = [&](int k) { return static_cast<F>(static_cast<int>(id) + k); };
  return {f(id, "noise", FieldKind::Float, 0.0, unit, "standard deviation of the Gaussian noise added to each number read", 0, kInf),
          f(next(1), "bias", FieldKind::Float, 0.0, unit, "a constant added to each number read"),
          f(next(2), "resolution", FieldKind::Float, 0.0, unit, "each number read is rounded to a multiple of this (0: not rounded)", 0, kInf)};
}

/// The sample rate of a sensor of `id`.
template <FieldId F>
FieldDesc rate(F id, double initial) {
  return f(id, "rate", FieldKind::Float, initial, "Hz", "samples per second (0: one every step)", 0, 1e6);
}

/// `a` with the fields of `b` after it.
std::vector<FieldDesc> with(std::vector<FieldDesc> a, const std::vector<FieldDesc>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

void registerBuiltinNodes(TypeRegistry& r) {
  using K = FieldKind;
  // structure
  r.add(type(NodeKind::Group, "Group", Category::Group, true, "holds child nodes", {}));
  r.add(type(NodeKind::Transform, "Transform", Category::Group, true, "places its children: scale, then rotate, then translate",
             {f(field::Transform::Translation, "translation", K::Vec3, V3{0, 0, 0}, "m", "offset from the parent"),
              f(field::Transform::Rotation, "rotation", K::Rotation, V4{0, 0, 1, 0}, "axis, deg", "axis and angle of rotation"),
              positive(f(field::Transform::Scale, "scale", K::Vec3, V3{1, 1, 1}, "", "scale factors along x, y, z"))}),
        "Group");
  // looks
  r.add(type(NodeKind::Material, "Material", Category::Look, false, "how the shapes after it look, and how they touch",
             {f(field::Material::Ambient, "ambient", K::Color, V3{0.2, 0.2, 0.2}, "", "ambient reflectance", 0, 1),
              f(field::Material::Diffuse, "diffuse", K::Color, V3{0.8, 0.8, 0.8}, "", "diffuse colour", 0, 1),
              f(field::Material::Specular, "specular", K::Color, V3{0, 0, 0}, "", "specular colour", 0, 1),
              f(field::Material::Emissive, "emissive", K::Color, V3{0, 0, 0}, "", "emitted colour", 0, 1),
              f(field::Material::Shininess, "shininess", K::Float, 0.2, "", "0 dull to 1 mirror-like", 0, 1),
              f(field::Material::Transparency, "transparency", K::Float, 0.0, "", "0 opaque to 1 invisible", 0, 1),
              f(field::Material::Friction, "friction", K::Float, 0.8, "", "Coulomb friction coefficient", 0, kInf),
              f(field::Material::Bounce, "bounce", K::Float, 0.0, "", "restitution: 0 no bounce to 1 elastic", 0, 1)}));
  r.add(type(NodeKind::Light, "Light", Category::Look, false, "a light, placed by its parents",
             {choice(field::Light::Kind, "kind", {"directional", "point", "spot"}, "what sort of light"),
              f(field::Light::Color, "color", K::Color, V3{1, 1, 1}, "", "colour", 0, 1),
              f(field::Light::Intensity, "intensity", K::Float, 1.0, "", "brightness factor", 0, kInf),
              f(field::Light::Direction, "direction", K::Vec3, V3{-1, -1, -2}, "", "where it shines (directional, spot)"),
              f(field::Light::Location, "location", K::Vec3, V3{0, 0, 5}, "m", "where it is (point, spot)"),
              f(field::Light::Cutoff, "cutoff", K::Float, 30.0, "deg", "half-angle of a spot's cone", 0, 90)}));
  r.add(type(NodeKind::Camera, "Camera", Category::Look, false, "a viewpoint",
             {choice(field::Camera::Kind, "kind", {"static", "orbit"}, "static, or orbiting its target"),
              f(field::Camera::Position, "position", K::Vec3, V3{5, -5, 4}, "m", "eye position"),
              f(field::Camera::Target, "target", K::Vec3, V3{0, 0, 0}, "m", "the point looked at"),
              f(field::Camera::Up, "up", K::Vec3, V3{0, 0, 1}, "", "which way is up"),
              f(field::Camera::Fov, "fov", K::Float, 45.0, "deg", "vertical field of view", 1, 179),
              f(field::Camera::Speed, "speed", K::Float, 10.0, "deg/s", "how fast an orbit camera turns about its target")}));
  r.add(type(NodeKind::Fog, "Fog", Category::Look, false, "fog over the whole scene",
             {choice(field::Fog::Kind, "kind", {"linear", "exponential"}, "how it thickens"),
              f(field::Fog::Color, "color", K::Color, V3{0.7, 0.7, 0.7}, "", "colour", 0, 1),
              positive(f(field::Fog::Visibility, "visibility", K::Float, 50.0, "m", "distance at which things vanish"))}));
  // shapes: the geometry of what they stand in; under a Body they are part of it
  r.add(type(NodeKind::Cube, "Cube", Category::Shape, false, "a box centred on its origin",
             {positive(f(field::Cube::Size, "size", K::Vec3, V3{1, 1, 1}, "m", "edge lengths along x, y, z"))}));
  r.add(type(NodeKind::Sphere, "Sphere", Category::Shape, false, "a sphere centred on its origin",
             {positive(f(field::Sphere::Radius, "radius", K::Float, 0.5, "m", "radius"))}));
  r.add(type(NodeKind::Cylinder, "Cylinder", Category::Shape, false, "a cylinder along z, centred on its origin",
             {positive(f(field::Cylinder::Radius, "radius", K::Float, 0.5, "m", "radius")),
              positive(f(field::Cylinder::Height, "height", K::Float, 1.0, "m", "height"))}));
  r.add(type(NodeKind::Cone, "Cone", Category::Shape, false, "a cone along z, base at -height/2, tip at +height/2",
             {positive(f(field::Cone::Radius, "radius", K::Float, 0.5, "m", "base radius")),
              positive(f(field::Cone::Height, "height", K::Float, 1.0, "m", "height"))}));
  r.add(type(NodeKind::Plane, "Plane", Category::Shape, false, "an endless flat ground through its origin",
             {f(field::Plane::Normal, "normal", K::Vec3, V3{0, 0, 1}, "", "which way the plane faces")}));
  r.add(type(NodeKind::Mesh, "Mesh", Category::Shape, false, "triangles from a file",
             {f(field::Mesh::File, "file", K::File, std::string(), "", "mesh file (obj, stl, 3ds, gltf, dae, ply, wrl, iv)"),
              f(field::Mesh::Part, "part", K::Int, std::int64_t{-1}, "", "which part of the file (-1: all of them)", -1, 1e9),
              positive(f(field::Mesh::Scale, "scale", K::Vec3, V3{1, 1, 1}, "", "scale factors")),
              choice(field::Mesh::Collision, "collision", {"trimesh", "box", "convex"}, "what the physics collides with: the triangles, "
                     "their bounding box, or their convex hull")}));
  r.add(type(NodeKind::Terrain, "Terrain", Category::Shape, false,
             "ground from an elevation file (GeoTIFF or another DEM, or a greyscale image), centred on its origin",
             {f(field::Terrain::File, "file", K::File, std::string(), "", "elevation file, read through GDAL"),
              positive(f(field::Terrain::Width, "width", K::Float, 100.0, "m", "extent along x")),
              positive(f(field::Terrain::Depth, "depth", K::Float, 100.0, "m", "extent along y")),
              f(field::Terrain::HeightScale, "height_scale", K::Float, 1.0, "m", "metres per unit of the file's values")}));
  // dynamics
  r.add(type(NodeKind::World, "World", Category::Dynamics, false, "settings of the rigid-body physics",
             {f(field::World::Gravity, "gravity", K::Vec3, V3{0, 0, -9.81}, "m/s^2", "gravity"),
              f(field::World::Erp, "erp", K::Float, 0.2, "", "error reduction per step", 0, 1),
              f(field::World::Cfm, "cfm", K::Float, 1e-5, "", "constraint force mixing", 0, 1),
              f(field::World::Substeps, "substeps", K::Int, std::int64_t{1}, "", "physics steps per net step", 1, 1000),
              f(field::World::Iterations, "iterations", K::Int, std::int64_t{40}, "", "solver iterations per physics step: fewer is faster and softer", 1, 1000),
              f(field::World::AutoDisable, "auto_disable", K::Bool, true, "", "let bodies at rest sleep")}));
  r.add(type(NodeKind::Body, "Body", Category::Dynamics, true, "a rigid body made of the shapes below it",
             {f(field::Body::Mass, "mass", K::Float, 0.0, "kg", "total mass; 0 means: from density and shapes", 0, kInf),
              f(field::Body::Density, "density", K::Float, 1000.0, "kg/m^3", "density, used when mass is 0", 0, kInf),
              f(field::Body::LinearDamping, "linear_damping", K::Float, 0.0, "", "share of linear velocity lost per second", 0, 1),
              f(field::Body::AngularDamping, "angular_damping", K::Float, 0.0, "", "share of angular velocity lost per second", 0, 1)}));
  r.add(type(NodeKind::Joint, "Joint", Category::Dynamics, true, "joins its parent body to its child body (or a body to the world)",
             {choice(field::Joint::Kind, "kind", {"hinge", "slider", "ball", "universal", "hinge2", "fixed"}, "what motion it allows"),
              f(field::Joint::Anchor, "anchor", K::Vec3, V3{0, 0, 0}, "m", "the joint's point, in the joint's frame"),
              f(field::Joint::Axis1, "axis1", K::Vec3, V3{0, 0, 1}, "", "first axis"),
              f(field::Joint::Axis2, "axis2", K::Vec3, V3{1, 0, 0}, "", "second axis (universal, hinge2)"),
              axis1(f(field::Joint::Lo1, "lo1", K::Float, -kInf, "deg", "lower limit on axis 1", -kInf, kInf), "m"),
              axis1(f(field::Joint::Hi1, "hi1", K::Float, kInf, "deg", "upper limit on axis 1", -kInf, kInf), "m"),
              f(field::Joint::Lo2, "lo2", K::Float, -kInf, "deg", "lower limit on axis 2", -kInf, kInf),
              f(field::Joint::Hi2, "hi2", K::Float, kInf, "deg", "upper limit on axis 2", -kInf, kInf),
              axis1(f(field::Joint::Vel1, "vel1", K::Float, 0.0, "deg/s", "motor target velocity on axis 1"), "m/s"),
              axis1(f(field::Joint::Fmax1, "fmax1", K::Float, 0.0, "N m", "motor's greatest force on axis 1 (0: no motor)", 0, kHuge), "N"),
              f(field::Joint::Vel2, "vel2", K::Float, 0.0, "deg/s", "motor target velocity on axis 2"),
              f(field::Joint::Fmax2, "fmax2", K::Float, 0.0, "N m", "motor's greatest force on axis 2", 0, kHuge),
              choice(field::Joint::Control, "control", {"velocity", "position"},
                     "what the motor on axis 1 follows: vel1, or target1 (at most |vel1| fast when vel1 is not 0)"),
              axis1(f(field::Joint::Target1, "target1", K::Float, 0.0, "deg", "position the motor drives axis 1 to, in position control"), "m"),
              f(field::Joint::ServoTime, "servo_time", K::Float, 0.1, "s",
                "position control: the motor's speed is the error over this time, so an error shrinks by e in it", 1e-3,
                kInf)}));
  r.add(type(NodeKind::Conveyor, "Conveyor", Category::Dynamics, false, "makes the shapes beside it move what touches them",
             {f(field::Conveyor::Speed, "speed", K::Float, 1.0, "m/s", "belt speed"),
              f(field::Conveyor::Direction, "direction", K::Vec3, V3{1, 0, 0}, "", "belt direction, in the conveyor's frame"),
              f(field::Conveyor::Radius, "radius", K::Float, 0.0, "m",
                "0: a straight belt; else a curved one: it moves along `direction` at the conveyor's origin and "
                "turns about an axis parallel to the conveyor's z this far to the left (negative: to the right)")}));
  r.add(type(NodeKind::GradientField, "GradientField", Category::Field, false,
             "a 2D grid of vectors over a region of the ground, centred on its origin",
             {positive(f(field::GradientField::Width, "width", K::Float, 10.0, "m", "extent along x")),
              positive(f(field::GradientField::Depth, "depth", K::Float, 10.0, "m", "extent along y")),
              f(field::GradientField::Nx, "nx", K::Int, std::int64_t{2}, "", "grid points along x", 2, 1e6),
              f(field::GradientField::Ny, "ny", K::Int, std::int64_t{2}, "", "grid points along y", 2, 1e6),
              f(field::GradientField::Vectors, "vectors", K::FloatList, std::vector<double>(8, 0.0), "",
                "nx * ny vectors (x, y), row by row from -y to +y, each row from -x to +x")}));
  // sensors: they feel the plant and make no contact forces
  r.add(type(NodeKind::Region, "Region", Category::Sensor, false, "reports the bodies and shapes inside its volume",
             {choice(field::Region::Shape, "shape", {"box", "sphere", "cylinder", "cone", "ray"}, "the volume's shape"),
              positive(f(field::Region::Size, "size", K::Vec3, V3{1, 1, 1}, "m", "edge lengths of a box")),
              positive(f(field::Region::Radius, "radius", K::Float, 0.5, "m", "radius of a sphere, cylinder or cone")),
              positive(f(field::Region::Height, "height", K::Float, 1.0, "m", "height of a cylinder or cone (along z)")),
              positive(f(field::Region::Length, "length", K::Float, 1.0, "m", "length of a ray (along +x)")),
              choice(field::Region::Scope, "scope", {"world", "siblings", "parent"},
                     "what it feels: its siblings and their subtrees, its parent's subtree, or everything"),
              choice(field::Region::Report, "report", {"all", "bodies"},
                     "what it reports: bodies and static shapes, or bodies only"),
              f(field::Region::Visible, "visible", K::Bool, false, "",
                "drawn always, not only with the sensor volumes: a ray as a red beam, a volume translucent red; "
                "green while it holds something")}));
  r.add(type(NodeKind::RangeFinder, "RangeFinder", Category::Sensor, false, "the distance along a ray (+x) to the first thing it hits",
             with({positive(f(field::RangeFinder::Length, "length", K::Float, 10.0, "m", "how far it sees")),
                   choice(field::RangeFinder::Scope, "scope", {"world", "siblings", "parent"}, "what it sees")},
                  noise(field::RangeFinder::Noise, "m"))));
  r.add(type(NodeKind::GradientSensor, "GradientSensor", Category::Sensor, false,
             "the gradient field's vector where its parent body is (bilinear)",
             {f(field::GradientSensor::Field, "field", K::String, std::string(), "", "the GradientField's path (empty: the scene's first one)")}));
  r.add(type(NodeKind::KeyboardSensor, "KeyboardSensor", Category::Sensor, false,
             "key presses, while the viewpoint is inside its parent's bounding box", {}));
  r.add(type(NodeKind::MouseSensor, "MouseSensor", Category::Sensor, false, "clicks (ray picks) on its parent's subtree", {}));
  r.add(type(NodeKind::TimeSensor, "TimeSensor", Category::Sensor, false, "ticks at a period",
             {positive(f(field::TimeSensor::Period, "period", K::Float, 1.0, "s", "time between ticks")),
              f(field::TimeSensor::Offset, "offset", K::Float, 0.0, "s", "time of the first tick", 0, kInf)}));
  // sensors of issue 23: each samples at its rate and may add noise
  using CC = field::ColorCamera;
  r.add(type(NodeKind::ColorCamera, "ColorCamera", Category::Sensor, false,
             "an RGB image looking along +x (up: +z), rendered only when a script reads it",
             with({f(CC::Width, "width", K::Int, std::int64_t{320}, "px", "image width", 1, 8192),
                   f(CC::Height, "height", K::Int, std::int64_t{240}, "px", "image height", 1, 8192),
                   f(CC::Fov, "fov", K::Float, 60.0, "deg", "horizontal field of view", 1, 179),
                   f(CC::Near, "near", K::Float, 0.05, "m", "nearest distance seen", 1e-6, kInf),
                   f(CC::Far, "far", K::Float, 100.0, "m", "farthest distance seen", 1e-6, kInf), rate(CC::Rate, 30.0)},
                  noise(CC::Noise, "level or m"))));
  r.add(type(NodeKind::DepthCamera, "DepthCamera", Category::Sensor, false,
             "distances along +x (metres per pixel, `far` where nothing is), rendered only when a script reads them", {}),
        "ColorCamera");
  using LS = field::LaserScan;
  r.add(type(NodeKind::LaserScan, "LaserScan", Category::Sensor, false,
             "distances along a fan of rays in its xy-plane, from +x towards +y",
             with({f(LS::Count, "count", K::Int, std::int64_t{360}, "", "rays", 1, 1e6),
                   f(LS::MinAngle, "min_angle", K::Float, -180.0, "deg", "angle of the first ray from +x", -360, 360),
                   f(LS::MaxAngle, "max_angle", K::Float, 180.0, "deg", "angle of the last ray (a whole turn: the first again, not repeated)", -360, 360),
                   positive(f(LS::Length, "length", K::Float, 10.0, "m", "how far each ray sees")),
                   choice(LS::Scope, "scope", {"world", "siblings", "parent"}, "what it sees"), rate(LS::Rate, 10.0)},
                  noise(LS::Noise, "m"))));
  r.add(type(NodeKind::Imu, "Imu", Category::Sensor, false,
             "acceleration (gravity's reaction included) and angular velocity of the point where it is on its body, in its frame",
             with({rate(field::Imu::Rate, 100.0)}, noise(field::Imu::Noise, "m/s^2, deg/s"))));
  r.add(type(NodeKind::Gps, "Gps", Category::Sensor, false, "the position of its node",
             with({choice(field::Gps::Frame, "frame", {"world", "geodetic"},
                          "metres in the world, or latitude, longitude (deg) and altitude (m) over a georeferenced Terrain"),
                   f(field::Gps::Terrain, "terrain", K::String, std::string(), "", "geodetic: the Terrain's path (empty: the scene's first)"),
                   rate(field::Gps::Rate, 10.0)},
                  noise(field::Gps::Noise, "m"))));
  r.add(type(NodeKind::Contact, "Contact", Category::Sensor, false, "the bodies and shapes touching its body, and the normal force of each",
             with({rate(field::Contact::Rate, 0.0)}, noise(field::Contact::Noise, "N"))));
  r.add(type(NodeKind::ForceTorque, "ForceTorque", Category::Sensor, false,
             "the force and torque its parent Joint applies to the body below it, at its origin and in its frame",
             with({rate(field::ForceTorque::Rate, 0.0)}, noise(field::ForceTorque::Noise, "N, N m"))));
}

}  // namespace gdpn::scene
