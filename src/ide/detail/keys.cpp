// Key names for keyboard sensors.

#include "keys.h"

#include <GLFW/glfw3.h>

#include <string>

namespace gdpn::ide {

const std::vector<std::pair<int, std::string>>& sensorKeys() {
  static const auto keys = [] {
    std::vector<std::pair<int, std::string>> k;
    for (int c = GLFW_KEY_A; c <= GLFW_KEY_Z; ++c) k.emplace_back(c, std::string(1, static_cast<char>('a' + c - GLFW_KEY_A)));
    for (int c = GLFW_KEY_0; c <= GLFW_KEY_9; ++c) k.emplace_back(c, std::string(1, static_cast<char>('0' + c - GLFW_KEY_0)));
    k.emplace_back(GLFW_KEY_SPACE, "space");
    k.emplace_back(GLFW_KEY_ENTER, "enter");
    k.emplace_back(GLFW_KEY_ESCAPE, "escape");
    k.emplace_back(GLFW_KEY_TAB, "tab");
    k.emplace_back(GLFW_KEY_LEFT, "left");
    k.emplace_back(GLFW_KEY_RIGHT, "right");
    k.emplace_back(GLFW_KEY_UP, "up");
    k.emplace_back(GLFW_KEY_DOWN, "down");
    k.emplace_back(GLFW_KEY_DELETE, "delete");
    return k;
  }();
  return keys;
}

const std::vector<std::pair<int, std::string>>& commandKeys() {
  static const auto keys = [] {
    std::vector<std::pair<int, std::string>> k;
    for (int f = 1; f <= 12; ++f) k.emplace_back(GLFW_KEY_F1 + f - 1, "f" + std::to_string(f));
    k.emplace_back(GLFW_KEY_HOME, "home");
    return k;
  }();
  return keys;
}

int keyCode(std::string_view name) {
  for (const auto* keys : {&sensorKeys(), &commandKeys()}) {
    for (const auto& [code, n] : *keys) {
      if (n == name) return code;
    }
  }
  return -1;
}

}  // namespace gdpn::ide
