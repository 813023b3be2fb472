// What the run holds of value tokens, shown in the inspector and the net view's tooltips: a
// coloured place's marking as its values, a coloured transition's binding, and its enabled
// bindings, each fired by hand.

#include <imgui.h>

#include "../views.h"
#include "gdpn/ide/colour_edit.h"

namespace gdpn::ide {
namespace {

/// Each value slot of place `p` with its set.
template <class F>
void forEachValueSlot(const net::Net& net, net::PlaceId p, F&& f) {
  const auto* c = net.colouring();
  if (c == nullptr) return;
  const auto& place = net.places()[p];
  for (net::PlaceSlotId ps{place.slots_begin}; ps < place.slots_end; ++ps) {
    if (const auto set = c->setOf(ps)) f(ps, *set);
  }
}

}  // namespace

void placeValues(const session::Session& session, net::PlaceId p, nlohmann::json& report) {
  const auto& sim = session.simulation();
  const auto& net = sim.net();
  forEachValueSlot(net, p, [&](net::PlaceSlotId ps, net::ColourId set) {
    const auto& colours = net.colouring()->colours;
    const auto& m = sim.kernel().values(ps);
    const std::string slot = net::slotName(net.placeSlots()[ps].slot);
    const std::string text = valuesText(colours, set, m, kShownValues);
    ImGui::TextDisabled("values %s (%s, %lld):", slot.c_str(), colours.at(set).name.c_str(),
                        static_cast<long long>(net::multisetSize(m)));
    ImGui::Indent();
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::Unindent();
    report["values"][slot] = text;
  });
}

std::string valuesTooltip(const session::Session& session, net::PlaceId p) {
  const auto& sim = session.simulation();
  const auto& net = sim.net();
  std::string out;
  forEachValueSlot(net, p, [&](net::PlaceSlotId ps, net::ColourId set) {
    // a tooltip is narrow: a line for each value, the first few
    const auto& colours = net.colouring()->colours;
    const auto& m = sim.kernel().values(ps);
    out += "\n" + net::slotName(net.placeSlots()[ps].slot) + ": " + valuesText(colours, set, m, kTooltipValues);
  });
  return out;
}

void transitionBindings(App& app, const session::Session& session, net::TransitionId t, const std::string& name,
                        nlohmann::json& report) {
  const auto& sim = session.simulation();
  const auto* c = sim.net().colouring();
  const auto* ti = c != nullptr ? c->of(t) : nullptr;
  if (ti == nullptr || ti->variables.empty()) return;
  const auto& kernel = sim.kernel();
  // the binding of the occurrence running now
  if (const auto* b = kernel.binding(t)) {
    const std::string text = bindingText(c->colours, *ti, b->binding);
    ImGui::TextWrapped("occurring in: %s", text.c_str());
    report["binding"] = text;
  }
  // the bindings enabled now, each fired by a click
  const auto found = kernel.enabled(t) ? kernel.bindings(t, kShownBindings + 1) : std::vector<net::BoundOccurrence>{};
  nlohmann::json list = nlohmann::json::array();
  if (found.empty()) {
    // occurring on its only server says enough; otherwise why there is nothing to fire
    if (kernel.enabled(t)) ImGui::TextDisabled("no binding of its variables is enabled");
    else if (!kernel.occurring(t)) ImGui::TextDisabled("not enabled: no binding to fire");
  } else {
    ImGui::TextDisabled("enabled bindings%s:", found.size() > kShownBindings ? " (the first 30)" : "");
  }
  std::optional<net::Binding> chosen;
  for (std::size_t i = 0; i < found.size() && i < kShownBindings; ++i) {
    const std::string text = bindingText(c->colours, *ti, found[i].binding);
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::SmallButton("Fire")) chosen = found[i].binding;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Fire %s now with %s", name.c_str(), text.c_str());
    noteItem(text, report["binding_at"]);
    ImGui::SameLine();
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopID();
    list.push_back(text);
  }
  if (found.size() > kShownBindings) ImGui::TextDisabled("... and more");
  report["bindings"] = list;
  if (chosen) {
    const auto why = app.run().fire(name, *chosen);
    app.message = app.run().message();
    (void)why;
  }
}

}  // namespace gdpn::ide
