#pragma once
/// \file
/// An analysis as every face asks for one (`gdpn analyze`, `Model.analyze()`): its limits with
/// their defaults (the memory guard among them), and the one call that runs each kind of
/// analysis under them: everything, a list of queries, or the reachability graph.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "gdpn/model/analysis.h"
#include "gdpn/net/analysis.h"
#include "gdpn/net/graph_export.h"
#include "gdpn/net/name_expansion.h"
#include "gdpn/net/query.h"

namespace gdpn::session {

/// The default --max-states of an analysis, states.
inline constexpr std::uint64_t kDefaultMaxStates = 20'000'000;

/// What an analysis may take and how it searches.
struct AnalysisRequest {
  std::uint64_t max_states = kDefaultMaxStates;  ///< stop after this many states (partial answer)
  /// Stop when the search holds this much, MiB (partial answer). 0: the memory guard, 3/4 of
  /// the memory the system has to give when the analysis starts (core::availableMemory()), so
  /// that a state space too big for the machine ends in a partial answer rather than in the
  /// system's out-of-memory kill.
  double max_memory_mib = 0.0;
  double time_limit_s = 0.0;  ///< stop every phase this many seconds after the start, seconds; 0: none
  unsigned threads = 1;       ///< threads for the state-space search
  bool shortest_path = false;  ///< a shortest path to a deadlock (a second pass)
  bool reduction = true;       ///< queries: stubborn sets in the searches on the fly
  double dt = 0.0;             ///< the model's step, seconds; 0 for a net without one (PNML)
  /// Progress of the state-space search (every 4,096 new states); may be empty.
  std::function<void(const net::ExploreProgress&)> progress;
  /// Progress of the invariants and cycle-time phases; may be empty.
  std::function<void(const char* phase, const net::InvariantProgress&)> phase_progress;

  /// True when no memory limit was asked for: the guard applies.
  [[nodiscard]] bool guarded() const { return max_memory_mib <= 0.0; }
  /// The search's limits, without progress or deadline: max_bytes from max_memory_mib, or
  /// the guard (3/4 of core::availableMemory() now, max_bytes_guard on) when none was asked.
  [[nodiscard]] net::ExploreOptions limits() const;
};

/// An analysis of everything (state space, invariants, cycle-time bounds) and the limit it
/// ran under.
struct AnalysisAnswer {
  model::Analysis analysis;     ///< what it found
  std::uint64_t max_bytes = 0;  ///< the memory limit it ran under, bytes
  bool guard = false;           ///< that limit was the guard, not one asked for
  /// True when the guard stopped a phase (the answer is partial for lack of memory).
  [[nodiscard]] bool stoppedAtGuard() const;
  /// What to tell the user when the guard stopped a phase, naming the face's `option`:
  /// "stopped at the default --max-memory, 3/4 of the memory available at the start (N MiB)".
  [[nodiscard]] std::string guardNote(std::string_view option) const;
};

/// How the analysis reads a coloured net (semantics: *Analysis*).
enum class ColourSearch : std::uint8_t {
  Auto,    ///< unfolded where unfolding can, else over markings with values
  Unfold,  ///< unfolded into a place/transition net, or refused with unfolding's reasons
  Native,  ///< over markings with values, never unfolded (the state space, no queries)
};

/// The net an analysis reads, and how a coloured net's names map onto it.
struct AnalysedNet {
  std::shared_ptr<const net::Net> net;       ///< compiled; a coloured net unfolded first, unless `native`
  bool native = false;                       ///< a coloured net compiled as it is, searched over markings with values
  /// A coloured net compiled as it is (its own invariants are found on it; `net` when native);
  /// null for a net without colours.
  std::shared_ptr<const net::Net> coloured;
  std::optional<net::NameExpansion> names;   ///< a coloured net's: its places and transitions -> the unfolded ones
  /// What the analysis leaves out of the model, for its notes (a hybrid net's continuous part).
  std::vector<std::string> notes;
  /// The expansion for the query parsers and printers (null for a net without colours).
  [[nodiscard]] const net::NameExpansion* expansion() const { return names ? &*names : nullptr; }
};

/// What every face analyses of `spec`: the spec compiled, or, when it has colours (value
/// tokens), unfolded into a place/transition net first, or compiled as it is (`how`; Auto:
/// natively where unfolding refuses, with a note saying why). Nullopt after mistakes, in
/// `diags`.
[[nodiscard]] std::optional<AnalysedNet> analysedNet(const net::NetSpec& spec, core::Diagnostics& diags,
                                                     ColourSearch how = ColourSearch::Auto);

/// The analysis of `analysed` (read from `path`) under `request`: of its net, and a coloured
/// net's own P-invariants found without unfolding it.
[[nodiscard]] AnalysisAnswer analyze(const AnalysedNet& analysed, std::string path, const AnalysisRequest& request);
/// The answers to `formulas` on `net` under `request`'s limits, each as soon as a search
/// decides it (in their order).
[[nodiscard]] std::vector<net::QueryAnswer> answerQueries(const net::Net& net, const std::vector<net::Formula>& formulas,
                                                          const AnalysisRequest& request);
/// Writes the reachability graph of `net` in `format` to `out` under `request`'s limits; what
/// stopped it (Done when it is whole).
[[nodiscard]] net::ExploreStop writeStateGraph(const net::Net& net, net::GraphFormat format, std::ostream& out,
                                               const AnalysisRequest& request);

}  // namespace gdpn::session
