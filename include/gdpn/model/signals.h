#pragma once
/// \file
/// Signals: what a run records over time (a place's tokens, a node's position or field, a
/// joint's angle, a sensor's reading, a Python expression), sampled at a period, and written
/// as a table (CSV) or handed to Python as columns.

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"

namespace gdpn::model {

/// One signal of the `signals` section (or of `--signal`).
struct SignalSpec {
  /// What the signal reads.
  enum class Kind : std::uint8_t {
    Place,       ///< `place: NAME`: the tokens on a place (all its slots), or with `value` one value's
    Node,        ///< `node: PATH, of: QUANTITY`: a scene node's quantity (below)
    Expression,  ///< `expression: PYTHON`: a number from the model's globals
  };
  std::string name;      ///< the column's name (an identifier in the section; the text of a --signal)
  Kind kind = Kind::Place;  ///< what it reads
  std::string target;    ///< the place's qualified name, the node's path, or the expression
  /// for a node: `position` (world, m: three columns), `velocity` (a body's, m/s: three
  /// columns), `angle` and `rate` (a joint's axis 1, in the model's angle unit, or m and m/s
  /// for a slider), `reading` (a sensor's: a Region's count of items, a RangeFinder's
  /// distance, a TimeSensor's ticks), or the name of one of its number fields
  std::string quantity;
  /// for a place: a value of its value slot's colour set, in the inscription language
  /// (`lathe`, `(lathe, shaft)`, `{id = 1, kind = shaft}`, `3`); the signal is then how many
  /// tokens of that value the slot holds. Empty: the place's tokens, all its slots together
  std::string value;
  core::SourceLoc value_loc;  ///< where `value`'s first character is written
  double every = 0.0;    ///< sampling period, seconds (0: every step)
  core::SourceLoc loc;   ///< where it was written
  friend bool operator==(const SignalSpec& a, const SignalSpec& b) {
    return a.name == b.name && a.kind == b.kind && a.target == b.target && a.quantity == b.quantity &&
           a.value == b.value && a.every == b.every;
  }
};

/// Parses a --signal argument: `place:NAME`, `place:NAME=VALUE` (one value's tokens: VALUE in
/// the inscription language, its syntax checked here), `node:PATH.QUANTITY` or
/// `python:EXPRESSION` (the text after the colon names the column). Nullopt with `why` when it
/// is none of these.
std::optional<SignalSpec> parseSignalArgument(const std::string& argument, std::string& why);

/// The samples of a run: a time column and one column per signal value (a position gives
/// three: `name.x`, `name.y`, `name.z`). A signal not sampled at a row's time has no value.
struct SignalTable {
  std::vector<std::string> columns;                      ///< the value columns, in signal order
  std::vector<double> time;                              ///< per row, seconds
  std::vector<std::vector<std::optional<double>>> rows;  ///< per row, one per column
  /// Writes the table as CSV: a header `time,<columns>`, a row per sample time, a value as
  /// its shortest exact decimal and an empty cell where a signal was not sampled.
  void writeCsv(std::ostream& out) const;
};

}  // namespace gdpn::model
