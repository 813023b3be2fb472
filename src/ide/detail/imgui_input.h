#pragma once
// The input queue's frames handed to Dear ImGui 1.86: the keys' and buttons' state, the
// modifiers, the characters, the wheel and the mouse's place. The window and the headless IDE
// both feed ImGui this way, never by writing io.KeysDown themselves.

struct ImGuiIO;

namespace gdpn::ide {

class InputQueue;
struct InputFrame;

/// Maps ImGui's named keys (Tab, the arrows, Enter, Backspace, Ctrl+A's A, ...) to GLFW's key
/// codes, as ImGui's GLFW backend does; for the headless IDE, which has no backend.
void mapGlfwKeys(ImGuiIO& io);
/// Hands `frame`, just taken from `queue`, to ImGui before ImGui::NewFrame() (after the GLFW
/// backend's NewFrame, whose mouse buttons it replaces): every key and button as the queue
/// holds them now, Ctrl, Shift, Alt and Super from their keys, the characters in order, the
/// wheel, and the mouse's place when the frame took mouse events or some still wait.
void feedImGui(const InputQueue& queue, const InputFrame& frame, ImGuiIO& io);

}  // namespace gdpn::ide
