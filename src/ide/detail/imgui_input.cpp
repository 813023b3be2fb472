// Feeding ImGui from the input queue.

#include "imgui_input.h"

#include <imgui.h>

#include <GLFW/glfw3.h>

#include "input_queue.h"

namespace gdpn::ide {

void mapGlfwKeys(ImGuiIO& io) {
  io.KeyMap[ImGuiKey_Tab] = GLFW_KEY_TAB;
  io.KeyMap[ImGuiKey_LeftArrow] = GLFW_KEY_LEFT;
  io.KeyMap[ImGuiKey_RightArrow] = GLFW_KEY_RIGHT;
  io.KeyMap[ImGuiKey_UpArrow] = GLFW_KEY_UP;
  io.KeyMap[ImGuiKey_DownArrow] = GLFW_KEY_DOWN;
  io.KeyMap[ImGuiKey_PageUp] = GLFW_KEY_PAGE_UP;
  io.KeyMap[ImGuiKey_PageDown] = GLFW_KEY_PAGE_DOWN;
  io.KeyMap[ImGuiKey_Home] = GLFW_KEY_HOME;
  io.KeyMap[ImGuiKey_End] = GLFW_KEY_END;
  io.KeyMap[ImGuiKey_Insert] = GLFW_KEY_INSERT;
  io.KeyMap[ImGuiKey_Delete] = GLFW_KEY_DELETE;
  io.KeyMap[ImGuiKey_Backspace] = GLFW_KEY_BACKSPACE;
  io.KeyMap[ImGuiKey_Space] = GLFW_KEY_SPACE;
  io.KeyMap[ImGuiKey_Enter] = GLFW_KEY_ENTER;
  io.KeyMap[ImGuiKey_Escape] = GLFW_KEY_ESCAPE;
  io.KeyMap[ImGuiKey_KeyPadEnter] = GLFW_KEY_KP_ENTER;
  io.KeyMap[ImGuiKey_A] = GLFW_KEY_A;
  io.KeyMap[ImGuiKey_C] = GLFW_KEY_C;
  io.KeyMap[ImGuiKey_V] = GLFW_KEY_V;
  io.KeyMap[ImGuiKey_X] = GLFW_KEY_X;
  io.KeyMap[ImGuiKey_Y] = GLFW_KEY_Y;
  io.KeyMap[ImGuiKey_Z] = GLFW_KEY_Z;
}

void feedImGui(const InputQueue& queue, const InputFrame& frame, ImGuiIO& io) {
  for (int k = 0; k < InputQueue::kKeys; ++k) io.KeysDown[k] = queue.keyDown(k);
  io.KeyCtrl = queue.ctrl();
  io.KeyShift = queue.shift();
  io.KeyAlt = queue.alt();
  io.KeySuper = queue.super();
  for (int b = 0; b < InputQueue::kButtons; ++b) io.MouseDown[b] = queue.buttonDown(b);
  io.MouseWheelH += frame.wheel_x;
  io.MouseWheel += frame.wheel_y;
  for (const unsigned int c : frame.characters) io.AddInputCharacter(c);
  if (frame.mouse) io.MousePos = {queue.mouseX(), queue.mouseY()};
}

}  // namespace gdpn::ide
