#include "gdpn/scene/sensor_rules.h"

#include "gdpn/core/text.h"

namespace gdpn::scene {

namespace {

/// Field `id` of `n` as a number, or `v` where `id` is field `i`.
template <FieldId F>
double numberWith(const Node& n, F id, std::size_t i, const FieldValue& v) {
  if (n.slot(id) != i) return n.number(id);
  if (const auto* whole = std::get_if<std::int64_t>(&v)) return static_cast<double>(*whole);
  const auto* x = std::get_if<double>(&v);
  return x ? *x : n.number(id);
}

}  // namespace

SensorRule sensorRule(const Node& n, std::size_t i, const FieldValue& v) {
  switch (n.kind()) {
    case NodeKind::ColorCamera:
    case NodeKind::DepthCamera: {
      using F = field::ColorCamera;
      const double near = numberWith(n, F::Near, i, v), far = numberWith(n, F::Far, i, v);
      if (far <= near) {
        return {"far (" + core::formatDouble(far) + " m) must lie beyond near (" + core::formatDouble(near) + " m)",
                n.slot(F::Far)};
      }
      if (far > kMaxDepthRange * near) {
        return {"far (" + core::formatDouble(far) + " m) is more than 100,000 times near (" + core::formatDouble(near) +
                    " m), which leaves the depth buffer too few steps to tell distances apart: raise near",
                n.slot(F::Near)};
      }
      return {};
    }
    case NodeKind::LaserScan: {
      using F = field::LaserScan;
      const double count = numberWith(n, F::Count, i, v);
      if (count > 1 && numberWith(n, F::MinAngle, i, v) == numberWith(n, F::MaxAngle, i, v)) {
        return {"has " + core::formatDouble(count) + " rays but no angle between min_angle and max_angle",
                n.slot(F::MaxAngle)};
      }
      return {};
    }
    // no rules between their fields
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
    case NodeKind::Region:
    case NodeKind::RangeFinder:
    case NodeKind::GradientSensor:
    case NodeKind::KeyboardSensor:
    case NodeKind::MouseSensor:
    case NodeKind::TimeSensor:
    case NodeKind::Imu:
    case NodeKind::Gps:
    case NodeKind::Contact:
    case NodeKind::ForceTorque: return {};
  }
  return {};
}

}  // namespace gdpn::scene
