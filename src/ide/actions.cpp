// The table of the IDE's actions: names, labels, menus, shortcuts and help.

#include "gdpn/ide/actions.h"

#include <array>
#include <cctype>

namespace gdpn::ide {

namespace {

using A = ActionId;
using M = Menu;

// id, name, label, menu, keys, text_first, toggle, separator_before, help
constexpr ActionInfo kActions[] = {
    {A::New, "new", "New", M::File, "Ctrl+N", false, false, false, "Start a new, empty model"},
    {A::Open, "open", "Open...", M::File, "Ctrl+O", false, false, false,
     "Open a model file, chosen in the file browser"},
    {A::Save, "save", "Save", M::File, "Ctrl+S", false, false, true, "Save the model to its file"},
    {A::SaveAs, "save-as", "Save As...", M::File, "Ctrl+Shift+S", false, false, false,
     "Save the model under another name, which it keeps"},
    {A::SaveAsPart, "save-as-part", "Save as Part...", M::File, "", false, false, false,
     "Save the selected scene node, with what it holds, as a new part in your parts folder ($XDG_DATA_HOME/gdpn/parts): the palette lists it"},
    {A::Close, "close", "Close", M::File, "Ctrl+W", false, false, false,
     "Close the model (a new, empty one takes its place)"},
    {A::Restore, "restore", "Restore Autosave", M::File, "", false, false, true,
     "Put the newer autosave found at the start in place of the model (undoable)"},
    {A::Discard, "discard", "Discard Autosave", M::File, "", false, false, false,
     "Remove the newer autosave found at the start"},
    {A::Quit, "quit", "Quit", M::File, "Ctrl+Q", false, false, true, "Close the IDE"},

    {A::Undo, "undo", "Undo", M::Edit, "Ctrl+Z", true, false, false, "Undo the last edit"},
    {A::Redo, "redo", "Redo", M::Edit, "Ctrl+Y", true, false, false, "Redo the last edit undone"},
    {A::Cut, "cut", "Cut", M::Edit, "Ctrl+X", true, false, true,
     "Copy the selected node's subtree, place or transition and delete it"},
    {A::Copy, "copy", "Copy", M::Edit, "Ctrl+C", true, false, false,
     "Copy the selected node's subtree, place or transition (as a model file)"},
    {A::Paste, "paste", "Paste", M::Edit, "Ctrl+V", true, false, false,
     "Paste a model file's nodes under the selected node (beside it, or at the top), its places and transitions into the net view's page"},
    {A::Delete, "delete", "Delete", M::Edit, "Delete", true, false, false,
     "Delete the selected node, or place or transition with its arcs"},
    {A::SelectAll, "select-all", "Select All", M::Edit, "Ctrl+A", true, false, false,
     "Select every place, transition, arc and instance of the net view's page"},
    {A::TurnQuarter, "turn-quarter", "Turn a Quarter", M::Edit, "R", false, false, false,
     "Turn the selected part (or Transform) a quarter round, anticlockwise seen from above, about its origin"},
    {A::UpdateParts, "update-parts", "Update Parts...", M::Edit, "", false, false, true,
     "Take the library's newer versions of the model's parts (what they change in the I/O is listed first)"},

    {A::SwapViews, "swap-views", "Swap World and Net", M::View, "", false, true, false,
     "Put the net view where the world view is, and the world view where the net view is"},
    {A::WorldFull, "world-full", "World Fills the Window", M::View, "F11", false, true, false,
     "The world view alone, in the whole window (again: back to the panels)"},
    {A::NetFull, "net-full", "Net Fills the Window", M::View, "F12", false, true, false,
     "The net view alone, in the whole window (again: back to the panels)"},
    {A::MiniView, "mini-view", "Mini Net View", M::View, "", false, true, false,
     "The net, fitted, in a small window over the world view"},
    {A::Palette, "palette", "Parts Palette", M::View, "", false, true, false,
     "The library's parts under the tree view: drag one into the world view to place it"},
    {A::IoList, "io-list", "I/O List", M::View, "", false, true, false,
     "Every part's inputs and outputs in the inspector's panel: live values, forces, what uses each, PLC addresses"},
    {A::ColourSets, "colour-sets", "Colour Sets", M::View, "", false, true, false,
     "The model's colour sets and variables in the inspector's panel: declare, edit and delete them"},
    {A::Sensors, "sensors", "Sensor Volumes", M::View, "", false, true, true, "Draw the sensors' volumes and rays"},
    {A::Joints, "joints", "Joint Axes", M::View, "", false, true, false, "Draw the joints' axes"},
    {A::Contacts, "contacts", "Contact Points", M::View, "", false, true, false,
     "Mark the contact points of the last step"},
    {A::Shadows, "shadows", "Shadows", M::View, "", false, true, false, "Let the main light cast shadows"},
    {A::Grid, "grid", "Ground Grid", M::View, "", false, true, false, "Draw the ground grid"},
    {A::SelectTool, "select-tool", "Select Tool", M::View, "", false, true, true,
     "A drag over the world view turns the view"},
    {A::MoveTool, "move-tool", "Move Tool", M::View, "", false, true, false,
     "Arrows along three axes move the selected node"},
    {A::TurnTool, "turn-tool", "Turn Tool", M::View, "", false, true, false,
     "Rings about three axes turn the selected node"},
    {A::ScaleTool, "scale-tool", "Scale Tool", M::View, "", false, true, false,
     "Tabs on a box's faces scale it along one axis, on its edges along two"},
    {A::AimTool, "aim-tool", "Aim Tool", M::View, "", false, true, false,
     "A spot light's dot aims it (dropped on a shape: at that shape), its square sizes its cone"},
    {A::Snap, "snap", "Snap", M::View, "", false, true, false, "Moves and turns go in steps"},
    {A::LocalAxes, "local-axes", "Local Axes", M::View, "", false, true, false,
     "The handles follow the node's own axes"},
    {A::FrameSelection, "frame", "Frame Selection", M::View, "Home", false, false, true,
     "Point the world view at the selected node (the whole scene when none)"},
    {A::Screenshot, "screenshot", "Screenshot", M::View, "", false, false, true,
     "Save the window as gdpn-ide-N.png in the current folder"},
    {A::Movie, "movie", "Movie", M::View, "", false, true, false,
     "Film the window into gdpn-ide-N.mp4 in the current folder (again: stop)"},

    {A::NetSelectTool, "net-select", "Select Tool", M::Net, "S", false, true, false,
     "A click selects, Shift or Ctrl adds; a drag moves the selection, or on paper draws a rubber band"},
    {A::NetPlaceTool, "net-place", "Place Tool", M::Net, "P", false, true, false, "A click on the paper adds a place there"},
    {A::NetTransitionTool, "net-transition", "Transition Tool", M::Net, "T", false, true, false,
     "A click on the paper adds a transition there"},
    {A::NetArcTool, "net-arc", "Arc Tool", M::Net, "A", false, true, false,
     "A drag from a place to a transition (or back) adds an arc"},
    {A::ReverseArc, "reverse-arc", "Reverse Arc", M::Net, "", false, false, true,
     "Swap the selected arc's source and target"},
    {A::AlignLeft, "align-left", "Align Left", M::Net, "", false, false, true,
     "Put the selected constructs' centres on the leftmost one's vertical line"},
    {A::AlignTop, "align-top", "Align Top", M::Net, "", false, false, false,
     "Put the selected constructs' centres on the topmost one's horizontal line"},
    {A::DistributeAcross, "distribute-across", "Distribute Across", M::Net, "", false, false, false,
     "Space the selected constructs evenly from the leftmost to the rightmost"},
    {A::DistributeDown, "distribute-down", "Distribute Down", M::Net, "", false, false, false,
     "Space the selected constructs evenly from the topmost to the lowest"},
    {A::PageTypeFromSelection, "page-type-from-selection", "Page Type from Selection", M::Net, "", false, false, true,
     "Move the selection into a new page type and put an instance of it in its place; crossing arcs become ports"},
    {A::OpenInstance, "open-instance", "Open Instance's Page", M::Net, "", false, false, false,
     "Show the selected instance's page (Up comes back)"},

    {A::Run, "run", "Run", M::Run, "F5", false, false, false, "Run the model in real time"},
    {A::Faster, "faster", "Run Faster (x8)", M::Run, "", false, false, false, "Run the model eight times real time"},
    {A::Fastest, "fastest", "Run As Fast As Possible", M::Run, "", false, false, false,
     "Run the model as fast as the machine allows"},
    {A::Pause, "pause", "Pause", M::Run, "F6", false, false, false, "Stop the clock; the run stays"},
    {A::Step, "step", "Step", M::Run, "F10", false, false, false,
     "One step (the plant alone when Plant Only is on)"},
    {A::RunN, "run-n", "Run N Steps", M::Run, "", false, false, false, "Run the toolbar's number of steps"},
    {A::Fire, "fire", "Fire", M::Run, "F9", false, false, false, "Fire the transition chosen in the toolbar"},
    {A::PlantOnly, "plant-only", "Plant Only", M::Run, "", false, true, true,
     "Run the plant with the net switched off"},
    {A::Reset, "reset", "Reset", M::Run, "Shift+F5", false, false, false, "Back to the model as edited"},
    {A::ClearBreakpoints, "clear-breakpoints", "Remove All Breakpoints", M::Run, "", false, false, true,
     "Remove every breakpoint of the run"},
    {A::ReleaseForces, "release-forces", "Release All Forces", M::Run, "", false, false, false,
     "Release every forced input and output of the I/O list at the next step"},
    {A::ServeOpcua, "serve-opcua", "Serve over OPC UA", M::Run, "", false, true, true,
     "Serve the run over OPC UA on 127.0.0.1:4840 (as gdpn run --opcua 4840): PLCs and HMIs read and write it"},

    {A::Keys, "keys", "Keys", M::Help, "F1", false, false, false, "List every action and its key"},
    {A::Guide, "guide", "IDE Guide", M::Help, "", false, false, false,
     "Open the IDE's guide (docs/ide.md) in the browser"},
};

bool equalNoCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

}  // namespace

const char* menuName(Menu menu) {
  switch (menu) {
    case Menu::File: return "File";
    case Menu::Edit: return "Edit";
    case Menu::View: return "View";
    case Menu::Net: return "Net";
    case Menu::Run: return "Run";
    case Menu::Help: return "Help";
  }
  return "?";
}

std::span<const ActionInfo> actionInfos() { return kActions; }

const ActionInfo& info(ActionId id) {
  for (const auto& a : kActions) {
    if (a.id == id) return a;
  }
  return kActions[0];  // unreachable: every id has its entry (tests/ide/actions_test.cpp)
}

std::optional<ActionId> findAction(std::string_view name) {
  for (const auto& a : kActions) {
    if (a.name == name) return a.id;
  }
  return std::nullopt;
}

std::string actionNames() {
  std::string out;
  for (const auto& a : kActions) out += (out.empty() ? "" : ", ") + std::string(a.name);
  return out;
}

std::optional<Shortcut> parseShortcut(std::string_view keys) {
  Shortcut s;
  while (!keys.empty()) {
    const auto plus = keys.find('+', 1);  // "+" alone would be the key itself
    const auto part = keys.substr(0, plus);
    keys = plus == std::string_view::npos ? std::string_view() : keys.substr(plus + 1);
    if (!s.key.empty()) return std::nullopt;  // a key before the last part
    if (equalNoCase(part, "ctrl")) s.ctrl = true;
    else if (equalNoCase(part, "shift")) s.shift = true;
    else if (equalNoCase(part, "alt")) s.alt = true;
    else {
      for (char c : part) s.key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  if (s.key.empty()) return std::nullopt;
  return s;
}

}  // namespace gdpn::ide
