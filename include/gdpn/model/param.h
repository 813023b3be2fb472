#pragma once
/// \file
/// A model's named numbers: the `params` section, and what a run sets from outside.

#include <optional>
#include <string>

#include "gdpn/core/diagnostics.h"

namespace gdpn::model {

/// A named value of the `params` section: scripts read it (`sim.params.belt_speed`), fields
/// refer to it (`speed: $belt_speed`), and a run may set it (`gdpn run --param`).
struct Param {
  std::string name;         ///< an identifier
  double value = 0.0;       ///< in effect: the file's, or what the run set
  double declared = 0.0;    ///< what the file says (what a saver writes)
  bool integer = false;     ///< a whole number (written without a point); only whole values
  std::string unit;         ///< free text for people ("m/s"); not converted
  std::string description;  ///< free text
  core::SourceLoc loc;      ///< where it was declared
  /// Same declaration (the value in effect and the location are not compared).
  friend bool operator==(const Param& x, const Param& y) {
    return x.name == y.name && x.declared == y.declared && x.integer == y.integer && x.unit == y.unit &&
           x.description == y.description;
  }
};

/// A parameter set from outside the file: `--param NAME=VALUE`, Python's `params=`.
struct ParamOverride {
  std::string name;  ///< the parameter
  std::string text;  ///< its value as written ("0.8")
  std::string where = "--param";  ///< what to name in a diagnostic
};

/// How a file writes what a number refers to: a parameter's name as `$name`, an expression
/// as written (`=length/2`).
inline std::string referenceText(const std::string& bound) {
  return !bound.empty() && bound[0] == '=' ? bound : "$" + bound;
}

/// Parses "NAME=VALUE" (a --param argument); nullopt when there is no '='.
std::optional<ParamOverride> parseParamArgument(const std::string& argument);

}  // namespace gdpn::model
