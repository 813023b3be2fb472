#pragma once
// The platform's input events, in the order they came, handed to ImGui a frame at a time so
// that none is lost. Dear ImGui 1.86 reads the keys' and the mouse buttons' state once a frame:
// a key pressed and released between two frames (xdotool's 12 ms Ctrl+S, a quick Enter) would
// never be seen. A frame takes the events from the front of the queue until one would change
// what the UI sees of the frame: a second change of a key or button (the release of a key
// pressed this frame waits for the next; the events behind it go on), a modifier changing after
// a key, a character or a click of this frame, a character after a key that types none (Enter,
// Ctrl+A: ImGui reads a frame's characters before its keys), keys and clicks together, the mouse
// moving on from a click or a button released where it was dragged. No ImGui, no GLFW: the
// codes are GLFW's, the platform (window.cpp, headless.cpp) hands each frame to ImGui
// (imgui_input.h).

#include <array>
#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string_view>
#include <vector>

namespace gdpn::ide {

/// One event from the platform.
struct QueuedEvent {
  /// What happened.
  enum class Kind : std::uint8_t {
    Key,        ///< a key pressed or released: `code` (GLFW's key code), `down`
    Character,  ///< a character typed: `character` (a Unicode code point)
    Button,     ///< a mouse button pressed or released where the mouse is: `code` (0 left, 1 right, 2 middle), `down`
    Move,       ///< the mouse moved to (`x`, `y`), window pixels from the top-left corner
    Scroll,     ///< the wheel turned `x` clicks sideways and `y` clicks forward
  };
  Kind kind = Kind::Key;       ///< what happened
  int code = 0;                ///< Key: GLFW's key code; Button: the button
  bool down = false;           ///< Key, Button: pressed (true) or released
  unsigned int character = 0;  ///< Character: the code point
  float x = 0, y = 0;          ///< Move: where the mouse is, pixels; Scroll: clicks
};

/// What one frame takes from the queue besides the keys' and buttons' state the queue holds.
struct InputFrame {
  std::vector<unsigned int> characters;  ///< typed, in order
  float wheel_x = 0, wheel_y = 0;        ///< clicks of the wheel, sideways and forward
  /// The frame took mouse events, or mouse events still wait: the mouse is where the queue
  /// says (InputQueue::mouseX, mouseY), not where the platform sees it now.
  bool mouse = false;
  std::size_t events = 0;  ///< how many events the frame took
};

/// The events not yet seen by the UI, and the keys' and buttons' state as the UI has seen them.
class InputQueue {
 public:
  static constexpr int kKeys = 512;   ///< key codes 0 to 511 (ImGui 1.86's io.KeysDown)
  static constexpr int kButtons = 5;  ///< mouse buttons 0 to 4 (io.MouseDown)

  /// Key `code` (GLFW's) pressed or released; codes outside 0 to 511 are ignored.
  void key(int code, bool down);
  /// A character typed (a Unicode code point; 0 is ignored).
  void character(unsigned int c);
  /// Each character of the UTF-8 `text` (a byte that starts no character is skipped).
  void text(std::string_view utf8);
  /// Mouse button `button` pressed or released where the mouse is; others are ignored.
  void button(int button, bool down);
  /// The mouse moved to (`x`, `y`), window pixels.
  void move(float x, float y);
  /// The wheel turned `dx` clicks sideways and `dy` forward.
  void scroll(float dx, float dy);

  /// Takes the next frame's events from the queue (at least one when it holds any) and
  /// changes the keys', buttons' and mouse's state by them.
  InputFrame next();
  /// True when every event has been taken.
  [[nodiscard]] bool empty() const { return pending_.empty(); }
  /// Whether key `code` is down as the frames taken so far left it.
  [[nodiscard]] bool keyDown(int code) const;
  /// Whether mouse button `button` is down as the frames taken so far left it.
  [[nodiscard]] bool buttonDown(int button) const;
  /// Whether either Control key is down.
  [[nodiscard]] bool ctrl() const;
  /// Whether either Shift key is down.
  [[nodiscard]] bool shift() const;
  /// Whether either Alt key is down.
  [[nodiscard]] bool alt() const;
  /// Whether either Super key is down.
  [[nodiscard]] bool super() const;
  /// Where the mouse is as the frames taken so far left it, window pixels (at first -FLT_MAX:
  /// nowhere, as ImGui says it).
  [[nodiscard]] float mouseX() const { return mouse_x_; }
  /// See mouseX().
  [[nodiscard]] float mouseY() const { return mouse_y_; }

 private:
  std::deque<QueuedEvent> pending_;
  std::array<bool, kKeys> keys_{};
  std::array<bool, kButtons> buttons_{};
  float mouse_x_ = -FLT_MAX, mouse_y_ = -FLT_MAX;
};

/// True for GLFW's codes of the Shift, Control, Alt and Super keys, left and right.
bool isModifierKey(int code);

}  // namespace gdpn::ide
