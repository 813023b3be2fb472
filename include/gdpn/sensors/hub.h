#pragma once
/// \file
/// Sensors (semantics §2, §6 phase 2): every sensor node's reading, and what changed in a
/// step: items that entered or left a Region, a RangeFinder's new distance, a TimeSensor's
/// tick. Regions and range finders are felt through the physics.

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
  /// Region: something is inside; RangeFinder: it sees something; TimeSensor: it ticked now.
  bool active = false;
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
  /// Phase 2: reads every sensor at time `now` (seconds); returns the sensors whose reading
  /// changed, in the order of their paths.
  const std::vector<Change>& update(double now);
  /// The current reading of sensor node `sensor` (an empty reading for others).
  [[nodiscard]] const Reading& reading(scene::NodeHandle sensor) const;
  /// True when `node` is a sensor this hub reads.
  [[nodiscard]] bool isSensor(scene::NodeHandle node) const;

 private:
  struct Entry {
    scene::Node* node;
    Reading reading;
  };
  Entry* find(scene::NodeHandle h);
  scene::Scene& scene_;
  physics::World* world_;
  std::vector<Entry> entries_;  // in path order
  std::vector<std::pair<scene::NodeHandle, physics::World::Feel>> felt_;
  std::unordered_map<scene::NodeHandle, std::size_t> index_;  // sensor -> its entry in felt_
  std::vector<Change> changes_;
};

}  // namespace gdpn::sensors
