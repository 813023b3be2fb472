// The toolbar: the menus, the run controls, the transition to fire, save, undo and redo; each
// button an action of the table.

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "../action_run.h"
#include "../views.h"
#include "gdpn/ide/actions.h"

namespace gdpn::ide {

namespace {

/// A button for action `id` of the table: its label (or `label`), faded and deaf to clicks
/// while the action cannot be done, its help as the tooltip, its centre noted in `report`.
void actionButton(App& app, ActionId id, nlohmann::json& report, const char* label = nullptr, ImVec2 size = {0, 0}) {
  const auto& a = info(id);
  const bool enabled = actionEnabled(app, id);
  const std::string text = label != nullptr ? std::string(label) : std::string(a.label);
  ImGui::PushStyleVar(ImGuiStyleVar_Alpha, enabled ? 1.0F : 0.5F);
  const bool pressed = ImGui::Button(text.c_str(), size);
  ImGui::PopStyleVar();
  noteItem(std::string(a.name), report);
  if (ImGui::IsItemHovered()) {
    const std::string keys = a.keys.empty() ? std::string() : " (" + std::string(a.keys) + ")";
    ImGui::SetTooltip("%s%s", std::string(a.help).c_str(), keys.c_str());
  }
  if (pressed && enabled) (void)performAction(app, id);
}

}  // namespace

void drawToolbar(App& app, const Rect& at, nlohmann::json& report, nlohmann::json& menu_report) {
  auto& run = app.run();
  ImGui::SetCursorScreenPos({at.x, at.y});
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {8, 6});
  ImGui::BeginChild("##toolbar", {at.w, at.h}, false, ImGuiWindowFlags_AlwaysUseWindowPadding);
  ImGui::PopStyleVar();
  drawMenus(app, menu_report);
  ImGui::SameLine(0, 16);
  const bool ready = run.session() != nullptr;
  const bool running = run.mode() == RunMode::Running;
  nlohmann::json buttons = nlohmann::json::object();

  // run at a speed, pause, step, run N steps
  static constexpr RunSpeed kSpeeds[] = {RunSpeed::RealTime, RunSpeed::Faster, RunSpeed::Fastest};
  static constexpr ActionId kRunAt[] = {ActionId::Run, ActionId::Faster, ActionId::Fastest};
  int speed = static_cast<int>(std::find(std::begin(kSpeeds), std::end(kSpeeds), app.toolbar.speed) - std::begin(kSpeeds));
  actionButton(app, kRunAt[speed], buttons, running ? "Running" : "Run", {70, 0});
  ImGui::SameLine();
  ImGui::SetNextItemWidth(130);
  if (!ready) ImGui::BeginDisabled();
  if (ImGui::Combo("##speed", &speed, "real time\0faster (x8)\0as fast as possible\0")) {
    app.toolbar.speed = kSpeeds[speed];
    if (running) (void)performAction(app, kRunAt[speed]);
  }
  if (!ready) ImGui::EndDisabled();
  ImGui::SameLine();
  actionButton(app, ActionId::Pause, buttons);
  ImGui::SameLine();
  actionButton(app, ActionId::Step, buttons);
  ImGui::SameLine();
  actionButton(app, ActionId::RunN, buttons, "Run N");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(64);
  ImGui::InputInt("##n", &app.toolbar.run_n, 0, 0);
  app.toolbar.run_n = std::clamp(app.toolbar.run_n, 1, 10'000'000);

  // fire a transition chosen from the net's (the net view picks it later)
  ImGui::SameLine(0, 18);
  const auto names = run.transitions();
  ImGui::SetNextItemWidth(170);
  if (ImGui::BeginCombo("##fire", app.toolbar.fire_target.empty() ? "(transition)" : app.toolbar.fire_target.c_str())) {
    for (const auto& n : names) {
      if (ImGui::Selectable(n.c_str(), n == app.toolbar.fire_target)) {
        app.toolbar.fire_target = n;
        app.document().select({SelectionKind::Transition, n});
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  actionButton(app, ActionId::Fire, buttons);

  // the net switched off; back to the edit-time state
  ImGui::SameLine(0, 18);
  bool plant_only = run.plantOnly();
  if (!ready) ImGui::BeginDisabled();
  if (ImGui::Checkbox("Plant only", &plant_only)) (void)performAction(app, ActionId::PlantOnly);
  if (!ready) ImGui::EndDisabled();
  ImGui::SameLine();
  actionButton(app, ActionId::Reset, buttons);

  // the document and its history
  ImGui::SameLine(0, 18);
  actionButton(app, ActionId::Save, buttons);
  ImGui::SameLine();
  actionButton(app, ActionId::Undo, buttons);
  ImGui::SameLine();
  actionButton(app, ActionId::Redo, buttons);
  ImGui::EndChild();

  const auto& history = app.document().history();
  report = {{"ready", ready},
            {"speed", runSpeedName(app.toolbar.speed)},
            {"fire_target", app.toolbar.fire_target},
            {"transitions", names.size()},
            {"run_n", app.toolbar.run_n},
            {"can_undo", history.canUndo()},
            {"can_redo", history.canRedo()},
            {"filming", app.movie != nullptr},
            {"buttons", buttons}};
}

}  // namespace gdpn::ide
