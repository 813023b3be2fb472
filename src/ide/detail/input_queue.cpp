// The input queue: events in, one frame's worth out.

#include "input_queue.h"

#include <GLFW/glfw3.h>

#include <bitset>

namespace gdpn::ide {

bool isModifierKey(int code) {
  switch (code) {
    case GLFW_KEY_LEFT_SHIFT:
    case GLFW_KEY_RIGHT_SHIFT:
    case GLFW_KEY_LEFT_CONTROL:
    case GLFW_KEY_RIGHT_CONTROL:
    case GLFW_KEY_LEFT_ALT:
    case GLFW_KEY_RIGHT_ALT:
    case GLFW_KEY_LEFT_SUPER:
    case GLFW_KEY_RIGHT_SUPER:
      return true;
    default:
      return false;
  }
}

void InputQueue::key(int code, bool down) {
  if (code < 0 || code >= kKeys) return;
  QueuedEvent e;
  e.kind = QueuedEvent::Kind::Key;
  e.code = code;
  e.down = down;
  pending_.push_back(e);
}

void InputQueue::character(unsigned int c) {
  if (c == 0) return;
  QueuedEvent e;
  e.kind = QueuedEvent::Kind::Character;
  e.character = c;
  pending_.push_back(e);
}

void InputQueue::text(std::string_view utf8) {
  std::size_t i = 0;
  while (i < utf8.size()) {
    const auto lead = static_cast<unsigned char>(utf8[i]);
    // how many bytes the character takes, and the bits its first byte gives
    std::size_t length = 0;
    unsigned int c = 0;
    if (lead < 0x80) {
      length = 1;
      c = lead;
    } else if ((lead & 0xE0U) == 0xC0U) {
      length = 2;
      c = lead & 0x1FU;
    } else if ((lead & 0xF0U) == 0xE0U) {
      length = 3;
      c = lead & 0x0FU;
    } else if ((lead & 0xF8U) == 0xF0U) {
      length = 4;
      c = lead & 0x07U;
    } else {
      ++i;  // a continuation byte with no start
      continue;
    }
    std::size_t n = 1;
    for (; n < length && i + n < utf8.size(); ++n) {
      const auto more = static_cast<unsigned char>(utf8[i + n]);
      if ((more & 0xC0U) != 0x80U) break;
      c = (c << 6U) | (more & 0x3FU);
    }
    if (n == length) character(c);
    i += n;
  }
}

void InputQueue::button(int button, bool down) {
  if (button < 0 || button >= kButtons) return;
  QueuedEvent e;
  e.kind = QueuedEvent::Kind::Button;
  e.code = button;
  e.down = down;
  pending_.push_back(e);
}

void InputQueue::move(float x, float y) {
  QueuedEvent e;
  e.kind = QueuedEvent::Kind::Move;
  e.x = x;
  e.y = y;
  pending_.push_back(e);
}

void InputQueue::scroll(float dx, float dy) {
  QueuedEvent e;
  e.kind = QueuedEvent::Kind::Scroll;
  e.x = dx;
  e.y = dy;
  pending_.push_back(e);
}

bool InputQueue::keyDown(int code) const { return code >= 0 && code < kKeys && keys_[static_cast<std::size_t>(code)]; }

bool InputQueue::buttonDown(int button) const {
  return button >= 0 && button < kButtons && buttons_[static_cast<std::size_t>(button)];
}

bool InputQueue::ctrl() const { return keyDown(GLFW_KEY_LEFT_CONTROL) || keyDown(GLFW_KEY_RIGHT_CONTROL); }
bool InputQueue::shift() const { return keyDown(GLFW_KEY_LEFT_SHIFT) || keyDown(GLFW_KEY_RIGHT_SHIFT); }
bool InputQueue::alt() const { return keyDown(GLFW_KEY_LEFT_ALT) || keyDown(GLFW_KEY_RIGHT_ALT); }
bool InputQueue::super() const { return keyDown(GLFW_KEY_LEFT_SUPER) || keyDown(GLFW_KEY_RIGHT_SUPER); }

InputFrame InputQueue::next() {
  InputFrame frame;
  std::bitset<kKeys> changed;   // keys changed this frame
  std::bitset<kKeys> waiting;   // keys whose release waits for the next frame
  std::bitset<kButtons> clicked;  // buttons changed this frame
  bool typed = false;    // a key other than a modifier pressed, or a character typed
  bool command = false;  // such a key pressed that typed no character (Enter, Ctrl+A)
  bool pointer = false;  // a button changed or the wheel turned
  bool moved = false;    // the mouse moved
  std::vector<bool> taken(pending_.size(), false);
  bool full = false;
  for (std::size_t i = 0; i < pending_.size() && !full; ++i) {
    const QueuedEvent& e = pending_[i];
    switch (e.kind) {
      case QueuedEvent::Kind::Key: {
        const auto k = static_cast<std::size_t>(e.code);
        if (waiting[k]) {
          full = true;
        } else if (e.down == keys_[k]) {
          taken[i] = true;  // it changes nothing (a release of a key pressed before the window had the keyboard)
        } else if (changed[k]) {
          // the release of a key pressed this frame waits for the next while the events behind
          // it go on (typing flows); a modifier's release ends the frame
          if (!e.down && !isModifierKey(e.code)) waiting[k] = true;
          else full = true;
        } else if (isModifierKey(e.code) ? (typed || pointer) : (e.down && (command || clicked.any()))) {
          // a modifier changes only before the keys and clicks it goes with; a key after a key
          // that typed nothing or after a click waits, so that ImGui sees them in order
          full = true;
        } else {
          if (e.down && !isModifierKey(e.code)) {
            const bool types = i + 1 < pending_.size() && pending_[i + 1].kind == QueuedEvent::Kind::Character;
            command = command || !types;
            typed = true;
          }
          keys_[k] = e.down;
          changed[k] = true;
          taken[i] = true;
        }
        break;
      }
      case QueuedEvent::Kind::Character:
        // ImGui reads a frame's characters before its keys: none after Enter or Ctrl+A
        if (command || clicked.any()) {
          full = true;
        } else {
          frame.characters.push_back(e.character);
          typed = true;
          taken[i] = true;
        }
        break;
      case QueuedEvent::Kind::Button: {
        const auto b = static_cast<std::size_t>(e.code);
        if (clicked[b]) {
          full = true;
        } else if (e.down == buttons_[b]) {
          taken[i] = true;
        } else if (typed || (!e.down && moved)) {
          // keys before a click (a click elsewhere ends the field typed into); a button
          // released after a move waits, so that the drag is seen with the button down
          full = true;
        } else {
          buttons_[b] = e.down;
          clicked[b] = true;
          pointer = true;
          frame.mouse = true;
          taken[i] = true;
        }
        break;
      }
      case QueuedEvent::Kind::Move:
        // a click is seen where it happened before the mouse moves on
        if (clicked.any()) {
          full = true;
        } else {
          mouse_x_ = e.x;
          mouse_y_ = e.y;
          moved = true;
          frame.mouse = true;
          taken[i] = true;
        }
        break;
      case QueuedEvent::Kind::Scroll:
        frame.wheel_x += e.x;
        frame.wheel_y += e.y;
        pointer = true;
        taken[i] = true;
        break;
    }
  }
  // what is left waits for the next frames, in order
  std::deque<QueuedEvent> rest;
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    if (taken[i]) {
      ++frame.events;
    } else {
      rest.push_back(pending_[i]);
      const auto kind = pending_[i].kind;
      if (kind == QueuedEvent::Kind::Move || kind == QueuedEvent::Kind::Button) frame.mouse = true;
    }
  }
  pending_ = std::move(rest);
  return frame;
}

}  // namespace gdpn::ide
