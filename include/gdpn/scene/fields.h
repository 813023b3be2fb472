#pragma once
/// \file
/// Field ids of the built-in node types, and the words their Enum fields take, as C++ enums.
/// Each enum lists a node type's own fields in the order its description in
/// builtin_nodes.cpp declares them; registration checks the order, so an id always names the
/// field it says. Code reads fields through these ids (`node.number(field::Joint::Vel1)`),
/// never by name: a misspelt id does not compile, and a field read from a node of another
/// kind is caught by an assertion.

#include <concepts>
#include <cstdint>
#include <type_traits>

#include "gdpn/scene/kind.h"

namespace gdpn::scene {

namespace field {
/// Transform: placement of its children.
enum class Transform : std::uint8_t { Translation, Rotation, Scale };
/// Material: looks and contact properties.
enum class Material : std::uint8_t { Ambient, Diffuse, Specular, Emissive, Shininess, Transparency, Friction, Bounce };
/// Light.
enum class Light : std::uint8_t { Kind, Color, Intensity, Direction, Location, Cutoff };
/// Camera.
enum class Camera : std::uint8_t { Kind, Position, Target, Up, Fov, Speed };
/// Fog.
enum class Fog : std::uint8_t { Kind, Color, Visibility };
/// Cube.
enum class Cube : std::uint8_t { Size };
/// Sphere.
enum class Sphere : std::uint8_t { Radius };
/// Cylinder.
enum class Cylinder : std::uint8_t { Radius, Height };
/// Cone.
enum class Cone : std::uint8_t { Radius, Height };
/// Plane.
enum class Plane : std::uint8_t { Normal };
/// Mesh.
enum class Mesh : std::uint8_t { File, Part, Scale, Collision };
/// Terrain.
enum class Terrain : std::uint8_t { File, Width, Depth, HeightScale };
/// World: physics settings.
enum class World : std::uint8_t { Gravity, Erp, Cfm, Substeps, Iterations, AutoDisable };
/// Body.
enum class Body : std::uint8_t { Mass, Density, LinearDamping, AngularDamping };
/// Joint.
enum class Joint : std::uint8_t {
  Kind, Anchor, Axis1, Axis2, Lo1, Hi1, Lo2, Hi2, Vel1, Fmax1, Vel2, Fmax2, Control, Target1, ServoTime
};
/// Conveyor.
enum class Conveyor : std::uint8_t { Speed, Direction, Radius };
/// GradientField.
enum class GradientField : std::uint8_t { Width, Depth, Nx, Ny, Vectors };
/// Region.
enum class Region : std::uint8_t { Shape, Size, Radius, Height, Length, Scope, Report, Visible };
/// RangeFinder.
enum class RangeFinder : std::uint8_t { Length, Scope, Noise, Bias, Resolution };
/// GradientSensor.
enum class GradientSensor : std::uint8_t { Field };
/// TimeSensor.
enum class TimeSensor : std::uint8_t { Period, Offset };
/// ColorCamera (and DepthCamera, which adds nothing).
enum class ColorCamera : std::uint8_t { Width, Height, Fov, Near, Far, Rate, Noise, Bias, Resolution };
/// DepthCamera: a ColorCamera's fields only.
enum class DepthCamera : std::uint8_t {};
/// LaserScan.
enum class LaserScan : std::uint8_t { Count, MinAngle, MaxAngle, Length, Scope, Rate, Noise, Bias, Resolution };
/// Imu.
enum class Imu : std::uint8_t { Rate, Noise, Bias, Resolution };
/// Gps.
enum class Gps : std::uint8_t { Frame, Terrain, Rate, Noise, Bias, Resolution };
/// Contact.
enum class Contact : std::uint8_t { Rate, Noise, Bias, Resolution };
/// ForceTorque.
enum class ForceTorque : std::uint8_t { Rate, Noise, Bias, Resolution };

/// The node kind that declares each field enum (found by overload resolution).
constexpr NodeKind ownerOf(Transform) { return NodeKind::Transform; }
constexpr NodeKind ownerOf(Material) { return NodeKind::Material; }
constexpr NodeKind ownerOf(Light) { return NodeKind::Light; }
constexpr NodeKind ownerOf(Camera) { return NodeKind::Camera; }
constexpr NodeKind ownerOf(Fog) { return NodeKind::Fog; }
constexpr NodeKind ownerOf(Cube) { return NodeKind::Cube; }
constexpr NodeKind ownerOf(Sphere) { return NodeKind::Sphere; }
constexpr NodeKind ownerOf(Cylinder) { return NodeKind::Cylinder; }
constexpr NodeKind ownerOf(Cone) { return NodeKind::Cone; }
constexpr NodeKind ownerOf(Plane) { return NodeKind::Plane; }
constexpr NodeKind ownerOf(Mesh) { return NodeKind::Mesh; }
constexpr NodeKind ownerOf(Terrain) { return NodeKind::Terrain; }
constexpr NodeKind ownerOf(World) { return NodeKind::World; }
constexpr NodeKind ownerOf(Body) { return NodeKind::Body; }
constexpr NodeKind ownerOf(Joint) { return NodeKind::Joint; }
constexpr NodeKind ownerOf(Conveyor) { return NodeKind::Conveyor; }
constexpr NodeKind ownerOf(GradientField) { return NodeKind::GradientField; }
constexpr NodeKind ownerOf(Region) { return NodeKind::Region; }
constexpr NodeKind ownerOf(RangeFinder) { return NodeKind::RangeFinder; }
constexpr NodeKind ownerOf(GradientSensor) { return NodeKind::GradientSensor; }
constexpr NodeKind ownerOf(TimeSensor) { return NodeKind::TimeSensor; }
constexpr NodeKind ownerOf(ColorCamera) { return NodeKind::ColorCamera; }
constexpr NodeKind ownerOf(DepthCamera) { return NodeKind::DepthCamera; }
constexpr NodeKind ownerOf(LaserScan) { return NodeKind::LaserScan; }
constexpr NodeKind ownerOf(Imu) { return NodeKind::Imu; }
constexpr NodeKind ownerOf(Gps) { return NodeKind::Gps; }
constexpr NodeKind ownerOf(Contact) { return NodeKind::Contact; }
constexpr NodeKind ownerOf(ForceTorque) { return NodeKind::ForceTorque; }
}  // namespace field

/// A field id: any of the enums in `field`.
template <class F>
concept FieldId = std::is_enum_v<F> && requires(F f) {
  { field::ownerOf(f) } -> std::same_as<NodeKind>;
};

// The words of Enum fields, in the order their descriptions list them (a test checks each).

/// Joint `kind`.
enum class JointKind : std::uint8_t { Hinge, Slider, Ball, Universal, Hinge2, Fixed };
/// Joint `control`: what the motor on axis 1 follows.
enum class JointControl : std::uint8_t { Velocity, Position };
/// Region `shape`.
enum class RegionShape : std::uint8_t { Box, Sphere, Cylinder, Cone, Ray };
/// Region `report`: what it reports, bodies and static shapes or bodies only.
enum class RegionReport : std::uint8_t { All, Bodies };
/// Region and RangeFinder `scope`: what a sensor feels.
enum class Scope : std::uint8_t { World, Siblings, Parent };
/// Gps `frame`: metres in the world, or latitude, longitude and altitude.
enum class GpsFrame : std::uint8_t { World, Geodetic };
/// Light `kind`.
enum class LightKind : std::uint8_t { Directional, Point, Spot };
/// Camera `kind`.
enum class CameraKind : std::uint8_t { Static, Orbit };
/// Fog `kind`.
enum class FogKind : std::uint8_t { Linear, Exponential };
/// Mesh `collision`: what the physics collides with.
enum class MeshCollision : std::uint8_t { Trimesh, Box, Convex };

}  // namespace gdpn::scene
