#pragma once
/// \file
/// `gdpn analyze`: the state space, the invariants and the cycle-time bounds of a net,
/// gathered once and printed as text or JSON.

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gdpn/net/analysis.h"
#include "gdpn/net/coloured_invariants.h"
#include "gdpn/net/query.h"
#include "gdpn/net/invariants.h"

namespace gdpn::model {

/// What to compute. The state space's limits bound every phase: max_states also caps the
/// invariants' candidate rows, max_bytes their memory, and the time limit runs over all of
/// them together.
struct AnalysisOptions {
  net::ExploreOptions explore;  ///< limits and progress of the state-space search
  double dt = 0.0;              ///< the model's step, seconds; 0 for a net without one (PNML)
  double time_limit_s = 0.0;    ///< stop every phase this many seconds after the start (partial answer); 0: none
  /// Progress of the invariants and cycle-time phases: the phase's name and how far it is.
  std::function<void(const char* phase, const net::InvariantProgress&)> progress;
  /// A coloured net as written (compiled without unfolding) whose own P-invariants are wanted
  /// beside the net analysed (its unfolding, or itself); null for none.
  const net::Net* coloured = nullptr;
};

/// A coloured net's P-invariants found on it without unfolding it (net::colouredInvariants),
/// as `gdpn analyze` reports them.
struct ColouredInvariantLines {
  bool complete = true;                 ///< false when a limit stopped their computation
  std::vector<std::string> invariants;  ///< each as net::colouredInvariantText writes it
  std::vector<std::string> notes;       ///< what was left out and why
};

/// `found`, of coloured net `net`, as lines.
ColouredInvariantLines colouredInvariantLines(const net::Net& net, const net::ColouredInvariants& found);

/// Everything `gdpn analyze` reports.
struct Analysis {
  std::string path;                     ///< the model or PNML file
  net::StateSpace space;                ///< the reachability (or coverability) graph
  net::Invariants invariants;           ///< P- and T-invariants, structural properties
  std::vector<net::CycleBound> cycles;  ///< cycle-time bounds, largest first (timed nets only)
  net::ExploreStop cycles_stop = net::ExploreStop::Done;  ///< why the cycle-time bounds stopped early
  /// A coloured net's P-invariants found without unfolding it (the others are the unfolded
  /// net's); none for a net without colours.
  std::optional<ColouredInvariantLines> coloured;
  /// What was left out of the model before the net was analysed (a hybrid net's continuous
  /// part), beside what the untimed view leaves out (untimedCaveats).
  std::vector<std::string> notes;
  /// True when every phase finished (a list of minimal semiflows too long to give leaves no
  /// answer open: net::Invariants::answered()).
  [[nodiscard]] bool complete() const {
    return space.complete && invariants.answered() && cycles_stop == net::ExploreStop::Done;
  }
};

/// The phases that a limit stopped ("invariants", "cycle times", "state space") and why, in
/// the order they ran; empty when the analysis is complete.
std::vector<std::pair<std::string, net::ExploreStop>> stoppedPhases(const Analysis& analysis);

/// Each transition's duration as the simulation sees it, seconds: fixed durations rounded to
/// whole steps of `dt` (one step at least), drawn ones by their mean. With dt = 0, as written.
std::vector<double> effectiveDurations(const net::Net& net, double dt);

/// True when some transition of `net` takes time (cycle-time bounds mean something).
bool timed(const net::Net& net);

/// A P-invariant as text: "p1 + 2*p2 + p3".
std::string invariantText(const net::Net& net, const net::Invariant& y);

/// A cycle bound with how many more have the same transitions, tokens and seconds (the same
/// cycle through the other slots of its places, or the same places with other weights).
struct DistinctCycle {
  const net::CycleBound& bound;  ///< the first of them (in the vector given to distinctCycles)
  int alike = 0;                 ///< how many more, not listed
};

/// `bounds` with alike ones merged, in their order; each refers into `bounds` (nothing copied:
/// a model of 100,000 instances has as many).
std::vector<DistinctCycle> distinctCycles(const std::vector<net::CycleBound>& bounds);
std::vector<DistinctCycle> distinctCycles(std::vector<net::CycleBound>&&) = delete;

/// The places of invariant text ("a + 2*b + c") as words for core::writeWrapped: "a +",
/// "2*b +", "c", cut after `most` places with "... and N more (`where` has all)".
std::vector<std::string> invariantWords(std::string_view text, std::size_t most, std::string_view where);

/// What the untimed analysis of `net` leaves out, one sentence each: guards, sensor
/// conditions and predicates taken to hold, scripts not run. Empty for a net without them.
std::vector<std::string> untimedCaveats(const net::Net& net);

/// Runs the analysis of `net`.
Analysis analyze(const net::Net& net, std::string path, const AnalysisOptions& options = {});
/// The analysis as pretty-printed JSON text.
std::string analysisJson(const net::Net& net, const Analysis& analysis);
/// The analysis as `gdpn analyze` prints it.
void printAnalysis(std::ostream& out, const net::Net& net, const Analysis& analysis);

/// One query of `gdpn analyze --query`: its text as given, where it came from (a file's line
/// or the command line), the formula read from it and the answer.
struct QueryResult {
  std::string text;
  net::Formula formula;
  net::QueryAnswer answer;
  std::string id;  ///< from a contest property file: printed as its FORMULA line
};
/// The answers as `gdpn analyze --query` prints them: per query its formula, the answer, and
/// the path and marking that show it, wrapped at 100 columns; a contest property as the
/// contest's line, `FORMULA <id> TRUE|FALSE|<number> TECHNIQUES <words>` (or `FORMULA <id>
/// CANNOT_COMPUTE` and why). With `names` (a coloured net's, unfolded), the places and
/// transitions it expands are written by their coloured names (net::formulaText). `notes`
/// (what was left out of the model: Analysis::notes) come first, with the caveats.
void printQueries(std::ostream& out, const net::Net& net, const std::vector<QueryResult>& results,
                  const net::NameExpansion* names = nullptr, const std::vector<std::string>& notes = {});
/// The answers as pretty-printed JSON text (`names` as for printQueries).
std::string queriesJson(const net::Net& net, const std::vector<QueryResult>& results,
                        const net::NameExpansion* names = nullptr);
/// A witness file: the answer of `result` as queriesJson gives it (with the firing sequence
/// that shows it, a lasso's cycle and the marking reached), and the model it is for.
std::string witnessJson(const net::Net& net, const QueryResult& result, const std::string& model_file);
/// The places that hold tokens in `marking` (per place slot) and how many, in place order.
std::vector<std::pair<std::string, std::int64_t>> markedPlaces(const net::Net& net,
                                                                const std::vector<std::int64_t>& marking);

}  // namespace gdpn::model
