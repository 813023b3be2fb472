// The inspector: the selected node's fields from its type's one description (units, ranges,
// documentation), each edit a command (a drag is one step); a place's or transition's state.

#include <imgui.h>

#include <variant>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "../action_run.h"
#include "../detail/picture_texture.h"
#include "../views.h"
#include "gdpn/core/text.h"
#include "gdpn/diagram/layout.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/ide/set_field.h"
#include "gdpn/scene/actions.h"
#include "gdpn/scene/user_data.h"

namespace gdpn::ide {

namespace {

using scene::FieldKind;
using scene::FieldValue;

/// One field's widget; true with `out` when the user changed the value this frame.
bool fieldWidget(const scene::FieldDesc& d, const FieldValue& v, FieldValue& out) {
  const double lo = d.boundedBelow() ? d.min : -1e9;
  const double hi = d.boundedAbove() ? d.max : 1e9;
  const float speed = static_cast<float>(d.boundedAbove() && d.boundedBelow() ? (hi - lo) / 300.0 : 0.01);
  switch (d.kind) {
    case FieldKind::Bool: {
      bool b = std::get<bool>(v);
      if (!ImGui::Checkbox("##v", &b)) return false;
      out = b;
      return true;
    }
    case FieldKind::Int: {
      auto i = std::get<std::int64_t>(v);
      const auto ilo = static_cast<std::int64_t>(std::max(lo, -1e15)), ihi = static_cast<std::int64_t>(std::min(hi, 1e15));
      if (!ImGui::DragScalar("##v", ImGuiDataType_S64, &i, 0.2F, &ilo, &ihi)) return false;
      out = i;
      return true;
    }
    case FieldKind::Float: {
      double x = std::get<double>(v);
      if (!ImGui::DragScalar("##v", ImGuiDataType_Double, &x, speed, &lo, &hi, "%.4g")) return false;
      out = x;
      return true;
    }
    case FieldKind::Color: {
      const auto c = std::get<std::array<double, 3>>(v);
      float f[3] = {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
      if (!ImGui::ColorEdit3("##v", f, ImGuiColorEditFlags_Float)) return false;
      // the widget holds 32 bits: a component it did not change keeps its value, a changed one
      // is what the widget shows (0.2, not 0.20000000298023224)
      std::array<double, 3> changed = c;
      for (std::size_t k = 0; k < 3; ++k) {
        if (f[k] != static_cast<float>(c[k])) changed[k] = core::widenFloat(f[k]);
      }
      out = changed;
      return true;
    }
    case FieldKind::Vec3: {
      auto a = std::get<std::array<double, 3>>(v);
      if (!ImGui::DragScalarN("##v", ImGuiDataType_Double, a.data(), 3, speed, &lo, &hi, "%.4g")) return false;
      out = a;
      return true;
    }
    case FieldKind::Rotation: {
      auto a = std::get<std::array<double, 4>>(v);
      if (!ImGui::DragScalarN("##v", ImGuiDataType_Double, a.data(), 4, 0.01F, nullptr, nullptr, "%.4g")) return false;
      out = a;
      return true;
    }
    case FieldKind::Enum: {
      const auto& cur = std::get<std::string>(v);
      bool changed = false;
      if (ImGui::BeginCombo("##v", cur.c_str())) {
        for (const auto& c : d.choices) {
          if (ImGui::Selectable(c.c_str(), c == cur) && c != cur) {
            out = c;
            changed = true;
          }
        }
        ImGui::EndCombo();
      }
      return changed;
    }
    case FieldKind::String:
    case FieldKind::File: {
      auto s = std::get<std::string>(v);
      if (!ImGui::InputText("##v", &s, ImGuiInputTextFlags_EnterReturnsTrue)) return false;
      out = s;
      return true;
    }
    case FieldKind::FloatList: {
      const auto& xs = std::get<std::vector<double>>(v);
      ImGui::TextDisabled("%zu numbers", xs.size());
      return false;
    }
  }
  return false;
}

/// Runs `command` on the document; its refusal is shown above the fields.
void edit(App& app, std::unique_ptr<Command> command) { app.inspector.error = app.document().execute(std::move(command)); }

/// A node's template mark and its user data, each edit a command: one line with the mark and
/// a datum to add, then a line per datum.
void nodeExtras(App& app, const scene::Node& node, const std::string& path, nlohmann::json& report) {
  bool on = node.is_template;
  if (ImGui::Checkbox("template", &on)) edit(app, std::make_unique<SetTemplateCommand>(path, on));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("kept to be copied by spawn: neither simulated, sensed nor drawn");
  report["template"] = node.is_template;
  for (const scene::Node* up = node.parent(); up != nullptr && !node.is_template; up = up->parent()) {
    if (!up->is_template) continue;
    ImGui::SameLine();
    ImGui::TextDisabled("(inside template %s)", up->path().c_str());
    report["inside_template"] = up->path();
    break;
  }
  // a datum to add: a name and a value (true/false, a number, [numbers] or text)
  const float right = ImGui::GetContentRegionMax().x;
  ImGui::SameLine(std::max(ImGui::GetCursorPosX() + 8.0F, right - 330.0F));
  ImGui::TextDisabled("add data");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  ImGui::InputTextWithHint("##datum_key", "name", &app.inspector.datum_key);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  const bool enter = ImGui::InputTextWithHint("##datum_value", "value", &app.inspector.datum_value,
                                              ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::SmallButton("add") || enter) && !app.inspector.datum_key.empty()) {
    edit(app, std::make_unique<SetDatumCommand>(path, app.inspector.datum_key, scene::datumFromText(app.inspector.datum_value)));
    if (app.inspector.error.empty()) {
      app.inspector.datum_key.clear();
      app.inspector.datum_value.clear();
    }
  }
  auto& data = report["data"] = nlohmann::json::object();
  // an edit changes node.data: made after the loop over it
  std::unique_ptr<Command> change;
  for (const auto& datum : node.data) {
    const std::string& key = datum.first;  // named, not bound: lambdas capture it below
    const scene::FieldValue& value = datum.second;
    ImGui::PushID(key.c_str());
    ImGui::AlignTextToFramePadding();
    ImGui::TextDisabled("data");
    ImGui::SameLine(50);
    ImGui::TextUnformatted(key.c_str());
    ImGui::SameLine(160);
    std::string text = scene::datumText(value);
    ImGui::SetNextItemWidth(-40);
    if (ImGui::InputText("##datum", &text, ImGuiInputTextFlags_EnterReturnsTrue)) {
      // text stays text ("007" is not the number 7); anything else reads as the file does
      const bool is_text = std::holds_alternative<std::string>(value);
      change = std::make_unique<SetDatumCommand>(path, key, is_text ? scene::FieldValue(text) : scene::datumFromText(text));
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) change = std::make_unique<SetDatumCommand>(path, key, std::nullopt);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("remove %s", key.c_str());
    ImGui::PopID();
    std::visit([&](const auto& v) { data[key] = v; }, value);
  }
  if (change) edit(app, std::move(change));
}

/// A channel's value as JSON for the report: numbers, flags, [x, y, z], lists, node paths, words.
nlohmann::json channelJson(const sensors::Value& v, const std::function<std::string(scene::NodeHandle)>& name_of) {
  return std::visit(
      [&](const auto& x) -> nlohmann::json {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, core::Vec3>) {
          return {x.x, x.y, x.z};
        } else if constexpr (std::is_same_v<T, std::vector<scene::NodeHandle>>) {
          auto out = nlohmann::json::array();
          for (auto h : x) out.push_back(name_of(h));
          return out;
        } else if constexpr (std::is_same_v<T, scene::NodeHandle>) {
          return x != 0 ? nlohmann::json(name_of(x)) : nlohmann::json();
        } else {
          return x;
        }
      },
      v);
}

/// What sensor `sensor` reads now in the run, channel by channel (a camera: the latest picture
/// a script read, nothing rendered for the asking, so that showing it leaves the run as it
/// would be).
void sensorReading(App& app, const model::Simulation& sim, const scene::Node& sensor, nlohmann::json& report) {
  const sensors::Reading& r = sim.reading(sensor.handle());
  const sensors::SensorKind* kind = sensors::sensorKind(sensor.kind());
  const std::function<std::string(scene::NodeHandle)> name_of = [&](scene::NodeHandle h) {
    const scene::Node* n = sim.plant()->resolve(h);
    return n != nullptr ? n->path() : std::string("(gone)");
  };
  const bool degrees = sim.model().settings.angles == scene::AngleUnit::Degrees;
  ImGui::Separator();
  ImGui::TextDisabled("What it reads in the run:");
  const auto channels = r.channels();
  for (std::size_t i = 0; i < channels.size(); ++i) {
    const sensors::Channel& c = channels[i];
    report[std::string(c.name)] = channelJson(r.value(i), name_of);
    if (c.per_item) continue;  // beside each item
    if (c.type != sensors::ChannelType::Items) {
      ImGui::Text("%s: %s", std::string(c.name).c_str(), sensors::channelText(c, r.value(i), name_of, degrees).c_str());
      continue;
    }
    // the items, the first few by name, each with its share of a per-item channel
    const auto& items = r.get<std::vector<scene::NodeHandle>>(i);
    ImGui::Text("%s: %zu", std::string(c.name).c_str(), items.size());
    for (std::size_t k = 0; k < items.size() && k < 8; ++k) {
      std::string line = name_of(items[k]);
      for (std::size_t j = 0; j < channels.size(); ++j) {
        const auto* per = std::get_if<std::vector<double>>(&r.value(j));
        if (!channels[j].per_item || per == nullptr || k >= per->size()) continue;
        line += "  " + sensors::numberText((*per)[k]) + (channels[j].unit.empty() ? "" : " ") + std::string(channels[j].unit);
      }
      ImGui::BulletText("%s", line.c_str());
    }
  }
  ImGui::Text("active: %s", r.active ? "yes" : "no");
  if (kind != nullptr) {
    ImGui::SameLine();
    ImGui::TextDisabled("(yes when %s)", std::string(kind->active).c_str());
  }
  report["active"] = r.active;
  if (kind == nullptr || !kind->pictures) return;
  const auto picture = sim.lastPicture(sensor.handle());
  report["picture"] = picture ? nlohmann::json{picture->width, picture->height} : nlohmann::json();
  if (!picture) {
    ImGui::TextDisabled("No picture read yet: a camera renders only when a script reads it.");
    return;
  }
  namespace F = scene::field;
  if (!app.inspector.picture_texture) app.inspector.picture_texture = std::make_unique<PictureTexture>();
  app.inspector.picture_texture->show(picture, sensor.number(F::ColorCamera::Near), sensor.number(F::ColorCamera::Far));
  const bool depth = !picture->depth.empty();
  ImGui::TextDisabled("the latest picture a script read, %d x %d%s", picture->width, picture->height,
                      depth ? " (near white, far black)" : "");
  // as large as the inspector allows, at most 4 times its size and half the panel's height,
  // so that the fields stay in sight
  const float aspect = static_cast<float>(picture->height) / static_cast<float>(picture->width);
  const float width = std::min({ImGui::GetContentRegionAvail().x, 4.0F * static_cast<float>(picture->width),
                                0.5F * ImGui::GetWindowHeight() / aspect});
  const float height = width * aspect;
  ImGui::Image(reinterpret_cast<ImTextureID>(app.inspector.picture_texture->texture()), {width, height});
}

void nodeInspector(App& app, const std::string& path, nlohmann::json& report) {
  // a part's Transform stands for the part: its parameters, I/O and control
  if (const auto part = partAtPath(app, path)) {
    report["node"] = path;
    drawPartInspector(app, *part, report["part"]);
    return;
  }
  auto* s = app.document().scene();
  auto* node = s != nullptr ? s->find(path) : nullptr;
  if (node == nullptr) {
    ImGui::TextDisabled("%s is not in the model (made by the run)", path.c_str());
    report["node"] = path;
    return;
  }
  ImGui::Text("%s  %s", node->type().name.c_str(), path.c_str());
  ImGui::SameLine();
  ImGui::TextDisabled("%s", node->type().doc.c_str());
  if (!app.inspector.error.empty()) ImGui::TextColored({1.0F, 0.4F, 0.35F, 1.0F}, "%s", app.inspector.error.c_str());
  if (app.run().mode() != RunMode::Edit) {
    ImGui::TextDisabled("The model as edited: the run takes edits at Reset.");
    // where a moving body is in the run now (world frame)
    auto* plant = app.run().session() != nullptr ? app.run().session()->simulation().plant() : nullptr;
    const auto* live = plant != nullptr ? plant->find(path) : nullptr;
    const auto box = live != nullptr && live->dynamic_pose ? scene::boundingBox(*live) : core::Aabb{};
    if (!box.empty()) {
      const auto p = (box.lo + box.hi) * 0.5;
      ImGui::Text("In the run its shapes' centre is at (%.3f, %.3f, %.3f) m.", p.x, p.y, p.z);
      report["live_position"] = {p.x, p.y, p.z};
    }
    if (live != nullptr && live->type().category == scene::Category::Sensor) {
      sensorReading(app, app.run().session()->simulation(), *live, report["reading"]);
    }
  }
  report["node"] = path;
  report["type"] = node->type().name;
  nodeExtras(app, *node, path, report);
  auto& fields = report["fields"] = nlohmann::json::array();
  const auto& types = node->type().fields;
  if (types.empty()) {
    ImGui::TextDisabled("(no fields)");
    return;
  }
  if (!ImGui::BeginTable("##fields", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                            ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp)) {
    return;
  }
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("field", ImGuiTableColumnFlags_WidthFixed, 110);
  ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch, 2.0F);
  ImGui::TableSetupColumn("unit", ImGuiTableColumnFlags_WidthFixed, 80);
  ImGui::TableSetupColumn("range", ImGuiTableColumnFlags_WidthStretch, 1.0F);
  ImGui::TableHeadersRow();
  for (std::size_t i = 0; i < types.size(); ++i) {
    const auto& d = *types[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(d.name.c_str());
    if (ImGui::IsItemHovered() && !d.doc.empty()) ImGui::SetTooltip("%s", d.doc.c_str());
    ImGui::TableNextColumn();
    ImGui::SetNextItemWidth(-1);
    FieldValue next;
    const bool changed = fieldWidget(d, node->value(i), next);
    // a drag of one widget is one step: a new drag id when it becomes active
    if (ImGui::IsItemActivated()) ++app.inspector.drag_id;
    if (changed) {
      auto why = app.document().execute(std::make_unique<SetFieldCommand>(path, d.name, std::move(next), app.inspector.drag_id));
      app.inspector.error = why;
    }
    if (ImGui::IsItemDeactivated()) app.document().history().seal();
    ImGui::TableNextColumn();
    ImGui::AlignTextToFramePadding();
    // a joint's axis-1 fields are in m in a slider, in deg in a hinge
    const auto& unit = scene::unitOf(*node, i);
    ImGui::TextDisabled("%s", unit.c_str());
    ImGui::TableNextColumn();
    const auto range = d.rangeText();
    // a field that names a model parameter says which, where its range would be
    const auto bound = std::find_if(node->params.begin(), node->params.end(),
                                    [i](const auto& b) { return b.field == static_cast<std::uint32_t>(i); });
    const std::string param = bound == node->params.end() ? std::string() : bound->text;
    ImGui::AlignTextToFramePadding();
    if (!param.empty()) {
      const std::string ref = model::referenceText(param);
      ImGui::Text("%s%s", param[0] == '=' ? "" : "= ", ref.c_str());
      if (ImGui::IsItemHovered()) {
        const std::string tip = param[0] == '='
                                    ? "computed from the part's parameters; a value typed here replaces it"
                                    : "the value of parameter '" + param +
                                          "' (the params section); a value typed here replaces it";
        ImGui::SetTooltip("%s", tip.c_str());
      }
    } else {
      ImGui::TextDisabled("%s", range.c_str());
      if (ImGui::IsItemHovered() && !range.empty()) ImGui::SetTooltip("%s", range.c_str());
    }
    ImGui::PopID();
    nlohmann::json value;
    std::visit([&](const auto& v) { value = v; }, node->value(i));
    fields.push_back({{"name", d.name}, {"unit", unit}, {"range", range}, {"kind", scene::fieldKindName(d.kind)},
                      {"value", value}});
    if (!param.empty()) fields.back()["param"] = param;
  }
  ImGui::EndTable();
}

/// A checkbox that adds or removes breakpoint `bp` of the run.
void breakpointBox(App& app, const char* label, session::Breakpoint bp, nlohmann::json& report) {
  const auto description = bp.describe();
  const auto list = app.run().breakpoints();
  bool on = std::find(list.begin(), list.end(), description) != list.end();
  if (ImGui::Checkbox(label, &on)) {
    if (on) app.message = app.run().addBreakpoint(std::move(bp));
    else (void)app.run().removeBreakpoint(description);
  }
  if (on) report["breakpoints"].push_back(description);
}

void runState(App& app, const session::Session& session, const Selection& sel, nlohmann::json& report);

/// An instance: its page type, the places it publishes (its ports), and a way into its page.
void instanceInspector(App& app, const Selection& sel, nlohmann::json& report) {
  const auto& net = app.document().model().net;
  const auto at = locateConstruct(net, sel.name);
  const auto* page = at ? findPage(net, at->page) : nullptr;
  const net::InstanceSpec* inst = nullptr;
  if (page != nullptr) {
    for (const auto& i : page->instances) {
      if (i.name == at->name) inst = &i;
    }
  }
  if (inst == nullptr) return;
  const auto* type = findPage(net, inst->type);
  ImGui::Text("of page type %s", inst->type.c_str());
  report["type"] = inst->type;
  std::string ports;
  if (type != nullptr) {
    for (const auto& r : type->references) ports += (ports.empty() ? "" : ", ") + r.place;
  }
  ImGui::TextWrapped("ports: %s", ports.empty() ? "none (its page type publishes no place)" : ports.c_str());
  report["ports"] = ports;
  if (ImGui::Button("Open Its Page")) (void)performAction(app, ActionId::OpenInstance);
  noteItem("Open Its Page", report["buttons"]);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show the instance's page in the net view (Up comes back)");
}

void netInspector(App& app, const Selection& sel, nlohmann::json& report) {
  auto* session = app.run().session();
  report["name"] = sel.name;
  ImGui::Text("%s  %s", selectionKindName(sel.kind), sel.name.c_str());
  if (sel.kind == SelectionKind::Instance) instanceInspector(app, sel, report);
  if (session != nullptr) runState(app, *session, sel, report);
  drawContents(app, sel, report["contents"]);
}

/// A continuous place in the run (hybrid nets): its amount of its capacity and the room
/// promised to occurring transitions (the contents view below draws the level and sets it).
void fluidPlaceState(const model::Simulation& sim, net::PlaceId p, nlohmann::json& report) {
  const auto& kernel = sim.kernel();
  const net::Fluid& fluid = *sim.net().fluid();
  const net::FluidPlace& fp = fluid.places[static_cast<std::size_t>(fluid.of_place[p])];
  const double amount = kernel.amount(p), reserved = kernel.amountReserved(p);
  const std::string capacity = std::isfinite(fp.capacity) ? "of " + diagram::amountText(fp.capacity, fp.unit) : "(unbounded)";
  ImGui::Text("amount: %s %s", diagram::amountText(amount, fp.unit).c_str(), capacity.c_str());
  ImGui::Text("reserved: %s", diagram::amountText(reserved, fp.unit).c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("room promised to occurring transitions that put an amount here");
  if (const auto& loc = sim.net().placeLoc(p); loc.line > 0) ImGui::TextDisabled("declared at %s", loc.str().c_str());
  report["amount"] = amount;
  report["reserved"] = reserved;
  report["unit"] = fp.unit;
}

/// A continuous transition in the run (hybrid nets): whether it flows, its effective rate and
/// the nominal rate it would flow at were no input empty and no output full.
void flowState(const model::Simulation& sim, net::TransitionId t, nlohmann::json& report) {
  const auto& kernel = sim.kernel();
  const net::Net& net = sim.net();
  const net::Fluid& fluid = *net.fluid();
  const net::Flow& flow = fluid.flows[static_cast<std::size_t>(fluid.of_transition[t])];
  // the rate's unit: its first output's place's, else its first input's
  std::string unit;
  for (std::uint32_t a = flow.outputs_begin; a < flow.outputs_end && unit.empty(); ++a) {
    unit = fluid.places[fluid.arcs[a].place].unit;
  }
  for (std::uint32_t a = flow.inputs_begin; a < flow.outputs_begin && unit.empty(); ++a) {
    unit = fluid.places[fluid.arcs[a].place].unit;
  }
  unit += "/s";
  const double rate = kernel.flowRate(t), nominal = kernel.nominalRate(t);
  const std::string state = rate != 0.0 ? "flowing" : nominal != 0.0 ? "cut to nothing" : "off";
  ImGui::Text("%s", state.c_str());
  ImGui::Text("rate: %s", diagram::rateText(rate, unit).c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the effective rate: the nominal one cut where an input is empty or an output full");
  ImGui::Text("nominal rate: %s", diagram::rateText(nominal, unit).c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the rate its expression gives while its arcs allow it (0 while switched off)");
  if (const auto& loc = net.transitionLoc(t); loc.line > 0) ImGui::TextDisabled("declared at %s", loc.str().c_str());
  report["state"] = state;
  report["flow_rate"] = rate;
  report["nominal_rate"] = nominal;
  report["rate_unit"] = unit;
}

/// What the run says of the selected place or transition, and its breakpoints; nothing for one
/// the run does not have yet (added since it was made).
void runState(App& app, const session::Session& session, const Selection& sel, nlohmann::json& report) {
  const auto& sim = session.simulation();
  if (sel.kind == SelectionKind::Place) {
    const auto p = sim.net().findPlace(sel.name);
    if (!p) return;
    if (sim.net().continuousPlace(*p)) {
      fluidPlaceState(sim, *p, report);
      return;
    }
    const auto tokens = sim.kernel().placeTokens(*p);
    ImGui::Text("tokens: %lld", static_cast<long long>(tokens));
    const auto& loc = sim.net().placeLoc(*p);
    if (loc.line > 0) ImGui::TextDisabled("declared at %s", loc.str().c_str());
    report["tokens"] = tokens;
    placeValues(session, *p, report);
    ImGui::SetNextItemWidth(90);
    ImGui::InputInt("##at_least", &app.inspector.break_tokens);
    ImGui::SameLine();
    breakpointBox(app, "break when it holds at least this many tokens",
                  session::Breakpoint::marking(sel.name, session::Compare::GreaterEqual, app.inspector.break_tokens), report);
  } else if (sel.kind == SelectionKind::Transition) {
    const auto t = sim.net().findTransition(sel.name);
    if (!t) return;
    const net::TransitionId id = *t;
    if (sim.net().continuous(id)) {
      flowState(sim, id, report);
      return;
    }
    const auto& tr = sim.net().transitions()[id];
    const auto& kernel = sim.kernel();
    // the kernel's own answer: what the last firing phase found (no script runs here)
    const net::Readiness ready = kernel.readiness(id);
    const bool able = ready == net::Readiness::Able;
    std::string state = kernel.occurring(id) ? "occurring" : able ? "enabled" : "not enabled";
    if (tr.servers != 1) {
      // with servers: how many run, of how many, and whether another may start
      const std::string busy = std::to_string(kernel.occurrences(id));
      state = tr.servers == net::kUnlimitedServers ? busy + " occurring (servers unlimited)"
                                                   : busy + " of " + std::to_string(tr.servers) + " servers busy";
      if (able) state += ", enabled";
    }
    // what holds it back, or why it is not enabled: "held back: guard false"
    std::string why;
    if (net::heldBack(ready)) why = "held back: " + kernel.readinessText(id);
    else if (ready == net::Readiness::Untried) why = "waiting: " + kernel.readinessText(id);
    else if (ready == net::Readiness::Tokens || ready == net::Readiness::Room) why = "not enabled: " + kernel.readinessText(id);
    if (!kernel.occurring(id) && net::heldBack(ready)) state = "held back";
    // one line where the reason says it all ("held back: guard false"), else the state first
    if (why.empty() || tr.servers != 1 || kernel.occurring(id)) ImGui::Text("%s", state.c_str());
    if (!why.empty()) {
      if (net::heldBack(ready)) ImGui::TextColored({0.95F, 0.70F, 0.10F, 1}, "%s", why.c_str());
      else ImGui::TextDisabled("%s", why.c_str());
    }
    report["readiness"] = net::readinessName(ready);
    report["why"] = why;
    transitionBindings(app, session, id, sel.name, report);
    // in edit mode the contents view below has them as fields
    if (app.run().mode() != RunMode::Edit) {
      ImGui::Text("priority %lld, probability %g", static_cast<long long>(tr.priority), tr.probability);
    }
    if (const auto& loc = sim.net().transitionLoc(id); loc.line > 0) ImGui::TextDisabled("declared at %s", loc.str().c_str());
    report["state"] = state;
    breakpointBox(app, "break when it starts", session::Breakpoint::starts(sel.name), report);
    ImGui::SameLine();
    breakpointBox(app, "break when it completes", session::Breakpoint::completes(sel.name), report);
  }
}

}  // namespace

void drawInspector(App& app, const Rect& at, nlohmann::json& report) {
  beginPanel("##inspector", at, nullptr);  // its tab names it
  const auto sel = app.document().selection();
  report = {{"kind", selectionKindName(sel.kind)}, {"error", app.inspector.error}};
  switch (sel.kind) {
    case SelectionKind::None:
      ImGui::TextDisabled("Select a node in the tree or the world view, or a place, transition or arc in the net view.");
      drawModelContents(app, report["contents"]);
      break;
    case SelectionKind::Node: nodeInspector(app, sel.name, report); break;
    case SelectionKind::Place:
    case SelectionKind::Transition:
    case SelectionKind::Instance:
      if (const auto part = findPartInstance(app.document().model(), sel.name)) {
        drawPartInspector(app, *part, report["part"]);
        ImGui::Separator();
      }
      netInspector(app, sel, report);
      break;
    case SelectionKind::Arc: arcInspector(app, sel, report); break;
  }
  endPanel();
}

}  // namespace gdpn::ide
