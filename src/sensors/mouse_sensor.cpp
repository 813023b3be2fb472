// MouseSensor: clicks whose first hit lies in its parent's subtree.

#include "gdpn/sensors/mouse_sensor.h"

#include "detail/sensor.h"
#include "gdpn/scene/actions.h"

namespace gdpn::sensors {

bool clickReaches(const scene::Node& sensor, const scene::Node* shape) {
  for (const scene::Node* n = shape; n != nullptr; n = n->parent()) {
    if (n == sensor.parent()) return true;
  }
  return false;
}

ClickTarget clickTarget(scene::Node& root, const core::Ray& ray) {
  ClickTarget out;
  out.hit = scene::pick(root, ray);
  // the sensors among the children of the shape and of each node above it
  for (scene::Node* n = out.hit.shape; n != nullptr; n = n->parent()) {
    for (const auto& child : n->children()) {
      if (child->kind() == scene::NodeKind::MouseSensor && !child->is_template) out.sensors.push_back(child.get());
    }
  }
  return out;
}

}  // namespace gdpn::sensors

namespace gdpn::sensors::detail {
namespace mouse_sensor {  // named, not anonymous: the kinds share a unity build

constexpr Channel kChannels[] = {
    {"hit", ChannelType::Node, "", "the shape the latest click hit"},
    {"clicks", ChannelType::Number, "", "clicks felt so far"},
};

class MouseSensor final : public Sensor {
 public:
  using Sensor::Sensor;
  bool read(Context& ctx, const Reading& last, Reading& next) override {
    // a click counts when its ray's first hit lies in the parent's subtree
    bool clicked = false;
    for (const auto* ev : ctx.due) {
      if (ev->kind != InputEvent::Kind::Click) continue;
      const scene::Pick hit = scene::pick(ctx.scene.root(), ev->ray);
      if (!clickReaches(node(), hit.shape)) continue;
      clicked = true;
      next.get<scene::NodeHandle>(0) = hit.shape->handle();
      next.get<double>(1) += 1;
    }
    next.active = clicked;
    return clicked || last.active;
  }
};

}  // namespace mouse_sensor

const KindDef kMouseSensor{{scene::NodeKind::MouseSensor, mouse_sensor::kChannels, 1, "a click fell on its parent now", Sampling::Events},
                           checkNothing,
                           makeSensor<mouse_sensor::MouseSensor>};

}  // namespace gdpn::sensors::detail
