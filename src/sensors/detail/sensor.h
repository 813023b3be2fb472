#pragma once
// Internal: no promises. What every kind of sensor implements (one file each:
// src/sensors/<kind>.cpp) and what the hub gives it in a step.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/core/random.h"
#include "gdpn/physics/world.h"
#include "gdpn/scene/fields.h"
#include "gdpn/scene/node.h"
#include "gdpn/sensors/hub.h"
#include "gdpn/sensors/sensor_kind.h"

namespace gdpn::sensors::detail {

/// What the hub gives every sensor in a step.
struct Context {
  scene::Scene& scene;                      ///< the plant
  physics::World* world = nullptr;          ///< what feels it (null: no physics)
  core::Vec3 gravity;                       ///< the World node's, m/s^2
  const std::string& model_dir;             ///< where Terrain files are
  Imager* imager = nullptr;                 ///< what renders pictures (null: none)
  double now = 0;                           ///< this step's time, s
  double last = 0;                          ///< the time of the update before, s
  std::span<const InputEvent* const> due;   ///< the input events due now, in time order
  std::optional<core::Vec3> viewpoint;      ///< where the viewer is (world, m), once known
  /// What the physics felt for Regions and RangeFinders this step, by sensor.
  const std::unordered_map<scene::NodeHandle, physics::World::Feel>* felt = nullptr;

  /// What the physics felt for `sensor` this step; null when nothing was.
  [[nodiscard]] const physics::World::Feel* feel(scene::NodeHandle sensor) const;
};

/// A sensor's noise: standard deviation, bias and resolution, in its reading's units.
struct Noise {
  double sd = 0, bias = 0, resolution = 0;
  [[nodiscard]] bool none() const { return sd == 0 && bias == 0 && resolution == 0; }
};

/// The noise fields that a type declares in a row from its `noise` field.
template <scene::FieldId Id>
Noise noiseFields(const scene::Node& n, Id noise) {
  const auto at = [&](int k) { return n.number(static_cast<Id>(static_cast<int>(noise) + k)); };
  return {at(0), at(1), at(2)};
}

/// The Body the node `n` rides on (its nearest ancestor that is one), or null.
[[nodiscard]] const scene::Node* bodyAbove(const scene::Node& n);

/// One sensor node of a run and what it keeps between steps.
class Sensor {
 public:
  /// `seed`: the model's; the sensor's noise draws from a stream of its own (from its path).
  Sensor(scene::Node& node, const SensorKind& kind, std::uint64_t seed);
  virtual ~Sensor() = default;
  Sensor(const Sensor&) = delete;
  Sensor& operator=(const Sensor&) = delete;

  /// Its new reading into `next`, which starts as a copy of `last`; false when it cannot have
  /// changed.
  virtual bool read(Context& ctx, const Reading& last, Reading& next) = 0;
  /// Cameras: the picture of the latest sample, rendered now if it was not yet.
  virtual std::shared_ptr<const Image> picture(Context& ctx, std::string& why);
  /// Cameras: the latest picture read, of any sample.
  [[nodiscard]] virtual std::shared_ptr<const Image> lastPicture() const { return nullptr; }

  /// The node.
  [[nodiscard]] scene::Node& node() const { return *node_; }
  /// Its kind.
  [[nodiscard]] const SensorKind& kind() const { return *kind_; }

 protected:
  /// Its noise, from its fields (none by default).
  [[nodiscard]] virtual Noise noise() const { return {}; }
  /// The `n` numbers of a sample at `x` with the sensor's noise, bias and resolution.
  void addNoise(double* x, std::size_t n);

 private:
  scene::Node* node_;
  const SensorKind* kind_;
  core::Random stream_;
};

/// A sensor that samples by its `rate` field: at 0, 1/rate, 2/rate, ... s (every step at 0).
class SampledSensor : public Sensor {
 public:
  using Sensor::Sensor;
  bool read(Context& ctx, const Reading& last, Reading& next) final;

 protected:
  /// Its rate, Hz (0: every step).
  [[nodiscard]] virtual double rate() const = 0;
  /// Called every step before a sample is due or not (an Imu follows its body's motion).
  virtual void follow(Context& /*ctx*/) {}
  /// Takes a sample into `next`.
  virtual void measure(Context& ctx, Reading& next) = 0;
  /// Samples taken so far.
  [[nodiscard]] std::uint64_t samples() const { return samples_; }

 private:
  std::uint64_t samples_ = 0;
};

/// A kind of sensor: its description, its check and how its sensors are made.
struct KindDef {
  SensorKind kind;  ///< what it reports
  /// Reports what keeps sensor `n` of `scene` from working, at its location (files relative to
  /// `model_dir`); false when something does.
  bool (*check)(const scene::Scene& scene, const scene::Node& n, core::Diagnostics& diags,
                const std::string& model_dir) = nullptr;
  /// A sensor for node `n`.
  std::unique_ptr<Sensor> (*make)(scene::Node& n, const SensorKind& kind, std::uint64_t seed) = nullptr;
  /// Asks the physics to keep what sensor `n` reads that it keeps only when asked (the forces
  /// of a body's contacts, of a joint); null for kinds that need nothing.
  void (*watch)(physics::World& world, const scene::Node& n) = nullptr;
};

/// Reports the first broken rule between the fields of sensor `n` (scene::sensorRule) at the
/// field it blames (the node where that field is not written), as `what` + the path +
/// `separator` + the rule's message; false when one is broken.
bool checkFieldRules(const scene::Node& n, core::Diagnostics& diags, const std::string& what, const std::string& separator);

/// A check for kinds that need nothing.
bool checkNothing(const scene::Scene& scene, const scene::Node& n, core::Diagnostics& diags, const std::string& model_dir);

/// Makes a `T` for node `n` (a KindDef's `make`).
template <typename T>
std::unique_ptr<Sensor> makeSensor(scene::Node& n, const SensorKind& kind, std::uint64_t seed) {
  return std::make_unique<T>(n, kind, seed);
}

/// The kind of sensor node kind `kind`; null for node kinds that are no sensors.
[[nodiscard]] const KindDef* kindDef(scene::NodeKind kind);

// one per kind, each in its file
extern const KindDef kRegion;
extern const KindDef kRangeFinder;
extern const KindDef kGradientSensor;
extern const KindDef kKeyboardSensor;
extern const KindDef kMouseSensor;
extern const KindDef kTimeSensor;
extern const KindDef kColorCamera;
extern const KindDef kDepthCamera;
extern const KindDef kLaserScan;
extern const KindDef kImu;
extern const KindDef kGps;
extern const KindDef kContact;
extern const KindDef kForceTorque;

}  // namespace gdpn::sensors::detail
