// The actions' behaviour: one switch over ActionId for each question (no default: the compiler
// lists every place a new action must be handled).

#include "action_run.h"

#include <imgui.h>

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "app.h"
#include "gdpn/ide/io_list.h"
#include "gdpn/ide/part_edit.h"
#include "detail/keys.h"
#include "net_actions.h"
#include "views/net_view_state.h"
#include "views.h"
#include "views/palette_state.h"

namespace gdpn::ide {

namespace {

bool editing(const App& app) { return app.run().mode() == RunMode::Edit; }

/// The selected node's path when it is a part's machine or a Transform: what Turn a Quarter
/// turns; "" for anything else.
std::string turnable(const App& app) {
  const auto& sel = app.document().selection();
  if (sel.kind != SelectionKind::Node) return {};
  const std::string path = partPathOf(app, sel.name);
  if (partAtPath(app, path)) return path;
  const auto* s = app.document().scene();
  const auto* node = s != nullptr ? s->find(path) : nullptr;
  return node != nullptr && node->kind() == scene::NodeKind::Transform ? path : std::string();
}

/// Turns the part being dragged from the palette a quarter round (where it lands is snapped
/// anew), else the selected part or Transform, about the vertical through its origin
/// (anticlockwise seen from above): one step of undo.
void turnQuarter(App& app) {
  if (auto& palette = app.palette(); !palette.dragged.empty()) {
    palette.drag_turn = std::fmod(palette.drag_turn + 90.0, 360.0);
    ++palette.generation;
    app.message = "turned " + palette.dragged + " a quarter round";
    return;
  }
  const std::string path = turnable(app);
  if (path.empty()) return;
  std::array<double, 4> now{0, 0, 1, 0};
  if (const auto at = partAtPath(app, path)) {
    now = instanceAt(app.document().model(), *at)->rotation;
  } else {
    const auto* node = app.document().scene()->find(path);
    now = std::get<std::array<double, 4>>(node->value(static_cast<std::size_t>(node->type().fieldIndex("rotation"))));
  }
  // the quarter turn about the world's z after the rotation it has
  const core::Vec3 axis{now[0], now[1], now[2]};
  const core::Quat before = axis.length() > 0 ? core::Quat::axisAngle(axis, core::radians(now[3])) : core::Quat{};
  const auto [a, angle] = (core::Quat::axisAngle({0, 0, 1}, core::radians(90)) * before).toAxisAngle();
  const double degrees = std::round(angle * 180.0 / std::numbers::pi * 1e9) / 1e9;
  const std::array<double, 4> turned = degrees == 0 ? std::array<double, 4>{0, 0, 1, 0}
                                                    : std::array<double, 4>{a.x, a.y, a.z, degrees};
  const auto why = app.document().execute(manipulatorCommand(app, path, "rotation", turned, 0));
  app.message = why.empty() ? "turned " + path + " a quarter round" : why;
}

bool hasRun(const App& app) { return app.run().session() != nullptr; }

/// Shows `why` in the status bar when an action was refused.
void note(App& app, const std::string& why) {
  if (!why.empty()) app.message = why;
}

/// A node, or something of the net, is selected: what Copy and Cut take.
bool copyableSelected(const App& app) {
  const auto kind = app.document().selection().kind;
  switch (kind) {
    case SelectionKind::None: return false;
    case SelectionKind::Node:
    case SelectionKind::Place:
    case SelectionKind::Transition:
    case SelectionKind::Instance:
    case SelectionKind::Arc: return true;
  }
  return false;
}

/// True when something of the net is selected (the current selection is not a node).
bool netSelected(const App& app) {
  const auto kind = app.document().selection().kind;
  return kind != SelectionKind::None && kind != SelectionKind::Node;
}

}  // namespace

bool actionEnabled(const App& app, ActionId id) {
  switch (id) {
    case ActionId::New:
    case ActionId::Open:
    case ActionId::Save:
    case ActionId::SaveAs:
    case ActionId::Close:
    case ActionId::Quit: return true;
    case ActionId::Restore:
    case ActionId::Discard: return app.restore_offered;
    case ActionId::Undo: return app.document().history().canUndo();
    case ActionId::Redo: return app.document().history().canRedo();
    case ActionId::Cut:
    case ActionId::Delete: return copyableSelected(app) && editing(app);
    case ActionId::TurnQuarter: return editing(app) && (!app.palette().dragged.empty() || !turnable(app).empty());
    case ActionId::Copy: return copyableSelected(app);
    case ActionId::SelectAll: return true;
    case ActionId::NetSelectTool:
    case ActionId::NetPlaceTool:
    case ActionId::NetTransitionTool:
    case ActionId::NetArcTool: return true;
    case ActionId::ReverseArc:
      return editing(app) && app.document().selection().kind == SelectionKind::Arc && app.document().selectedCount() == 1;
    case ActionId::AlignLeft:
    case ActionId::AlignTop:
    case ActionId::DistributeAcross:
    case ActionId::DistributeDown: return editing(app) && netSelected(app) && app.document().selectedCount() >= 2;
    case ActionId::PageTypeFromSelection: return editing(app) && netSelected(app);
    case ActionId::OpenInstance: return app.document().selection().kind == SelectionKind::Instance;
    case ActionId::SaveAsPart: return app.document().selection().kind == SelectionKind::Node;
    case ActionId::UpdateParts: return editing(app) && !app.part_updates.updates.empty();
    case ActionId::Paste: return editing(app);  // what the clipboard holds is read then (another program's text, too)
    case ActionId::SwapViews:
    case ActionId::WorldFull:
    case ActionId::NetFull:
    case ActionId::MiniView:
    case ActionId::Palette:
    case ActionId::Sensors:
    case ActionId::Joints:
    case ActionId::Contacts:
    case ActionId::Shadows:
    case ActionId::Grid:
    case ActionId::SelectTool:
    case ActionId::MoveTool:
    case ActionId::TurnTool:
    case ActionId::ScaleTool:
    case ActionId::AimTool:
    case ActionId::Snap:
    case ActionId::LocalAxes:
    case ActionId::FrameSelection:
    case ActionId::Screenshot:
    case ActionId::Movie: return true;
    case ActionId::Run:
    case ActionId::Faster:
    case ActionId::Fastest:
    case ActionId::Step:
    case ActionId::RunN:
    case ActionId::PlantOnly: return hasRun(app);
    case ActionId::Pause: return app.run().mode() == RunMode::Running;
    case ActionId::Fire: return hasRun(app) && !app.toolbar.fire_target.empty();
    case ActionId::Reset: return true;
    case ActionId::ClearBreakpoints: return !app.run().breakpoints().empty();
    case ActionId::IoList:
    case ActionId::ColourSets: return true;
    case ActionId::ReleaseForces: return app.run().mode() != RunMode::Edit && hasRun(app);
    case ActionId::ServeOpcua: return hasRun(app) || !app.run().opcuaUrl().empty();
    case ActionId::Keys:
    case ActionId::Guide: return true;
  }
  return false;
}

bool actionChecked(const App& app, ActionId id) {
  switch (id) {
    case ActionId::SwapViews: return app.splittersView().swapped;
    case ActionId::WorldFull: return app.splittersView().full == FullView::World;
    case ActionId::NetFull: return app.splittersView().full == FullView::Net;
    case ActionId::MiniView: return app.world.show_mini;
    case ActionId::Palette: return app.splittersView().show_palette;
    case ActionId::Sensors: return app.world.show_sensors;
    case ActionId::Joints: return app.world.show_joints;
    case ActionId::Contacts: return app.world.show_contacts;
    case ActionId::Shadows: return app.world.show_shadows;
    case ActionId::Grid: return app.world.show_grid;
    case ActionId::SelectTool: return app.world.tool == Tool::Select;
    case ActionId::MoveTool: return app.world.tool == Tool::Move;
    case ActionId::TurnTool: return app.world.tool == Tool::Turn;
    case ActionId::ScaleTool: return app.world.tool == Tool::Scale;
    case ActionId::AimTool: return app.world.tool == Tool::Aim;
    case ActionId::Snap: return app.world.snap;
    case ActionId::LocalAxes: return app.world.local_axes;
    case ActionId::Movie: return app.movie != nullptr;
    case ActionId::PlantOnly: return app.run().plantOnly();
    case ActionId::ServeOpcua: return !app.run().opcuaUrl().empty();
    case ActionId::IoList: return app.io_list.shown;
    case ActionId::ColourSets: return app.colour_sets.shown;
    case ActionId::NetSelectTool: return app.netView().tool == NetTool::Select;
    case ActionId::NetPlaceTool: return app.netView().tool == NetTool::Place;
    case ActionId::NetTransitionTool: return app.netView().tool == NetTool::Transition;
    case ActionId::NetArcTool: return app.netView().tool == NetTool::Arc;
    case ActionId::SelectAll:
    case ActionId::ReverseArc:
    case ActionId::AlignLeft:
    case ActionId::AlignTop:
    case ActionId::DistributeAcross:
    case ActionId::DistributeDown:
    case ActionId::PageTypeFromSelection:
    case ActionId::OpenInstance:
    case ActionId::ReleaseForces:
    case ActionId::SaveAsPart:
    case ActionId::UpdateParts:
    case ActionId::New:
    case ActionId::Open:
    case ActionId::Save:
    case ActionId::SaveAs:
    case ActionId::Close:
    case ActionId::Quit:
    case ActionId::Restore:
    case ActionId::Discard:
    case ActionId::Undo:
    case ActionId::Redo:
    case ActionId::Cut:
    case ActionId::Copy:
    case ActionId::Paste:
    case ActionId::Delete:
    case ActionId::TurnQuarter:
    case ActionId::FrameSelection:
    case ActionId::Screenshot:
    case ActionId::Run:
    case ActionId::Faster:
    case ActionId::Fastest:
    case ActionId::Pause:
    case ActionId::Step:
    case ActionId::RunN:
    case ActionId::Fire:
    case ActionId::Reset:
    case ActionId::ClearBreakpoints:
    case ActionId::Keys:
    case ActionId::Guide: return false;
  }
  return false;
}

std::string performAction(App& app, ActionId id) {
  if (!actionEnabled(app, id)) {
    return "'" + std::string(info(id).name) + "' cannot be done now (" + std::string(info(id).help) + ")";
  }
  auto& run = app.run();
  switch (id) {
    case ActionId::New: app.newModel(); break;
    case ActionId::Open: app.browse(BrowseFor::Open); break;
    case ActionId::Save: app.save(); break;
    case ActionId::SaveAs: app.browse(BrowseFor::SaveAs); break;
    case ActionId::Close: app.closeModel(); break;
    case ActionId::Quit: app.quit(); break;
    case ActionId::Restore: app.restoreAutosave(); break;
    case ActionId::Discard: app.discardAutosave(); break;
    case ActionId::Undo: app.undo(); break;
    case ActionId::Redo: app.redo(); break;
    case ActionId::Cut:
      if (app.copySelection()) app.deleteSelection();  // nothing goes that the clipboard does not hold
      break;
    case ActionId::Copy: app.copySelection(); break;
    case ActionId::Paste: app.paste(); break;
    case ActionId::Delete: app.deleteSelection(); break;
    case ActionId::SelectAll: selectAllOnPage(app); break;
    case ActionId::NetSelectTool: app.netView().tool = NetTool::Select; break;
    case ActionId::NetPlaceTool: app.netView().tool = NetTool::Place; break;
    case ActionId::NetTransitionTool: app.netView().tool = NetTool::Transition; break;
    case ActionId::NetArcTool: app.netView().tool = NetTool::Arc; break;
    case ActionId::ReverseArc: note(app, reverseSelectedArc(app)); break;
    case ActionId::AlignLeft: note(app, arrangeNetSelection(app, Arrange::Left)); break;
    case ActionId::AlignTop: note(app, arrangeNetSelection(app, Arrange::Top)); break;
    case ActionId::DistributeAcross: note(app, arrangeNetSelection(app, Arrange::Across)); break;
    case ActionId::DistributeDown: note(app, arrangeNetSelection(app, Arrange::Down)); break;
    case ActionId::PageTypeFromSelection: note(app, pageTypeFromSelection(app)); break;
    case ActionId::OpenInstance: openSelectedInstance(app); break;
    case ActionId::TurnQuarter: turnQuarter(app); break;
    case ActionId::SaveAsPart: openSaveAsPart(app); break;
    case ActionId::UpdateParts: openPartUpdates(app); break;
    case ActionId::SwapViews: app.swapViews(); break;
    case ActionId::WorldFull: app.fill(FullView::World); break;
    case ActionId::NetFull: app.fill(FullView::Net); break;
    case ActionId::MiniView: app.world.show_mini = !app.world.show_mini; break;
    case ActionId::Palette: app.splitters().show_palette = !app.splitters().show_palette; break;
    case ActionId::Sensors: app.world.show_sensors = !app.world.show_sensors; break;
    case ActionId::Joints: app.world.show_joints = !app.world.show_joints; break;
    case ActionId::Contacts: app.world.show_contacts = !app.world.show_contacts; break;
    case ActionId::Shadows: app.world.show_shadows = !app.world.show_shadows; break;
    case ActionId::Grid: app.world.show_grid = !app.world.show_grid; break;
    case ActionId::SelectTool: app.world.tool = Tool::Select; break;
    case ActionId::MoveTool: app.world.tool = Tool::Move; break;
    case ActionId::TurnTool: app.world.tool = Tool::Turn; break;
    case ActionId::ScaleTool: app.world.tool = Tool::Scale; break;
    case ActionId::AimTool: app.world.tool = Tool::Aim; break;
    case ActionId::Snap: app.world.snap = !app.world.snap; break;
    case ActionId::LocalAxes: app.world.local_axes = !app.world.local_axes; break;
    case ActionId::FrameSelection: app.frameSelection(); break;
    case ActionId::Screenshot: app.screenshot_requested = true; break;
    case ActionId::Movie: app.toggleMovie(); break;
    case ActionId::Run: run.run(RunSpeed::RealTime); break;
    case ActionId::Faster: run.run(RunSpeed::Faster); break;
    case ActionId::Fastest: run.run(RunSpeed::Fastest); break;
    case ActionId::Pause: run.pause(); break;
    case ActionId::Step: run.step(); break;
    case ActionId::RunN: run.runSteps(app.toolbar.run_n); break;
    case ActionId::Fire:
      (void)run.fire(app.toolbar.fire_target);
      app.message = run.message();
      break;
    case ActionId::PlantOnly: run.setPlantOnly(!run.plantOnly()); break;
    case ActionId::Reset: app.reset(); break;
    case ActionId::ClearBreakpoints:
      for (const auto& b : run.breakpoints()) (void)run.removeBreakpoint(b);
      app.message = "removed every breakpoint";
      break;
    case ActionId::IoList:
      app.io_list.shown = !app.io_list.shown;
      app.colour_sets.shown = false;
      break;
    case ActionId::ColourSets:
      app.colour_sets.shown = !app.colour_sets.shown;
      app.io_list.shown = false;
      break;
    case ActionId::ReleaseForces:
      app.message = releaseAllIo(run);
      if (app.message.empty()) app.message = "every force is released at the next step";
      break;
    case ActionId::ServeOpcua:
      if (run.opcuaUrl().empty()) {
        (void)run.serveOpcua("4840");
      } else {
        run.stopServing();
      }
      app.message = run.message();
      break;
    case ActionId::Keys: app.keys_open = true; break;
    case ActionId::Guide: app.openGuide(); break;
  }
  return {};
}

void handleShortcuts(App& app) {
  // each action's key taken apart once: (action, shortcut, GLFW code)
  struct Key {
    const ActionInfo* action;
    Shortcut shortcut;
    int code;
  };
  static const std::vector<Key> keys = [] {
    std::vector<Key> out;
    for (const auto& a : actionInfos()) {
      const auto shortcut = a.keys.empty() ? std::nullopt : parseShortcut(a.keys);
      if (shortcut && keyCode(shortcut->key) >= 0) out.push_back({&a, *shortcut, keyCode(shortcut->key)});
    }
    return out;
  }();
  const auto& io = ImGui::GetIO();
  for (const auto& [a, shortcut, code] : keys) {
    if (!ImGui::IsKeyPressed(code, false)) continue;
    if (io.KeyCtrl != shortcut.ctrl || io.KeyShift != shortcut.shift || io.KeyAlt != shortcut.alt) continue;
    // a field being typed in keeps its editing keys (and every key without Ctrl but F1..F12)
    const bool function_key = shortcut.key.size() > 1 && shortcut.key[0] == 'f' && shortcut.key[1] >= '0' && shortcut.key[1] <= '9';
    if (io.WantTextInput && (a->text_first || !shortcut.ctrl) && !function_key) continue;
    if (actionEnabled(app, a->id)) (void)performAction(app, a->id);
  }
}

}  // namespace gdpn::ide
