#pragma once
/// \file
/// The continuous part of a hybrid net (semantics: *Hybrid nets*): continuous places holding
/// real amounts, continuous transitions flowing between them at rates, and the terms by which
/// discrete transitions read and move amounts. `Fluid` is frozen with the Net; `FluidSolver`
/// advances the amounts over one step, locating every level crossing at its exact time.

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/core/expression.h"
#include "gdpn/net/id.h"
#include "gdpn/net/spec.h"

namespace gdpn::net {

/// An amount with no bound.
inline constexpr double kNoBound = std::numeric_limits<double>::infinity();

/// What an arc between a continuous place and a transition asks of the place's amount `x`.
enum class LevelTest : std::uint8_t {
  AtLeast,  ///< x >= w (a normal input, which takes w when the transition starts, or a test arc)
  Below,    ///< x < w (an inhibitor arc)
  Room,     ///< x + reserved + w <= capacity (an output of a discrete transition, which puts w on completion)
};

/// A continuous place, frozen.
struct FluidPlace {
  PlaceId place;                    ///< the place
  PlaceSlotId slot;                 ///< its only slot (a0, kind Continuous)
  double initial = 0.0;             ///< initial amount
  double capacity = kNoBound;       ///< the most it holds
  std::string unit;                 ///< for people
  /// The amounts at which something may change: 0, the capacity, and every arc's threshold
  /// (ascending, once each). A crossing of one of them is located and traced.
  std::vector<double> levels;
  std::uint32_t terms_begin = 0;    ///< its discrete terms: range in Fluid::terms (grouped by place)
  std::uint32_t terms_end = 0;      ///< end of that range
  std::vector<FluidDrive> drives;   ///< plant fields it sets (paths qualified)
};

/// A term of a discrete transition on a continuous place: a kernel Condition term whose truth
/// the amount decides.
struct FluidTerm {
  TermId term;                      ///< the kernel's term (kind Condition)
  TransitionId transition;          ///< its transition (discrete)
  std::uint32_t place = 0;          ///< its place, an index in Fluid::places
  double weight = 1.0;              ///< w, in the place's unit
  LevelTest test = LevelTest::AtLeast;  ///< what it asks
  bool moves = false;               ///< a normal arc: takes w at the start (AtLeast) or puts w at the completion (Room)
};

/// A flow arc or a threshold of a continuous transition.
struct FlowArc {
  std::uint32_t place = 0;  ///< an index in Fluid::places
  double weight = 1.0;      ///< amount per unit of flow (arcs), or the threshold (tests, inhibitors)
};

/// A continuous transition, frozen.
struct Flow {
  TransitionId transition;                 ///< the transition (in Net::transitions(), never fired)
  std::uint32_t inputs_begin = 0;          ///< its input arcs: range in Fluid::arcs
  std::uint32_t outputs_begin = 0;         ///< its output arcs: [outputs_begin, outputs_end)
  std::uint32_t outputs_end = 0;
  std::uint32_t tests_begin = 0;           ///< its thresholds: x >= w in [tests_begin, inhibitors_begin)
  std::uint32_t inhibitors_begin = 0;      ///< x < w in [inhibitors_begin, thresholds_end) of Fluid::thresholds
  std::uint32_t thresholds_end = 0;
  /// Its rate, units per second: slots 0..places-1 are the continuous places' amounts, then
  /// Fluid::reads' values, then Fluid::constants.
  core::Program rate;
  bool stateful = false;                   ///< its rate reads an amount (an ODE, not a constant)
};

/// A number of the plant a rate reads, set from outside every step (Kernel::setFluidInput).
struct FluidRead {
  std::string node;  ///< the node's path, qualified
  std::string of;    ///< what of it (a signal's `of`)
  SourceLoc loc;     ///< where it was written
  TransitionId transition;  ///< the flow whose rate reads it
};

/// The continuous part of a net.
struct Fluid {
  std::vector<FluidPlace> places;       ///< in place order
  std::vector<Flow> flows;              ///< in transition order
  std::vector<FlowArc> arcs;            ///< the flows' arcs
  std::vector<FlowArc> thresholds;      ///< the flows' test and inhibitor arcs on continuous places
  std::vector<FluidTerm> terms;         ///< grouped by place
  std::vector<FluidRead> reads;         ///< what rates read of the plant
  std::vector<double> constants;        ///< the parameters rates name, after the reads in a rate's slots
  std::vector<std::int32_t> of_place;       ///< per place: its index in `places`, -1 for a discrete one
  std::vector<std::int32_t> of_transition;  ///< per transition: its index in `flows`, -1 for a discrete one
  std::vector<std::int32_t> of_term;        ///< per term: its index in `terms`, -1 for others
  /// True when transition `t` is continuous.
  [[nodiscard]] bool continuous(TransitionId t) const { return of_transition[t] >= 0; }
};

/// True when `spec` has a continuous place or transition (a hybrid net).
[[nodiscard]] bool hybrid(const NetSpec& spec);

/// How much of a hybrid net discretePart() left out (counted per page or page type declared).
struct DiscretePart {
  std::size_t places = 0;       ///< continuous places
  std::size_t transitions = 0;  ///< continuous transitions
  std::size_t arcs = 0;         ///< arcs with one of them
};

/// `spec` without its continuous part: its continuous places and transitions and every arc
/// with one of them (a port publishing a continuous place, and the links to it, too). What
/// the analysis reads of a hybrid net (semantics: *Analysis*): every discrete run of the
/// hybrid net is a run of it, not the other way round.
[[nodiscard]] NetSpec discretePart(const NetSpec& spec, DiscretePart* counts = nullptr);

/// Whether fluid term `term` holds at amount `x` with `reserved` promised to occurring transitions.
[[nodiscard]] bool levelHolds(const FluidTerm& term, double x, double reserved, double capacity);

/// A level crossed within a step, at its exact time.
struct Crossing {
  std::uint32_t place = 0;  ///< an index in Fluid::places
  double level = 0.0;       ///< the amount crossed (or reached: 0 when it runs empty, the capacity when full)
  double time = 0.0;        ///< when, seconds
  bool rising = false;      ///< from below
};

/// What the amounts and flows did over a run, as FluidSolver::advance() went (the report's
/// figures): exact where rates are constant over a segment, by the trapezoid rule over each
/// solver segment where a rate reads an amount.
struct FluidTally {
  std::vector<double> lowest;   ///< per place: the least amount at a step or segment boundary (+inf: none yet)
  std::vector<double> highest;  ///< per place: the most (-inf: none yet)
  std::vector<double> area;     ///< per place: the amount integrated over time, unit x seconds
  std::vector<double> moved;    ///< per flow: its effective rate integrated over time (units of flow)
  std::vector<double> flowing;  ///< per flow: seconds its effective rate was not 0
  double time = 0.0;            ///< seconds advanced in all
};

/// Advances the amounts of a Fluid through time by the first-order rules (semantics: *Hybrid
/// nets*): piecewise-linear and exact while no flowing rate reads an amount, with SUNDIALS
/// CVODE otherwise; each crossing of a level is located at its time. Copies start afresh (the
/// solver's memory is not shared).
class FluidSolver {
 public:
  /// A solver for `fluid` (which must outlive it).
  explicit FluidSolver(const Fluid& fluid);
  ~FluidSolver();
  FluidSolver(const FluidSolver& other);
  FluidSolver& operator=(const FluidSolver& other);

  /// Advances `x` (amounts, per Fluid::places) from `t0` over `h` seconds. `on[f]` says whether
  /// flow f's discrete terms hold (the marking is fixed within a step); `inputs` are the reads'
  /// values, held over the step; `reserved` per place the room promised to occurring
  /// transitions. Appends the crossings to `out` in time order. `flowing` says afterwards
  /// whether any flow moved an amount at the end of the interval.
  void advance(std::vector<double>& x, std::span<const std::uint8_t> on, std::span<const double> inputs,
               std::span<const double> reserved, double t0, double h, std::vector<Crossing>& out);
  /// The flows' effective rates (units per second, per Fluid::flows) at the end of the last
  /// advance(), or as rates() computes them.
  [[nodiscard]] std::span<const double> flowRates() const { return f_; }
  /// The flows' rates before the first-order rules cut them (0 for a flow switched off).
  [[nodiscard]] std::span<const double> nominalRates() const { return v_; }
  /// Computes the effective rates at amounts `x` without advancing (for a fresh kernel's figures).
  void rates(const std::vector<double>& x, std::span<const std::uint8_t> on, std::span<const double> inputs,
             std::span<const double> reserved);
  /// True when some flow's effective rate is not 0.
  [[nodiscard]] bool flowing() const;
  /// What the amounts and flows did over every advance() so far (copies carry it).
  [[nodiscard]] const FluidTally& tally() const { return tally_; }

 private:
  struct Cvode;
  // the mode at x: on flows, nominal and effective rates; returns whether a flowing rate reads amounts
  bool mode(const double* x);
  void derivative(const double* x, double* dx);
  void reduce(const double* x);  // the first-order rules: empty and full places cut the flows
  [[nodiscard]] bool thresholdsHold(std::uint32_t flow, const double* x) const;
  [[nodiscard]] bool moves(std::uint32_t flow, std::uint32_t place, bool draws) const;
  // the level place p reaches next from amount x going up or down (kNoBound: none)
  [[nodiscard]] double nextLevel(std::uint32_t p, double x, bool up) const;

  const Fluid* fluid_;
  std::vector<double> values_;   // amounts, then inputs: what rates read
  std::vector<double> v_, f_;    // per flow: nominal and effective rate
  std::vector<std::uint8_t> active_;  // per flow: on and its thresholds hold
  std::vector<std::int8_t> side_;     // per place: after a crossing at a level, the side it went to (+1, -1; 0 none)
  std::vector<double> side_level_;    // and that level
  std::vector<double> full_;          // per place: the level it counts as full at (capacity - reserved)
  std::vector<std::vector<std::pair<std::uint32_t, double>>> feeds_, draws_;  // per place: (flow, weight) in, out
  std::vector<std::uint32_t> bounded_;  // places at 0 or full, where the rules may cut flows
  std::vector<std::uint32_t> held_;     // those of them (and of sliding_) the rules hold there
  struct Sliding {  // an on flow at a threshold of its own that it moves its place towards
    std::uint32_t flow, place;
    bool floor;     // a test it draws down to (else an inhibitor it fills up to)
  };
  std::vector<Sliding> sliding_;        // grouped by (place, floor): see mode()
  std::vector<double> dx_;
  std::span<const std::uint8_t> on_;
  std::unique_ptr<Cvode> cvode_;
  FluidTally tally_;
  std::vector<double> f_start_, x_start_;  // a solver segment's rates and amounts at its start
  void count(const std::vector<double>& x, double tau);  // a segment of constant rates, into tally_
  void extremes(const std::vector<double>& x);           // the amounts now, into lowest and highest
};

}  // namespace gdpn::net
