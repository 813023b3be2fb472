#pragma once
/// \file
/// Sensors (semantics §2, §6 phase 2): every sensor node's reading, and what changed in a
/// step: items that entered or left a Region, a RangeFinder's new distance, a TimeSensor's
/// tick. Regions and range finders are felt through the physics.

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/physics/world.h"
#include "gdpn/scene/node.h"

namespace gdpn::sensors {

/// What a sensor reports now.
struct Reading {
  std::vector<scene::NodeHandle> items;  ///< Region: what is inside, in path order
  double value = 0;                      ///< RangeFinder: distance, m; TimeSensor: ticks so far
  scene::NodeHandle hit = 0;             ///< RangeFinder: what it sees (0: nothing)
  core::Vec3 vector;                     ///< GradientSensor: the field's vector where its body is
  std::vector<std::string> keys;         ///< KeyboardSensor: the keys held down now
  std::string key;                       ///< KeyboardSensor: the key of the latest event
  bool down = false;                     ///< KeyboardSensor: whether that event pressed it
  /// Region: something is inside; RangeFinder: it sees something; TimeSensor: it ticked now.
  bool active = false;
};

/// An input event of a headless run (from `gdpn run --input`; later from the IDE).
struct InputEvent {
  double t = 0;               ///< when, seconds
  enum class Kind : std::uint8_t { Key, Click, Viewpoint } kind = Kind::Key;
  std::string key;            ///< Key: which
  bool down = true;           ///< Key: pressed or released
  core::Ray ray;              ///< Click: the pick ray (world frame)
  core::Vec3 position;        ///< Viewpoint: where the viewer now is (m)
  core::SourceLoc loc;        ///< where it was written
};

/// What changed for one sensor in a step. Entered before exited, each in path order.
struct Change {
  scene::NodeHandle sensor = 0;
  std::vector<scene::NodeHandle> entered;
  std::vector<scene::NodeHandle> exited;
};

/// Keeps the readings of every sensor node of a scene.
class Hub {
 public:
  /// Finds the sensors of `scene`; `world` feels Regions and RangeFinders (may be null when
  /// the scene has none).
  Hub(scene::Scene& scene, physics::World* world);
  /// Reports sensors that cannot work, at their location: a GradientSensor with no Body
  /// above it, or with no GradientField to read. False when there was one.
  static bool check(const scene::Scene& scene, core::Diagnostics& diags);
  /// Input events to deliver when their time comes (in time order).
  void setInput(std::vector<InputEvent> events) { input_ = std::move(events); next_input_ = 0; }
  /// One more input event, after the pending ones of the same or an earlier time.
  void push(InputEvent event);
  /// Phase 2: reads every sensor at time `now` (seconds), delivering the input events due;
  /// returns the sensors whose reading changed, in the order of their paths.
  const std::vector<Change>& update(double now);
  /// The current reading of sensor node `sensor` (an empty reading for others).
  [[nodiscard]] const Reading& reading(scene::NodeHandle sensor) const;
  /// True when a reading may still change without anything moving: input events are
  /// pending, or a TimeSensor will tick.
  [[nodiscard]] bool mayChange() const;
  /// True when `node` is a sensor this hub reads.
  [[nodiscard]] bool isSensor(scene::NodeHandle node) const;

 private:
  struct Entry {
    scene::Node* node;
    Reading reading;
  };
  Entry* find(scene::NodeHandle h);
  // the new reading of sensor `e` into `next`; false when it cannot have changed
  bool read(const Entry& e, double now, const std::vector<const InputEvent*>& due, Reading& next) const;
  scene::Scene& scene_;
  physics::World* world_;
  std::vector<Entry> entries_;  // in path order
  std::vector<std::pair<scene::NodeHandle, physics::World::Feel>> felt_;
  std::unordered_map<scene::NodeHandle, std::size_t> index_;  // sensor -> its entry in felt_
  std::vector<Change> changes_;
  std::vector<InputEvent> input_;
  std::size_t next_input_ = 0;
  std::optional<core::Vec3> viewpoint_;
};

}  // namespace gdpn::sensors
