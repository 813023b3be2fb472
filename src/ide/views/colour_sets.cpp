// The colour sets view: the model's colour sets and variables, as its file declares them, each
// editable in place; a definition with a mistake is shown with it and not applied.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

#include "../views.h"
#include "gdpn/ide/colour_edit.h"
#include "gdpn/model/colour_text.h"

namespace gdpn::ide {
namespace {

const ImVec4 kDefinitionErrorColour{1.0f, 0.45f, 0.4f, 1.0f};
const char* const kForms = "int, bool, string, dot, {range: [lo, hi]}, {enum: [a, b]}, {cyclic: [a, b]}, {product: [A, B]}, {record: {f: A}}";

/// The text field `field` of the view: what was typed and not applied, else `current`.
std::string typedText(const App& app, const std::string& field, const std::string& current) {
  const auto it = app.colour_sets.typed.find(field);
  return it == app.colour_sets.typed.end() ? current : it->second;
}

/// Keeps `text` typed in field `field` while it differs from `current` (the model's).
void keepTyped(App& app, const std::string& field, const std::string& text, const std::string& current) {
  if (text == current) app.colour_sets.typed.erase(field);
  else app.colour_sets.typed[field] = text;
}

/// The problem of `row` under it: "column 12: ..." in red, with a mark under the column of the
/// definition field drawn at `field_x`.
void problemLine(const TextProblem& p, nlohmann::json& report, const std::string& row) {
  const std::string where = p.column > 0 ? "column " + std::to_string(p.column) + ": " : std::string();
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextColored(kDefinitionErrorColour, "%s%s", where.c_str(), p.message.c_str());
  ImGui::PopTextWrapPos();
  report["problems"][row] = {{"column", p.column}, {"message", p.message}};
}

/// A red line under column `column` of the one-line field just drawn, holding `text`.
void markDefinitionColumn(const std::string& text, int column) {
  if (column <= 0) return;
  const auto at = std::min(static_cast<std::size_t>(column - 1), text.size());
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  const float x = lo.x + ImGui::GetStyle().FramePadding.x + ImGui::CalcTextSize(text.data(), text.data() + at).x;
  const float w = at < text.size() ? ImGui::CalcTextSize(text.data() + at, text.data() + at + 1).x : 6.0f;
  ImGui::GetWindowDrawList()->AddLine({x, hi.y - 2}, {std::min(x + std::max(w, 4.0f), hi.x), hi.y - 2}, IM_COL32(240, 80, 70, 255), 2.0f);
}

/// "5 values", "not finite".
std::string sizeText(const net::ColourSet& s) {
  if (!s.size) return "not finite";
  return std::to_string(*s.size) + (*s.size == 1 ? " value" : " values");
}

/// The declared sets: each row's name and definition, editable; the new set's row.
void setRows(App& app, bool editing, nlohmann::json& report) {
  auto& st = app.colour_sets;
  const auto& net = app.document().model().net;
  const auto scope = colourScopeOf(net);
  nlohmann::json sets = nlohmann::json::array();
  const std::size_t n = net.colours.size();
  for (std::size_t i = 0; i <= n; ++i) {
    const bool fresh = i == n;  // the row that declares a new one
    const std::string suffix = fresh ? "new" : std::to_string(i);
    const std::string row = fresh ? "new set" : "set " + std::to_string(i);
    const std::string name_now = fresh ? std::string() : net.colours[i].name;
    const std::string definition_now = fresh ? std::string() : model::colourDefinition(net.colours[i]);
    ImGui::PushID(row.c_str());
    std::string name = typedText(app, "name " + suffix, name_now);
    std::string definition = typedText(app, "definition " + suffix, definition_now);
    ImGui::SetNextItemWidth(110);
    bool enter = ImGui::InputTextWithHint("##name", fresh ? "new set" : "name", &name, ImGuiInputTextFlags_EnterReturnsTrue);
    noteItem(fresh ? "new name" : "name " + name_now, report["fields"]);
    bool left = ImGui::IsItemDeactivatedAfterEdit();
    ImGui::SameLine();
    ImGui::SetNextItemWidth(fresh ? -90.0f : -120.0f);
    enter = ImGui::InputTextWithHint("##definition", fresh ? "{range: [1, 5]}" : "definition", &definition,
                                     ImGuiInputTextFlags_EnterReturnsTrue) || enter;
    noteItem(fresh ? "new definition" : "definition " + name_now, report["fields"]);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("A colour set is %s", kForms);
    left = ImGui::IsItemDeactivatedAfterEdit() || left;
    const bool changed = name != name_now || definition != definition_now;
    // checked as typed: the mistake shows at once, and nothing is applied until it is gone
    TextProblem problem;
    std::optional<std::vector<net::ColourSetSpec>> edited;
    if (changed && !(fresh && name.empty() && definition.empty())) edited = editedColours(net, i, name, definition, problem);
    if (changed && !edited) markDefinitionColumn(definition, problem.column);
    ImGui::SameLine();
    bool declare = false, remove = false;
    if (fresh) {
      declare = ImGui::Button("Declare");
      noteItem("Declare set", report["buttons"]);
    } else {
      const auto id = scope.colours.find(name_now);
      ImGui::TextDisabled("%s", id ? sizeText(scope.colours.at(*id)).c_str() : "not resolved");
      ImGui::SameLine();
      remove = ImGui::SmallButton("x");
      noteItem("delete " + name_now, report["buttons"]);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("Delete colour set %s (refused while something uses it)", name_now.c_str());
    }
    if (editing && edited && (declare || enter || (!fresh && left))) {
      const std::string label = (fresh ? "declare colour set " : "edit colour set ") + name;
      const auto why = app.document().execute(std::make_unique<SetDeclarationsCommand>(std::move(*edited), net.variables, label));
      if (why.empty()) {
        name = name_now;  // applied: the fields show the model again
        definition = definition_now;
        st.problems.erase(row);
      } else {
        st.problems[row] = {0, 0, why};
      }
    } else if (editing && remove) {
      const auto uses = usesOfColour(net, name_now);
      if (!uses.empty()) {
        std::string list;
        for (std::size_t u = 0; u < uses.size() && u < 3; ++u) list += (u == 0 ? "" : ", ") + uses[u];
        if (uses.size() > 3) list += " and " + std::to_string(uses.size() - 3) + " more";
        st.problems[row] = {0, 0, "colour set '" + name_now + "' is used by " + list + ": not deleted"};
      } else {
        auto colours = net.colours;
        colours.erase(colours.begin() + static_cast<std::ptrdiff_t>(i));
        const auto why = app.document().execute(
            std::make_unique<SetDeclarationsCommand>(std::move(colours), net.variables, "delete colour set " + name_now));
        if (!why.empty()) st.problems[row] = {0, 0, why};
      }
    } else if ((declare || enter) && !edited && changed) {
      st.problems[row] = problem;
    }
    if (changed && !edited) problemLine(problem, report, row);
    else if (const auto p = st.problems.find(row); p != st.problems.end()) {
      if (changed || remove || p->second.message.find("not deleted") != std::string::npos) problemLine(p->second, report, row);
      else st.problems.erase(p);
    }
    keepTyped(app, "name " + suffix, name, name_now);
    keepTyped(app, "definition " + suffix, definition, definition_now);
    if (!fresh && net.colours.size() == n) {
      const auto id = scope.colours.find(name_now);
      sets.push_back({{"name", name_now}, {"definition", definition_now},
                      {"kind", id ? net::colourKindName(scope.colours.at(*id).kind) : "?"},
                      {"values", id ? sizeText(scope.colours.at(*id)) : "not resolved"}});
    }
    if (name != name_now || definition != definition_now) report["typed"][row] = {{"name", name}, {"definition", definition}};
    ImGui::PopID();
    if (net.colours.size() != n) break;  // a set deleted: the rows are drawn again next frame
  }
  report["sets"] = sets;
}

/// The declared variables: each one's name and set, editable; the new variable's row.
void variableRows(App& app, bool editing, nlohmann::json& report) {
  auto& st = app.colour_sets;
  const auto& net = app.document().model().net;
  const auto scope = colourScopeOf(net);
  std::vector<std::string> set_names;
  for (const auto& s : scope.colours.sets()) set_names.push_back(s.name);
  if (st.new_variable_set.empty() && !set_names.empty()) st.new_variable_set = set_names.back();
  nlohmann::json variables = nlohmann::json::array();
  const std::size_t n = net.variables.size();
  for (std::size_t i = 0; i <= n; ++i) {
    const bool fresh = i == n;
    const std::string suffix = fresh ? "new variable" : "variable " + std::to_string(i);
    const std::string row = suffix;
    const std::string name_now = fresh ? std::string() : net.variables[i].name;
    ImGui::PushID(row.c_str());
    std::string name = typedText(app, "name " + suffix, name_now);
    ImGui::SetNextItemWidth(110);
    bool enter = ImGui::InputTextWithHint("##name", fresh ? "new variable" : "name", &name, ImGuiInputTextFlags_EnterReturnsTrue);
    noteItem(fresh ? "new variable" : "variable " + name_now, report["fields"]);
    const bool left = ImGui::IsItemDeactivatedAfterEdit();
    ImGui::SameLine();
    ImGui::TextUnformatted(":");
    ImGui::SameLine();
    std::string set = fresh ? st.new_variable_set : net.variables[i].colour;
    ImGui::SetNextItemWidth(140);
    bool set_changed = false;
    const bool open = ImGui::BeginCombo("##set", set.c_str());
    noteItem(fresh ? "new variable set" : "set of " + name_now, report["fields"]);
    if (open) {
      for (const auto& s : set_names) {
        if (ImGui::Selectable(s.c_str(), s == set)) {
          set_changed = s != set;
          set = s;
        }
        noteItem((fresh ? "new variable set " : "set of " + name_now + " ") + s, report["fields"]);
      }
      ImGui::EndCombo();
    }
    if (fresh) st.new_variable_set = set;
    bool declare = false, remove = false;
    ImGui::SameLine();
    if (fresh) {
      declare = ImGui::Button("Declare");
      noteItem("Declare variable", report["buttons"]);
    } else {
      remove = ImGui::SmallButton("x");
      noteItem("delete " + name_now, report["buttons"]);
    }
    const bool changed = name != name_now || set_changed;
    if (editing && ((fresh && (declare || enter)) || (!fresh && (enter || left || set_changed))) && changed) {
      TextProblem problem;
      if (auto edited = editedVariables(net, i, name, set, problem)) {
        const std::string label = (fresh ? "declare variable " : "edit variable ") + name;
        const auto why = app.document().execute(std::make_unique<SetDeclarationsCommand>(net.colours, std::move(*edited), label));
        if (why.empty()) {
          name = name_now;
          st.problems.erase(row);
        } else {
          st.problems[row] = {0, 0, why};
        }
      } else {
        st.problems[row] = problem;
      }
    } else if (editing && remove) {
      const auto uses = usesOfVariable(net, name_now);
      if (!uses.empty()) {
        st.problems[row] = {0, 0, "variable '" + name_now + "' is used by " + uses.front() +
                                      (uses.size() > 1 ? " and " + std::to_string(uses.size() - 1) + " more" : "") + ": not deleted"};
      } else {
        auto vars = net.variables;
        vars.erase(vars.begin() + static_cast<std::ptrdiff_t>(i));
        (void)app.document().execute(std::make_unique<SetDeclarationsCommand>(net.colours, std::move(vars), "delete variable " + name_now));
      }
    }
    keepTyped(app, "name " + suffix, name, name_now);
    if (const auto p = st.problems.find(row); p != st.problems.end()) problemLine(p->second, report, row);
    if (!fresh && i < net.variables.size()) variables.push_back({{"name", name_now}, {"set", net.variables[i].colour}});
    ImGui::PopID();
    if (net.variables.size() != n) break;  // one deleted: the rows are drawn again next frame
  }
  report["variables"] = variables;
}

}  // namespace

void drawColourSets(App& app, const Rect& at, nlohmann::json& report) {
  beginPanel("##colour_sets", at, nullptr);
  const bool editing = app.run().mode() == RunMode::Edit;
  report = {{"shown", true}, {"editable", editing}};
  report["problems"] = nlohmann::json::object();
  report["fields"] = nlohmann::json::object();
  report["buttons"] = nlohmann::json::object();
  ImGui::TextColored({0.6f, 0.75f, 1.0f, 1.0f}, "Colour sets");
  ImGui::SameLine();
  ImGui::TextDisabled("(bool, int, string and dot are built in)");
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("Each as the model file's colours section writes it: %s. Enter applies; a set may name only "
                      "sets above it.", kForms);
  ImGui::PopTextWrapPos();
  if (!editing) ImGui::TextDisabled("Reset the run to edit them.");
  ImGui::BeginDisabled(!editing);
  setRows(app, editing, report);
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextColored({0.6f, 0.75f, 1.0f, 1.0f}, "Variables");
  ImGui::SameLine();
  ImGui::TextDisabled("(what the inscriptions bind)");
  variableRows(app, editing, report);
  ImGui::EndDisabled();
  endPanel();
}

}  // namespace gdpn::ide
