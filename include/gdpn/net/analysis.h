#pragma once
/// \file
/// Analysis of the untimed view (semantics §11): node tokens counted per slot, scripts and
/// durations ignored. Explicit state-space exploration: the reachability graph and the
/// behavioural properties read off it.

#include <cstdint>
#include <vector>

#include "gdpn/net/net.h"

namespace gdpn::net {

/// Limits of an exploration.
struct ExploreOptions {
  std::uint64_t max_states = 20'000'000;  ///< stop (partial answer) after this many states
};

/// What the reachability graph says.
struct StateSpace {
  bool complete = true;                  ///< false when max_states cut the search short
  std::uint64_t states = 0;              ///< reachable markings
  std::uint64_t edges = 0;               ///< one per marking and enabled transition
  bool deadlock = false;                 ///< a dead marking is reachable
  std::vector<TransitionId> deadlock_path;  ///< the shortest firing sequence to the first one
  std::vector<std::int64_t> place_bound; ///< per place: the most tokens it ever holds
  std::int64_t max_place = 0;            ///< the most tokens in one place
  std::int64_t max_marking = 0;          ///< the most tokens in one marking
  bool one_safe = true;                  ///< no place ever holds more than one token
  std::vector<bool> fired;               ///< per transition: it can fire at least once
  bool quasi_live = true;                ///< every transition can fire at least once
  bool live = true;                      ///< every transition can fire again from every marking
  bool reversible = true;                ///< the initial marking is reachable from every marking
  std::vector<PlaceId> constant_places;  ///< places whose token count never changes
};

/// Explores the reachability graph of `net` from its initial marking.
StateSpace explore(const Net& net, const ExploreOptions& options = {});

}  // namespace gdpn::net
