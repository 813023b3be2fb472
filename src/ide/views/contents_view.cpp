// The contents view (read-only in this part): the selected place's 8 x 4 slot grid, each slot
// coloured by kind and marked when it holds tokens, with its tokens' names; the selected
// transition's duration; and the construct's scripts with Python highlighting.

#include <imgui.h>

#include <string_view>

#include "../views.h"
#include "gdpn/core/text.h"
#include "gdpn/net/script_kind.h"
#include "gdpn/net/slot.h"
#include "gdpn/ide/python_text.h"

namespace gdpn::ide {
namespace {

/// The slot grid's colours: the net view's (diagram::colours), dimmed when the slot is empty.
ImVec4 slotColour(net::SlotKind kind, bool marked) {
  const float a = marked ? 1.0f : 0.35f;
  switch (kind) {
    case net::SlotKind::Control: return {0.55f, 0.55f, 0.58f, a};
    case net::SlotKind::Node: return {0.12f, 0.47f, 0.71f, a};
    case net::SlotKind::Sensor: return {1.0f, 0.50f, 0.05f, a};
  }
  return {0.3f, 0.3f, 0.3f, a};
}

std::string durationText(const net::Duration& d) {
  switch (d.law) {
    case net::Duration::Law::Fixed: return core::formatDouble(d.a) + " s";
    case net::Duration::Law::Uniform: return "uniform in [" + core::formatDouble(d.a) + ", " + core::formatDouble(d.b) + ") s";
    case net::Duration::Law::Normal: return "normal, mean " + core::formatDouble(d.a) + " s, sd " + core::formatDouble(d.b) + " s";
    case net::Duration::Law::Exponential: return "exponential, mean " + core::formatDouble(d.a) + " s";
  }
  return "?";
}

/// One script, headed by its kind (and slot), its lines numbered and highlighted.
void scriptBlock(const net::ScriptSpec& script, std::string_view heading, nlohmann::json& report) {
  ImGui::Separator();
  ImGui::TextColored({0.6f, 0.75f, 1.0f, 1.0f}, "%.*s", static_cast<int>(heading.size()), heading.data());
  if (!script.file.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s%s%s", script.file.c_str(), script.function.empty() ? "" : ": ", script.function.c_str());
  }
  const int lines = drawPython(script.code, script.loc.line);
  report["scripts"].push_back({{"what", heading}, {"lines", lines}, {"file", script.file}});
}

void placeContents(const session::Session& session, net::PlaceId p, nlohmann::json& report) {
  const auto& sim = session.simulation();
  const auto& net = sim.net();
  const auto& place = net.places()[p];
  // the 8 x 4 grid: rows a to d, columns 0 to 7, as the model file names slots
  nlohmann::json slots = nlohmann::json::object();
  if (ImGui::BeginTable("##slots", 8, ImGuiTableFlags_SizingFixedSame)) {
    for (int s = 0; s < net::kSlotCount; ++s) {
      ImGui::TableNextColumn();
      const auto slot = static_cast<net::SlotId>(s);
      const std::string name = net::slotName(slot);
      const auto ps = net.findPlaceSlot(p, slot);
      if (ps < 0) {  // a slot the place does not use: a faint cell, so that the rows line up
        ImGui::BeginDisabled();
        ImGui::PushStyleColor(ImGuiCol_Button, {0.2f, 0.21f, 0.23f, 1.0f});
        ImGui::Button(name.c_str(), {56, 0});
        ImGui::PopStyleColor();
        ImGui::EndDisabled();
        continue;
      }
      const auto& info = net.placeSlots()[static_cast<std::size_t>(ps)];
      const bool sensor = !net.sensorPath(static_cast<net::PlaceSlotId>(ps)).empty();
      const auto kind = sensor ? net::SlotKind::Sensor : info.kind;
      const auto tokens = sim.kernel().marking(static_cast<net::PlaceSlotId>(ps));
      std::vector<std::string> names;
      if (kind == net::SlotKind::Node) {
        for (net::NodeRef ref : sim.kernel().nodes(static_cast<net::PlaceSlotId>(ps))) names.push_back(sim.nodeName(ref));
      }
      const std::string label = sensor ? name : name + " " + std::to_string(tokens);
      ImGui::PushStyleColor(ImGuiCol_Button, slotColour(kind, sensor || tokens > 0));
      ImGui::Button(label.c_str(), {56, 0});
      ImGui::PopStyleColor();
      if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::Text("%s: %s slot", name.c_str(), net::slotKindName(kind));
        if (sensor) ImGui::Text("reads %s", net.sensorPath(static_cast<net::PlaceSlotId>(ps)).c_str());
        else ImGui::Text("%lld token(s)%s", static_cast<long long>(tokens),
                         info.capacity == net::kUnbounded ? "" : (", capacity " + std::to_string(info.capacity)).c_str());
        for (const auto& n : names) ImGui::BulletText("%s", n.c_str());
        ImGui::EndTooltip();
      }
      slots[name] = {{"kind", net::slotKindName(kind)}, {"tokens", tokens}, {"names", names}};
    }
    ImGui::EndTable();
  }
  report["slots"] = slots;
  // the node tokens by name, under the grid
  for (const auto& [name, slot] : slots.items()) {
    if (slot["names"].empty()) continue;
    std::string line = name + ":";
    for (const auto& n : slot["names"]) line += " " + n.get<std::string>();
    ImGui::TextWrapped("%s", line.c_str());
  }
  const auto& index = net.scriptIndex();
  for (auto ps = place.slots_begin; ps < place.slots_end && ps < index.slots.size(); ++ps) {
    for (std::size_t k = 0; k < net::kSlotScripts.size(); ++k) {
      const auto i = index.slots[ps][k];
      if (i < 0) continue;
      const std::string heading = std::string(net::info(net::kSlotScripts[k]).key) + " (" +
                                  net::slotName(net.placeSlots()[ps].slot) + ")";
      scriptBlock(net.scripts()[static_cast<std::size_t>(i)], heading, report);
    }
  }
}

void transitionContents(const session::Session& session, net::TransitionId t, nlohmann::json& report) {
  const auto& net = session.simulation().net();
  const auto& tr = net.transitions()[t];
  const auto duration = durationText(tr.duration);
  ImGui::Text("duration %s", duration.c_str());
  report["duration"] = duration;
  const auto& index = net.scriptIndex();
  if (t >= index.transitions.size()) return;
  for (std::size_t k = 0; k < net::kTransitionScripts.size(); ++k) {
    const auto i = index.transitions[t][k];
    if (i >= 0) scriptBlock(net.scripts()[static_cast<std::size_t>(i)], net::info(net::kTransitionScripts[k]).key, report);
  }
}

}  // namespace

void drawContents(App& app, const Selection& sel, nlohmann::json& report) {
  const auto* session = app.run().session();
  if (session == nullptr) return;
  const auto& net = session->simulation().net();
  report["scripts"] = nlohmann::json::array();
  if (sel.kind == SelectionKind::Place) {
    if (const auto p = net.findPlace(sel.name); p >= 0) placeContents(*session, static_cast<net::PlaceId>(p), report);
  } else if (sel.kind == SelectionKind::Transition) {
    if (const auto t = net.findTransition(sel.name); t >= 0) {
      transitionContents(*session, static_cast<net::TransitionId>(t), report);
    }
  }
}

}  // namespace gdpn::ide
