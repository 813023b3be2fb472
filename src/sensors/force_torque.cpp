// ForceTorque: the force and torque its joint passes on, at a rate.

#include "detail/sensor.h"

namespace gdpn::sensors::detail {
namespace force_torque {  // named, not anonymous: the kinds share a unity build

namespace F = scene::field;

constexpr Channel kChannels[] = {
    {"force", ChannelType::Vector, "N", "the force on the body below its joint, in its frame"},
    {"torque", ChannelType::Vector, "N m", "the torque about its origin, in its frame"},
    {"magnitude", ChannelType::Number, "N", "the force's length"},
};

/// A force-torque sensor sits in the joint it reads.
bool check(const scene::Scene& /*scene*/, const scene::Node& n, core::Diagnostics& diags, const std::string& /*dir*/) {
  if (n.parent() && n.parent()->kind() == scene::NodeKind::Joint) return true;
  diags.error(n.loc, "a ForceTorque reads the joint it sits in, but the parent of '" + n.path() + "' is no Joint");
  return false;
}

class ForceTorque final : public SampledSensor {
 public:
  using SampledSensor::SampledSensor;

 protected:
  [[nodiscard]] Noise noise() const override { return noiseFields(node(), F::ForceTorque::Noise); }
  [[nodiscard]] double rate() const override { return node().number(F::ForceTorque::Rate); }
  void measure(Context& ctx, Reading& next) override {
    const scene::Node& n = node();
    core::Vec3 f, t;
    if (ctx.world && n.parent()) ctx.world->jointWrench(*n.parent(), n.world.position, f, t);
    const core::Quat to_local = n.world.rotation.conjugate();
    f = to_local.rotate(f);
    t = to_local.rotate(t);
    double x[6] = {f.x, f.y, f.z, t.x, t.y, t.z};
    addNoise(x, 6);
    const core::Vec3 force{x[0], x[1], x[2]};
    next.get<core::Vec3>(0) = force;
    next.get<core::Vec3>(1) = {x[3], x[4], x[5]};
    next.get<double>(2) = force.length();
  }
};

}  // namespace force_torque

const KindDef kForceTorque{{scene::NodeKind::ForceTorque, force_torque::kChannels, 2, "it took a sample now", Sampling::Rate},
                           force_torque::check,
                           makeSensor<force_torque::ForceTorque>,
                           [](physics::World& world, const scene::Node& n) {
                             if (n.parent() != nullptr) world.watchJoint(*n.parent());
                           }};

}  // namespace gdpn::sensors::detail
