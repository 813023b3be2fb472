#pragma once
// Test support: firing a net's transitions by hand on explicit markings, to replay the paths
// the analysis reports without the analysis' own successor code.

#include <cstdint>
#include <vector>

#include "gdpn/net/query.h"

namespace gdpn::testing {

/// The initial marking of `net`, per place slot.
inline std::vector<std::int64_t> initialMarking(const net::Net& net) {
  std::vector<std::int64_t> m;
  for (const net::PlaceSlot& ps : net.placeSlots()) m.push_back(ps.initial);
  return m;
}

/// Fires `t` in `m` when it is enabled there (tested by the query's own fireable atom); false
/// and `m` unchanged when it is not.
inline bool fire(const net::Net& net, net::TransitionId t, std::vector<std::int64_t>& m) {
  net::Formula fireable;
  fireable.kind = net::FormulaKind::Fireable;
  fireable.transitions = {t};
  if (!net::holdsIn(net, fireable, m)) return false;
  for (const net::Term& term : net.termsOf(t)) {
    if (term.kind == net::TermKind::Input) m[term.place_slot] -= term.weight;
    if (term.kind == net::TermKind::Output) m[term.place_slot] += term.weight;
  }
  return true;
}

}  // namespace gdpn::testing
