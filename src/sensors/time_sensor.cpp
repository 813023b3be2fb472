// TimeSensor: ticks at a period from an offset, by model time alone.

#include <cmath>

#include "detail/sensor.h"

namespace gdpn::sensors::detail {
namespace time_sensor {  // named, not anonymous: the kinds share a unity build

namespace F = scene::field;

constexpr Channel kChannels[] = {
    {"ticks", ChannelType::Number, "", "ticks so far: one at its offset, then one each period"},
};

class TimeSensor final : public Sensor {
 public:
  using Sensor::Sensor;
  bool read(Context& ctx, const Reading& last, Reading& next) override {
    const double period = node().number(F::TimeSensor::Period);
    const double offset = node().number(F::TimeSensor::Offset);
    const double ticks = ctx.now + 1e-9 < offset ? 0.0 : std::floor((ctx.now - offset) / period + 1e-9) + 1.0;
    next.active = ticks > last.get<double>(0);
    next.get<double>(0) = ticks;
    return true;
  }
};

}  // namespace time_sensor

const KindDef kTimeSensor{{scene::NodeKind::TimeSensor, time_sensor::kChannels, 0, "it ticked now", Sampling::Clock},
                          checkNothing,
                          makeSensor<time_sensor::TimeSensor>};

}  // namespace gdpn::sensors::detail
