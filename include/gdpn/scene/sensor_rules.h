#pragma once
/// \file
/// The rules between a sensor's fields that no one field's range can say: a camera's far
/// beyond its near and within 100,000 times it, a laser's angles apart. Checked when a model
/// is loaded and whenever a field is set from outside (a script, the I/O map, the IDE).

#include <cstddef>
#include <limits>
#include <string>

#include "gdpn/scene/node.h"

namespace gdpn::scene {

/// The largest far / near of a camera: at far = 1e5 near, a 24-bit depth buffer tells apart
/// distances about 1/170 of the distance apart at far, 1/1,700 at a tenth of far.
inline constexpr double kMaxDepthRange = 1e5;

/// A broken rule between the fields of a sensor node: what is wrong, and the field to point at.
struct SensorRule {
  std::string message;  ///< "" when every rule holds
  std::size_t field = 0;  ///< index in the node's type().fields of the field to blame
};

/// Field index meaning "no field changes" for sensorRule().
inline constexpr std::size_t kAsItIs = std::numeric_limits<std::size_t>::max();

/// The first rule between the fields of `n` that breaks were field `i` to hold `v` (i =
/// kAsItIs: the node as it stands); an empty message when all hold or `n` has no such rule.
SensorRule sensorRule(const Node& n, std::size_t i, const FieldValue& v);

}  // namespace gdpn::scene
