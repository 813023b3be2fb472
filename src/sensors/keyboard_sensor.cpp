// KeyboardSensor: the keys a viewer inside its parent's box presses and releases.

#include <algorithm>

#include "detail/sensor.h"
#include "gdpn/scene/actions.h"

namespace gdpn::sensors::detail {
namespace keyboard_sensor {  // named, not anonymous: the kinds share a unity build

constexpr Channel kChannels[] = {
    {"keys", ChannelType::Texts, "", "the keys held down now"},
    {"key", ChannelType::Text, "", "the key of the latest event"},
    {"down", ChannelType::Flag, "", "whether that event pressed it"},
    {"events", ChannelType::Number, "", "key events heard so far"},
};

class KeyboardSensor final : public Sensor {
 public:
  using Sensor::Sensor;
  bool read(Context& ctx, const Reading& last, Reading& next) override {
    // it hears keys while the viewer is inside its parent's box
    const scene::Node* parent = node().parent();
    const core::Aabb box = parent ? scene::boundingBox(*parent) : core::Aabb{};
    const auto& v = ctx.viewpoint ? *ctx.viewpoint : core::Vec3{};
    next.active = ctx.viewpoint && !box.empty() && v.x >= box.lo.x && v.x <= box.hi.x && v.y >= box.lo.y &&
                  v.y <= box.hi.y && v.z >= box.lo.z && v.z <= box.hi.z;
    auto& keys = next.get<std::vector<std::string>>(0);
    bool heard = false;
    for (const auto* ev : ctx.due) {
      if (ev->kind != InputEvent::Kind::Key || !next.active) continue;
      heard = true;
      next.get<std::string>(1) = ev->key;
      next.get<bool>(2) = ev->down;
      auto it = std::find(keys.begin(), keys.end(), ev->key);
      if (ev->down && it == keys.end()) keys.push_back(ev->key);
      if (!ev->down && it != keys.end()) keys.erase(it);
      next.get<double>(3) += 1;
    }
    return heard || next.active != last.active;
  }
};

}  // namespace keyboard_sensor

const KindDef kKeyboardSensor{
    {scene::NodeKind::KeyboardSensor, keyboard_sensor::kChannels, 3, "the viewer is inside its parent's box", Sampling::Events},
    checkNothing,
    makeSensor<keyboard_sensor::KeyboardSensor>};

}  // namespace gdpn::sensors::detail
