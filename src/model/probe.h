#pragma once
// Internal: no promises. A probe: one quantity of a run (a place's tokens, a node's position,
// velocity, joint angle or rate, a sensor's reading, a field), resolved once against the run
// and read whenever asked. Signals and the I/O map read the plant through probes.

#include <cstdint>
#include <optional>
#include <string>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/colour.h"
#include "gdpn/net/net.h"
#include "gdpn/scene/node.h"

namespace gdpn::model {

class Simulation;

/// A quantity of a run, resolved.
struct Probe {
  /// What it reads.
  enum class What : std::uint8_t {
    Tokens,      ///< a place's tokens, all its slots
    Count,       ///< how many tokens of one value a place's value slot holds
    Amount,      ///< a continuous place's amount, in its unit
    Position,    ///< a node's world position, m
    Velocity,    ///< a body's linear velocity, m/s
    JointAngle,  ///< a joint's position on axis 1 (the model's angle unit, or m for a slider)
    JointRate,   ///< its rate on axis 1 (per second)
    Reading,     ///< a sensor's main number (its kind's `primary` channel: a Region's count, a distance)
    Channel,     ///< one of a sensor's channels that gives numbers: a number, a flag (1 or 0), a vector
    Active,      ///< a sensor's: 1 while it feels something (a Region holds, a RangeFinder sees), else 0
    Key,         ///< a KeyboardSensor's: 1 while `key` is held down, else 0
    ItemDatum,   ///< a sensor's: what its first item (`all`: all its items, summed) holds as `key` (see nodeProbe)
    Field,       ///< one of the node's number or bool fields
  };
  What what = What::Tokens;
  net::PlaceId place{0};         ///< Tokens, Count, Amount: the place
  net::PlaceSlotId slot{0};       ///< Count: its value slot
  net::Value value;               ///< Count: the value counted
  scene::NodeHandle node = 0;     ///< the node
  std::size_t field = 0;          ///< Field: its index; Channel: the channel's
  bool vector = false;            ///< Channel: a vector's (three numbers, or `axis` alone)
  bool degrees = false;           ///< Channel: an angular rate given in deg/s
  std::string key;                ///< Key: the key's name; ItemDatum: the datum's (or number field's)
  std::optional<std::string> match;  ///< ItemDatum: 1 for an item whose datum reads as this text, else 0
  bool all = false;               ///< ItemDatum: every item summed, not the first
  bool linear = false;            ///< a slider's angle and rate: metres, never degrees
  int axis = -1;                  ///< Position, Velocity, a vector Channel: 0, 1, 2 for x, y, z alone; -1 for all three
  /// How many numbers it gives: 3 for a whole position, velocity or vector channel, else 1.
  [[nodiscard]] int width() const {
    return (what == What::Position || what == What::Velocity || (what == What::Channel && vector)) && axis < 0 ? 3 : 1;
  }
};

/// The tokens on the place named `place` (qualified), or its amount for a continuous place;
/// nullopt and `why` when there is none.
std::optional<Probe> placeProbe(const Simulation& sim, const std::string& place, std::string& why);

/// Turns place probe `p` (Tokens) into one that counts the tokens of a single value (Count):
/// `text`, in the inscription language with its first character at `at`, is parsed, checked to
/// be one value of the colour set of the place's value slot, and evaluated. The place must have
/// exactly one value slot. Mistakes go to `diags`, located in the text, each message after
/// `context` (`signal 'idle': `); false when there was one.
bool countValue(const Simulation& sim, Probe& p, const std::string& text, const core::SourceLoc& at,
                const std::string& context, core::Diagnostics& diags);

/// Quantity `quantity` of the plant's node `path`: `position`, `velocity` (each also `.x`,
/// `.y`, `.z` alone), `angle`, `rate`, `reading`, `active`, a sensor's channel that gives
/// numbers (`distance`, `acceleration`, `acceleration.z`), `item.KEY` (a sensor's first item's
/// user datum KEY as a number, else its number field KEY: a colour sensor's code, a body's
/// mass), `item.KEY=TEXT` (1 when that datum reads TEXT: an inductive sensor's `material=metal`),
/// `items.KEY` and `items.KEY=TEXT` (the same summed over every item: a scale's `items.mass`,
/// a count), or a number or bool field's name.
/// Nullopt and `why` (naming what the node has) when it does not have it.
std::optional<Probe> nodeProbe(const Simulation& sim, const std::string& path, const std::string& quantity,
                               std::string& why);

/// Whether `key` is held down at KeyboardSensor `path`; nullopt and `why` when it is none.
std::optional<Probe> keyProbe(const Simulation& sim, const std::string& path, const std::string& key, std::string& why);

/// A bool, whole number or number field value as a number (a bool as 1 or 0); 0 for any other.
double numberOf(const scene::FieldValue& v);

/// Reads `p` into `out` (p.width() numbers); false when its node has been deleted.
bool readProbe(const Simulation& sim, const Probe& p, double* out);

}  // namespace gdpn::model
