// The toolbar: the run controls, the transition to fire, undo and redo.

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include <imgui_stdlib.h>

#include "../views.h"

namespace gdpn::ide {

namespace {

/// A button drawn faded, and deaf to clicks, while `enabled` is false.
bool toolButton(const char* label, bool enabled) {
  ImGui::PushStyleVar(ImGuiStyleVar_Alpha, enabled ? 1.0F : 0.5F);
  const bool pressed = ImGui::Button(label);
  ImGui::PopStyleVar();
  return pressed && enabled;
}

}  // namespace

void drawToolbar(App& app, const Rect& at, nlohmann::json& report) {
  auto& run = app.run();
  ImGui::SetCursorScreenPos({at.x, at.y});
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {8, 6});
  ImGui::BeginChild("##toolbar", {at.w, at.h}, false, ImGuiWindowFlags_AlwaysUseWindowPadding);
  ImGui::PopStyleVar();
  const bool ready = run.session() != nullptr;
  const bool running = run.mode() == RunMode::Running;
  if (!ready) ImGui::BeginDisabled();

  // run at a speed, pause, step, run N steps
  static const RunSpeed kSpeeds[] = {RunSpeed::RealTime, RunSpeed::Faster, RunSpeed::Fastest};
  static int speed = 0;
  if (ImGui::Button(running ? "Running" : "Run", {70, 0})) run.run(kSpeeds[speed]);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Run the model at the chosen speed");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(130);
  if (ImGui::Combo("##speed", &speed, "real time\0faster (x8)\0as fast as possible\0") && running) {
    run.run(kSpeeds[speed]);
  }
  ImGui::SameLine();
  if (ImGui::Button("Pause")) run.pause();
  ImGui::SameLine();
  if (ImGui::Button("Step")) run.step();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("One step (the plant alone when Plant only is on)");
  ImGui::SameLine();
  if (ImGui::Button("Run N")) run.runSteps(app.run_n);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(64);
  ImGui::InputInt("##n", &app.run_n, 0, 0);
  app.run_n = std::clamp(app.run_n, 1, 10'000'000);

  // fire a transition chosen from the net's (the net view picks it later)
  ImGui::SameLine(0, 18);
  const auto names = run.transitions();
  ImGui::SetNextItemWidth(170);
  if (ImGui::BeginCombo("##fire", app.fire_target.empty() ? "(transition)" : app.fire_target.c_str())) {
    for (const auto& n : names) {
      if (ImGui::Selectable(n.c_str(), n == app.fire_target)) {
        app.fire_target = n;
        app.document().select({SelectionKind::Transition, n});
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Button("Fire") && !app.fire_target.empty()) {
    (void)run.fire(app.fire_target);
    app.message = run.message();
  }

  // the net switched off; back to the edit-time state
  ImGui::SameLine(0, 18);
  bool plant_only = run.plantOnly();
  if (ImGui::Checkbox("Plant only", &plant_only)) run.setPlantOnly(plant_only);
  ImGui::SameLine();
  if (!ready) ImGui::EndDisabled();
  if (ImGui::Button("Reset")) app.reset();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back to the model as edited");

  // the document's history
  ImGui::SameLine(0, 18);
  auto& history = app.document().history();
  if (ImGui::Button("Save")) app.save();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Save the model to its file (Ctrl+S)");
  ImGui::SameLine();
  if (ImGui::Button("Save As")) app.save_as_open = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Save the model under another name, which it keeps (Ctrl+Shift+S)");
  nlohmann::json save_as = {{"open", false}};
  if (app.save_as_open) {
    if (!ImGui::IsPopupOpen("##save_as")) {
      ImGui::OpenPopup("##save_as");
      app.save_as_path = app.document().model().path;
    }
  }
  if (ImGui::BeginPopup("##save_as")) {
    ImGui::TextUnformatted("Save the model as");
    ImGui::SetNextItemWidth(420);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    const bool entered = ImGui::InputText("##path", &app.save_as_path, ImGuiInputTextFlags_EnterReturnsTrue);
    save_as = {{"open", true}, {"path", app.save_as_path}};
    ImGui::SameLine();
    if (ImGui::Button("Save") || entered) {
      app.saveAs(app.save_as_path);
      app.save_as_open = false;
      ImGui::CloseCurrentPopup();
    }
    noteItem("save", save_as);
    ImGui::EndPopup();
  } else {
    app.save_as_open = false;
  }
  ImGui::SameLine();
  if (toolButton("Undo", history.canUndo())) app.undo();
  ImGui::SameLine();
  if (toolButton("Redo", history.canRedo())) app.redo();
  ImGui::SameLine(0, 18);
  if (ImGui::Button("Screenshot")) app.screenshot_requested = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Save the window as gdpn-ide-N.png in the current folder");
  ImGui::SameLine();
  if (ImGui::Button(app.movie ? "Stop movie" : "Movie")) app.toggleMovie();
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Film the window into gdpn-ide-N.mp4 in the current folder (through ffmpeg), one movie frame "
                      "a drawn frame at the frame rate when filming began");
  }
  ImGui::EndChild();

  report = {{"ready", ready},
            {"speed", runSpeedName(kSpeeds[speed])},
            {"fire_target", app.fire_target},
            {"transitions", names.size()},
            {"run_n", app.run_n},
            {"can_undo", history.canUndo()},
            {"can_redo", history.canRedo()},
            {"filming", app.movie != nullptr},
            {"save_as", save_as}};
}

}  // namespace gdpn::ide
