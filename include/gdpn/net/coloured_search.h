#pragma once
/// \file
/// The state space of a coloured net over markings with values (semantics: *Analysis*, value
/// tokens), found without unfolding it: each marking holds, per value slot, the multiset of
/// values it holds and, per other slot, its count. What an unfolding would build up front (a
/// place per value, a transition per binding) is met only as far as the search reaches it.

#include <cstdint>
#include <string>

#include "gdpn/net/analysis.h"
#include "gdpn/net/net.h"

namespace gdpn::net {

/// Why the native search cannot explore `net` (an arc without inscription on a value slot);
/// empty when it can.
std::string colouredRefusal(const Net& net);

/// Explores the reachability graph of coloured `net` (Net::colouring() not null, and
/// colouredRefusal() empty) breadth first, one edge per marking and enabled binding. The
/// bounds are per place (all values counted); StateSpace::max_value_count is the most copies
/// of one value in one place slot. A transition is live when from every reachable marking
/// some binding of it can occur again; the path to a deadlock is a shortest one. The graph
/// is kept for the liveness passes: 8 bytes an edge, 16 a state and the markings' values
/// (about 2 bytes a value held), and per transition the contents of its input places met.
/// ExploreOptions::threads, reduction and state_equation are not used. Unbounded nets run
/// into `max_states` or `max_bytes`, or stop at ExploreStop::Overflow where a count passes
/// 2^32 - 2 or a marking's values take more than 1 MiB.
StateSpace exploreColoured(const Net& net, const ExploreOptions& options = {});

}  // namespace gdpn::net
