// Region: what is inside a volume, felt through the physics.

#include "detail/sensor.h"

namespace gdpn::sensors::detail {
namespace region {  // named, not anonymous: the kinds share a unity build

constexpr Channel kChannels[] = {
    {"items", ChannelType::Items, "", "the bodies (or static shapes) inside, in path order"},
    {"count", ChannelType::Number, "", "how many items are inside"},
    {"hit", ChannelType::Node, "", "what its ray hits first, a static shape too (shape: ray; none otherwise)"},
};

class Region final : public Sensor {
 public:
  using Sensor::Sensor;
  bool read(Context& ctx, const Reading& /*last*/, Reading& next) override {
    const physics::World::Feel* feel = ctx.feel(node().handle());
    if (feel == nullptr) return false;
    next.get<std::vector<scene::NodeHandle>>(0) = feel->items;
    next.get<double>(1) = static_cast<double>(feel->items.size());
    next.get<scene::NodeHandle>(2) = feel->hit;
    next.active = !feel->items.empty();
    return true;
  }
};

}  // namespace region

const KindDef kRegion{{scene::NodeKind::Region, region::kChannels, 1, "something is inside", Sampling::EveryStep},
                      checkNothing,
                      makeSensor<region::Region>};

}  // namespace gdpn::sensors::detail
