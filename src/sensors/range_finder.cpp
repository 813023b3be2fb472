// RangeFinder: the distance along a ray to the first thing it sees, felt through the physics.

#include "detail/sensor.h"

namespace gdpn::sensors::detail {
namespace range_finder {  // named, not anonymous: the kinds share a unity build

namespace F = scene::field;

constexpr Channel kChannels[] = {
    {"distance", ChannelType::Number, "m", "to the first thing along the ray (its length when it sees nothing)"},
    {"hit", ChannelType::Node, "", "what it sees (none: nothing)"},
};

class RangeFinder final : public Sensor {
 public:
  using Sensor::Sensor;
  bool read(Context& ctx, const Reading& /*last*/, Reading& next) override {
    const physics::World::Feel* feel = ctx.feel(node().handle());
    if (feel == nullptr) return false;
    double distance = feel->distance;
    addNoise(&distance, 1);
    next.get<double>(0) = distance;
    next.get<scene::NodeHandle>(1) = feel->hit;
    next.active = feel->hit != 0;
    return true;
  }

 protected:
  [[nodiscard]] Noise noise() const override { return noiseFields(node(), F::RangeFinder::Noise); }
};

}  // namespace range_finder

const KindDef kRangeFinder{{scene::NodeKind::RangeFinder, range_finder::kChannels, 0, "it sees something", Sampling::EveryStep},
                           checkNothing,
                           makeSensor<range_finder::RangeFinder>};

}  // namespace gdpn::sensors::detail
