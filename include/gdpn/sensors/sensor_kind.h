#pragma once
/// \file
/// The kinds of sensor: for each, the channels it reports and how it samples. Each kind lives
/// in one file, `src/sensors/<kind>.cpp` (its check, rate, noise, measurement and reading);
/// docs/architecture.md gives the recipe for a new one.

#include <span>
#include <string>
#include <string_view>

#include "gdpn/scene/kind.h"
#include "gdpn/sensors/channel.h"

namespace gdpn::sensors {

/// When a kind of sensor takes a new reading.
enum class Sampling : std::uint8_t {
  EveryStep,  ///< each step, from the plant as it stands (Region, RangeFinder, GradientSensor)
  Rate,       ///< at 0, 1/rate, 2/rate, ... s, by its `rate` field (every step at 0)
  Events,     ///< when input events arrive (KeyboardSensor, MouseSensor)
  Clock,      ///< by model time alone (TimeSensor)
};

/// What a kind of sensor reports and how.
struct SensorKind {
  scene::NodeKind node_kind;           ///< the scene node kind
  std::span<const Channel> channels;   ///< what it reports, in order
  /// The number channel that `value` (scripts) and `reading` (signals, the I/O map) give.
  /// Its Items channel, if it has one (at most one), is what `items` gives and whose changes
  /// are the `on_enter` and `on_exit` events.
  std::size_t primary = 0;
  std::string_view active;  ///< what `active` means for it, one line
  Sampling sampling = Sampling::EveryStep;  ///< when it reads
  /// It takes pictures (cameras): `Hub::image` renders them when read.
  bool pictures = false;

  /// `active` is a pulse (a sample taken, a tick): its rise and fall alone are no change of
  /// the reading (what the sample or tick measured is).
  [[nodiscard]] bool pulse() const { return sampling == Sampling::Rate || sampling == Sampling::Clock; }
};

/// The description of sensor kind `kind`; null for node kinds that are no sensors.
[[nodiscard]] const SensorKind* sensorKind(scene::NodeKind kind);

/// Every kind of sensor, in the order of `scene::NodeKind`.
[[nodiscard]] std::span<const SensorKind* const> sensorKinds();

/// The table of every kind's channels as Markdown, for docs/format.md (a test keeps the two the
/// same): one row per channel with the kind, the name, the type, the unit and the help; the
/// main number marked.
[[nodiscard]] std::string channelsMarkdown();

/// True when sensor `kind` samples at a rate of its own (a `rate` field).
[[nodiscard]] bool sampled(scene::NodeKind kind);

}  // namespace gdpn::sensors
