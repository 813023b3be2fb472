// The diagnostics: every error and warning of the model (and of compiling it for the run) at
// file:line:col; a click selects the construct declared there.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

#include "../views.h"
#include "gdpn/scene/actions.h"

namespace gdpn::ide {

namespace {

/// Selects the node, place or transition declared at `loc` (the nearest line at or before it).
void selectAt(App& app, const core::SourceLoc& loc) {
  if (loc.line == 0) return;
  std::string best;
  int best_line = 0;
  SelectionKind kind = SelectionKind::None;
  if (auto* s = app.document().scene()) {
    scene::traverse(s->root(), [&](scene::Node& n, const scene::TraversalState&) {
      if (n.loc.line <= loc.line && n.loc.line > best_line) {
        best_line = n.loc.line;
        best = n.path();
        kind = SelectionKind::Node;
      }
    });
  }
  // the net as written (so that a net that does not compile is found too): top-level pages
  const auto consider = [&](const core::SourceLoc& at, SelectionKind k, std::string name) {
    if (at.line <= loc.line && at.line > best_line) {
      best_line = at.line;
      best = std::move(name);
      kind = k;
    }
  };
  for (const auto& page : app.document().model().net.pages) {
    for (const auto& p : page.places) consider(p.loc, SelectionKind::Place, page.name + "/" + p.name);
    for (const auto& t : page.transitions) consider(t.loc, SelectionKind::Transition, page.name + "/" + t.name);
    for (const auto& i : page.instances) consider(i.loc, SelectionKind::Instance, page.name + "/" + i.name);
  }
  if (kind == SelectionKind::Node) app.selectNode(best);
  else if (kind != SelectionKind::None) app.document().select({kind, best});
}

}  // namespace

void drawDiagnostics(App& app, const Rect& at, nlohmann::json& report, nlohmann::json& breakpoints) {
  beginPanel("##diagnostics", at, "Diagnostics");
  report = nlohmann::json::array();
  int i = 0;
  for (const auto* list : {&app.document().diagnostics(), &app.runDiagnostics()}) {
    for (const auto& d : list->all()) {
      const ImVec4 colour = d.severity == core::Severity::Error     ? ImVec4{1.0F, 0.42F, 0.38F, 1}
                            : d.severity == core::Severity::Warning ? ImVec4{1.0F, 0.8F, 0.3F, 1}
                                                                    : ImVec4{0.7F, 0.7F, 0.7F, 1};
      ImGui::PushID(i++);
      ImGui::PushStyleColor(ImGuiCol_Text, colour);
      // the whole message, wrapped, is one clickable row
      const auto text = d.str();
      const float wrap = ImGui::GetContentRegionAvail().x;
      const auto size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
      const auto top = ImGui::GetCursorPos();
      if (ImGui::Selectable("##row", false, 0, {0, size.y})) selectAt(app, d.loc);
      const auto after = ImGui::GetCursorPos();
      ImGui::SetCursorPos(top);
      ImGui::PushTextWrapPos(top.x + wrap);
      ImGui::TextUnformatted(text.c_str());
      ImGui::PopTextWrapPos();
      ImGui::SetCursorPos(after);
      ImGui::PopStyleColor();
      ImGui::PopID();
      report.push_back(text);
    }
  }
  if (i == 0) ImGui::TextDisabled("No errors or warnings.");
  drawBreakpoints(app, breakpoints);
  endPanel();
}

void drawBreakpoints(App& app, nlohmann::json& report) {
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextDisabled("Breakpoints");
  report = nlohmann::json::array();
  int i = 0;
  for (const auto& description : app.run().breakpoints()) {
    ImGui::PushID(i++);
    if (ImGui::SmallButton("x")) (void)app.run().removeBreakpoint(description);
    ImGui::PopID();
    ImGui::SameLine();
    ImGui::TextUnformatted(description.c_str());
    report.push_back(description);
  }
  if (i == 0) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("None. Set them on a selected place or transition (inspector), or on a condition:");
    ImGui::PopTextWrapPos();
  }
  // a Python condition, checked after every step (the run's globals and sim are in scope)
  ImGui::SetNextItemWidth(std::max(80.0f, ImGui::GetContentRegionAvail().x - 60.0f));
  const bool entered = ImGui::InputTextWithHint("##when", "when (Python), e.g. sim.time > 20", &app.inspector.break_condition,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button("Add") || entered) && !app.inspector.break_condition.empty()) {
    app.message = app.run().addBreakpoint(session::Breakpoint::predicate(app.inspector.break_condition));
    if (app.message.empty()) app.inspector.break_condition.clear();
  }
}

}  // namespace gdpn::ide
