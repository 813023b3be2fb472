// What every kind of sensor shares: its noise stream, sampling by rate, and the hub's context.

#include "detail/sensor.h"

#include <cmath>

#include "gdpn/core/text.h"
#include "gdpn/scene/sensor_rules.h"

namespace gdpn::sensors::detail {

const physics::World::Feel* Context::feel(scene::NodeHandle sensor) const {
  if (felt == nullptr) return nullptr;
  const auto at = felt->find(sensor);
  return at == felt->end() ? nullptr : &at->second;
}

const scene::Node* bodyAbove(const scene::Node& n) {
  for (const scene::Node* p = n.parent(); p; p = p->parent()) {
    if (p->kind() == scene::NodeKind::Body) return p;
  }
  return nullptr;
}

bool checkFieldRules(const scene::Node& n, core::Diagnostics& diags, const std::string& what, const std::string& separator) {
  const auto rule = scene::sensorRule(n, scene::kAsItIs, {});
  if (rule.message.empty()) return true;
  const auto& at = n.field_locs[rule.field].line ? n.field_locs[rule.field] : n.loc;
  diags.error(at, what + " '" + n.path() + "'" + separator + rule.message);
  return false;
}

bool checkNothing(const scene::Scene& /*scene*/, const scene::Node& /*n*/, core::Diagnostics& /*diags*/,
                  const std::string& /*model_dir*/) {
  return true;
}

Sensor::Sensor(scene::Node& node, const SensorKind& kind, std::uint64_t seed) : node_(&node), kind_(&kind) {
  stream_.reseed(seed ^ core::fnv1a(node.path()));
}

std::shared_ptr<const Image> Sensor::picture(Context& /*ctx*/, std::string& why) {
  why = "it is no camera";
  return nullptr;
}

void Sensor::addNoise(double* x, std::size_t n) {
  const Noise noise = this->noise();
  if (noise.none()) return;
  for (std::size_t i = 0; i < n; ++i) {
    double v = x[i] + noise.bias;
    if (noise.sd > 0) v += stream_.normal(0.0, noise.sd);
    if (noise.resolution > 0) v = std::round(v / noise.resolution) * noise.resolution;
    x[i] = v;
  }
}

bool SampledSensor::read(Context& ctx, const Reading& last, Reading& next) {
  follow(ctx);
  // a sample at 0, 1/rate, 2/rate, ... s (every step at rate 0)
  const double r = rate();
  const auto due = r > 0 ? static_cast<std::uint64_t>(std::floor(ctx.now * r + 1e-9)) + 1 : samples_ + 1;
  next.active = due > samples_;
  if (!next.active) return last.active;
  samples_ = due;
  measure(ctx, next);
  return true;
}

}  // namespace gdpn::sensors::detail
