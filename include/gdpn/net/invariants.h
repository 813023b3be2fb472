#pragma once
/// \file
/// Structural analysis of the untimed view (semantics §11): P- and T-invariants as minimal
/// generating sets of semi-positive invariants (the Farkas algorithm on sparse rows, one
/// connected part of the net at a time, parts alike solved once), structural
/// boundedness and conservativeness, bounds per place slot, and cycle-time bounds for timed
/// nets. Works on the incidence matrix; test, inhibitor and condition terms do not count.
/// P-invariants are found slot by slot (a b0 token stays a b0 token): for a net with one slot
/// per place they are all the minimal ones; invariants that mix slots are not listed.

#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "gdpn/net/analysis.h"
#include "gdpn/net/net.h"

namespace gdpn::net {

/// A semi-positive invariant: its non-zero weights, by place slot (P) or transition (T).
struct Invariant {
  std::vector<std::pair<std::uint32_t, std::int64_t>> weights;  ///< (index, weight > 0), sorted
};

/// How far the invariant computation has got; passed to InvariantOptions::progress.
struct InvariantProgress {
  std::size_t round = 0;    ///< columns eliminated so far in the current system
  std::size_t columns = 0;  ///< columns the current system has
  std::size_t rows = 0;     ///< candidate rows now
  std::uint64_t bytes = 0;  ///< memory the rows hold now, bytes
};

/// Limits of the invariant computation (and of the cycle-time bounds).
struct InvariantOptions {
  /// Give up on a part of the net (partial answer) past this many candidate rows at once: the
  /// Farkas algorithm's rows can grow exponentially, and past a few thousand they rarely end.
  std::size_t max_candidates = 5'000;
  std::uint64_t max_bytes = 0;          ///< give up (partial answer) past this much memory, bytes; 0: none
  /// Give up (partial answer) at this moment; none when empty.
  std::optional<std::chrono::steady_clock::time_point> deadline;
  /// Called now and then (at least every few thousand candidate rows); may be empty.
  std::function<void(const InvariantProgress&)> progress;
  /// Solve parts of the net that are alike (the instances of a page type) once; false solves
  /// every part on its own (the same answer, slower: for tests).
  bool reuse_alike = true;
};

/// What the incidence matrix says.
struct Invariants {
  bool complete = true;                ///< false when a limit or 64-bit overflow stopped it
  bool p_complete = true;              ///< the P-invariants listed are all of them
  bool t_complete = true;              ///< the T-invariants listed are all of them
  ExploreStop stop = ExploreStop::Done;  ///< why it stopped (Candidates, MaxMemory, TimeLimit, Overflow)
  std::vector<Invariant> p;            ///< minimal semi-positive P-invariants: y·C = 0
  std::vector<Invariant> t;            ///< minimal semi-positive T-invariants: C·x = 0
  /// some y > 0 on every place slot has y·C = 0 (from the list, or a linear program where it was cut)
  bool conservative = false;
  bool structurally_bounded = false;   ///< some y > 0 on every place slot has y·C <= 0 (likewise)
  bool consistent = false;             ///< some x > 0 on every transition has C·x = 0 (likewise)
  std::vector<std::int64_t> bound;     ///< per place slot: a bound from the invariants, -1 when none
  /// conservative, structurally_bounded and consistent are decided: by whole lists, or by
  /// linear programs where a list was cut (false only where the solver failed)
  bool decided = true;
  /// Every answer is whole: nothing was cut, or only a list of minimal semiflows, by the
  /// candidates' budget (there are too many to list: a contest net has 83,616,500 minimal
  /// T-invariants), while the yes-or-no answers are decided. A time, memory or 64-bit limit
  /// leaves answers open.
  [[nodiscard]] bool answered() const { return complete || (stop == ExploreStop::Candidates && decided); }
};

/// The incidence of transition `t` on place slot `ps`: tokens it puts there minus tokens it takes.
std::int64_t incidence(const Net& net, PlaceSlotId ps, TransitionId t);

/// The incidence matrix C (tokens put minus tokens taken), sparse: its non-zero entries by
/// place slot and, the same entries, by transition; each list sorted by index.
struct Incidence {
  std::vector<std::vector<std::pair<TransitionId, std::int64_t>>> by_place;       ///< per place slot: (t, C[p][t])
  std::vector<std::vector<std::pair<PlaceSlotId, std::int64_t>>> by_transition;  ///< per transition: (p, C[p][t])
};

/// The incidence matrix of `net`.
Incidence incidenceMatrix(const Net& net);

/// Computes the invariants of `net`.
Invariants invariants(const Net& net, const InvariantOptions& options = {});

/// The minimal semi-positive semiflows y·A = 0 of any sparse integer matrix A, given by its
/// rows (each (column, value) pairs sorted by column, no zeros; columns below `columns`): the
/// Farkas algorithm that invariants() runs, a connected part at a time, under `options`. Where
/// a limit stops it, what was found is returned and `stop` (when given) says why; else Done.
std::vector<Invariant> semiflowsOf(const std::vector<std::vector<std::pair<std::uint32_t, std::int64_t>>>& rows,
                                   std::size_t columns, const InvariantOptions& options = {},
                                   ExploreStop* stop = nullptr);

/// True when `y` really is a P-invariant of `net` (y·C = 0, y semi-positive).
bool isPInvariant(const Net& net, const Invariant& y);
/// True when `x` really is a T-invariant of `net` (C·x = 0, x semi-positive).
bool isTInvariant(const Net& net, const Invariant& x);

/// The cycle time of one P-invariant of a timed net.
struct CycleBound {
  std::size_t invariant = 0;               ///< index into Invariants::p
  std::vector<TransitionId> transitions;   ///< transitions taking tokens from the invariant's places (the circuit's, in order, when `circuit`)
  std::int64_t tokens = 0;                 ///< weighted tokens on it, y·M0
  double seconds = 0.0;                    ///< sum of duration × weight taken, over tokens; or the longest circuit's duration
  bool circuit = false;                    ///< one token through a state machine: `seconds` is its longest elementary circuit
  bool alternatives = false;               ///< a circuit with choices: the token's round trips take more than one path
  /// the tokens take alternative paths (a place of it feeds several of its transitions) and no
  /// circuit bounds them: a flow through the net, not a cycle; `seconds` is 0 (no bound)
  bool flow = false;
  /// every transition of it takes no time (immediate, or a duration of 0): its pace is set by
  /// what they wait for (a sensor, a guard, another cycle), not by durations; `seconds` is 0
  /// (no bound: the steps its firings take are no bound worth giving)
  bool immediate = false;
};

/// Cycle-time bounds, one per P-invariant that carries tokens, feeds a transition and is a
/// cycle: its tokens can come back to every place of it (its places, joined by its transitions,
/// are strongly connected; tokens that end in a sink are no cycle), largest first; `seconds[t]` is the duration of transition `t` (its mean for drawn durations). The
/// net cannot repeat faster than the first one's `seconds`. Where one token runs through a
/// state machine with choices (a cell that either skips a box or works on it), each choice
/// is a conflict-free circuit of its own and the bound is the longest circuit's duration.
/// Several tokens taking alternative paths (boxes that either pass a station or enter it) are
/// a flow, not a cycle: no bound (`flow`), listed last.
/// With `options`, it gives up at the deadline and says so in `stop` (when given); the bounds
/// found so far are returned.
std::vector<CycleBound> cycleBounds(const Net& net, const Invariants& invariants, std::span<const double> seconds,
                                    const InvariantOptions& options = {}, ExploreStop* stop = nullptr);

/// The mean of a duration, seconds.
double meanSeconds(const DurationLaw& duration);

/// A place slot's name for reports: the place's name, with ".slot" when not a0.
std::string placeSlotName(const Net& net, PlaceSlotId ps);

}  // namespace gdpn::net
