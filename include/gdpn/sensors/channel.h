#pragma once
/// \file
/// A sensor's reading as a set of named channels (MuJoCo's `sensor_dim`/`sensor_adr` is the
/// model): each kind of sensor declares its channels once, with a type, a unit and a line of
/// help, and every reader of readings (the inspector, scripts, signals, the I/O map, the
/// report) loops over them without knowing the kind.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "gdpn/core/math.h"
#include "gdpn/scene/node.h"

namespace gdpn::sensors {

/// What a channel holds. The order is that of `Value`'s alternatives.
enum class ChannelType : std::uint8_t {
  Number,   ///< one number
  Flag,     ///< true or false
  Vector,   ///< three numbers: x, y, z
  Numbers,  ///< a list of numbers (one per ray, one per item)
  Items,    ///< the nodes sensed, in path order
  Node,     ///< one node, or none (0)
  Text,     ///< a word (a key's name)
  Texts,    ///< words (the keys held down)
};

/// A channel's value now: the alternative whose index is its `ChannelType`.
using Value = std::variant<double, bool, core::Vec3, std::vector<double>, std::vector<scene::NodeHandle>,
                           scene::NodeHandle, std::string, std::vector<std::string>>;

/// One named quantity a kind of sensor reports.
struct Channel {
  std::string_view name;  ///< how scripts, signals and the I/O map address it: `distance`
  ChannelType type = ChannelType::Number;  ///< what it holds
  std::string_view unit;  ///< SI unit ("m", "m/s^2", "N"); empty for counts, flags, nodes and words
  std::string_view help;  ///< what it means, one line
  /// An angular rate held in rad/s and given in deg/s where the model's angles are degrees.
  bool angular = false;
  /// Numbers: one per item of the kind's Items channel, in its order (a Contact's forces).
  bool per_item = false;
  /// Significant digits a person is shown (latitudes need more than distances).
  int digits = 5;
};

/// The name of `type`: "number", "flag", "vector", "numbers", "items", "node", "text", "texts".
[[nodiscard]] std::string_view channelTypeName(ChannelType type);

/// The value a channel of `type` holds before anything is sensed (0, false, empty).
[[nodiscard]] Value emptyValue(ChannelType type);

/// `x` as a person reads it: whole numbers without decimals, others to `digits` significant
/// digits.
[[nodiscard]] std::string numberText(double x, int digits = 5);

/// The unit channel `c` is shown in: its own, or deg/s for an angular rate when `degrees`.
[[nodiscard]] std::string_view shownUnit(const Channel& c, bool degrees);

/// Channel `c`'s value `v` as text with its unit ("0.421 m", "(0, 0, 9.81) m/s^2", "180 values,
/// 0.5 to 4 m", "a space"), nodes named by `name_of`; angular rates in deg/s when `degrees`.
[[nodiscard]] std::string channelText(const Channel& c, const Value& v,
                                      const std::function<std::string(scene::NodeHandle)>& name_of, bool degrees);

/// What a sensor reports now: whether it is active, and one value per channel of its kind.
class Reading {
 public:
  /// An empty reading with no channels (what a node that is no sensor reads).
  Reading() = default;
  /// The empty reading of a sensor with channels `channels`.
  explicit Reading(std::span<const Channel> channels);

  /// Something is inside or seen, a key is heard, a click fell, a tick or a sample happened
  /// now (each kind says which).
  bool active = false;

  /// The channels, in their kind's order.
  [[nodiscard]] std::span<const Channel> channels() const { return channels_; }
  /// The index of channel `name`, or -1 when this reading has none of that name.
  [[nodiscard]] int find(std::string_view name) const;
  /// The value of channel `index`.
  [[nodiscard]] const Value& value(std::size_t index) const { return values_[index]; }
  /// The value of channel `index`, to be set by the sensor.
  [[nodiscard]] Value& value(std::size_t index) { return values_[index]; }

  /// Channel `index`'s value as `T` (the alternative of its type).
  template <typename T>
  [[nodiscard]] const T& get(std::size_t index) const {
    return std::get<T>(values_[index]);
  }
  /// Channel `index`'s value as `T`, to be set.
  template <typename T>
  [[nodiscard]] T& get(std::size_t index) {
    return std::get<T>(values_[index]);
  }
  /// The number channel `name` (a channel of that name and type must exist: asserted).
  [[nodiscard]] double number(std::string_view name) const;
  /// The vector channel `name`.
  [[nodiscard]] core::Vec3 vector(std::string_view name) const;
  /// The list of numbers of channel `name`.
  [[nodiscard]] const std::vector<double>& numbers(std::string_view name) const;
  /// The node channel `name` (0: none).
  [[nodiscard]] scene::NodeHandle node(std::string_view name) const;
  /// The items the sensor senses (its Items channel; empty for kinds that have none).
  [[nodiscard]] const std::vector<scene::NodeHandle>& items() const;

  /// True when every channel holds the same value as in `other` (of the same kind); `active`
  /// is not compared.
  [[nodiscard]] bool sameValues(const Reading& other) const { return values_ == other.values_; }

 private:
  [[nodiscard]] const Value& named(std::string_view name, ChannelType type) const;
  std::span<const Channel> channels_;
  std::vector<Value> values_;
};

}  // namespace gdpn::sensors
