#include "gdpn/diagram/net_state.h"

namespace gdpn::diagram {
namespace {

// whether term `id` of the kernel's net holds now
bool termHolds(const net::Kernel& k, net::TermId id) {
  const net::Term& term = k.net().terms()[id];
  const std::int64_t m = k.marking(term.place_slot);
  switch (term.kind) {
    case net::TermKind::Input:
    case net::TermKind::Test: return m >= term.weight;
    case net::TermKind::Inhibitor: return m < term.weight;
    case net::TermKind::Output: {
      const std::int64_t cap = k.capacity(term.place_slot);  // a script may have changed it
      return cap == net::kUnbounded || m + k.reserve(term.place_slot) + term.weight - term.take <= cap;
    }
    case net::TermKind::Condition: return k.condition(id);
  }
  return false;
}

std::string qualify(const PageView& view, const std::string& name) {
  return view.prefix.empty() ? std::string() : view.prefix + "/" + name;
}

}  // namespace

Activity activityOf(net::Readiness readiness) {
  switch (readiness) {
    case net::Readiness::Able: return Activity::Enabled;
    case net::Readiness::Untried: return Activity::Waiting;
    case net::Readiness::Occurring: return Activity::Occurring;
    case net::Readiness::Tokens:
    case net::Readiness::Room: return Activity::Idle;
    case net::Readiness::Condition:
    case net::Readiness::Guard:
    case net::Readiness::Predicate:
    case net::Readiness::NoBinding:
    case net::Readiness::Probability:
    case net::Readiness::Halted: return Activity::HeldBack;
  }
  return Activity::Idle;
}

PageBinding bindPage(const net::Net& net, const PageView& view) {
  PageBinding b;
  if (view.page == nullptr) return b;
  const net::PageSpec& page = *view.page;
  const bool alone = view.prefix.empty();
  b.places.assign(page.places.size(), std::nullopt);
  b.transitions.assign(page.transitions.size(), std::nullopt);
  b.arcs.assign(page.arcs.size(), {});
  if (alone) return b;
  for (std::size_t i = 0; i < page.places.size(); ++i) b.places[i] = net.findPlace(qualify(view, page.places[i].name));
  for (std::size_t i = 0; i < page.transitions.size(); ++i) {
    b.transitions[i] = net.findTransition(qualify(view, page.transitions[i].name));
  }
  for (std::size_t a = 0; a < page.arcs.size(); ++a) {
    const auto& arc = page.arcs[a];
    auto& out = b.arcs[a];
    if ((out.transition = net.findTransition(qualify(view, arc.to)))) {
      out.place = net.findPlace(qualify(view, arc.from));
    } else if ((out.transition = net.findTransition(qualify(view, arc.from)))) {
      out.place = net.findPlace(qualify(view, arc.to));
      out.output = true;
    }
  }
  return b;
}

NetState netStateOf(const net::Kernel& kernel, const PageView& view, const NodeNamer& names) {
  return netStateOf(kernel, bindPage(kernel.net(), view), names);
}

NetState netStateOf(const net::Kernel& kernel, const PageBinding& binding, const NodeNamer& names) {
  NetState s;
  s.time = kernel.now();
  const net::Net& net = kernel.net();
  auto nameOf = [&](net::NodeRef ref) -> std::string {
    if (names) return names(ref);
    return ref < net.nodeNames().size() ? net.nodeNames()[ref] : "#" + std::to_string(ref);
  };
  // places: each slot in use, with its tokens
  s.places.resize(binding.places.size());
  for (std::size_t i = 0; i < binding.places.size(); ++i) {
    const auto p = binding.places[i];
    if (!p) continue;
    const net::Place& place = net.places()[*p];
    for (net::PlaceSlotId ps{place.slots_begin}; ps < place.slots_end; ++ps) {
      const net::PlaceSlot& slot = net.placeSlots()[ps];
      SlotMarking m{slot.slot, slot.kind, kernel.marking(ps), {}};
      if (!net.sensorPath(ps).empty()) {
        m.kind = net::SlotKind::Sensor;
        m.count = 1;
      }
      if (m.kind == net::SlotKind::Node)
        for (net::NodeRef ref : kernel.nodes(ps)) m.names.push_back(nameOf(ref));
      if (m.kind == net::SlotKind::Continuous) continue;  // its amount, below
      if (m.count > 0) s.places[i].push_back(std::move(m));
    }
  }
  // the continuous part: amounts, capacities, rates
  const net::Fluid* fluid = net.fluid();
  s.amounts.assign(binding.places.size(), std::nullopt);
  s.capacities.assign(binding.places.size(), net::kNoBound);
  s.flow_rates.assign(binding.transitions.size(), std::nullopt);
  if (fluid != nullptr) {
    for (std::size_t i = 0; i < binding.places.size(); ++i) {
      const auto p = binding.places[i];
      if (!p || fluid->of_place[*p] < 0) continue;
      s.amounts[i] = kernel.amount(*p);
      s.capacities[i] = fluid->places[static_cast<std::size_t>(fluid->of_place[*p])].capacity;
    }
    for (std::size_t i = 0; i < binding.transitions.size(); ++i) {
      const auto t = binding.transitions[i];
      if (t && fluid->continuous(*t)) s.flow_rates[i] = kernel.flowRate(*t);
    }
  }
  // transitions: the kernel's own answer (what the last firing phase found), read, not evaluated
  s.transitions.assign(binding.transitions.size(), Activity::Idle);
  s.readiness.assign(binding.transitions.size(), net::Readiness::Tokens);
  s.occurrences.assign(binding.transitions.size(), 0);
  for (std::size_t i = 0; i < binding.transitions.size(); ++i) {
    if (!binding.transitions[i]) continue;
    const auto t = *binding.transitions[i];
    s.readiness[i] = kernel.readiness(t);
    s.transitions[i] = kernel.occurring(t) ? Activity::Occurring : activityOf(s.readiness[i]);
    s.occurrences[i] = static_cast<std::uint32_t>(kernel.occurrences(t));
    // a flow never fires: enabled while it moves an amount, idle when off or cut to nothing
    if (s.flow_rates[i]) s.transitions[i] = *s.flow_rates[i] != 0.0 ? Activity::Enabled : Activity::Idle;
  }
  // arcs: the terms of the arc's transition on the arc's place, inputs or outputs by its direction
  s.arcs.assign(binding.arcs.size(), std::nullopt);
  for (std::size_t a = 0; a < binding.arcs.size(); ++a) {
    const auto [t, p, output] = binding.arcs[a];
    if (!t || !p) continue;
    if (net.continuous(*t)) {  // a flow's arcs hold while it flows
      s.arcs[a] = kernel.flowRate(*t) != 0.0;
      continue;
    }
    const auto first = net.transitions()[*t].terms_begin;
    bool any = false, all = true;
    const auto terms = net.termsOf(*t);
    for (std::size_t k = 0; k < terms.size(); ++k) {
      if (net.placeSlots()[terms[k].place_slot].place != *p) continue;
      if ((terms[k].kind == net::TermKind::Output) != output) continue;
      any = true;
      all = all && termHolds(kernel, net::TermId{first + k});
    }
    if (any) s.arcs[a] = all;
  }
  return s;
}

}  // namespace gdpn::diagram
