#pragma once
/// \file
/// Replay files: the actions a headless IDE performs, one a list item in YAML (docs/ide.md):
/// select, press a control, fire, run for a time, press keys, click or drag at a point, set a
/// field, undo, redo, choose a view, take a screenshot. Reading only; the IDE performs them.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"

namespace gdpn::ide {

/// What an action does.
enum class ActionKind : std::uint8_t {
  Select,      ///< `select: NAME`: a node path, else a place, transition or instance name
  Press,       ///< `press: NAME`: an action of the table by its name (gdpn/ide/actions.h: save, undo, run, ...)
  Fire,        ///< `fire: TRANSITION`
  RunFor,      ///< `run: SECONDS` of model time (whole steps)
  Steps,       ///< `steps: N` steps
  Frames,      ///< `frames: N` frames drawn (the run advancing as Run says, 1/60 s a frame);
               ///< `frames: {count: N, seconds: S}`: each frame S wall seconds long (a slow machine)
  Key,         ///< `key: CHORDS` over the world view: each chord (`s`, `enter`, `ctrl+s`,
               ///< `ctrl+shift+s`; several separated by spaces, `ctrl+a x`) pressed and released,
               ///< all before one frame, through the input queue that gives each press and release
               ///< a frame; a-z, 0-9 and space type their character unless Ctrl, Alt or Super is
               ///< held. `hold: NAME` presses one key (a modifier too) and keeps it down,
               ///< `release: NAME` lets it go (field: hold, release)
  Type,        ///< `type: TEXT`: the characters typed into the field that has the keyboard
  Click,       ///< `click: [X, Y]` window pixels, left button; `click: {at: [X, Y], button: right}`
  Drag,        ///< `drag: {from: [X, Y], to: [X, Y], button: left|right|middle}`; with `hold: true`
               ///< the button stays down at `to` (a screenshot shows the drag under way) and the
               ///< next drag goes on from there
               ///< (a point of Click and Drag may also be an item the last frame's report placed,
               ///< named by the keys that lead to it: `click: [tree, rows, belt]`)
  Wheel,       ///< `wheel: {at: [X, Y], clicks: N}`: the mouse wheel turned N clicks (negative: back) there
  Set,         ///< `set: {node: PATH, field: NAME, value: V}` through the inspector's command
  View,        ///< `view: front|back|left|right|top|iso|frame|all` or a Camera node's path
  Screenshot,  ///< `screenshot: FILE.png` of the whole window
  Break,       ///< `break: {starts: T}`, `{completes: T}`, `{place: P, at_least: N}` or `{when: PYTHON}`
};

/// One action, where it was written.
struct Action {
  ActionKind kind = ActionKind::Select;  ///< what it does
  std::string text;            ///< the name, control, key, file, node path or view
  std::string field;           ///< Set: the field; Break: starts, completes, place, when, or written (`text` in gdpn run --break's syntax)
  std::vector<std::string> value;  ///< Set: the value's words (one for a scalar, more for a list)
  bool list = false;           ///< Set: the value was a list
  bool quoted = false;         ///< Set: the value was quoted (text, for a datum)
  double number = 0;           ///< RunFor: seconds; Steps, Frames: the count; Break: at_least; Wheel: clicks
  double seconds = 0;          ///< Frames: the wall seconds each frame stands for (0: 1/60 s)
  double x = 0, y = 0;         ///< Click, Drag, Wheel: the point (Drag: where it starts), pixels
  double x2 = 0, y2 = 0;       ///< Drag: where it ends, pixels
  int button = 0;              ///< Click, Drag: 0 left, 1 right, 2 middle
  bool hold = false;           ///< Drag: the button stays down at the end
  std::vector<std::string> on;   ///< Click, Drag: the report's keys to the item at (x, y), when named so
  std::vector<std::string> on2;  ///< Drag: the report's keys to the item at (x2, y2), when named so
  core::SourceLoc loc;         ///< where it was written
};

/// The actions in the replay file at `path`; nullopt with located errors when it has mistakes.
std::optional<std::vector<Action>> loadReplay(const std::string& path, core::Diagnostics& diags);
/// The same from text; `file` names it in diagnostics.
std::optional<std::vector<Action>> parseReplay(const std::string& text, const std::string& file,
                                               core::Diagnostics& diags);

}  // namespace gdpn::ide
