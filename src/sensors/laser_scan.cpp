// LaserScan: distances along a fan of rays, at a rate.

#include <algorithm>
#include <cmath>

#include "detail/sensor.h"

namespace gdpn::sensors::detail {
namespace laser_scan {  // named, not anonymous: the kinds share a unity build

namespace F = scene::field;

constexpr Channel kChannels[] = {
    {"ranges", ChannelType::Numbers, "m", "the distance along each ray (its length where nothing is hit)"},
    {"nearest", ChannelType::Number, "m", "the shortest of them"},
};

/// The directions of a LaserScan's rays in its frame: from min_angle to max_angle about +z,
/// evenly, the last left out when the fan is a whole turn (it would repeat the first).
std::vector<core::Vec3> fanOf(const scene::Node& n) {
  const auto count = static_cast<std::size_t>(n.number(F::LaserScan::Count));
  const double lo = n.number(F::LaserScan::MinAngle), hi = n.number(F::LaserScan::MaxAngle);
  const bool turn = std::abs(std::abs(hi - lo) - 360.0) < 1e-9;
  const double step = count < 2 ? 0.0 : (hi - lo) / static_cast<double>(turn ? count : count - 1);
  std::vector<core::Vec3> dirs(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double a = core::radians(lo + step * static_cast<double>(i));
    dirs[i] = {std::cos(a), std::sin(a), 0};
  }
  return dirs;
}

/// A fan with an angle between its rays.
bool check(const scene::Scene& /*scene*/, const scene::Node& n, core::Diagnostics& diags, const std::string& /*dir*/) {
  return checkFieldRules(n, diags, "laser scan", " ");
}

class LaserScan final : public SampledSensor {
 public:
  using SampledSensor::SampledSensor;

 protected:
  [[nodiscard]] Noise noise() const override { return noiseFields(node(), F::LaserScan::Noise); }
  [[nodiscard]] double rate() const override { return node().number(F::LaserScan::Rate); }
  void measure(Context& ctx, Reading& next) override {
    const scene::Node& n = node();
    auto dirs = fanOf(n);
    for (auto& d : dirs) d = n.world.rotation.rotate(d);
    auto& ranges = next.get<std::vector<double>>(0);
    const double length = n.number(F::LaserScan::Length);
    if (ctx.world) {
      hits_.clear();
      ctx.world->castRays(n, n.choice<scene::Scope>(F::LaserScan::Scope), n.world.position, dirs, length, ranges, hits_);
    } else {
      ranges.assign(dirs.size(), length);
    }
    addNoise(ranges.data(), ranges.size());
    next.get<double>(1) = ranges.empty() ? length : *std::min_element(ranges.begin(), ranges.end());
  }

 private:
  std::vector<scene::NodeHandle> hits_;  // what each ray hit (kept for its room)
};

}  // namespace laser_scan

const KindDef kLaserScan{{scene::NodeKind::LaserScan, laser_scan::kChannels, 1, "it took a sample now", Sampling::Rate},
                         laser_scan::check,
                         makeSensor<laser_scan::LaserScan>};

}  // namespace gdpn::sensors::detail
