// The diagnostics: every error and warning of the model (and of compiling it for the run) at
// file:line:col; a click selects the construct declared there.

#include <imgui.h>

#include "../views.h"
#include "gdpn/scene/actions.h"

namespace gdpn::ide {

namespace {

/// Selects the node, place or transition declared at `loc` (the nearest line at or before it).
void selectAt(App& app, const core::SourceLoc& loc) {
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
  if (auto* session = app.run().session()) {
    const auto& net = session->simulation().net();
    for (const auto& p : net.places()) {
      if (p.loc.line <= loc.line && p.loc.line > best_line) {
        best_line = p.loc.line;
        best = p.name;
        kind = SelectionKind::Place;
      }
    }
    for (const auto& t : net.transitions()) {
      if (t.loc.line <= loc.line && t.loc.line > best_line) {
        best_line = t.loc.line;
        best = t.name;
        kind = SelectionKind::Transition;
      }
    }
  }
  if (kind == SelectionKind::Node) app.selectNode(best);
  else if (kind != SelectionKind::None) app.document().select({kind, best});
}

}  // namespace

void drawDiagnostics(App& app, const Rect& at, nlohmann::json& report) {
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
      const auto text = d.str();
      if (ImGui::Selectable(text.c_str())) selectAt(app, d.loc);
      ImGui::PopStyleColor();
      ImGui::PopID();
      report.push_back(text);
    }
  }
  if (i == 0) ImGui::TextDisabled("No errors or warnings.");
  endPanel();
}

}  // namespace gdpn::ide
