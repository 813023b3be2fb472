#pragma once
/// \file
/// The figures of a run: per transition occurrences, cycle times and utilisation; per place
/// mean and max tokens and throughput; per continuous place its amount's extremes and mean, per
/// continuous transition what it moved. Printed as a table and written as JSON.

#include <cstdint>
#include <ostream>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/model/simulation.h"
#include "gdpn/net/analysis.h"

namespace gdpn::model {

/// One transition's line of the report.
struct TransitionFigures {
  std::string name;             ///< qualified name
  std::int64_t occurrences = 0; ///< starts
  std::int64_t cycles = 0;      ///< intervals measured between successive starts
  double mean_cycle = 0.0;      ///< seconds (0 when no cycle)
  double min_cycle = 0.0;       ///< seconds
  double max_cycle = 0.0;       ///< seconds
  double utilisation = 0.0;     ///< share of its servers busy over the run, 0..1 (NaN for unlimited servers)
  std::uint32_t servers = 1;    ///< occurrences at once it may have; 0 for unlimited
  double mean_busy = 0.0;       ///< occurrences running at once, averaged over the run
  bool continuous = false;      ///< a continuous transition (it flows: `flows` has its figures)
};

/// One place's line of the report.
struct PlaceFigures {
  std::string name;          ///< qualified name
  double mean_tokens = 0.0;  ///< time-weighted mean over the run
  std::int64_t max_tokens = 0;
  std::int64_t final_tokens = 0;
  double throughput = 0.0;   ///< tokens deposited per second
  bool sensors_only = false; ///< every slot of it reads a sensor (it holds no tokens of its own)
  /// its value slots' values at the end, as the inscription language writes them (`2'p1 ++
  /// 1'p3`; a slot other than a0 named first: `a1: ...`); "" for a place without value slots
  std::string final_values;
  bool continuous = false;   ///< a continuous place (it holds an amount: `amounts` has its figures)
};

/// One continuous place's line of the report (hybrid nets): its amount over the run.
struct AmountFigures {
  std::string name;           ///< qualified name
  std::string unit;           ///< its unit ("" when the model gives none)
  double final_amount = 0.0;  ///< at the end, in its unit
  double lowest = 0.0;        ///< the least it held (at a step or solver segment boundary), in its unit
  double highest = 0.0;       ///< the most, in its unit
  double mean = 0.0;          ///< time-weighted mean over the run, in its unit
};

/// One continuous transition's line of the report (hybrid nets): what it moved.
struct FlowFigures {
  std::string name;        ///< qualified name
  /// the amount of flow it moved (its effective rate integrated over the run): each output arc
  /// put, each input arc took, its weight times this
  double moved = 0.0;
  /// the unit of `moved`: its first arc's place's when that arc weighs 1 ("" otherwise)
  std::string unit;
  double flowing = 0.0;    ///< share of the run's time its effective rate was not 0, 0..1
};

/// One path the token of a cycle with alternative circuits took, as the run measured it.
struct CircuitFigures {
  std::vector<std::string> transitions;  ///< in the order they started; the first takes the token from its home
  std::int64_t trips = 0;                ///< times the token took it
  double bound = 0.0;                    ///< seconds: its transitions' durations summed
  double measured = 0.0;                 ///< seconds: the mean from a trip's start to the next trip's
};

/// One cycle of the net (a P-invariant carrying tokens): its bound beside what the run measured.
struct CycleFigures {
  std::string invariant;        ///< its places, weighted: "a + b + 2*c"
  std::int64_t tokens = 0;      ///< weighted tokens on it
  bool flow = false;            ///< its tokens take alternative paths: no bound, nothing measured
  /// seconds: the least time between two rounds its durations allow (its durations summed,
  /// weighted, over its tokens; for one token with alternative circuits, the circuits' own
  /// bounds averaged over the trips it took, else the longest circuit's); none for a flow and
  /// for a cycle of transitions that take no time (docs/semantics.md, "Cycle figures")
  std::optional<double> bound;
  /// seconds: the mean time between two rounds measured (the intervals between successive
  /// starts of its transitions, pooled; the token's trips for alternative circuits); none
  /// when no round was completed, and for a flow
  std::optional<double> measured;
  int alike = 0;                ///< further invariants with the same transitions, tokens and bound (not listed)
  /// one token with alternative circuits (a station that skips a box or paints it): each
  /// circuit it took, most taken first (watched only when watchRoundTrips ran before the run)
  std::vector<CircuitFigures> circuits;
  std::int64_t other_trips = 0;  ///< trips not in `circuits` (too long, or too many circuits)
};

/// Everything the summary shows.
struct Report {
  std::string model;              ///< model file
  std::uint64_t seed = 1;
  std::vector<Param> params;      ///< the model's parameters, with the values the run had
  double dt = 0.0;                ///< seconds
  RunOutcome outcome;
  std::vector<TransitionFigures> transitions;
  std::vector<PlaceFigures> places;
  std::vector<AmountFigures> amounts;  ///< per continuous place, in place order (none for a net without one)
  std::vector<FlowFigures> flows;      ///< per continuous transition, in transition order
  std::vector<CycleFigures> cycles;  ///< largest bound first; empty for an untimed net
  net::ExploreStop cycles_stop = net::ExploreStop::Done;  ///< why the cycle bounds were cut short (Done: not)
  std::vector<script::Figure> figures;  ///< the model's own, from its summary()
  std::string figures_error;         ///< why summary() failed ("" when it did not)
};

/// The cycle bounds' budget by default, seconds of wall-clock time.
inline constexpr double kCycleBoundSeconds = 10.0;

/// Works out the net's cycles before `sim` runs (within `cycle_seconds` of wall-clock time) and
/// watches the round trips of every token with alternative circuits, so that the report can
/// show the measured cycle of each circuit; makeReport then reuses the cycles. Costs what the
/// report's cycle bounds cost, and one lookup per transition start of a watched cycle.
void watchRoundTrips(Simulation& sim, double cycle_seconds = kCycleBoundSeconds);
/// Gathers the report of a finished run. The cycle bounds (from the P-invariants) stop after
/// `cycle_seconds` of wall-clock time, and the report says so.
Report makeReport(Simulation& sim, const RunOutcome& outcome, double cycle_seconds = kCycleBoundSeconds);
/// The report as pretty-printed JSON text.
std::string reportJson(const Report& report);
/// The same text written to `out` as it is made (none of it held: for large models).
void writeReportJson(std::ostream& out, const Report& report);
/// The most lines of each of the summary's tables (transitions, places, cycles); a longer one
/// ends with how many more the JSON report has.
inline constexpr std::size_t kMostRows = 100;
/// The summary tables, as `gdpn run` prints them.
void printSummary(std::ostream& out, const Report& report);

}  // namespace gdpn::model
