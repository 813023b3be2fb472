// The status bar: model time, steps, real-time factor, frames per second, the mode (and whether
// the run is served over OPC UA), the last message.

#include <imgui.h>

#include "../views.h"

namespace gdpn::ide {

void drawStatusBar(App& app, const Rect& at, nlohmann::json& report) {
  auto& run = app.run();
  ImGui::SetCursorScreenPos({at.x, at.y});
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {8, 4});
  ImGui::PushStyleColor(ImGuiCol_ChildBg, ImVec4{0.10F, 0.11F, 0.13F, 1.0F});
  ImGui::BeginChild("##status", {at.w, at.h}, false, ImGuiWindowFlags_AlwaysUseWindowPadding);
  const auto& msg = run.message().empty() ? app.message : run.message();
  ImGui::Text("t = %.3f s", run.time());
  ImGui::SameLine(150);
  ImGui::Text("steps %lld", static_cast<long long>(run.steps()));
  ImGui::SameLine(270);
  ImGui::Text("x%.2f real time", run.realTimeFactor());
  ImGui::SameLine(410);
  const double scale = app.worldScale();
  if (scale < 1) {
    ImGui::Text("%.0f fps, world at %.0f %%", app.fps, 100 * scale);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("While running, the world view is drawn at fewer pixels to keep the frame rate; "
                        "paused, it is drawn in full");
    }
  } else {
    ImGui::Text("%.0f fps", app.fps);
  }
  ImGui::SameLine(scale < 1 ? 560 : 490);
  const std::string served = run.opcuaUrl();
  ImGui::Text("%s%s%s", runModeName(run.mode()), run.plantOnly() ? ", plant only" : "", served.empty() ? "" : ", OPC UA");
  if (!served.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("served over OPC UA on %s", served.c_str());
  ImGui::SameLine(scale < 1 ? 690 + (served.empty() ? 0 : 70) : 620 + (served.empty() ? 0 : 70));
  ImGui::TextUnformatted(msg.c_str());
  ImGui::EndChild();
  ImGui::PopStyleColor();
  ImGui::PopStyleVar();
  report = {{"time", run.time()},          {"steps", run.steps()}, {"real_time_factor", run.realTimeFactor()},
            {"fps", app.fps},              {"mode", runModeName(run.mode())}, {"message", msg},
            {"world_scale", scale},        {"opcua", served}};
}

}  // namespace gdpn::ide
