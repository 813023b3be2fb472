// The kinds of sensor: the one switch over node kinds that says which are sensors.

#include "gdpn/sensors/sensor_kind.h"

#include <array>

#include "detail/sensor.h"
#include "gdpn/scene/types.h"

namespace gdpn::sensors {

namespace detail {

const KindDef* kindDef(scene::NodeKind kind) {
  using scene::NodeKind;
  switch (kind) {
    case NodeKind::Region: return &kRegion;
    case NodeKind::RangeFinder: return &kRangeFinder;
    case NodeKind::GradientSensor: return &kGradientSensor;
    case NodeKind::KeyboardSensor: return &kKeyboardSensor;
    case NodeKind::MouseSensor: return &kMouseSensor;
    case NodeKind::TimeSensor: return &kTimeSensor;
    case NodeKind::ColorCamera: return &kColorCamera;
    case NodeKind::DepthCamera: return &kDepthCamera;
    case NodeKind::LaserScan: return &kLaserScan;
    case NodeKind::Imu: return &kImu;
    case NodeKind::Gps: return &kGps;
    case NodeKind::Contact: return &kContact;
    case NodeKind::ForceTorque: return &kForceTorque;
    // not sensors
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
    case NodeKind::GradientField: return nullptr;
  }
  return nullptr;
}

}  // namespace detail

const SensorKind* sensorKind(scene::NodeKind kind) {
  const detail::KindDef* def = detail::kindDef(kind);
  return def != nullptr ? &def->kind : nullptr;
}

std::span<const SensorKind* const> sensorKinds() {
  static const auto kinds = [] {
    std::vector<const SensorKind*> out;
    for (std::size_t k = 0; k < scene::kNodeKinds; ++k) {
      if (const auto* s = sensorKind(static_cast<scene::NodeKind>(k))) out.push_back(s);
    }
    return out;
  }();
  return kinds;
}

std::string channelsMarkdown() {
  const auto row = [](std::initializer_list<std::string> cells) {
    std::string out = "|";
    for (const auto& c : cells) out += c.empty() ? " |" : " " + c + " |";
    return out + "\n";
  };
  std::string out = row({"sensor", "channel", "type", "unit", "meaning"}) + row({"---", "---", "---", "---", "---"});
  for (const SensorKind* kind : sensorKinds()) {
    const scene::NodeType* type = scene::builtinTypes().find(kind->node_kind);
    const std::string name = type != nullptr ? type->name : "?";
    for (std::size_t i = 0; i < kind->channels.size(); ++i) {
      const Channel& c = kind->channels[i];
      out += row({i == 0 ? name : "", "`" + std::string(c.name) + "`" + (i == kind->primary ? " (value)" : ""),
                  std::string(channelTypeName(c.type)),
                  c.angular ? "rad/s (deg/s where the model's angles are degrees)" : std::string(c.unit), std::string(c.help)});
    }
    out += row({"", "`active`", "flag", "", std::string(kind->active)});
  }
  return out;
}

bool sampled(scene::NodeKind kind) {
  const SensorKind* s = sensorKind(kind);
  return s != nullptr && s->sampling == Sampling::Rate;
}

}  // namespace gdpn::sensors
