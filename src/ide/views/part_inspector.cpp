// The inspector of a part instance: its type and version, where it stands, its parameters
// (each edit one step of undo; the world view shows the machine made again), its I/O as a PLC's
// I/O list has them, and its control pattern (added with one button when nothing controls it).

#include <imgui.h>

#include <algorithm>
#include <string>

#include "../views.h"
#include "gdpn/core/text.h"
#include "gdpn/ide/part_snap.h"
#include "gdpn/model/part_library.h"

namespace gdpn::ide {

namespace {

/// The description of page type `type` of `model`.
std::string typeDescription(const model::Model& model, const std::string& type) {
  for (const auto& t : model.net.page_types) {
    if (t.name == type) return t.description;
  }
  return {};
}

}  // namespace

void drawPartInspector(App& app, const PartInstanceAt& at, nlohmann::json& report) {
  const auto& m = app.document().model();
  const auto* inst = instanceAt(m, at);
  const auto spec_at = inst != nullptr ? m.parts.find(inst->type) : m.parts.end();
  if (inst == nullptr || spec_at == m.parts.end()) {
    ImGui::TextDisabled("%s is no part instance of the model", at.name.c_str());
    return;
  }
  const model::PartSpec& spec = spec_at->second;
  const bool edit = app.run().mode() == RunMode::Edit;
  ImGui::Text("part %s  %s", inst->type.c_str(), at.name.c_str());
  ImGui::SameLine();
  ImGui::TextDisabled("version %d%s%s, on page %s", spec.version, spec.group.empty() ? "" : ", ", spec.group.c_str(),
                      at.page.c_str());
  if (const auto description = typeDescription(m, inst->type); !description.empty()) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextDisabled("%s", description.c_str());
    ImGui::PopTextWrapPos();
  }
  const auto& t = inst->translation;
  ImGui::TextDisabled("at (%s, %s, %s) m, turned %s deg about z", core::formatDouble(t[0]).c_str(), core::formatDouble(t[1]).c_str(),
                      core::formatDouble(t[2]).c_str(), core::formatDouble(angleAboutZ(inst->rotation)).c_str());
  if (!app.inspector.error.empty()) ImGui::TextColored({1.0F, 0.4F, 0.35F, 1.0F}, "%s", app.inspector.error.c_str());
  report["part"] = at.name;
  report["type"] = inst->type;
  report["page"] = at.page;
  report["version"] = spec.version;
  report["translation"] = inst->translation;

  // its control: the pattern's instance bound to it, or a button per pattern that adds one
  nlohmann::json buttons = nlohmann::json::object();
  const auto patterns = model::controlPatterns(m, inst->type);
  const auto controller = controllerOf(m, at);
  if (!controller.empty()) {
    std::string with;
    if (const auto* c = instanceAt(m, {at.page, controller}); c != nullptr) {
      for (const auto& u : c->uses) with += (with.empty() ? " (" : ", ") + u.role + ": " + u.part;
    }
    ImGui::Text("controlled by %s%s", controller.c_str(), with.empty() ? "" : (with + ")").c_str());
  } else {
    for (std::size_t k = 0; k < patterns.size(); ++k) {
      const auto& pattern = patterns[k];
      std::string unfilled;
      model::fillRoles(m, at.page, at.name, pattern, {}, unfilled);
      ImGui::BeginDisabled(!edit || !unfilled.empty());
      const std::string label = "Add control: " + pattern;
      if (ImGui::Button(label.c_str())) {
        auto command = std::make_unique<AddPartControlCommand>(at, pattern);
        const auto* adding = command.get();
        app.inspector.error = app.document().execute(std::move(command));
        app.message = app.inspector.error.empty() ? "added " + adding->made() + ", the control of " + at.name : app.inspector.error;
      }
      ImGui::EndDisabled();
      if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        ImGui::SetTooltip("%s", unfilled.empty() ? ("An instance of " + pattern + " in the net, bound to " + at.name + "'s I/O").c_str()
                                                 : unfilled.c_str());
      }
      noteItem(k == 0 ? "add-control" : pattern, buttons);
    }
  }
  report["control"] = {{"pattern", patterns.empty() ? std::string() : patterns.front()}, {"patterns", patterns},
                       {"controller", controller}};
  report["buttons"] = buttons;

  // its parameters: the type's, with this instance's values (Enter commits)
  nlohmann::json fields = nlohmann::json::object(), params = nlohmann::json::object();
  if (!spec.params.empty() && ImGui::BeginTable("##part_params", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                                                        ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("parameter", ImGuiTableColumnFlags_WidthFixed, 110);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthFixed, 120);
    ImGui::TableSetupColumn("unit", ImGuiTableColumnFlags_WidthFixed, 50);
    ImGui::TableSetupColumn("what it is", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableHeadersRow();
    for (const auto& p : spec.params) {
      const auto set = std::find_if(inst->params.begin(), inst->params.end(), [&](const auto& x) { return x.name == p.name; });
      const bool here = set != inst->params.end();
      double value = here ? set->value : p.value;
      ImGui::PushID(p.name.c_str());
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::AlignTextToFramePadding();
      ImGui::TextUnformatted(p.name.c_str());
      ImGui::TableNextColumn();
      ImGui::SetNextItemWidth(-1);
      ImGui::BeginDisabled(!edit);
      if (!here) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
      const bool entered = ImGui::InputDouble("##value", &value, 0, 0, p.integer ? "%.0f" : "%g",
                                              ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
      if (!here) ImGui::PopStyleColor();
      ImGui::EndDisabled();
      noteItem(p.name, fields);
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("%s (the type's: %s)", here ? "set for this instance" : "the type's value", core::formatDouble(p.value).c_str());
      }
      if (entered && edit) {
        app.inspector.error = app.document().execute(SetInstanceCommand::param(at, p.name, value));
        app.message = app.inspector.error.empty() ? "set " + at.name + "." + p.name + " = " + core::formatDouble(value)
                                                  : app.inspector.error;
      }
      ImGui::TableNextColumn();
      ImGui::AlignTextToFramePadding();
      ImGui::TextDisabled("%s", p.unit.c_str());
      ImGui::TableNextColumn();
      ImGui::AlignTextToFramePadding();
      ImGui::TextUnformatted(p.description.c_str());
      ImGui::PopID();
      params[p.name] = {{"value", here ? set->value : p.value}, {"unit", p.unit}, {"set", here}, {"default", p.value}};
    }
    ImGui::EndTable();
  }
  report["params"] = params;
  report["fields"] = fields;

  // its I/O, as a PLC's I/O list names them
  auto& io = report["io"] = nlohmann::json::array();
  if (!spec.io.empty() && ImGui::BeginTable("##part_io", 5, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                                                ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("I/O", ImGuiTableColumnFlags_WidthFixed, 110);
    ImGui::TableSetupColumn("direction", ImGuiTableColumnFlags_WidthFixed, 70);
    ImGui::TableSetupColumn("signal", ImGuiTableColumnFlags_WidthFixed, 60);
    ImGui::TableSetupColumn("unit", ImGuiTableColumnFlags_WidthFixed, 50);
    ImGui::TableSetupColumn("what it tells or drives", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableHeadersRow();
    for (const auto& i : spec.io) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(i.name.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(model::ioDirectionName(i.direction));
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(model::ioSignalName(i.signal));
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", i.unit.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(i.description.c_str());
      io.push_back({{"name", i.name},
                    {"direction", model::ioDirectionName(i.direction)},
                    {"signal", model::ioSignalName(i.signal)},
                    {"unit", i.unit},
                    {"description", i.description}});
    }
    ImGui::EndTable();
  }
}

}  // namespace gdpn::ide
