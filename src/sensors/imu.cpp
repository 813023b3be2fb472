// Imu: the acceleration (less gravity) and angular velocity of its point on its body, at a rate.

#include <cmath>

#include "detail/sensor.h"

namespace gdpn::sensors::detail {
namespace imu {  // named, not anonymous: the kinds share a unity build

namespace F = scene::field;

constexpr Channel kChannels[] = {
    {"acceleration", ChannelType::Vector, "m/s^2", "acceleration less gravity, in its frame (at rest: -gravity)"},
    {"angular_velocity", ChannelType::Vector, "rad/s", "angular velocity in its frame", true},
    {"samples", ChannelType::Number, "", "samples taken so far"},
};

/// An accelerometer and gyroscope needs a body to ride on.
bool check(const scene::Scene& /*scene*/, const scene::Node& n, core::Diagnostics& diags, const std::string& /*dir*/) {
  if (bodyAbove(n)) return true;
  diags.error(n.loc, "an Imu feels the motion of its body, but '" + n.path() + "' has no Body above it");
  return false;
}

class Imu final : public SampledSensor {
 public:
  using SampledSensor::SampledSensor;

 protected:
  // the noise fields' units: m/s^2 for the acceleration, deg/s for the angular velocity
  [[nodiscard]] Noise noise() const override { return noiseFields(node(), F::Imu::Noise); }
  [[nodiscard]] double rate() const override { return node().number(F::Imu::Rate); }

  void follow(Context& ctx) override {
    // the velocity of the Imu's point on its body, differenced over the step
    const scene::Node* body = bodyAbove(node());
    core::Vec3 v, w;
    if (ctx.world && body && ctx.world->isBody(*body)) {
      v = ctx.world->pointVelocity(*body, node().world.position);
      w = ctx.world->angularVelocity(*body);
    }
    const double dt = ctx.now - ctx.last;
    acceleration_ = moved_ && dt > 0 ? (v - velocity_) * (1.0 / dt) : core::Vec3{};
    // the change of velocity over the step belongs to the middle of the step: seen in the
    // frame the sensor had then (on a turntable, the chord's direction)
    const core::Quat now_rot = node().world.rotation;
    const core::Quat last = moved_ ? rotation_ : now_rot;
    const double sign = last.w * now_rot.w + last.x * now_rot.x + last.y * now_rot.y + last.z * now_rot.z < 0 ? -1.0 : 1.0;
    core::Quat mid{last.w + sign * now_rot.w, last.x + sign * now_rot.x, last.y + sign * now_rot.y, last.z + sign * now_rot.z};
    const double norm = std::sqrt(mid.w * mid.w + mid.x * mid.x + mid.y * mid.y + mid.z * mid.z);
    middle_ = norm > 0 ? core::Quat{mid.w / norm, mid.x / norm, mid.y / norm, mid.z / norm} : now_rot;
    rotation_ = now_rot;
    velocity_ = v;
    spin_ = w;
    moved_ = true;
  }

  void measure(Context& ctx, Reading& next) override {
    // what an accelerometer feels: its acceleration less gravity; both in its frame
    const core::Quat to_local = node().world.rotation.conjugate();
    const core::Vec3 a = middle_.conjugate().rotate(acceleration_ - ctx.gravity), w = to_local.rotate(spin_);
    double x[6] = {a.x, a.y, a.z, core::degrees(w.x), core::degrees(w.y), core::degrees(w.z)};
    addNoise(x, 6);
    next.get<core::Vec3>(0) = {x[0], x[1], x[2]};
    next.get<core::Vec3>(1) = {core::radians(x[3]), core::radians(x[4]), core::radians(x[5])};
    next.get<double>(2) = static_cast<double>(samples());
  }

 private:
  core::Vec3 velocity_, spin_;   // its point's velocity (m/s), its body's (rad/s), world, last step
  core::Vec3 acceleration_;      // its point's, m/s^2 (world), over the last step
  core::Quat rotation_, middle_; // its rotation (world) at the last step, and halfway through the step
  bool moved_ = false;           // velocity_ and spin_ hold a step's values
};

}  // namespace imu

const KindDef kImu{{scene::NodeKind::Imu, imu::kChannels, 2, "it took a sample now", Sampling::Rate},
                   imu::check,
                   makeSensor<imu::Imu>};

}  // namespace gdpn::sensors::detail
