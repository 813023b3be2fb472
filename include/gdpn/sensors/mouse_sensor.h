#pragma once
/// \file
/// Which MouseSensors a click reaches: the one rule that the MouseSensor applies to each click
/// it is given (from `gdpn run --input` or the IDE's world view, both through `Hub::push` or
/// `Hub::setInput`) and that the IDE asks to say what a click will do.

#include <vector>

#include "gdpn/core/math.h"
#include "gdpn/scene/actions.h"
#include "gdpn/scene/node.h"

namespace gdpn::sensors {

/// True when a click whose pick ray hit `shape` first reaches MouseSensor node `sensor`: the
/// shape lies in the subtree of the sensor's parent. False for a null shape (the ray hit
/// nothing).
[[nodiscard]] bool clickReaches(const scene::Node& sensor, const scene::Node* shape);

/// What a click along a pick ray hits.
struct ClickTarget {
  scene::Pick hit;                      ///< the shape the ray hits first (from `scene::pick`)
  std::vector<scene::Node*> sensors;    ///< the MouseSensors it reaches (not templates), nearest parent first
};

/// The shape that a click along `ray` (world frame) hits first below `root`, and the
/// MouseSensors that count it, from the last `scene::updateTransforms()`.
[[nodiscard]] ClickTarget clickTarget(scene::Node& root, const core::Ray& ray);

}  // namespace gdpn::sensors
