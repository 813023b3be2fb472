#pragma once
// Internal: no promises. The `scene` section of a model file.

#include <memory>

#include "gdpn/scene/node.h"
#include "yaml_reader.h"

namespace gdpn::model::detail {

/// Reads a scene section (a list of nodes written `- Type: {fields, name, children}`),
/// reporting every mistake through `r`; angles are written in `angles`. Returns the scene,
/// with what could be read.
std::shared_ptr<scene::Scene> readScene(const YAML::Node& list, YamlReader& r, const core::SourceLoc& at,
                                        scene::AngleUnit angles);

/// Writes `scene`'s nodes below its root in canonical form: a node without children as a
/// flow map of its non-default fields, one with children as a block map; angles in `angles`.
void writeScene(YAML::Emitter& out, const scene::Scene& scene, scene::AngleUnit angles);

}  // namespace gdpn::model::detail
