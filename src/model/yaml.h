#pragma once
// Internal: no promises. The one include of yaml-cpp for the model module.
// Beware: a map iterator's `it->first` and `it->second` live in a temporary; copy the
// YAML::Node handles (they are cheap) instead of binding references to them.

#include <yaml-cpp/yaml.h>
