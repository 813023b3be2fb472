// Key chords: named keys with their modifiers, queued as a keyboard sends them.

#include "key_chord.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <utility>

#include "input_queue.h"
#include "keys.h"

namespace gdpn::ide {

namespace {

/// The keys a replay may name beyond those the sensors hear: modifiers and editing keys.
const std::vector<std::pair<int, std::string>>& chordOnlyKeys() {
  static const std::vector<std::pair<int, std::string>> keys = {
      {GLFW_KEY_LEFT_CONTROL, "ctrl"}, {GLFW_KEY_LEFT_SHIFT, "shift"}, {GLFW_KEY_LEFT_ALT, "alt"},
      {GLFW_KEY_LEFT_SUPER, "super"},  {GLFW_KEY_BACKSPACE, "backspace"}, {GLFW_KEY_HOME, "home"},
      {GLFW_KEY_END, "end"},           {GLFW_KEY_INSERT, "insert"},       {GLFW_KEY_PAGE_UP, "page_up"},
      {GLFW_KEY_PAGE_DOWN, "page_down"},
  };
  return keys;
}

/// The character key `code` types with `modifiers` held (0: none).
unsigned int characterOf(int code, const std::vector<int>& modifiers) {
  bool shift = false;
  for (const int m : modifiers) {
    if (m != GLFW_KEY_LEFT_SHIFT) return 0;  // Ctrl, Alt and Super type nothing
    shift = true;
  }
  if (code >= GLFW_KEY_A && code <= GLFW_KEY_Z) return static_cast<unsigned int>((shift ? 'A' : 'a') + (code - GLFW_KEY_A));
  if (shift) return 0;
  if (code >= GLFW_KEY_0 && code <= GLFW_KEY_9) return static_cast<unsigned int>('0' + (code - GLFW_KEY_0));
  if (code == GLFW_KEY_SPACE) return ' ';
  return 0;
}

}  // namespace

int keyByName(std::string_view name) {
  const int code = keyCode(name);
  if (code >= 0) return code;
  for (const auto& [c, n] : chordOnlyKeys()) {
    if (n == name) return c;
  }
  return -1;
}

std::string knownKeyNames() {
  return "a-z, 0-9, space, enter, escape, tab, left, right, up, down, delete, backspace, home, end, insert, page_up, "
         "page_down, ctrl, shift, alt, super; a chord such as ctrl+shift+s";
}

std::optional<std::vector<KeyChord>> parseChords(std::string_view text, std::string& error) {
  std::vector<KeyChord> chords;
  std::size_t at = 0;
  while (at < text.size()) {
    if (text[at] == ' ') {
      ++at;
      continue;
    }
    const auto end = std::min(text.find(' ', at), text.size());
    const auto word = text.substr(at, end - at);
    at = end;
    // the names before the last '+' are modifiers, the last the key
    KeyChord chord;
    std::size_t from = 0;
    while (true) {
      const auto plus = word.find('+', from);
      const auto name = word.substr(from, plus == std::string_view::npos ? std::string_view::npos : plus - from);
      const int code = keyByName(name);
      if (code < 0) {
        error = "unknown key '" + std::string(name.empty() ? word : name) + "' (" + knownKeyNames() + ")";
        return std::nullopt;
      }
      if (plus == std::string_view::npos) {
        chord.key = code;
        break;
      }
      if (!isModifierKey(code)) {
        error = "'" + std::string(name) + "' in '" + std::string(word) + "' is no modifier (ctrl, shift, alt, super)";
        return std::nullopt;
      }
      chord.modifiers.push_back(code);
      from = plus + 1;
    }
    chord.character = characterOf(chord.key, chord.modifiers);
    chords.push_back(std::move(chord));
  }
  if (chords.empty()) {
    error = "expects a key (" + knownKeyNames() + ")";
    return std::nullopt;
  }
  return chords;
}

void queueChord(InputQueue& queue, const KeyChord& chord) {
  for (const int m : chord.modifiers) queue.key(m, true);
  queue.key(chord.key, true);
  queue.character(chord.character);
  queue.key(chord.key, false);
  for (auto m = chord.modifiers.rbegin(); m != chord.modifiers.rend(); ++m) queue.key(*m, false);
}

}  // namespace gdpn::ide
