#pragma once
// The keys the world view passes to keyboard sensors: their GLFW codes (the index into
// ImGui's io.KeysDown in 1.86) and the names sensors hear ("a", "7", "space", "left").

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gdpn::ide {

/// Every key the sensors hear: GLFW key code and name.
const std::vector<std::pair<int, std::string>>& sensorKeys();
/// The keys only the IDE's shortcuts use (sensors do not hear them): "f1".."f12", "home".
const std::vector<std::pair<int, std::string>>& commandKeys();
/// The GLFW code of the key called `name` (a sensor's or a command's), or -1.
int keyCode(std::string_view name);

}  // namespace gdpn::ide
