#pragma once
/// \file
/// How paths to scene nodes are told to the user when they find nothing.

#include <string>
#include <string_view>

namespace gdpn::scene {

/// Why `path` finds no node of a scene: "no scene node 'x'", with how a node without a name
/// is addressed (its index among its siblings: "#2/box"), the mistake most often made.
[[nodiscard]] std::string noSceneNode(std::string_view path);

}  // namespace gdpn::scene
