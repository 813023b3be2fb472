#pragma once
// Keys as a replay names them: a key ("s", "enter", "ctrl"), a chord of modifiers and a key
// ("ctrl+shift+s"), and several chords in a row ("ctrl+a x y", as xdotool's key takes them);
// each queued pressed and released, with the character it types, as a keyboard would.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gdpn::ide {

class InputQueue;

/// A key pressed with the modifiers held down around it.
struct KeyChord {
  int key = -1;                ///< GLFW's code of the key
  std::vector<int> modifiers;  ///< GLFW's codes of the modifiers, pressed in this order before the key
  unsigned int character = 0;  ///< what it types (0: nothing): a to z (A to Z with Shift), 0 to 9 and
                               ///< space, unless Ctrl, Alt or Super is held
};

/// The GLFW code of the key called `name`: a key keyboard sensors hear (keys.h), "ctrl",
/// "shift", "alt", "super" (the left ones), "backspace", "home", "end", "insert", "page_up",
/// "page_down"; -1 when none.
int keyByName(std::string_view name);
/// The names keyByName() knows, for messages ("a-z, 0-9, space, ...").
std::string knownKeyNames();
/// The chords of `text`, separated by spaces; nullopt with `error` naming the unknown key.
std::optional<std::vector<KeyChord>> parseChords(std::string_view text, std::string& error);
/// Queues `chord` pressed and released: the modifiers down, the key down and its character,
/// the key up, the modifiers up (the last first).
void queueChord(InputQueue& queue, const KeyChord& chord);

}  // namespace gdpn::ide
