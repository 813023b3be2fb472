#include "marking_store.h"

#include "gdpn/net/invariants.h"

namespace gdpn::net::detail {

bool enabledIn(const Net& net, const Layout& layout, TransitionId t, const std::uint64_t* m) {
  for (const Term& term : net.termsOf(t)) {
    const std::int64_t v = layout.value(m, term.place_slot);
    switch (term.kind) {
      case TermKind::Input:
      case TermKind::Test:
        if (v < term.weight) return false;
        break;
      case TermKind::Inhibitor:
        if (v >= term.weight) return false;
        break;
      case TermKind::Output: {
        const auto cap = net.placeSlots()[term.place_slot].capacity;
        if (cap != kUnbounded && v != kW && v - term.take + term.weight > cap) return false;
        break;
      }
      case TermKind::Condition:
        break;  // sensor conditions are free to be either: explore as if true
    }
  }
  return true;
}

std::size_t markEnabled(const Net& net, const Layout& layout, const std::uint64_t* m, std::vector<bool>& seen) {
  std::size_t added = 0;
  for (TransitionId t = 0; t < seen.size(); ++t) {
    if (!seen[t] && enabledIn(net, layout, t, m)) seen[t] = true, ++added;
  }
  return added;
}

Fired fireInto(const Net& net, const Layout& layout, TransitionId t, const std::uint64_t* m, std::uint64_t* out,
               std::size_t& field) {
  if (!enabledIn(net, layout, t, m)) return Fired::NotEnabled;
  std::memcpy(out, m, layout.words() * sizeof(std::uint64_t));
  // inputs come before outputs among a transition's terms
  for (const Term& term : net.termsOf(t)) {
    const std::size_t k = term.place_slot;
    const std::uint64_t c = layout.code(out, k);
    if (layout.isOmega(k, c)) continue;
    if (term.kind == TermKind::Input) layout.setCode(out, k, c - static_cast<std::uint64_t>(term.weight));
    if (term.kind == TermKind::Output) {
      const std::uint64_t next = c + static_cast<std::uint64_t>(term.weight);
      if (next > layout.maxCount(k)) {
        field = k;
        return Fired::TooBig;
      }
      layout.setCode(out, k, next);
    }
  }
  return Fired::Ok;
}

Plan plan(const Net& net, const ExploreOptions& options) {
  // field sizes from the invariants' bounds (under the search's limits); the others start
  // small and widen when needed
  const std::size_t width = net.placeSlots().size();
  InvariantOptions limits;
  limits.max_candidates = 2'000;
  limits.max_bytes = options.max_bytes;
  limits.deadline = options.deadline;
  const Invariants inv = invariants(net, limits);
  Plan p;
  p.bits.assign(width, 1);
  p.omega.assign(width, false);
  p.accel.assign(width, false);
  p.m0.assign(width, 0);
  for (std::size_t k = 0; k < width; ++k) {
    const PlaceSlot& ps = net.placeSlots()[k];
    std::int64_t bound = inv.bound[k];
    if (ps.capacity != kUnbounded && (bound < 0 || ps.capacity < bound)) bound = ps.capacity;
    p.m0[k] = ps.initial;
    if (bound >= 0) {
      p.bits[k] = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::bit_width(static_cast<std::uint64_t>(bound))));
    } else {
      p.omega[k] = p.accel[k] = p.cover = true;
      std::uint32_t b = 4;
      while (b < kMaxBits && static_cast<std::uint64_t>(ps.initial) + 1 >= (std::uint64_t{1} << b)) b *= 2;
      p.bits[k] = b;
    }
    if (p.bits[k] > kMaxBits || static_cast<std::uint64_t>(ps.initial) > (std::uint64_t{1} << kMaxBits) - 2) {
      p.overflow = true;
    }
  }
  // only where the firing sequence surely repeats: no inhibitor reads the slot
  for (const Term& term : net.terms()) {
    if (term.kind == TermKind::Inhibitor) p.accel[term.place_slot] = false;
  }
  return p;
}

void Observed::note(const Layout& layout, const std::uint64_t* m) {
  std::int64_t total = 0;
  for (std::size_t k = 0; k < layout.width(); ++k) {
    const std::int64_t v = layout.value(m, k);
    low[k] = std::min(low[k], v);
    high[k] = std::max(high[k], v);
    if (v != kW) total += v;
  }
  max_marking = std::max(max_marking, total);
}

void Observed::merge(const Observed& other) {
  for (std::size_t k = 0; k < low.size(); ++k) {
    low[k] = std::min(low[k], other.low[k]);
    high[k] = std::max(high[k], other.high[k]);
  }
  max_marking = std::max(max_marking, other.max_marking);
}

void summarise(const Net& net, const Observed& seen, StateSpace& out) {
  out.quasi_live = std::all_of(out.fired.begin(), out.fired.end(), [](bool b) { return b; });
  const auto places = net.places();
  out.place_bound.assign(places.size(), 0);
  for (PlaceId p = 0; p < places.size(); ++p) {
    bool constant = true;
    for (auto ps = places[p].slots_begin; ps < places[p].slots_end; ++ps) {
      if (seen.high[ps] == kW) {
        out.place_bound[p] = kOmega;
      } else if (out.place_bound[p] != kOmega) {
        out.place_bound[p] += seen.high[ps];
      }
      constant = constant && seen.low[ps] == seen.high[ps];
    }
    if (constant) out.constant_places.push_back(p);
    if (out.place_bound[p] == kOmega) {
      out.bounded = false;
      out.unbounded_places.push_back(p);
    } else {
      out.max_place = std::max(out.max_place, out.place_bound[p]);
    }
  }
  out.max_marking = seen.max_marking;
  out.one_safe = out.bounded && out.max_place <= 1;
  out.decided = out.complete && out.bounded;
  if (!out.decided) out.live = out.reversible = false;
}

StateSpace overflowAnswer(const Net& net) {
  StateSpace out;
  out.complete = false;
  out.stop = ExploreStop::Overflow;
  out.decided = out.live = out.reversible = false;
  out.fired.assign(net.transitions().size(), false);
  out.quasi_live = net.transitions().empty();
  return out;
}

}  // namespace gdpn::net::detail
