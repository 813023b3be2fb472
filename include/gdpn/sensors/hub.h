#pragma once
/// \file
/// Sensors (semantics §2, §6 phase 2): every sensor node's reading, and what changed in a
/// step: items that entered or left a Region, a RangeFinder's new distance, a TimeSensor's
/// tick. Regions and range finders are felt through the physics.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "gdpn/core/random.h"

#include "gdpn/core/diagnostics.h"
#include "gdpn/physics/world.h"
#include "gdpn/scene/node.h"
#include "gdpn/sensors/channel.h"
#include "gdpn/sensors/sensor_kind.h"

namespace gdpn::sensors {

namespace detail {
class Sensor;
}

/// A camera's picture: RGB bytes (ColorCamera) or distances (DepthCamera), top row first.
struct Image {
  int width = 0;                   ///< pixels
  int height = 0;                  ///< pixels
  std::vector<std::uint8_t> rgb;   ///< ColorCamera: 3 bytes per pixel
  std::vector<float> depth;        ///< DepthCamera: metres along the view axis per pixel (`far` where nothing is)
};

/// What renders a camera sensor's picture of the scene as it stands (the render module's, set
/// by the application: the sensors know nothing of OpenGL).
class Imager {
 public:
  virtual ~Imager() = default;
  /// Renders ColorCamera or DepthCamera node `camera` of `scene` into `out`; false with `why`.
  virtual bool render(const scene::Scene& scene, const scene::Node& camera, Image& out, std::string& why) = 0;
};

/// An input event for the keyboard and mouse sensors: from `gdpn run --input`, or live from the
/// IDE's world view (`Session::push`), delivered at the next step at or after its time.
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
  /// Finds the sensors of `scene` (not those in templates); `world` feels Regions,
  /// RangeFinders, laser scans, contacts and joints (may be null when the scene has none).
  /// `seed`: the model's, from which each sensor's noise gets a stream of its own (drawn from
  /// its path), so a sensor's noise does not depend on which others are read.
  Hub(scene::Scene& scene, physics::World* world, std::uint64_t seed = 1);
  ~Hub();
  Hub(const Hub&) = delete;
  Hub& operator=(const Hub&) = delete;
  /// Reports sensors that cannot work, at their location: a GradientSensor with no Body
  /// above it, or with no GradientField to read; an Imu or Contact with no Body above it; a
  /// ForceTorque whose parent is no Joint; a camera whose `far` is not beyond `near`; a
  /// LaserScan with no angle between its rays; a geodetic Gps with no georeferenced Terrain.
  /// `model_dir`: where the Terrain files are. False when there was one.
  static bool check(const scene::Scene& scene, core::Diagnostics& diags, const std::string& model_dir = ".");
  /// What renders camera pictures (none: reading one is an error that says so).
  void setImager(std::shared_ptr<Imager> imager) { imager_ = std::move(imager); }
  /// The picture of camera sensor `camera` at its latest sample, rendered now if it was not
  /// yet (only pictures read are rendered); null with `why` when it cannot be.
  std::shared_ptr<const Image> image(scene::NodeHandle camera, std::string& why);
  /// The latest picture of camera `camera` that was read, of whatever sample; null when none
  /// was. Renders nothing and draws no noise: what the IDE shows, not changing the run.
  [[nodiscard]] std::shared_ptr<const Image> lastPicture(scene::NodeHandle camera) const;
  /// Where the Terrain files of geodetic Gps sensors are found (the model's folder).
  void setModelDir(std::string dir) { model_dir_ = std::move(dir); }
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
  /// Reads the sensors in the subtree of `top` from the next update on, as if they had been
  /// there from the start (a copy that spawn made, already in the physics): first checked as
  /// check() does, and none is added when one cannot work (false, with diagnostics). Costs
  /// in the size of the subtree, not of the scene.
  bool add(scene::Node& top, core::Diagnostics& diags);
  /// Forgets the sensors in the subtree of `top`, which is about to be deleted. Costs in the
  /// size of the subtree, not of the scene.
  void forget(scene::Node& top);

 private:
  struct Entry {
    std::unique_ptr<detail::Sensor> sensor;
    Reading reading;
  };
  /// Where an entry is kept: its sensor's path when it was added (and its handle).
  using Key = std::pair<std::string, scene::NodeHandle>;
  Entry* find(scene::NodeHandle h);
  /// Makes the entries of the sensors in the subtree of `top` (none in templates).
  void enter(scene::Node& top);
  scene::Scene& scene_;
  physics::World* world_;
  std::uint64_t seed_;
  std::map<Key, Entry> entries_;  // in path order
  std::unordered_map<scene::NodeHandle, std::map<Key, Entry>::iterator> entry_of_;  // sensor -> its entry
  std::vector<std::pair<scene::NodeHandle, physics::World::Feel>> felt_;
  std::unordered_map<scene::NodeHandle, physics::World::Feel> felt_of_;  // sensor -> what it felt
  std::vector<Change> changes_;
  std::vector<InputEvent> input_;
  std::size_t next_input_ = 0;
  std::optional<core::Vec3> viewpoint_;
  double last_now_ = 0;   // the time of the update before
  core::Vec3 gravity_{0, 0, -9.81};  // the World node's, m/s^2
  std::shared_ptr<Imager> imager_;
  std::string model_dir_ = ".";
};

}  // namespace gdpn::sensors
