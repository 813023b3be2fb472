#pragma once
// Internal: no promises. The `scene` section of a model file.

#include <memory>

#include "gdpn/scene/node.h"
#include "yaml_reader.h"

namespace gdpn::model::detail {

/// Reads a scene section (a list of nodes written `- Type: {fields, name, children}`),
/// reporting every mistake through `r`. Returns the scene, with what could be read.
std::shared_ptr<scene::Scene> readScene(const YAML::Node& list, YamlReader& r, const core::SourceLoc& at);

/// Writes `scene`'s nodes below its root in canonical form: a node without children as a
/// flow map of its non-default fields, one with children as a block map.
void writeScene(YAML::Emitter& out, const scene::Scene& scene);

}  // namespace gdpn::model::detail
