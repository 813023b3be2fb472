// Round trips of one token through a state machine, recorded from the kernel's starts.

#include "gdpn/net/round_trips.h"

#include <algorithm>

namespace gdpn::net {

std::size_t RoundTrips::watch(const Net& net, PlaceSlotId home, std::span<const TransitionId> transitions) {
  const auto w = static_cast<std::uint32_t>(watches_.size());
  watches_.emplace_back();
  for (TransitionId t : transitions) {
    const auto terms = net.termsOf(t);
    const bool leaves = std::any_of(terms.begin(), terms.end(), [&](const Term& term) {
      return term.kind == TermKind::Input && term.place_slot == home;
    });
    of_[t].push_back({w, leaves});
  }
  return w;
}

void RoundTrips::onStart(TransitionId t, std::int64_t step) {
  for (const Role& role : of_[t]) {
    Watch& w = watches_[role.watch];
    if (role.leaves_home) {
      // the trip before ends where this one begins
      if (w.departed >= 0) {
        auto it = w.too_long ? w.index.end() : w.index.find(w.current);
        if (!w.too_long && it == w.index.end() && w.seen.size() < kMostCircuits) {
          it = w.index.emplace(w.current, w.seen.size()).first;
          w.seen.push_back({w.current, 0, 0});
        }
        if (it == w.index.end()) {
          ++w.overlong;
        } else {
          Circuit& c = w.seen[it->second];
          ++c.trips;
          c.steps += step - w.departed;
        }
      }
      w.current.clear();
      w.too_long = false;
      w.departed = step;
    }
    if (w.departed < 0 || w.too_long) continue;
    if (w.current.size() == kMostTransitions) {
      w.too_long = true;
      continue;
    }
    w.current.push_back(t);
  }
}

}  // namespace gdpn::net
