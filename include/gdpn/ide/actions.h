#pragma once
/// \file
/// The IDE's actions, described once: each has an id, the name a replay file presses, the label
/// the menus and the toolbar show, its menu, its shortcut and a line of help. The menus, the
/// toolbar, the shortcuts, the Help's list of keys and the replay's `press:` all read this
/// table, so that a new action is one entry here (and one case in the App's switches, which
/// the compiler lists). Pure data: what an action does is the App's (src/ide/action_run.cpp).

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gdpn::ide {

/// Every action of the IDE.
enum class ActionId : std::uint8_t {
  // File
  New, Open, Save, SaveAs, Close, Quit, Restore, Discard, SaveAsPart,
  // Edit
  Undo, Redo, Cut, Copy, Paste, Delete, SelectAll, TurnQuarter, UpdateParts,
  // View
  SwapViews, WorldFull, NetFull, MiniView, Palette, Sensors, Joints, Contacts, Shadows, Grid,
  SelectTool, MoveTool, TurnTool, ScaleTool, AimTool, Snap, LocalAxes, FrameSelection, Screenshot, Movie,
  IoList, ColourSets,
  // Net
  NetSelectTool, NetPlaceTool, NetTransitionTool, NetArcTool, ReverseArc, AlignLeft, AlignTop, DistributeAcross,
  DistributeDown, PageTypeFromSelection, OpenInstance,
  // Run
  Run, Faster, Fastest, Pause, Step, RunN, Fire, PlantOnly, Reset, ClearBreakpoints,
  ReleaseForces, ServeOpcua,
  // Help
  Keys, Guide,
};

/// The menu an action is listed in.
enum class Menu : std::uint8_t { File, Edit, View, Net, Run, Help };

/// The menus in the menu bar's order.
inline constexpr Menu kMenus[] = {Menu::File, Menu::Edit, Menu::View, Menu::Net, Menu::Run, Menu::Help};

/// "File", "Edit", "View", "Net", "Run", "Help".
[[nodiscard]] const char* menuName(Menu menu);

/// A key with modifiers, as a shortcut ("Ctrl+Shift+S").
struct Shortcut {
  std::string key;     ///< the key's name as keys.h names it ("s", "delete", "f5"); "" for none
  bool ctrl = false;   ///< Ctrl held
  bool shift = false;  ///< Shift held
  bool alt = false;    ///< Alt held
};

/// One action's description.
struct ActionInfo {
  ActionId id;             ///< which
  std::string_view name;   ///< what a replay presses (`press: save-as`)
  std::string_view label;  ///< the menus' and the toolbar's word ("Save As...")
  Menu menu;               ///< where it is listed
  std::string_view keys;   ///< its shortcut as shown ("Ctrl+Shift+S"; "" for none)
  bool text_first;         ///< a text field being typed in takes its keys first (Ctrl+C there copies text)
  bool toggle;             ///< it switches something on and off (the menu shows a check mark)
  bool separator_before;   ///< the menu draws a line above it
  std::string_view help;   ///< what it does, for tooltips and the Help's list
};

/// Every action, in the menus' order.
[[nodiscard]] std::span<const ActionInfo> actionInfos();
/// The description of `id`.
[[nodiscard]] const ActionInfo& info(ActionId id);
/// The action a replay calls `name`, if any.
[[nodiscard]] std::optional<ActionId> findAction(std::string_view name);
/// Every action's replay name, separated by ", " (for messages listing what may be pressed).
[[nodiscard]] std::string actionNames();
/// `keys` ("Ctrl+Shift+S") taken apart; nullopt when a part is not a modifier or a key.
[[nodiscard]] std::optional<Shortcut> parseShortcut(std::string_view keys);

}  // namespace gdpn::ide
