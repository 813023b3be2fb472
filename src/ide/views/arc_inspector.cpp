// The inspector of a selected arc: its kind, its weight on each slot, the predicates of its
// node slots and the conditions of its sensor slots, reverse and delete. Each change is one
// undoable edit of the arc (NetEditKind::SetArc).

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <string>

#include "../action_run.h"
#include "../views.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/net/slot.h"

namespace gdpn::ide {

namespace {

/// The arc `sel` names, and the page it is written on; null when it is gone.
const net::ArcSpec* arcOf(const Document& doc, const Selection& sel, std::string& page) {
  const auto name = parseArcName(sel.name);
  if (!name) return nullptr;
  const auto at = locateConstruct(doc.model().net, name->prefix + "/_");  // the page of the prefix
  const auto* spec = at ? findPage(doc.model().net, at->page) : nullptr;
  if (spec == nullptr) return nullptr;
  page = at->page;
  for (const auto& a : spec->arcs) {
    if (a.from == name->from && a.to == name->to && a.kind == name->kind) return &a;
  }
  return nullptr;
}

/// Puts `changed` in place of `was` on `page` as one step and keeps it selected; "" or why not.
std::string setArc(App& app, const std::string& page, const net::ArcSpec& was, const net::ArcSpec& changed) {
  auto e = makeNetEdit(NetEditKind::SetArc, page, was.from, was.to);
  e.arc_kind = was.kind;
  e.arc = changed;
  const std::string why = app.document().execute(std::make_unique<NetEditCommand>(std::move(e)));
  if (!why.empty()) {
    app.message = why;
    return why;
  }
  const auto name = parseArcName(app.document().selection().name);
  if (name) app.document().select({SelectionKind::Arc, arcName(name->prefix, changed.from, changed.to, changed.kind)});
  return {};
}

/// The text field of the expression `what` ("predicate", "condition") of `slot` in `list`,
/// changed when the field is left; an empty text removes it. True when it changed.
bool expressionRow(const char* what, net::SlotId slot, std::vector<net::SlotPredicate>& list, const core::SourceLoc& owner,
                   nlohmann::json& report) {
  const std::string name = net::slotName(slot);
  auto it = std::find_if(list.begin(), list.end(), [&](const net::SlotPredicate& p) { return p.slot == slot; });
  ImGui::PushID(what);
  ImGui::PushID(static_cast<int>(std::hash<std::string>{}(name)));
  ImGui::Text("%s %s", what, name.c_str());
  ImGui::SameLine(150);
  ImGui::SetNextItemWidth(-1);
  std::string text = it != list.end() ? it->expression.code : std::string();
  ImGui::InputTextWithHint("##expr", "a Python expression", &text);
  noteItem(std::string(what) + " " + name, report["fields"]);
  bool changed = false;
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    if (it == list.end()) {
      list.push_back({slot, {}});
      it = std::prev(list.end());
    }
    setInlineCode(it->expression, text, owner);
    if (text.empty()) list.erase(it);
    changed = true;
  }
  report[std::string(what) + " " + name] = text;
  ImGui::PopID();
  ImGui::PopID();
  return changed;
}

/// The continuous place at either end of `arc` on page `page` (hybrid nets); null for none.
const net::PlaceSpec* continuousEnd(App& app, const std::string& page, const net::ArcSpec& arc) {
  const auto* spec = findPage(app.document().model().net, page);
  if (spec == nullptr) return nullptr;
  for (const auto& p : spec->places) {
    if ((p.name == arc.from || p.name == arc.to) && p.continuous()) return &p;
  }
  return nullptr;
}

/// The weight of an arc with a continuous place: a real number in the place's unit (1 when
/// none is written), applied when the field is left; a threshold for a test or an inhibitor arc.
void realWeight(App& app, const std::string& page, const net::ArcSpec& was, const net::PlaceSpec& place,
                nlohmann::json& report) {
  const double weight = was.amount.value_or(1.0);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(was.kind == net::ArcKind::Normal ? "weight" : "threshold");
  ImGui::SameLine(150);
  ImGui::SetNextItemWidth(110);
  double typed = weight;
  ImGui::InputDouble("##amount", &typed, 0, 0, "%g");
  noteItem("weight", report["fields"]);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s", was.kind == net::ArcKind::Normal
                                ? "the amount it moves (a continuous transition: per unit of its rate), in the place's unit"
                                : "the amount it compares the place's with, in the place's unit");
  }
  const bool left = ImGui::IsItemDeactivatedAfterEdit();
  ImGui::SameLine();
  ImGui::TextDisabled("%s  (continuous place %s)", place.fluid->unit.c_str(), place.name.c_str());
  report["weight"] = weight;
  if (left && typed != weight) {
    net::ArcSpec next = was;
    next.amount = typed;
    next.weights.clear();
    if (typed == 1.0) next.amount.reset();  // 1 is what an arc without a weight means
    (void)setArc(app, page, was, next);
  }
}

}  // namespace

void arcInspector(App& app, const Selection& sel, nlohmann::json& report) {
  report["name"] = sel.name;
  std::string page;
  const net::ArcSpec* found = arcOf(app.document(), sel, page);
  ImGui::Text("arc  %s", sel.name.c_str());
  if (app.document().selectedCount() > 1) {
    ImGui::SameLine();
    ImGui::TextDisabled("(and %zu more selected)", app.document().selectedCount() - 1);
  }
  if (found == nullptr) return;
  const net::ArcSpec was = *found;  // the edits below replace the page's copy
  net::ArcSpec arc = was;
  if (was.loc.line > 0) ImGui::TextDisabled("declared at %s", was.loc.str().c_str());
  const bool editing = app.run().mode() == RunMode::Edit;
  ImGui::BeginDisabled(!editing);
  // the kind: test and inhibitor arcs run from a place to a transition
  ImGui::SetNextItemWidth(130);
  const bool open = ImGui::BeginCombo("kind", net::arcKindName(arc.kind));
  noteItem("kind", report["fields"]);
  if (open) {
    for (const auto kind : {net::ArcKind::Normal, net::ArcKind::Test, net::ArcKind::Inhibitor}) {
      const bool chosen = ImGui::Selectable(net::arcKindName(kind), kind == arc.kind);
      noteItem(std::string("kind ") + net::arcKindName(kind), report["fields"]);
      if (chosen && kind != arc.kind) {
        net::ArcSpec changed = arc;
        changed.kind = kind;
        (void)setArc(app, page, was, changed);
      }
    }
    ImGui::EndCombo();
  }
  report["arc_kind"] = net::arcKindName(arc.kind);
  ImGui::SameLine();
  if (ImGui::Button("Reverse")) (void)performAction(app, ActionId::ReverseArc);
  noteItem("Reverse", report["buttons"]);
  ImGui::SameLine();
  if (ImGui::Button("Delete")) (void)performAction(app, ActionId::Delete);
  noteItem("Delete", report["buttons"]);
  // an arc with a continuous place (hybrid nets): one real weight, in the place's unit
  if (const net::PlaceSpec* fluid = continuousEnd(app, page, was)) {
    realWeight(app, page, was, *fluid, report);
    ImGui::EndDisabled();
    return;
  }
  // the weight on each slot (none written: 1 on a0)
  // a slot with an inscription has no weight: the inscription says what moves
  const auto inscribed = [&](net::SlotId slot) {
    return std::any_of(was.inscriptions.begin(), was.inscriptions.end(), [&](const net::SlotText& t) { return t.slot == slot; });
  };
  if (arc.weights.empty() && !inscribed(net::kDefaultSlot)) arc.weights.push_back({net::kDefaultSlot, 1, {}, {}});
  bool changed = false;
  int remove = -1;
  for (std::size_t i = 0; i < arc.weights.size(); ++i) {
    auto& w = arc.weights[i];
    if (inscribed(w.slot)) continue;
    ImGui::PushID(static_cast<int>(i));
    const std::string slot = net::slotName(w.slot);
    ImGui::Text("weight %s", slot.c_str());
    ImGui::SameLine(150);
    ImGui::SetNextItemWidth(110);
    int value = static_cast<int>(std::clamp<std::int64_t>(w.value, 1, 1'000'000'000));
    ImGui::InputInt("##weight", &value, 0, 0);
    noteItem("weight " + slot, report["fields"]);
    if (ImGui::IsItemDeactivatedAfterEdit()) {
      if (value != w.value) {
        w.value = value;
        w.param.clear();
        changed = true;
      }
    }
    report["weight " + slot] = w.value;
    if (arc.weights.size() > 1) {
      ImGui::SameLine();
      if (ImGui::SmallButton("x")) remove = static_cast<int>(i);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("This slot no longer takes part in the arc");
    }
    ImGui::PopID();
  }
  if (remove >= 0) {
    arc.weights.erase(arc.weights.begin() + remove);
    changed = true;
  }
  // another slot: its name, then Enter
  ImGui::SetNextItemWidth(80);
  const bool slot_entered = ImGui::InputTextWithHint("##newslot", "slot", &app.inspector.new_arc_slot, ImGuiInputTextFlags_EnterReturnsTrue);
  noteItem("add slot", report["fields"]);
  if (slot_entered) {
    const auto slot = net::parseSlot(app.inspector.new_arc_slot);
    const bool there = slot && std::any_of(arc.weights.begin(), arc.weights.end(), [&](const auto& w) { return w.slot == *slot; });
    if (!slot) app.message = "'" + app.inspector.new_arc_slot + "' is not a slot (a0, b1, c0, ...)";
    else if (!there) {
      arc.weights.push_back({*slot, 1, {}, {}});
      changed = true;
    }
    app.inspector.new_arc_slot.clear();
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Another slot the arc takes or gives tokens of (a0, b1, d0, ...), then Enter");
  ImGui::SameLine();
  ImGui::TextDisabled("add a slot");
  // a0 with weight 1 is what an arc without weights means: written the short way
  if (arc.weights.size() == 1 && arc.weights.front().slot == net::kDefaultSlot && arc.weights.front().value == 1 &&
      arc.weights.front().param.empty()) {
    arc.weights.clear();
  }
  // a node slot of an input arc has a predicate, a sensor slot a condition (as the place says)
  const auto* spec = findPage(app.document().model().net, page);
  const net::PlaceSpec* place = nullptr;
  if (spec != nullptr) {
    for (const auto& p : spec->places) {
      if (p.name == arc.from) place = &p;
    }
  }
  if (place != nullptr) {
    std::vector<net::SlotId> slots;
    const auto add = [&](net::SlotId slot) {
      if (std::find(slots.begin(), slots.end(), slot) == slots.end()) slots.push_back(slot);
    };
    if (arc.weights.empty()) add(net::kDefaultSlot);
    for (const auto& w : arc.weights) add(w.slot);
    for (const auto& p : arc.predicates) add(p.slot);
    for (const auto& c : arc.conditions) add(c.slot);
    for (const auto slot : slots) {
      switch (slotKindOf(*place, slot)) {
        case net::SlotKind::Node: changed = expressionRow("predicate", slot, arc.predicates, was.loc, report) || changed; break;
        case net::SlotKind::Sensor: changed = expressionRow("condition", slot, arc.conditions, was.loc, report) || changed; break;
        case net::SlotKind::Control:
        case net::SlotKind::Continuous:
        case net::SlotKind::Value: break;  // an inscription: below
      }
    }
  }
  ImGui::EndDisabled();
  if (changed && editing) {
    (void)setArc(app, page, was, arc);
    return;
  }
  // the inscriptions of the value slots of its place (input or output), in the inscription
  // language, checked as typed
  const net::PlaceSpec* valued = nullptr;
  if (spec != nullptr) {
    for (const auto& p : spec->places) {
      if (p.name == was.from || p.name == was.to) valued = &p;
    }
  }
  if (valued == nullptr || valued->colours.empty()) return;
  std::vector<net::SlotId> slots;
  for (const auto& i : was.inscriptions) slots.push_back(i.slot);
  for (const auto& c : valued->colours) {
    const bool weighed = std::any_of(was.weights.begin(), was.weights.end(), [&](const auto& w) { return w.slot == c.slot; });
    if ((weighed || (was.weights.empty() && c.slot == net::kDefaultSlot)) &&
        std::find(slots.begin(), slots.end(), c.slot) == slots.end()) {
      slots.push_back(c.slot);
    }
  }
  ImGui::BeginDisabled(!editing);
  for (const auto slot : slots) {
    std::string set, text;
    for (const auto& c : valued->colours) {
      if (c.slot == slot) set = c.text;
    }
    for (const auto& i : was.inscriptions) {
      if (i.slot == slot) text = i.text;
    }
    const std::string name = net::slotName(slot);
    inscriptionField(app, sel.name + "#inscription " + name, "inscription " + name, text, set, InscriptionRole::Arc,
                     [&app, page, was, slot](const std::string& typed) {
                       net::ArcSpec next = was;
                       const auto it = std::find_if(next.inscriptions.begin(), next.inscriptions.end(),
                                                    [&](const net::SlotText& t) { return t.slot == slot; });
                       if (typed.empty()) {
                         if (it != next.inscriptions.end()) next.inscriptions.erase(it);
                       } else if (it != next.inscriptions.end()) {
                         it->text = typed;
                         it->layout.clear();
                       } else {
                         next.inscriptions.push_back({slot, typed, was.loc});
                         // an inscription replaces the weight on its slot
                         std::erase_if(next.weights, [&](const net::SlotCount& w) { return w.slot == slot; });
                       }
                       (void)setArc(app, page, was, next);
                     },
                     report);
    report["inscription " + name] = text;
  }
  ImGui::EndDisabled();
}

}  // namespace gdpn::ide
