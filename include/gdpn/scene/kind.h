#pragma once
/// \file
/// The kinds of scene node. Code that depends on a node's type switches on its kind, so that
/// adding a kind makes the compiler list every place to touch.

#include <cstddef>
#include <cstdint>

namespace gdpn::scene {

/// Each built-in node type, one value each (NodeType::kind).
enum class NodeKind : std::uint8_t {
  Group,           ///< holds child nodes
  Transform,       ///< places its children
  Material,        ///< looks and contact properties of the shapes after it
  Light,           ///< a light
  Camera,          ///< a viewpoint
  Fog,             ///< fog over the scene
  Cube,            ///< a box shape
  Sphere,          ///< a sphere shape
  Cylinder,        ///< a cylinder shape
  Cone,            ///< a cone shape
  Plane,           ///< endless flat ground
  Mesh,            ///< triangles from a file
  Terrain,         ///< ground from an elevation file
  World,           ///< physics settings
  Body,            ///< a rigid body
  Joint,           ///< joins two bodies
  Conveyor,        ///< moves what touches the shapes beside it
  GradientField,   ///< a 2D vector field over the ground
  Region,          ///< senses what is inside a volume
  RangeFinder,     ///< senses the distance along a ray
  GradientSensor,  ///< reads a gradient field where its body is
  KeyboardSensor,  ///< hears keys
  MouseSensor,     ///< feels clicks
  TimeSensor,      ///< ticks at a period
  ColorCamera,     ///< an RGB image, rendered when read
  DepthCamera,     ///< an image of distances, rendered when read
  LaserScan,       ///< distances along a fan of rays
  Imu,             ///< acceleration and angular velocity of its body
  Gps,             ///< the position of its node
  Contact,         ///< what touches its body, and how hard
  ForceTorque,     ///< the force and torque of its joint
};

/// The number of node kinds.
inline constexpr std::size_t kNodeKinds = static_cast<std::size_t>(NodeKind::ForceTorque) + 1;

}  // namespace gdpn::scene
