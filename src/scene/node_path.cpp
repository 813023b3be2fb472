#include "gdpn/scene/node_path.h"

namespace gdpn::scene {

std::string noSceneNode(std::string_view path) {
  return "no scene node '" + std::string(path) +
         "' (a node without a name is addressed by its index among its siblings: '#2', '#2/box')";
}

}  // namespace gdpn::scene
