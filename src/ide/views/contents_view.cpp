// The contents view. While a run is shown: the selected place's 8 x 4 slot grid, each slot
// coloured by kind and marked when it holds tokens, with its tokens' names; the selected
// transition's duration; and the construct's scripts with Python highlighting. In edit mode
// the same, from the model as written and editable: slot kinds (a menu; a node dragged from
// the tree makes a node slot holding it), tokens, capacities, durations, priorities,
// probabilities, and every script in an editor compiled when it loses focus.

#include <imgui.h>

#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string_view>
#include <utility>

#include "../views.h"
#include "net_view_state.h"
#include "gdpn/core/expression.h"
#include "gdpn/core/text.h"
#include "gdpn/diagram/layout.h"
#include "gdpn/net/script_kind.h"
#include "gdpn/net/slot.h"
#include "gdpn/ide/colour_edit.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/ide/python_text.h"
#include "gdpn/ide/token_types.h"
#include "script_editor.h"
#include "gdpn/model/schema.h"
#include "gdpn/scene/node.h"

namespace gdpn::ide {
namespace {

namespace schema = model::schema;
using schema::Section;

/// The slot grid's colours: the net view's (diagram::colours), dimmed when the slot is empty.
ImVec4 slotColour(net::SlotKind kind, bool marked) {
  const float a = marked ? 1.0f : 0.35f;
  switch (kind) {
    case net::SlotKind::Control: return {0.55f, 0.55f, 0.58f, a};
    case net::SlotKind::Node: return {0.12f, 0.47f, 0.71f, a};
    case net::SlotKind::Sensor: return {1.0f, 0.50f, 0.05f, a};
    case net::SlotKind::Value: return {0.58f, 0.40f, 0.74f, a};
    case net::SlotKind::Continuous: return {0.09f, 0.75f, 0.81f, a};
  }
  return {0.3f, 0.3f, 0.3f, a};
}

std::string durationText(const net::Duration& d) {
  // a number that comes from a model parameter shows as `$name (value)`
  const auto num = [&](std::size_t k) {
    const std::string value = core::formatDouble(k == 0 ? d.a : d.b);
    return d.params[k].empty() ? value : model::referenceText(d.params[k]) + " (" + value + ")";
  };
  switch (d.law) {
    case net::Duration::Law::Fixed: return num(0) + " s";
    case net::Duration::Law::Uniform: return "uniform in [" + num(0) + ", " + num(1) + ") s";
    case net::Duration::Law::Normal: return "normal, mean " + num(0) + " s, sd " + num(1) + " s";
    case net::Duration::Law::Exponential: return "exponential, mean " + num(0) + " s";
    case net::Duration::Law::Immediate: return "immediate" + std::string(d.params[0].empty() ? "" : " ($" + d.params[0] + " = 0)");
  }
  return "?";
}

/// Notes the last item, the field of `key`, under the key's name (as noteItem does) and, while
/// it is hovered, shows the key's help and range from the schema.
void keyItem(const schema::KeyDesc& key, nlohmann::json& fields) {
  noteItem(key.name, fields);
  if (ImGui::IsItemHovered()) {
    const std::string range = schema::rangeText(key);
    ImGui::SetTooltip("%s%s", key.help.c_str(), range.empty() ? "" : (" (" + range + ")").c_str());
  }
}

/// After a field that comes from a model parameter: "= $name" (nothing for a number typed in).
void paramNote(const std::string& param) {
  if (param.empty()) return;
  ImGui::SameLine();
  ImGui::TextDisabled("= $%s", param.c_str());
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("the value of parameter '%s' (the params section); a value typed here replaces it", param.c_str());
  }
}

/// The parameter the count of `slot` in `counts` comes from ("" for none).
std::string slotParam(const std::vector<net::SlotCount>& counts, net::SlotId slot) {
  const auto* c = slotEntry(counts, slot);
  return c ? c->param : std::string();
}

/// The run's error (runError: a line of the model file and a message), none by default.
using FileError = std::pair<int, std::string>;

/// One script, headed by its kind (and slot), its lines numbered with the model file's and
/// highlighted; the line `error` names, when it is one of the script's, marked with its message.
void scriptBlock(const net::ScriptSpec& script, std::string_view heading, nlohmann::json& report,
                 const FileError& error = {}) {
  ImGui::Separator();
  ImGui::TextColored({0.6f, 0.75f, 1.0f, 1.0f}, "%.*s", static_cast<int>(heading.size()), heading.data());
  if (!script.file.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s%s%s", script.file.c_str(), script.function.empty() ? "" : ": ", script.function.c_str());
  }
  const int error_line = scriptLineOf(script, error.first);
  const int lines = drawPython(script.code, script.loc.line, error_line);
  nlohmann::json entry = {{"what", heading}, {"lines", lines}, {"file", script.file}, {"first_line", script.loc.line}};
  if (error_line > 0) {
    ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "the run stopped at line %d (file line %d): %s", error_line, error.first,
                       error.second.c_str());
    entry["run_error"] = {{"line", error_line}, {"file_line", error.first}, {"message", error.second}};
  }
  report["scripts"].push_back(entry);
}

/// The colour of amounts (hybrid nets): the net view's colours::kContinuous.
ImVec4 levelColour() { return {0.09f, 0.75f, 0.81f, 1.0f}; }

/// A continuous place in the run (hybrid nets): its amount as a level, a bar of its capacity
/// with the amount and unit on it, and the room promised to occurring transitions; while the
/// run is paused, a field that sets the amount (Kernel::setAmount; its refusal shown under it).
void levelContents(App& app, session::Session& session, net::PlaceId p, nlohmann::json& report) {
  auto& kernel = session.simulation().kernel();
  const net::Fluid& fluid = *session.simulation().net().fluid();
  const net::FluidPlace& fp = fluid.places[static_cast<std::size_t>(fluid.of_place[p])];
  const double amount = kernel.amount(p), reserved = kernel.amountReserved(p);
  const bool bounded = std::isfinite(fp.capacity);
  const std::string text = bounded ? diagram::amountText(amount) + " of " + diagram::amountText(fp.capacity, fp.unit)
                                   : diagram::amountText(amount, fp.unit) + " (unbounded)";
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("level");
  ImGui::SameLine(80);
  ImGui::PushStyleColor(ImGuiCol_PlotHistogram, levelColour());
  ImGui::ProgressBar(bounded && fp.capacity > 0 ? static_cast<float>(amount / fp.capacity) : 0.0f, {280, 0}, text.c_str());
  ImGui::PopStyleColor();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the amount on the place now, of its capacity");
  noteItem("level", report["fields"]);
  report["amount"] = amount;
  report["capacity"] = bounded ? nlohmann::json(fp.capacity) : nlohmann::json();
  report["unit"] = fp.unit;
  report["reserved"] = reserved;
  report["level_text"] = text;
  if (reserved > 0) ImGui::TextDisabled("room promised to occurring transitions: %s", diagram::amountText(reserved, fp.unit).c_str());
  if (app.run().mode() != RunMode::Paused) {
    ImGui::TextDisabled("Pause the run to set its amount.");
    return;
  }
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("set to");
  ImGui::SameLine(80);
  double typed = amount;
  ImGui::SetNextItemWidth(120);
  const bool entered = ImGui::InputDouble("##amount", &typed, 0, 0, "%g", ImGuiInputTextFlags_EnterReturnsTrue);
  noteItem("set amount", report["fields"]);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("a new amount, in %s; Enter sets it", fp.unit.empty() ? "its unit" : fp.unit.c_str());
  if (!fp.unit.empty()) {
    ImGui::SameLine();
    ImGui::TextUnformatted(fp.unit.c_str());
  }
  const std::string& name = session.simulation().net().placeName(p);
  if (entered) {
    app.inspector.amount_error = kernel.setAmount(p, typed);
    app.inspector.amount_error_of = name;
    app.inspector.amount_error_step = app.run().steps();
    app.netView().state_kernel = nullptr;  // the net view draws the new amount
  }
  // the refusal of this place's last amount, until the run moves on
  const bool refused = app.inspector.amount_error_of == name && app.inspector.amount_error_step == app.run().steps();
  if (refused && !app.inspector.amount_error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4{1.0f, 0.45f, 0.4f, 1.0f});
    ImGui::TextWrapped("%s", app.inspector.amount_error.c_str());
    ImGui::PopStyleColor();
  }
  report["amount_error"] = refused ? app.inspector.amount_error : std::string();
}

void placeContents(App& app, session::Session& session, net::PlaceId p, nlohmann::json& report, const FileError& error) {
  const auto& sim = session.simulation();
  const auto& net = sim.net();
  const auto& place = net.places()[p];
  if (net.continuousPlace(p)) {
    levelContents(app, session, p, report);
    return;
  }
  // the 8 x 4 grid: rows a to d, columns 0 to 7, as the model file names slots
  nlohmann::json slots = nlohmann::json::object();
  if (ImGui::BeginTable("##slots", 8, ImGuiTableFlags_SizingFixedSame)) {
    for (int s = 0; s < net::kSlotCount; ++s) {
      ImGui::TableNextColumn();
      const auto slot = static_cast<net::SlotId>(s);
      const std::string name = net::slotName(slot);
      const auto found = net.findPlaceSlot(p, slot);
      if (!found) {  // a slot the place does not use: a faint cell, so that the rows line up
        ImGui::BeginDisabled();
        ImGui::PushStyleColor(ImGuiCol_Button, {0.2f, 0.21f, 0.23f, 1.0f});
        ImGui::Button(name.c_str(), {56, 0});
        ImGui::PopStyleColor();
        ImGui::EndDisabled();
        continue;
      }
      const net::PlaceSlotId ps = *found;
      const auto& info = net.placeSlots()[ps];
      const bool sensor = !net.sensorPath(ps).empty();
      const auto kind = sensor ? net::SlotKind::Sensor : info.kind;
      const auto tokens = sim.kernel().marking(ps);
      std::vector<std::string> names;
      if (kind == net::SlotKind::Node) {
        for (net::NodeRef ref : sim.kernel().nodes(ps)) names.push_back(sim.nodeName(ref));
      }
      const std::string label = sensor ? name : name + " " + std::to_string(tokens);
      ImGui::PushStyleColor(ImGuiCol_Button, slotColour(kind, sensor || tokens > 0));
      ImGui::Button(label.c_str(), {56, 0});
      ImGui::PopStyleColor();
      if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::Text("%s: %s slot", name.c_str(), net::slotKindName(kind));
        if (sensor) ImGui::Text("reads %s", net.sensorPath(ps).c_str());
        // the capacity now: a script may have changed it
        const auto capacity = sim.kernel().capacity(ps);
        if (!sensor) ImGui::Text("%lld token(s)%s", static_cast<long long>(tokens),
                                 capacity == net::kUnbounded ? "" : (", capacity " + std::to_string(capacity)).c_str());
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
  for (net::PlaceSlotId ps{place.slots_begin}; ps < place.slots_end && ps < index.slots.size(); ++ps) {
    for (std::size_t k = 0; k < net::kSlotScripts.size(); ++k) {
      const auto i = index.slots[ps][k];
      if (i < 0) continue;
      const std::string heading = std::string(net::info(net::kSlotScripts[k]).key) + " (" +
                                  net::slotName(net.placeSlots()[ps].slot) + ")";
      scriptBlock(net.scripts()[static_cast<std::size_t>(i)], heading, report, error);
    }
  }
}

/// The duration of transition `t` as its model writes it (naming the parameters it comes
/// from); its law alone when the model does not write it.
net::Duration writtenDuration(const session::Session& session, net::TransitionId t) {
  const auto& net = session.simulation().net();
  const auto& written = session.simulation().model().net;
  if (const auto at = locateConstruct(written, net.transitionName(t))) {
    if (const net::PageSpec* page = findPage(written, at->page)) {
      for (const auto& spec : page->transitions) {
        if (spec.name == at->name) return spec.duration;
      }
    }
  }
  const auto& law = net.transitions()[t].duration;
  return {law.law, law.a, law.b};
}

void transitionContents(const session::Session& session, net::TransitionId t, nlohmann::json& report,
                        const FileError& error) {
  const auto& net = session.simulation().net();
  if (net.continuous(t)) {  // a flow (hybrid nets): its rate as written, no duration
    std::string rate;
    const auto& written = session.simulation().model().net;
    if (const auto at = locateConstruct(written, net.transitionName(t))) {
      if (const net::PageSpec* page = findPage(written, at->page)) {
        for (const auto& spec : page->transitions) {
          if (spec.name == at->name && spec.flow) rate = spec.flow->rate.text;
        }
      }
    }
    ImGui::Text("continuous, rate %s", rate.c_str());
    report["rate"] = rate;
    return;
  }
  const auto duration = durationText(writtenDuration(session, t));
  ImGui::Text("duration %s", duration.c_str());
  report["duration"] = duration;
  const auto& index = net.scriptIndex();
  if (t >= index.transitions.size()) return;
  for (std::size_t k = 0; k < net::kTransitionScripts.size(); ++k) {
    const auto i = index.transitions[t][k];
    if (i >= 0) {
      scriptBlock(net.scripts()[static_cast<std::size_t>(i)], net::info(net::kTransitionScripts[k]).key, report, error);
    }
  }
}


// ---- edit mode: the model as written ----

/// Applies a SetPlace or SetTransition edit; the message line says why when refused.
void commit(App& app, NetEdit edit) {
  const auto why = app.document().execute(std::make_unique<NetEditCommand>(std::move(edit)));
  if (!why.empty()) app.message = why;
}

void commitPlace(App& app, const ConstructAt& at, net::PlaceSpec place) {
  auto e = makeNetEdit(NetEditKind::SetPlace, at.page, at.name);
  e.place = std::move(place);
  commit(app, std::move(e));
}

void commitTransition(App& app, const ConstructAt& at, net::TransitionSpec t) {
  auto e = makeNetEdit(NetEditKind::SetTransition, at.page, at.name);
  e.transition = std::move(t);
  commit(app, std::move(e));
}

/// The text `list` holds for `slot` ("" when none).
std::string slotText(const std::vector<net::SlotText>& list, net::SlotId slot) {
  for (const auto& t : list) {
    if (t.slot == slot) return t.text;
  }
  return {};
}

/// Sets the text of `slot` in `list` to `text` (its place in the file kept, else `owner`); ""
/// removes it.
void setSlotText(std::vector<net::SlotText>& list, net::SlotId slot, const std::string& text, const core::SourceLoc& owner) {
  const auto it = std::find_if(list.begin(), list.end(), [&](const net::SlotText& t) { return t.slot == slot; });
  if (text.empty()) {
    if (it != list.end()) list.erase(it);
    return;
  }
  if (it != list.end()) {
    it->text = text;
    it->layout.clear();  // the text is new: its characters follow its first one
    return;
  }
  list.push_back({slot, text, owner});
}

/// Makes slot `slot` of `p` a value slot of colour set `set`.
void setValueSlot(net::PlaceSpec& p, net::SlotId slot, const std::string& set) {
  if (slotKindOf(p, slot) != net::SlotKind::Value) setSlotKind(p, slot, net::SlotKind::Value);
  std::erase_if(p.kinds, [&](const net::SlotDecl& d) { return d.slot == slot; });  // the colour says it
  setSlotText(p.colours, slot, set, p.loc);
}

/// The sensor nodes of the document's scene, by path.
void sensorPaths(const scene::Node& node, std::vector<std::string>& out) {
  for (const auto& c : node.children()) {
    if (c->type().category == scene::Category::Sensor) out.push_back(c->path());
    sensorPaths(*c, out);
  }
}

/// The menu of a slot (right click): make it a control, node or sensor slot.
void slotMenu(App& app, const ConstructAt& at, const net::PlaceSpec& place, net::SlotId slot, nlohmann::json& report) {
  if (!ImGui::BeginPopupContextItem()) return;
  nlohmann::json& menu = report["menu"];
  const auto kind = slotKindOf(place, slot);
  if (menuItem("Control slot", menu) && kind != net::SlotKind::Control) {
    auto p = place;
    setSlotKind(p, slot, net::SlotKind::Control);
    commitPlace(app, at, std::move(p));
  }
  if (menuItem("Node slot", menu) && kind != net::SlotKind::Node) {
    auto p = place;
    setSlotKind(p, slot, net::SlotKind::Node);
    commitPlace(app, at, std::move(p));
  }
  if (beginMenu("Value slot", menu)) {
    // a colour set makes it one: the built-ins and the model's own
    const auto scope = colourScopeOf(app.document().model().net);
    for (const auto& s : scope.colours.sets()) {
      if (menuItem(s.name.c_str(), menu) && slotText(place.colours, slot) != s.name) {
        auto p = place;
        setValueSlot(p, slot, s.name);
        commitPlace(app, at, std::move(p));
      }
    }
    ImGui::EndMenu();
  }
  if (beginMenu("Sensor slot", menu)) {
    std::vector<std::string> sensors;
    if (const auto* s = app.document().scene()) sensorPaths(s->root(), sensors);
    if (sensors.empty()) ImGui::TextDisabled("The scene has no sensor node");
    for (const auto& path : sensors) {
      if (menuItem(path.c_str(), menu)) {
        auto p = place;
        setSlotKind(p, slot, net::SlotKind::Sensor, path);
        commitPlace(app, at, std::move(p));
      }
    }
    ImGui::EndMenu();
  }
  ImGui::EndPopup();
}

/// A value slot's colour set (a list of the model's sets) and its initial values (a field of the
/// inscription language, checked as typed).
void valueFields(App& app, const ConstructAt& at, const net::PlaceSpec& place, net::SlotId slot, nlohmann::json& report) {
  const std::string name = net::slotName(slot);
  const std::string set = slotText(place.colours, slot);
  const auto scope = colourScopeOf(app.document().model().net);
  ImGui::TextUnformatted(("colour " + name).c_str());
  ImGui::SameLine(150);
  ImGui::SetNextItemWidth(160);
  const bool open = ImGui::BeginCombo("##colour", set.empty() ? "(none)" : set.c_str());
  noteItem("colour " + name, report["fields"]);
  if (open) {
    for (const auto& s : scope.colours.sets()) {
      const bool chosen = ImGui::Selectable(s.name.c_str(), s.name == set);
      noteItem("colour " + name + " " + s.name, report["fields"]);
      if (chosen && s.name != set) {
        auto p = place;
        setValueSlot(p, slot, s.name);
        commitPlace(app, at, std::move(p));
      }
    }
    ImGui::EndCombo();
  }
  if (set.empty()) ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "a value slot needs a colour set");
  report["colour " + name] = set;
  const std::string construct = at.page + "/" + at.name;
  inscriptionField(app, construct + "#values " + name, "values " + name, slotText(place.values, slot), set,
                   InscriptionRole::Values,
                   [&app, at, place, slot](const std::string& text) {
                     auto p = place;
                     setSlotText(p.values, slot, text, p.loc);
                     commitPlace(app, at, std::move(p));
                   },
                   report);
}

/// The chosen slot's own fields: tokens and capacity, or its node tokens, or its sensor.
void slotFields(App& app, const ConstructAt& at, const net::PlaceSpec& place, net::SlotId slot, nlohmann::json& report) {
  const auto kind = slotKindOf(place, slot);
  const std::string name = net::slotName(slot);
  ImGui::Text("Slot %s: %s", name.c_str(), net::slotKindName(kind));
  nlohmann::json fields;
  if (kind == net::SlotKind::Sensor) {
    for (const auto& b : place.sensors) {
      if (b.slot == slot) ImGui::TextWrapped("reads the sensor %s", b.path.c_str());
    }
  } else {
    if (kind == net::SlotKind::Control) {
      int tokens = static_cast<int>(slotCount(place.tokens, slot).value_or(0));
      ImGui::SetNextItemWidth(110);
      const int tokens_before = tokens;
      const auto& tokens_key = schema::key(Section::Place, "tokens");
      ImGui::InputInt(tokens_key.name.c_str(), &tokens, 0, 0);
      keyItem(tokens_key, fields);
      // a value left as it was keeps the parameter it came from
      if (ImGui::IsItemDeactivatedAfterEdit() && tokens >= 0 && tokens != tokens_before) {
        auto p = place;
        setSlotCount(p.tokens, slot, tokens > 0 ? std::optional<std::int64_t>(tokens) : std::nullopt);
        commitPlace(app, at, std::move(p));
      }
      paramNote(slotParam(place.tokens, slot));
      ImGui::SameLine();
    }
    int capacity = static_cast<int>(slotCount(place.capacity, slot).value_or(-1));
    ImGui::SetNextItemWidth(110);
    const int capacity_before = capacity;
    const auto& capacity_key = schema::key(Section::Place, "capacity");
    ImGui::InputInt((capacity_key.name + " (-1: none)").c_str(), &capacity, 0, 0);
    keyItem(capacity_key, fields);
    if (ImGui::IsItemDeactivatedAfterEdit() && capacity >= -1 && capacity != capacity_before) {
      auto p = place;
      setSlotCount(p.capacity, slot, capacity >= 0 ? std::optional<std::int64_t>(capacity) : std::nullopt);
      commitPlace(app, at, std::move(p));
    }
    paramNote(slotParam(place.capacity, slot));
    if (kind == net::SlotKind::Value) valueFields(app, at, place, slot, report);
    if (kind == net::SlotKind::Node) {
      for (const auto& n : place.nodes) {
        if (n.slot != slot) continue;
        for (const auto& path : n.nodes) {
          ImGui::PushID(path.c_str());
          if (ImGui::SmallButton("x")) {
            auto p = place;
            removeNodeToken(p, slot, path);
            commitPlace(app, at, std::move(p));
          }
          ImGui::SameLine();
          ImGui::TextUnformatted(path.c_str());
          ImGui::PopID();
        }
      }
      ImGui::TextDisabled("Drag a node from the tree onto the slot to add it as a token.");
    }
  }
  report["slot"] = {{"name", name}, {"kind", net::slotKindName(kind)}, {"fields", fields}};
}

/// What type propagation says of `construct`: the node types of its slots, the conflicts that
/// arise there, and its scripts' reads of fields the slot's nodes lack.
void typeFindings(App& app, const std::string& construct, nlohmann::json& report) {
  const auto& found = app.tokenTypes();
  nlohmann::json types = nlohmann::json::object();
  std::string line;
  for (int i = 0; i < net::kSlotCount; ++i) {
    const auto slot = static_cast<net::SlotId>(i);
    const auto it = found.types.find({construct, slot});
    if (it == found.types.end() || it->second.empty()) continue;
    std::string names;
    for (const auto& t : it->second) names += (names.empty() ? "" : " or ") + t;
    types[net::slotName(slot)] = it->second;
    line += (line.empty() ? "" : "; ") + net::slotName(slot) + " holds a " + names;
  }
  if (!line.empty()) ImGui::TextDisabled("%s", line.c_str());
  nlohmann::json conflicts = nlohmann::json::array();
  for (const auto& c : found.conflicts) {
    if (c.slot.first != construct) continue;
    std::string names, from;
    for (const auto& t : c.types) names += (names.empty() ? "" : " and ") + t;
    for (const auto& f : c.from) from += (from.empty() ? "" : ", ") + f;
    const auto text = net::slotName(c.slot.second) + ": a " + names + " meet here (brought by " + from + ")";
    ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s", text.c_str());
    conflicts.push_back(text);
  }
  nlohmann::json unknown = nlohmann::json::array();
  for (const auto& u : found.unknown) {
    if (u.construct != construct) continue;
    const auto text = u.script + ", line " + std::to_string(u.line) + ": " + u.use + ": " + u.message;
    ImGui::TextColored({1.0f, 0.8f, 0.3f, 1.0f}, "%s", text.c_str());
    unknown.push_back(text);
  }
  report["types"] = types;
  report["conflicts"] = conflicts;
  report["unknown"] = unknown;
}

/// The scripts along the path of slot `slot`'s tokens from `place` (token_types.h), read-only.
void pathScripts(const net::PageSpec& page, const std::string& place, net::SlotId slot, nlohmann::json& report) {
  const auto path = tokenPath(page, place, slot);
  report["path"] = path;
  const std::string title = "Scripts along the path of " + net::slotName(slot) + "'s tokens (" +
                            std::to_string(path.size()) + (path.size() == 1 ? " construct)" : " constructs)");
  const bool open = ImGui::CollapsingHeader(title.c_str());
  noteItem("path_header", report);
  if (!open) return;
  nlohmann::json shown;
  for (const auto& name : path) {
    for (const auto& p : page.places) {
      if (p.name != name) continue;
      for (const auto& ss : p.scripts) {
        if (ss.slot != slot) continue;
        for (const auto k : {net::ScriptKind::OnDeposit, net::ScriptKind::OnRemove}) {
          if (!net::scriptOf(ss, k).empty()) {
            scriptBlock(net::scriptOf(ss, k), name + " " + std::string(net::info(k).key) + " (" + net::slotName(slot) + ")", shown);
          }
        }
      }
    }
    for (const auto& t : page.transitions) {
      if (t.name != name) continue;
      for (const auto k : net::kTransitionScripts) {
        if (!net::scriptOf(t, k).empty()) scriptBlock(net::scriptOf(t, k), name + " " + std::string(net::info(k).key), shown);
      }
    }
  }
  report["path_scripts"] = shown["scripts"];
}

/// A place made continuous (hybrid nets): its tokens become its amount, its a0 capacity its
/// capacity; what only discrete places have (slot kinds, nodes, scripts, sensors, colours) goes.
net::PlaceSpec madeContinuous(const net::PlaceSpec& place) {
  net::PlaceSpec p = place;
  net::FluidSpec f;
  f.loc = place.loc;
  f.amount = static_cast<double>(std::max<std::int64_t>(slotCount(place.tokens, net::kDefaultSlot).value_or(0), 0));
  if (const auto cap = slotCount(place.capacity, net::kDefaultSlot)) f.capacity = static_cast<double>(*cap);
  p.kinds.clear();
  p.tokens.clear();
  p.nodes.clear();
  p.capacity.clear();
  p.scripts.clear();
  p.sensors.clear();
  p.colours.clear();
  p.values.clear();
  p.fluid = std::move(f);
  return p;
}

/// A continuous place made discrete: its whole amount becomes tokens on a0, its capacity a0's.
net::PlaceSpec madeDiscrete(const net::PlaceSpec& place) {
  net::PlaceSpec p = place;
  if (!place.fluid) return p;
  const auto whole = [](double x) { return static_cast<std::int64_t>(std::floor(x)); };
  if (whole(place.fluid->amount) > 0) p.tokens = {{net::kDefaultSlot, whole(place.fluid->amount)}};
  if (place.fluid->capacity) p.capacity = {{net::kDefaultSlot, whole(*place.fluid->capacity)}};
  p.fluid.reset();
  return p;
}

/// The checkbox that makes a place continuous (hybrid nets) or discrete, one undoable edit.
void continuousPlaceBox(App& app, const ConstructAt& at, const net::PlaceSpec& place, nlohmann::json& report) {
  bool on = place.continuous();
  if (ImGui::Checkbox("continuous", &on)) commitPlace(app, at, on ? madeContinuous(place) : madeDiscrete(place));
  noteItem("continuous", report["fields"]);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("a continuous place holds a real amount (litres, kg, Ah) rather than tokens (hybrid nets)");
  }
  report["continuous"] = place.continuous();
}

/// A continuous place's amount, capacity and unit, each committed when its field is left.
void fluidPlaceFields(App& app, const ConstructAt& at, const net::PlaceSpec& place, nlohmann::json& report) {
  const net::FluidSpec& f = *place.fluid;
  nlohmann::json& fields = report["fields"];
  auto next = place;
  bool changed = false;
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("amount");
  ImGui::SameLine(100);
  double amount = f.amount;
  ImGui::SetNextItemWidth(110);
  ImGui::InputDouble("##fluid_amount", &amount, 0, 0, "%g");
  noteItem("amount", fields);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the amount it holds at the start, in its unit (0 or more)");
  if (ImGui::IsItemDeactivatedAfterEdit() && amount != f.amount) {
    next.fluid->amount = amount;
    changed = true;
  }
  ImGui::SameLine();
  ImGui::TextDisabled("%s", f.unit.c_str());
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("capacity");
  ImGui::SameLine(100);
  bool bounded = f.capacity.has_value();
  if (ImGui::Checkbox("##bounded", &bounded)) {
    next.fluid->capacity = bounded ? std::optional<double>(std::max(f.amount, 1.0)) : std::nullopt;
    changed = true;
  }
  noteItem("bounded", fields);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("bounded: it holds at most its capacity; unticked: unbounded");
  ImGui::SameLine();
  if (bounded && f.capacity) {
    double capacity = *f.capacity;
    ImGui::SetNextItemWidth(80);
    ImGui::InputDouble("##fluid_capacity", &capacity, 0, 0, "%g");
    noteItem("capacity", fields);
    if (ImGui::IsItemDeactivatedAfterEdit() && capacity != *f.capacity) {
      next.fluid->capacity = capacity;
      changed = true;
    }
    ImGui::SameLine();
    ImGui::TextDisabled("%s", f.unit.c_str());
  } else {
    ImGui::TextDisabled("unbounded");
  }
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("unit");
  ImGui::SameLine(100);
  std::string unit = f.unit;
  ImGui::SetNextItemWidth(110);
  ImGui::InputTextWithHint("##fluid_unit", "L, kg, Ah", &unit);
  noteItem("unit", fields);
  if (ImGui::IsItemDeactivatedAfterEdit() && unit != f.unit) {
    next.fluid->unit = unit;
    changed = true;
  }
  report["amount"] = f.amount;
  report["capacity"] = f.capacity ? nlohmann::json(*f.capacity) : nlohmann::json();
  report["unit"] = f.unit;
  report["editable"] = true;
  if (!f.drives.empty()) {
    std::string drives;
    for (const auto& d : f.drives) drives += (drives.empty() ? "" : ", ") + d.node + "." + d.field;
    ImGui::TextDisabled("drives %s", drives.c_str());
  }
  if (changed) commitPlace(app, at, std::move(next));
}

void editPlace(App& app, const ConstructAt& at, const net::PlaceSpec& place, const net::PageSpec& page,
               nlohmann::json& report) {
  const std::string construct = at.page + "/" + at.name;
  continuousPlaceBox(app, at, place, report);
  if (place.continuous()) {
    fluidPlaceFields(app, at, place, report);
    return;
  }
  nlohmann::json slots = nlohmann::json::object();
  nlohmann::json grid = nlohmann::json::object();
  if (ImGui::BeginTable("##slots", 8, ImGuiTableFlags_SizingFixedSame)) {
    for (int i = 0; i < net::kSlotCount; ++i) {
      ImGui::TableNextColumn();
      const auto slot = static_cast<net::SlotId>(i);
      const std::string name = net::slotName(slot);
      const auto kind = slotKindOf(place, slot);
      const std::int64_t tokens = slotCount(place.tokens, slot).value_or(0);
      std::vector<std::string> names;
      for (const auto& n : place.nodes) {
        if (n.slot == slot) names = n.nodes;
      }
      const bool used = kind != net::SlotKind::Control || tokens > 0 || slotCount(place.capacity, slot) ||
                        std::any_of(place.scripts.begin(), place.scripts.end(), [&](const auto& x) { return x.slot == slot; });
      const auto count = kind == net::SlotKind::Node ? static_cast<std::int64_t>(names.size()) : tokens;
      const std::string label = kind == net::SlotKind::Sensor ? name : name + " " + std::to_string(count);
      const bool chosen = app.inspector.contents_slot == slot;
      ImGui::PushStyleColor(ImGuiCol_Button, slotColour(kind, used));
      if (chosen) ImGui::PushStyleVar(ImGuiStyleVar_FrameBorderSize, 2.0f);
      if (ImGui::Button(label.c_str(), {56, 0})) app.inspector.contents_slot = slot;
      if (chosen) ImGui::PopStyleVar();
      ImGui::PopStyleColor();
      noteItem(name, grid);
      if (ImGui::BeginDragDropTarget()) {
        if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload(kNodePayload)) {
          auto p = place;
          addNodeToken(p, slot, std::string(static_cast<const char*>(payload->Data), static_cast<std::size_t>(payload->DataSize)));
          app.inspector.contents_slot = slot;
          commitPlace(app, at, std::move(p));
        }
        ImGui::EndDragDropTarget();
      }
      slotMenu(app, at, place, slot, report);
      if (used) slots[name] = {{"kind", net::slotKindName(kind)}, {"tokens", count}, {"names", names}};
    }
    ImGui::EndTable();
  }
  report["slots"] = slots;
  report["grid"] = grid;
  report["editable"] = true;
  slotFields(app, at, place, app.inspector.contents_slot, report);
  typeFindings(app, construct, report);
  pathScripts(page, at.name, app.inspector.contents_slot, report);

  // the chosen slot's scripts, then every other script of the place: side by side
  const auto kind = slotKindOf(place, app.inspector.contents_slot);
  const auto scriptsOf = [&](net::SlotId slot) {
    const auto it = std::find_if(place.scripts.begin(), place.scripts.end(), [&](const auto& x) { return x.slot == slot; });
    net::SlotScripts none;
    none.slot = slot;
    return it == place.scripts.end() ? none : *it;
  };
  const auto chosen = scriptsOf(app.inspector.contents_slot);
  for (const auto k : net::kSlotScripts) {
    const bool sensor_only = k != net::ScriptKind::OnDeposit && k != net::ScriptKind::OnRemove;
    if (sensor_only != (kind == net::SlotKind::Sensor)) continue;
    const std::string heading = std::string(net::info(k).key) + " (" + net::slotName(app.inspector.contents_slot) + ")";
    const auto slot = app.inspector.contents_slot;
    scriptEditor(app, construct + "#" + heading, heading, net::scriptOf(chosen, k), false, ScriptAt{at.page, at.name, k, slot},
                 [&app, at, place, slot, k](const std::string& code) {
                   auto p = place;
                   setSlotScript(p, slot, k, code);
                   commitPlace(app, at, std::move(p));
                 }, report);
  }
  for (const auto& s : place.scripts) {
    if (s.slot == app.inspector.contents_slot) continue;
    for (const auto k : net::kSlotScripts) {
      const auto& script = net::scriptOf(s, k);
      if (script.empty()) continue;
      const std::string heading = std::string(net::info(k).key) + " (" + net::slotName(s.slot) + ")";
      const auto slot = s.slot;
      scriptEditor(app, construct + "#" + heading, heading, script, false, ScriptAt{at.page, at.name, k, slot},
                   [&app, at, place, slot, k](const std::string& code) {
                     auto p = place;
                     setSlotScript(p, slot, k, code);
                     commitPlace(app, at, std::move(p));
                   }, report);
    }
  }
}

/// Why `rate` is not a rate of a continuous transition on `page` (hybrid nets), located in
/// it ("column 3: no name 'tnak' ..."); "" when it compiles. A rate names the continuous
/// places of its page, its reads and the model's parameters.
std::string rateError(const std::string& rate, const net::PageSpec& page, const net::FlowSpec& flow) {
  if (rate.empty()) return "a continuous transition needs a rate ('0.5', units per second)";
  std::vector<std::string> known;
  for (const auto& p : page.places) {
    if (p.continuous()) known.push_back(p.name);
  }
  for (const auto& r : flow.reads) known.push_back(r.name);
  for (const auto& [name, value] : flow.params) known.push_back(name);
  const auto resolve = [&](std::string_view name) -> std::optional<std::uint32_t> {
    const auto it = std::find(known.begin(), known.end(), name);
    if (it == known.end()) return std::nullopt;
    return static_cast<std::uint32_t>(it - known.begin());
  };
  core::ExpressionError error;
  if (core::compileExpression(rate, resolve, error, known)) return {};
  std::string why = "rate, column " + std::to_string(error.column + 1) + ": " + error.message;
  if (error.message.rfind("no name", 0) == 0) {
    why += " (a rate names the continuous places of its page, its reads and the model's parameters)";
  }
  return why;
}

/// A transition made continuous (hybrid nets): a flow at rate 1 that names the model's
/// parameters; what only firing transitions have (duration, priority, probability, servers,
/// condition, scripts) goes.
net::TransitionSpec madeFlow(const net::TransitionSpec& t, const model::Model& model) {
  net::TransitionSpec next = t;
  net::FlowSpec f;
  f.loc = t.loc;
  f.rate.text = "1";
  f.rate.loc = t.loc;
  for (const auto& p : model.params) f.params.emplace_back(p.name, p.value);
  next.duration = net::Duration{};
  next.priority = 0;
  next.probability = 1.0;
  next.servers = 1;
  next.priority_param.clear();
  next.probability_param.clear();
  next.servers_param.clear();
  next.guard = {};
  next.pre_fire = {};
  next.in_fire = {};
  next.post_fire = {};
  next.when = {};
  next.flow = std::move(f);
  return next;
}

/// A continuous transition's fields (hybrid nets): its rate, checked as typed and committed
/// when it compiles and the field is left, and its reads.
void flowFields(App& app, const ConstructAt& at, const net::TransitionSpec& t, const net::PageSpec& page,
                nlohmann::json& report) {
  const std::string construct = at.page + "/" + at.name;
  auto& edit = app.inspector;
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("rate");
  ImGui::SameLine(100);
  ImGui::SetNextItemWidth(220);
  if (!edit.rate_active || edit.rate_of != construct) {  // not being typed: the model's
    edit.rate_of = construct;
    edit.rate_text = t.flow->rate.text;
  }
  ImGui::InputTextWithHint("##rate", "0.5, k * tank", &edit.rate_text);
  edit.rate_active = ImGui::IsItemActive();
  const bool left = ImGui::IsItemDeactivatedAfterEdit();
  noteItem("rate", report["fields"]);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("units per second per unit of arc weight: a number, or an expression over the amounts of "
                      "the continuous places of its page, its reads and the model's parameters");
  }
  const std::string why = rateError(edit.rate_text, page, *t.flow);
  ImGui::SameLine();
  ImGui::TextDisabled("%s", diagram::rateUnit(page, at.name).c_str());
  if (!why.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4{1.0f, 0.45f, 0.4f, 1.0f});
    ImGui::TextWrapped("%s", why.c_str());
    ImGui::PopStyleColor();
  }
  if (left && why.empty() && edit.rate_text != t.flow->rate.text) {
    auto next = t;
    next.flow->rate.text = edit.rate_text;
    next.flow->rate.layout.clear();
    if (next.flow->rate.loc.line <= 0) next.flow->rate.loc = t.loc;
    commitTransition(app, at, std::move(next));
  }
  report["rate"] = t.flow->rate.text;
  report["rate_typed"] = edit.rate_text;
  report["rate_error"] = why;
  for (const auto& r : t.flow->reads) ImGui::TextDisabled("reads %s: %s of %s", r.name.c_str(), r.of.c_str(), r.node.c_str());
  report["editable"] = true;
}

void editTransition(App& app, const ConstructAt& at, const net::TransitionSpec& t, const net::PageSpec& page,
                    nlohmann::json& report) {
  const std::string construct = at.page + "/" + at.name;
  bool on = t.continuous();
  if (ImGui::Checkbox("continuous", &on)) {
    auto next = on ? madeFlow(t, app.document().model()) : t;
    if (!on) next.flow.reset();
    commitTransition(app, at, std::move(next));
  }
  noteItem("continuous", report["fields"]);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("a continuous transition flows at a rate instead of firing: it moves amounts between "
                      "continuous places (hybrid nets)");
  }
  report["continuous"] = t.continuous();
  if (t.continuous()) {
    flowFields(app, at, t, page, report);
    return;
  }
  nlohmann::json fields = report["fields"];
  // the duration: a law and its parameters, committed when a field is left
  int law = static_cast<int>(t.duration.law);
  net::Duration d = t.duration;
  bool changed = false;
  ImGui::SetNextItemWidth(130);
  if (ImGui::Combo("##law", &law, "fixed\0uniform\0normal\0exponential\0immediate\0")) {
    d.law = static_cast<net::Duration::Law>(law);
    d.params = {};  // another law's numbers mean other things: they no longer name parameters
    if (d.law == net::Duration::Law::Uniform && d.b < d.a) d.b = d.a;
    if (d.law == net::Duration::Law::Immediate) d.a = d.b = 0.0;
    changed = true;
  }
  noteItem("law", fields);
  const bool two = d.law == net::Duration::Law::Uniform || d.law == net::Duration::Law::Normal;
  const char* first = d.law == net::Duration::Law::Fixed ? "s" : d.law == net::Duration::Law::Uniform ? "low, s" : "mean, s";
  if (d.law != net::Duration::Law::Immediate) {  // no time, no number
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    ImGui::InputDouble(first, &d.a, 0, 0, "%g");
    keyItem(schema::key(Section::Transition, "duration"), fields);
    changed = changed || ImGui::IsItemDeactivatedAfterEdit();
    paramNote(t.duration.params[0]);
  }
  if (two) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    ImGui::InputDouble(d.law == net::Duration::Law::Uniform ? "high, s" : "sd, s", &d.b, 0, 0, "%g");
    noteItem("duration2", fields);
    changed = changed || ImGui::IsItemDeactivatedAfterEdit();
    paramNote(t.duration.params[1]);
  }
  int priority = static_cast<int>(t.priority);
  ImGui::SetNextItemWidth(90);
  const auto& priority_key = schema::key(Section::Transition, "priority");
  ImGui::InputInt(priority_key.name.c_str(), &priority, 0, 0);
  keyItem(priority_key, fields);
  const bool priority_changed = ImGui::IsItemDeactivatedAfterEdit();
  paramNote(t.priority_param);
  ImGui::SameLine();
  double probability = t.probability;
  ImGui::SetNextItemWidth(90);
  const auto& probability_key = schema::key(Section::Transition, "probability");
  ImGui::InputDouble(probability_key.name.c_str(), &probability, 0, 0, "%g");
  keyItem(probability_key, fields);
  const bool probability_changed = ImGui::IsItemDeactivatedAfterEdit();
  paramNote(t.probability_param);
  // servers: how many occurrences at once; "unlimited" greys the number out
  bool unlimited = t.servers == net::kUnlimitedServers;
  int servers = unlimited ? 1 : static_cast<int>(t.servers);
  ImGui::BeginDisabled(unlimited);
  ImGui::SetNextItemWidth(90);
  const auto& servers_key = schema::key(Section::Transition, "servers");
  ImGui::InputInt(servers_key.name.c_str(), &servers, 0, 0);
  ImGui::EndDisabled();
  keyItem(servers_key, fields);
  bool servers_changed = ImGui::IsItemDeactivatedAfterEdit();
  paramNote(t.servers_param);
  ImGui::SameLine();
  servers_changed = ImGui::Checkbox("unlimited", &unlimited) || servers_changed;
  noteItem("unlimited", fields);
  if (changed || priority_changed || probability_changed || servers_changed) {
    auto next = t;
    // a value typed in no longer comes from the parameter it named
    if (d.a != t.duration.a) d.params[0].clear();
    if (d.b != t.duration.b) d.params[1].clear();
    if (priority != t.priority) next.priority_param.clear();
    if (probability != t.probability) next.probability_param.clear();
    // a number typed below 1 is not "unlimited" (the spec's 0): it goes on to be refused
    const std::int64_t servers_now = unlimited ? net::kUnlimitedServers : servers >= 1 ? servers : -1;
    if (servers_now != t.servers) next.servers_param.clear();
    next.duration = d;
    next.priority = priority;
    next.probability = probability;
    next.servers = servers_now;
    commitTransition(app, at, std::move(next));
  }
  // the condition over its variables, in the inscription language (beside the Python guard)
  inscriptionField(app, construct + "#when", "condition (when)", t.when.text, {}, InscriptionRole::Condition,
                   [&app, at, t](const std::string& text) {
                     auto next = t;
                     next.when.text = text;
                     next.when.layout.clear();
                     if (next.when.loc.line <= 0) next.when.loc = t.loc;
                     commitTransition(app, at, std::move(next));
                   },
                   report);
  if (report.contains("fields")) {
    for (auto& [k, v] : report["fields"].items()) fields[k] = v;
  }
  report["duration"] = durationText(t.duration);
  report["fields"] = fields;
  report["editable"] = true;
  typeFindings(app, construct, report);
  for (const auto k : net::kTransitionScripts) {
    const std::string heading(net::info(k).key);
    scriptEditor(app, construct + "#" + heading, heading, net::scriptOf(t, k), net::info(k).expression,
                 ScriptAt{at.page, at.name, k}, [&app, at, t, k](const std::string& code) {
                   auto next = t;
                   setInlineCode(net::scriptOf(next, k), code, t.loc);
                   commitTransition(app, at, std::move(next));
                 }, report);
  }
}

/// Draws the edit-mode contents of the selected place or transition; false when the selection
/// is not one written in the model.
bool editContents(App& app, const Selection& sel, nlohmann::json& report) {
  auto& net = app.document().editableNet();
  const auto at = locateConstruct(net, sel.name);
  if (!at) return false;
  const net::PageSpec* page = findPage(net, at->page);
  if (page == nullptr) return false;
  if (sel.kind == SelectionKind::Place) {
    const auto it = std::find_if(page->places.begin(), page->places.end(), [&](const auto& p) { return p.name == at->name; });
    if (it == page->places.end()) return false;
    editPlace(app, *at, net::PlaceSpec(*it), *page, report);
    return true;
  }
  const auto it = std::find_if(page->transitions.begin(), page->transitions.end(), [&](const auto& t) { return t.name == at->name; });
  if (it == page->transitions.end()) return false;
  editTransition(app, *at, net::TransitionSpec(*it), *page, report);
  return true;
}

}  // namespace

void drawModelContents(App& app, nlohmann::json& report) {
  report["scripts"] = nlohmann::json::array();
  ImGui::Spacing();
  ImGui::TextUnformatted("The model's globals: run once at the start; every script sees their names, and a");
  ImGui::TextUnformatted("function summary() returning a dict adds the model's own figures to a run's summary.");
  const auto& globals = app.document().model().net.globals;
  if (app.run().mode() != RunMode::Edit) {
    // as the run has them: on their file lines
    const auto* session = app.run().session();
    scriptBlock(session != nullptr ? session->simulation().model().net.globals : globals, "globals", report, runError(app));
    return;
  }
  scriptEditor(app, "#globals", "globals", globals, false, ScriptAt{},
               [&app](const std::string& code) {
                 const auto why = app.document().execute(std::make_unique<SetGlobalsCommand>(code));
                 if (!why.empty()) app.message = why;
               }, report);
}

void drawContents(App& app, const Selection& sel, nlohmann::json& report) {
  report["scripts"] = nlohmann::json::array();
  const bool construct = sel.kind == SelectionKind::Place || sel.kind == SelectionKind::Transition;
  if (construct && app.run().mode() == RunMode::Edit && editContents(app, sel, report)) return;
  auto* session = app.run().session();
  if (session == nullptr) return;
  const auto& net = session->simulation().net();
  if (sel.kind == SelectionKind::Place) {
    if (const auto p = net.findPlace(sel.name)) placeContents(app, *session, *p, report, runError(app));
  } else if (sel.kind == SelectionKind::Transition) {
    if (const auto t = net.findTransition(sel.name)) transitionContents(*session, *t, report, runError(app));
  }
}

}  // namespace gdpn::ide
