#include "gdpn/net/net.h"

#include <algorithm>
#include <tuple>

#include "gdpn/core/assert.h"
#include "gdpn/core/memory.h"
#include "gdpn/net/builder.h"

namespace gdpn::net {

const char* arcKindName(ArcKind kind) {
  switch (kind) {
    case ArcKind::Normal: return "normal";
    case ArcKind::Test: return "test";
    case ArcKind::Inhibitor: return "inhibitor";
  }
  return "?";
}

std::string Net::placeName(PlaceId p) const {
  std::string out;
  appendPlaceName(out, p);
  return out;
}

std::string Net::transitionName(TransitionId t) const {
  std::string out;
  appendTransitionName(out, t);
  return out;
}

void Net::appendPlaceName(std::string& out, PlaceId p) const {
  names_.appendName(out, places_[p].scope, placeLocalName(p));
}

void Net::appendTransitionName(std::string& out, TransitionId t) const {
  names_.appendName(out, transitions_[t].scope, transitionLocalName(t));
}

std::optional<PlaceSlotId> Net::findPlaceSlot(PlaceId place, SlotId slot) const {
  const auto& p = places_[place];
  for (auto ps = p.slots_begin; ps < p.slots_end; ++ps) {
    if (place_slots_[ps].slot == slot) return PlaceSlotId{ps};
  }
  return std::nullopt;
}

std::size_t Net::memoryBytes() const {
  std::size_t bytes = places_.capacity() * sizeof(Place) +
                      transitions_.capacity() * sizeof(Transition) +
                      place_slots_.capacity() * sizeof(PlaceSlot) + terms_.capacity() * sizeof(Term) +
                      watch_begin_.capacity() * sizeof(std::uint32_t) +
                      watchers_.capacity() * sizeof(TermId) +
                      initial_nodes_.capacity() * sizeof(std::uint32_t);
  auto heap = [](const std::string& s) { return s.capacity() > 15 ? s.capacity() + 1 : 0; };
  for (const auto& n : node_names_) bytes += sizeof(std::string) + heap(n);
  bytes += names_.memoryBytes();
  return bytes;
}

void NetBuilder::reserve(std::size_t places, std::size_t transitions, std::size_t terms) {
  core::reserveLarge(places_, places);
  core::reserveLarge(first_slot_, places);
  core::reserveLarge(slots_, places);
  core::reserveLarge(transitions_, transitions);
  core::reserveLarge(arcs_, terms);
}

namespace {

/// `qualified_name` split at its last '/': (prefix, local name, whether it has no '/').
std::tuple<std::string_view, std::string_view, bool> splitName(std::string_view qualified_name) {
  const auto slash = qualified_name.rfind('/');
  if (slash == std::string_view::npos) return {{}, qualified_name, true};
  return {qualified_name.substr(0, slash), qualified_name.substr(slash + 1), false};
}

}  // namespace

PlaceId NetBuilder::addPlace(std::string name, SourceLoc loc) {
  const auto [prefix, local, bare] = splitName(name);
  const auto scope = names_.scopeForPrefix(prefix, bare);
  const auto table = names_.scope(scope).table;
  const auto p = addScopedPlace(scope, names_.addPlace(table, std::string(local), std::move(loc)));
  names_.addPlaceId(table, p);
  return p;
}

PlaceId NetBuilder::addScopedPlace(std::uint32_t scope, std::uint32_t local) {
  places_.push_back({0, 0, scope, local});
  first_slot_.push_back(kNoSlot);
  return static_cast<PlaceId>(places_.size() - 1);
}

NetBuilder::BuildSlot& NetBuilder::slotOf(PlaceId place, SlotId slot) {
  std::uint32_t* link = &first_slot_[place];
  while (*link != kNoSlot) {
    if (slots_[*link].slot == slot) return slots_[*link];
    link = &slots_[*link].next;
  }
  *link = static_cast<std::uint32_t>(slots_.size());
  slots_.emplace_back().slot = slot;
  return slots_.back();
}

void NetBuilder::setSlot(PlaceId place, SlotId slot, SlotKind kind, std::int64_t capacity,
                         std::int64_t initial) {
  auto& s = slotOf(place, slot);
  s.kind = kind;
  s.capacity = capacity;
  s.initial = initial;
}

void NetBuilder::setNodes(PlaceId place, SlotId slot, const std::vector<std::string>& nodes) {
  auto& s = slotOf(place, slot);
  s.kind = SlotKind::Node;
  if (s.nodes < 0) {
    s.nodes = static_cast<std::int32_t>(nodes_.size());
    nodes_.emplace_back();
  }
  auto& tokens = nodes_[static_cast<std::size_t>(s.nodes)];
  tokens.clear();
  for (const auto& n : nodes) {
    auto [it, fresh] = node_index_.try_emplace(n, static_cast<std::uint32_t>(node_names_.size()));
    if (fresh) node_names_.push_back(n);
    tokens.push_back(it->second);
  }
  s.initial = static_cast<std::int64_t>(tokens.size());
}

TransitionId NetBuilder::addTransition(std::string name, const Duration& duration, std::int64_t priority,
                                       double probability, SourceLoc loc) {
  const auto [prefix, local, bare] = splitName(name);
  const auto scope = names_.scopeForPrefix(prefix, bare);
  const auto table = names_.scope(scope).table;
  const auto t = addScopedTransition(scope, names_.addTransition(table, std::string(local), std::move(loc)),
                                     duration, priority, probability);
  names_.addTransitionId(table, t);
  return t;
}

TransitionId NetBuilder::addScopedTransition(std::uint32_t scope, std::uint32_t local, const DurationLaw& duration,
                                             std::int64_t priority, double probability) {
  Transition t;
  t.scope = scope;
  t.local = local;
  t.duration = duration;
  t.priority = priority;
  t.probability = probability;
  transitions_.push_back(std::move(t));
  return static_cast<TransitionId>(transitions_.size() - 1);
}

void NetBuilder::setServers(TransitionId t, std::uint32_t servers) { transitions_[t].servers = servers; }

std::int32_t NetBuilder::addScript(ScriptSpec script) {
  scripts_.push_back(std::move(script));
  return static_cast<std::int32_t>(scripts_.size() - 1);
}

void NetBuilder::setTransitionScript(TransitionId t, ScriptKind kind, std::int32_t index) {
  GDPN_ASSERT(info(kind).owner == ScriptOwner::Transition, "a transition gets a transition's script");
  if (transition_scripts_.size() <= t) transition_scripts_.resize(t + 1, {-1, -1, -1, -1});
  transition_scripts_[t][info(kind).position] = index;
}

void NetBuilder::setSlotScript(PlaceId place, SlotId slot, ScriptKind kind, std::int32_t index) {
  GDPN_ASSERT(info(kind).owner == ScriptOwner::PlaceSlot, "a slot gets a slot's script");
  slotOf(place, slot).scripts[info(kind).position] = index;
}

void NetBuilder::setLastPredicate(std::int32_t index) { arcs_.back().predicate = index; }

void NetBuilder::setValues(PlaceId place, SlotId slot, ColourId set, Multiset initial) {
  auto& s = slotOf(place, slot);
  s.kind = SlotKind::Value;
  s.set = static_cast<std::int32_t>(set);
  s.initial = multisetSize(initial);
  if (s.values < 0) {
    s.values = static_cast<std::int32_t>(values_.size());
    values_.emplace_back();
  }
  values_[static_cast<std::size_t>(s.values)] = std::move(initial);
}

void NetBuilder::setColouring(Colouring colouring, std::vector<std::vector<std::uint32_t>> arcs) {
  colouring_ = std::move(colouring);
  colour_arcs_ = std::move(arcs);
}

void NetBuilder::setSensor(PlaceId place, SlotId slot, std::string path) {
  auto& s = slotOf(place, slot);
  s.kind = SlotKind::Sensor;
  if (s.sensor < 0) {
    s.sensor = static_cast<std::int32_t>(sensors_.size());
    sensors_.emplace_back();
  }
  sensors_[static_cast<std::size_t>(s.sensor)] = std::move(path);
}

void NetBuilder::addCondition(PlaceId place, TransitionId transition, SlotId slot, std::int32_t index) {
  slotOf(place, slot);
  arcs_.push_back({place, transition, slot, TermKind::Condition, 0, index});
}

std::uint32_t NetBuilder::addFluidTerm(PlaceId place, TransitionId transition) {
  slotOf(place, kDefaultSlot);
  arcs_.push_back({place, transition, kDefaultSlot, TermKind::Condition, 0, -1});
  return static_cast<std::uint32_t>(arcs_.size() - 1);
}

void NetBuilder::setFluid(Fluid fluid, std::vector<std::uint32_t> fluid_arcs) {
  fluid_ = std::move(fluid);
  fluid_arcs_ = std::move(fluid_arcs);
}

void NetBuilder::addInput(PlaceId place, TransitionId transition, SlotId slot, std::int32_t weight,
                          ArcKind kind) {
  slotOf(place, slot);
  const TermKind tk = kind == ArcKind::Normal ? TermKind::Input
                      : kind == ArcKind::Test ? TermKind::Test
                                              : TermKind::Inhibitor;
  arcs_.push_back({place, transition, slot, tk, weight});
}

void NetBuilder::addOutput(TransitionId transition, PlaceId place, SlotId slot, std::int32_t weight) {
  slotOf(place, slot);
  arcs_.push_back({place, transition, slot, TermKind::Output, weight});
}

std::shared_ptr<const Net> NetBuilder::freeze() {
  auto net = std::make_shared<Net>();

  // place slots: grouped per place, ordered by slot
  core::reserveLarge(net->place_slots_, slots_.size());
  std::vector<std::uint32_t> chain;
  for (PlaceId p{0}; p < places_.size(); ++p) {
    Place& place = places_[p];
    chain.clear();
    for (auto i = first_slot_[p]; i != kNoSlot; i = slots_[i].next) chain.push_back(i);
    std::sort(chain.begin(), chain.end(), [&](std::uint32_t a, std::uint32_t b) { return slots_[a].slot < slots_[b].slot; });
    place.slots_begin = static_cast<std::uint32_t>(net->place_slots_.size());
    for (const auto i : chain) {
      auto& s = slots_[i];
      PlaceSlot ps;
      ps.place = p;
      ps.slot = s.slot;
      ps.kind = s.kind;
      ps.capacity = s.capacity;
      ps.initial = s.initial;
      ps.nodes_begin = static_cast<std::uint32_t>(net->initial_nodes_.size());
      if (s.nodes >= 0) {
        const auto& tokens = nodes_[static_cast<std::size_t>(s.nodes)];
        net->initial_nodes_.insert(net->initial_nodes_.end(), tokens.begin(), tokens.end());
      }
      ps.nodes_end = static_cast<std::uint32_t>(net->initial_nodes_.size());
      for (int k = 0; k < 6; ++k) {
        if (s.scripts[static_cast<std::size_t>(k)] >= 0) ps.scripts = static_cast<std::uint8_t>(ps.scripts | (1 << k));
      }
      if (s.sensor >= 0 && !sensors_[static_cast<std::size_t>(s.sensor)].empty()) {
        net->sensor_paths_.resize(net->place_slots_.size() + 1);
        net->sensor_paths_.back() = std::move(sensors_[static_cast<std::size_t>(s.sensor)]);
      }
      if (!scripts_.empty()) net->script_index_.slots.push_back(s.scripts);
      if (colouring_) {
        colouring_->slot_set.push_back(s.set);
        colouring_->initial.push_back(s.values >= 0 ? std::move(values_[static_cast<std::size_t>(s.values)]) : Multiset{});
      }
      net->place_slots_.push_back(ps);
    }
    place.slots_end = static_cast<std::uint32_t>(net->place_slots_.size());
  }
  net->places_ = std::move(places_);
  auto psOf = [&](PlaceId p, SlotId slot) -> PlaceSlotId {
    for (auto ps = net->places_[p].slots_begin; ps < net->places_[p].slots_end; ++ps) {
      if (net->place_slots_[ps].slot == slot) return PlaceSlotId{ps};
    }
    return PlaceSlotId{0};  // unreachable: addInput/addOutput made the slot
  };

  // terms grouped per transition: inputs, conditions, outputs (stable within each group)
  std::vector<std::uint32_t> count(transitions_.size() + 1, 0);
  for (const auto& a : arcs_) ++count[a.transition + 1];
  for (std::size_t t = 0; t < transitions_.size(); ++t) count[t + 1] += count[t];
  // a stable counting sort by (transition, group): linear in the number of terms
  auto group = [](TermKind k) -> std::uint32_t { return k == TermKind::Input ? 0 : k == TermKind::Output ? 2 : 1; };
  std::vector<std::uint32_t> order(arcs_.size());
  {
    std::vector<std::uint32_t> next(transitions_.size() * 3 + 1, 0);
    for (const auto& a : arcs_) ++next[a.transition * 3 + group(a.kind) + 1];
    for (std::size_t k = 1; k < next.size(); ++k) next[k] += next[k - 1];
    for (std::uint32_t i = 0; i < arcs_.size(); ++i) order[next[arcs_[i].transition * 3 + group(arcs_[i].kind)]++] = i;
  }
  core::reserveLarge(net->terms_, arcs_.size());
  for (const auto i : order) {
    const auto& a = arcs_[i];
    Term term;
    term.transition = a.transition;
    term.place_slot = psOf(a.place, a.slot);
    term.kind = a.kind;
    term.weight = a.weight;
    term.predicate = a.predicate >= 0 && a.kind != TermKind::Condition;
    if (!scripts_.empty()) net->script_index_.predicates.push_back(a.predicate);
    net->terms_.push_back(term);
  }

  // transition ranges, node-slot masks, and what each output's transition takes from its place
  std::vector<std::int64_t> priorities;
  for (TransitionId t{0}; t < transitions_.size(); ++t) {
    auto& tr = transitions_[t];
    tr.terms_begin = count[t];
    tr.terms_end = count[t + 1];
    std::uint32_t i = tr.terms_begin;
    while (i < tr.terms_end && net->terms_[i].kind == TermKind::Input) ++i;
    tr.inputs_end = i;
    while (i < tr.terms_end && net->terms_[i].kind != TermKind::Output) ++i;
    tr.conditions_end = i;
    for (auto k = tr.terms_begin; k < tr.terms_end; ++k) {
      auto& term = net->terms_[k];
      const auto& ps = net->place_slots_[term.place_slot];
      if (ps.kind == SlotKind::Node) tr.node_slot_mask |= 1u << ps.slot;
      if (term.kind != TermKind::Output) continue;
      for (auto j = tr.terms_begin; j < tr.inputs_end; ++j) {
        if (net->terms_[j].place_slot == term.place_slot) term.take += net->terms_[j].weight;
      }
    }
    priorities.push_back(tr.priority);
    if (!scripts_.empty()) {
      std::array<std::int32_t, 4> idx{-1, -1, -1, -1};
      if (t < transition_scripts_.size()) idx = transition_scripts_[t];
      net->script_index_.transitions.push_back(idx);
      for (int k = 0; k < 4; ++k) {
        if (idx[static_cast<std::size_t>(k)] >= 0) tr.scripts = static_cast<std::uint8_t>(tr.scripts | (1 << k));
      }
    }
  }
  std::sort(priorities.begin(), priorities.end(), std::greater<>());
  priorities.erase(std::unique(priorities.begin(), priorities.end()), priorities.end());
  net->priority_levels_ = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(priorities.size()));
  for (auto& tr : transitions_) {
    auto it = std::lower_bound(priorities.begin(), priorities.end(), tr.priority, std::greater<>());
    tr.priority_rank = static_cast<std::uint32_t>(it - priorities.begin());
  }

  // watchers: every term whose truth can change; outputs to unbounded slots are always true
  const std::size_t slot_count = net->place_slots_.size();
  net->watch_begin_.assign(slot_count + 1, 0);
  auto watched = [&](const Term& term) {
    if (term.kind == TermKind::Condition) return false;  // set from outside, not by markings
    return term.kind != TermKind::Output || net->place_slots_[term.place_slot].capacity != kUnbounded;
  };
  for (const auto& term : net->terms_) {
    if (watched(term)) ++net->watch_begin_[term.place_slot + 1];
  }
  for (std::size_t ps = 0; ps < slot_count; ++ps) net->watch_begin_[ps + 1] += net->watch_begin_[ps];
  net->watchers_.resize(net->watch_begin_[slot_count]);
  std::vector<std::uint32_t> fill(net->watch_begin_.begin(), net->watch_begin_.end() - 1);
  for (TermId id{0}; id < net->terms_.size(); ++id) {
    const auto& term = net->terms_[id];
    if (watched(term)) net->watchers_[fill[term.place_slot]++] = id;
  }

  // each added arc's term: what setColouring and setFluid name arcs by
  std::vector<std::uint32_t> final_of;
  if (colouring_ || fluid_) {
    final_of.resize(arcs_.size());
    for (std::uint32_t pos = 0; pos < order.size(); ++pos) final_of[order[pos]] = pos;
  }
  if (colouring_) {
    // each coloured transition's arcs: from the order they were added to their terms
    std::vector<std::vector<std::uint32_t>> added(colouring_->transitions.size());
    for (std::uint32_t i = 0; i < arcs_.size(); ++i) {
      const auto c = colouring_->of_transition[arcs_[i].transition];
      if (c >= 0) added[static_cast<std::size_t>(c)].push_back(i);
    }
    colouring_->arc_terms.resize(colouring_->transitions.size());
    for (std::size_t c = 0; c < colour_arcs_.size() && c < added.size(); ++c) {
      for (const auto k : colour_arcs_[c]) colouring_->arc_terms[c].push_back(TermId{final_of[added[c][k]]});
    }
    net->colouring_ = std::make_shared<const Colouring>(std::move(*colouring_));
  }
  if (fluid_) {
    fluid_->of_term.assign(net->terms_.size(), -1);
    for (std::size_t k = 0; k < fluid_->terms.size(); ++k) {
      fluid_->terms[k].term = TermId{final_of[fluid_arcs_[k]]};
      fluid_->of_term[fluid_->terms[k].term] = static_cast<std::int32_t>(k);
    }
    for (auto& fp : fluid_->places) fp.slot = psOf(fp.place, kDefaultSlot);
    net->fluid_ = std::make_shared<const Fluid>(std::move(*fluid_));
  }
  net->transitions_ = std::move(transitions_);
  net->scripts_ = std::move(scripts_);
  net->globals_script_ = globals_script_;
  net->node_names_ = std::move(node_names_);
  names_.freeze();
  net->names_ = std::move(names_);

  *this = NetBuilder{};
  return net;
}

}  // namespace gdpn::net
