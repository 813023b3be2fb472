#pragma once
/// \file
/// Analysis of the untimed view (semantics §11): node tokens counted per slot, scripts and
/// durations ignored, sensor conditions free. Explicit state-space exploration: the
/// reachability graph (a coverability graph with ω when the net is unbounded) and the
/// behavioural properties read off it.

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/net/net.h"

namespace gdpn::net {

/// How far an exploration has got; passed to ExploreOptions::progress.
struct ExploreProgress {
  std::uint64_t states = 0;  ///< markings stored so far
  std::uint64_t edges = 0;   ///< edges met so far
  std::uint64_t bytes = 0;   ///< memory the search holds now, bytes
};

struct Invariants;

/// The moment `seconds` from now (a limit's deadline); past 10^9 s (31 years), 10^9 s, so that
/// any number given stays within the clock's range.
inline std::chrono::steady_clock::time_point deadlineAfter(double seconds) {
  const double s = seconds < 1e9 ? seconds : 1e9;
  return std::chrono::steady_clock::now() +
         std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(s));
}

/// How many dead markings a search gives a path to (the first it meets).
inline constexpr std::size_t kDeadPaths = 3;

/// Limits of an exploration.
struct ExploreOptions {
  std::uint64_t max_states = 20'000'000;  ///< stop (partial answer) past this many states
  /// Stop (partial answer) past this much memory, bytes; 0: none. Looked at as the search
  /// stores, expands and walks back (one thread every 4,096 new states and every 4,096
  /// states done, the threads after each round of batches), before a table grows and before
  /// a state's successors are made and stored (room that would pass it is never taken; only
  /// markings not stored yet count towards the growth): a chunk allocated between two looks
  /// may pass it by that much.
  std::uint64_t max_bytes = 0;
  /// `max_bytes` is a guard that the caller set on its own (`gdpn analyze` without
  /// --max-memory: 3/4 of the memory available), not a limit asked for: a race of two
  /// searches (below) runs under it, half each.
  bool max_bytes_guard = false;
  /// Worker threads. Above 1, markings are shared out among the threads by hash, each
  /// expanding its markings in batches, and the graph is kept as arrays (4 bytes an edge and
  /// 4 a state more; 8 a state more again after the search where a dead state or one that
  /// cannot get back to the start makes the passes read it by state; reversed for a while,
  /// 5 bytes an edge and 4 a state more, unless that would pass `max_bytes`) for the passes
  /// that decide liveness and reversibility. A net with a place that nothing bounds needs
  /// the coverability search (one walk): two threads race it against a plain search that
  /// never accelerates (the first to end answers; without `max_bytes`, or under a guard).
  unsigned threads = 1;
  /// Called every 4,096 new states; may be empty.
  std::function<void(const ExploreProgress&)> progress;
  /// Stop (partial answer) at this moment; none when empty. The invariants that size the
  /// markings are computed under the same limit.
  std::optional<std::chrono::steady_clock::time_point> deadline;
  /// The net's invariants when already computed (their bounds size the markings); when
  /// empty they are computed again, under a small candidate limit.
  const Invariants* invariants = nullptr;
  /// Queries: simplify each formula and answer it on the fly first, with stubborn sets (a
  /// partial-order reduction that fires only some of the enabled transitions where the
  /// answer cannot depend on the others) for reachability, EF and AG in CTL, and LTL without
  /// next; off (`--no-reduction`): the whole graph first, every transition fired.
  bool reduction = true;
  /// Queries: before a reachability search, try to refute the formula by the state equation
  /// (a linear program; no search when it is infeasible).
  bool state_equation = true;
  /// Give a shortest firing sequence to a dead marking: a breadth-first pass over the states
  /// after the search (one thread: time and 12 bytes per state). Without it, one thread gives
  /// the path its search walked to the first dead marking, cut short wherever one firing
  /// reaches further along it; more threads always give a shortest one.
  bool shortest_path = false;
};

/// Why a phase of analysis (the exploration, the invariants, the cycle-time bounds) ended
/// before its whole answer was found.
enum class ExploreStop : std::uint8_t {
  Done,        ///< complete
  MaxStates,   ///< ExploreOptions::max_states reached
  MaxMemory,   ///< ExploreOptions::max_bytes reached
  Overflow,    ///< a count went past 2^32 - 2 tokens in a place that no invariant bounds (invariants: past 2^63)
  TimeLimit,   ///< the deadline passed
  Candidates,  ///< invariants: too many candidate rows (InvariantOptions::max_candidates)
};

/// Marks a place bound of ω: the place is unbounded.
inline constexpr std::int64_t kOmega = -1;

/// What the reachability (or coverability) graph says.
struct StateSpace {
  bool complete = true;                  ///< false when a limit cut the search short
  ExploreStop stop = ExploreStop::Done;  ///< why it ended
  bool bounded = true;                   ///< no place is unbounded (false: a coverability graph)
  std::uint64_t states = 0;              ///< reachable markings (ω-markings when unbounded)
  std::uint64_t edges = 0;               ///< one per marking and enabled transition
  bool deadlock = false;                 ///< a dead marking is reachable
  std::vector<TransitionId> deadlock_path;  ///< a firing sequence to one (ExploreOptions::shortest_path: a shortest)
  /// Dead markings met (every one when the search is complete).
  std::uint64_t dead_markings = 0;
  /// Firing sequences to the next dead markings the search met after the first, at most
  /// kDeadPaths - 1 of them (one thread).
  std::vector<std::vector<TransitionId>> more_dead_paths;
  std::vector<std::int64_t> place_bound; ///< per place: the most tokens it ever holds, or kOmega
  std::vector<PlaceId> unbounded_places; ///< places that can hold any number of tokens
  std::int64_t max_place = 0;            ///< the most tokens in one bounded place
  std::int64_t max_marking = 0;          ///< the most tokens in one marking (bounded places)
  bool one_safe = true;                  ///< no place ever holds more than one token
  std::vector<bool> fired;               ///< per transition: it can fire at least once
  bool quasi_live = true;                ///< every transition can fire at least once
  /// Liveness, reversibility and deadlock are decided only on a complete, bounded graph.
  bool decided = true;
  bool live = true;                      ///< every transition can fire again from every marking
  bool reversible = true;                ///< the initial marking is reachable from every marking
  std::vector<PlaceId> constant_places;  ///< places whose token count never changes
  std::uint64_t peak_bytes = 0;          ///< the most memory the search held, bytes
  /// exploreColoured (value tokens): the most copies of one value in one place slot (or tokens
  /// in a count slot), the most tokens one place of the unfolded net would hold; 0 for other
  /// searches.
  std::int64_t max_value_count = 0;
  /// exploreColoured: the distinct (transition, binding) pairs that occur, the transitions an
  /// unfolding would need at least; 0 for other searches.
  std::uint64_t bindings = 0;
  /// exploreColoured: per step of deadlock_path, the binding it occurs in ("x=1, y=p2"; empty
  /// for a transition without variables).
  std::vector<std::string> deadlock_bindings;
  /// exploreColoured: the first dead marking, per marked place slot "name = what it holds"
  /// ("main/bin = red ++ 2'blue"; a count slot's count), in place slot order.
  std::vector<std::string> dead_marking;
};

/// Explores the reachability graph of `net` from its initial marking. Markings are packed
/// into bit fields sized by the invariants' bounds; strongly connected components are found
/// during the depth-first search of one thread, so that no edge is stored.
StateSpace explore(const Net& net, const ExploreOptions& options = {});

/// A word for why a phase stopped ("complete", "partial: --max-states reached", ...).
const char* stopReason(ExploreStop stop);

}  // namespace gdpn::net
