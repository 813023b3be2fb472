// Contact: what touches its body, and how hard, at a rate.

#include "detail/sensor.h"

namespace gdpn::sensors::detail {
namespace contact {  // named, not anonymous: the kinds share a unity build

namespace F = scene::field;

constexpr Channel kChannels[] = {
    {"items", ChannelType::Items, "", "what touches its body: bodies or static shapes, in path order"},
    {"forces", ChannelType::Numbers, "N", "the normal force from each item", false, true},
    {"total", ChannelType::Number, "N", "the sum of the forces"},
};

/// A contact sensor needs a body to feel.
bool check(const scene::Scene& /*scene*/, const scene::Node& n, core::Diagnostics& diags, const std::string& /*dir*/) {
  if (bodyAbove(n)) return true;
  diags.error(n.loc, "a Contact feels what touches its body, but '" + n.path() + "' has no Body above it");
  return false;
}

class Contact final : public SampledSensor {
 public:
  using SampledSensor::SampledSensor;

 protected:
  [[nodiscard]] Noise noise() const override { return noiseFields(node(), F::Contact::Noise); }
  [[nodiscard]] double rate() const override { return node().number(F::Contact::Rate); }
  void measure(Context& ctx, Reading& next) override {
    auto& items = next.get<std::vector<scene::NodeHandle>>(0);
    auto& forces = next.get<std::vector<double>>(1);
    items.clear();
    forces.clear();
    if (ctx.world) {
      for (const auto& t : ctx.world->touches(node())) {
        items.push_back(t.other);
        forces.push_back(t.normal_force);
      }
    }
    addNoise(forces.data(), forces.size());
    double total = 0;
    for (double f : forces) total += f;
    next.get<double>(2) = total;
  }
};

}  // namespace contact

const KindDef kContact{{scene::NodeKind::Contact, contact::kChannels, 2, "it took a sample now", Sampling::Rate},
                       contact::check,
                       makeSensor<contact::Contact>,
                       [](physics::World& world, const scene::Node& n) { world.watchContacts(n); }};

}  // namespace gdpn::sensors::detail
