#pragma once
/// \file
/// The runtime kernel (semantics §5-§7): markings, reserves, occurrences and the incremental
/// enabling of the dissertation's kernel. A change at one place slot re-examines only the arc
/// terms that watch it; each transition counts its unsatisfied terms; the ready set is kept
/// in order of priority, time enabled and declaration. The cost of a step grows with what
/// changed in it, not with the size of the net.

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/random.h"
#include "gdpn/net/hooks.h"
#include "gdpn/net/net.h"
#include "gdpn/net/observer.h"

namespace gdpn::net {

/// How a kernel runs.
struct KernelSettings {
  /// Settings with step `dt_s` seconds, generator `seed_value` and node references `refs`.
  KernelSettings(double dt_s = 1.0 / 60.0, std::uint64_t seed_value = 1, std::vector<NodeRef> refs = {})
      : dt(dt_s), seed(seed_value), node_refs(std::move(refs)) {}
  double dt = 1.0 / 60.0;   ///< length of a step, seconds (> 0)
  std::uint64_t seed = 1;   ///< seed of the model's random generator
  /// What each initial node token (an index into Net::nodeNames()) refers to; empty means
  /// the index itself.
  std::vector<NodeRef> node_refs;
  /// How the firing phase orders enabled transitions of equal priority that became enabled
  /// in the same step: false, in declaration order; true, in an order drawn from the model's
  /// generator at the phase's start (semantics: Ties).
  bool random_ties = false;
};

/// Whether a transition can start, as the kernel last found it (semantics: When a transition
/// is enabled). Rules 1 to 4 and the conditions are the kernel's counts, known at any time;
/// the guard, the predicates and the probability draw are what the last attempt to start it
/// (a firing phase, or Kernel::fire()) found, kept until it is disabled or tried again.
enum class Readiness : std::uint8_t {
  Able,         ///< its arcs allow it and nothing held it back: it starts (or started) when tried
  Untried,      ///< its arcs allow it, but no attempt has looked at its guard, predicates or draw since
  Occurring,    ///< it is occurring: no server is free
  Tokens,       ///< an input or test arc lacks tokens, or an inhibitor arc finds too many
  Room,         ///< an output arc finds no room (capacity)
  Condition,    ///< its marking suffices, but a sensor condition on one of its arcs is false
  Guard,        ///< its marking suffices, but its guard was false
  Predicate,    ///< its marking suffices, but too few node tokens satisfied its predicates
  NoBinding,    ///< its counts suffice, but no binding of its variables is enabled (value tokens)
  Probability,  ///< its marking suffices, but it lost its probability draw
  Halted,       ///< its marking suffices, but the model's scripts have stopped (an error, a timeout)
};

/// True for the readiness of a transition whose marking suffices but that something else
/// (condition, guard, predicate, probability draw, stopped scripts) held back.
[[nodiscard]] bool heldBack(Readiness r);
/// A word for `r` ("able", "untried", "occurring", "tokens", "room", "condition", "guard", "binding",
/// "predicate", "probability", "halted"), for reports.
[[nodiscard]] const char* readinessName(Readiness r);

/// Whole steps of `dt` seconds an occurrence of `seconds` lasts: max(1, ceil(seconds / dt)),
/// a duration within a billionth of a whole number of steps counting as that number.
std::int64_t durationSteps(double seconds, double dt);

/// The changing state of one frozen Net, and the step loop's net phases.
class Kernel {
 public:
  /// A kernel in the initial marking, at step 0, not yet started.
  Kernel(std::shared_ptr<const Net> net, KernelSettings settings);

  /// Subscribes `observer` (not owned; it must outlive the kernel's use of it).
  void addObserver(NetObserver* observer);
  /// Unsubscribes `observer` (nothing happens when it is not subscribed).
  void removeObserver(NetObserver* observer);
  /// Lets `hooks` run the net's scripts (not owned). Without hooks, scripts are not run.
  void setHooks(ScriptHooks* hooks) { hooks_ = hooks; }
  /// Runs phase 4 (firing) once at time 0. Call once, before the first step().
  void start();
  /// One whole step for a net without a plant: advance the clock, complete, fire.
  void step();

  /// Phase 1 of the continuous part (hybrid nets): the amounts advance over the step that
  /// beginStep() began, at the rates the marking, the amounts and the reads (setFluidInput)
  /// give; each level crossed is reported at its time (NetObserver::onCross), and the terms
  /// on the places that changed are examined again. Nothing for a net without one.
  void advanceFluid();

  /// Phase 0: the clock moves to the end of the next step.
  void beginStep() {
    ++step_;
    settled_ = false;
  }
  /// A step with the net switched off: the clock moves on and nothing in the net changes.
  /// Occurrences are paused: their start and end move with the clock.
  void idleStep() {
    if (start_idle_.empty()) start_idle_.assign(tr_.size(), 0);  // from now on starts note idle_
    ++idle_;
  }
  /// Phase 3: occurring transitions whose duration has elapsed complete, in start order.
  void completeOccurrences();
  /// Phase 4: enabled transitions start, by priority, then time enabled, then declaration
  /// (or, with random ties, an order drawn for each group of equal priority and time).
  void fireEnabled();

  /// Starts `t` now, outside the firing phase: the user's "fire the selected transition".
  /// Returns "" when it started, or why not: it is occurring (all its servers busy), a term does not hold (the first
  /// such is named), the scripts have stopped (an error, a timeout), its guard is false, or
  /// no node token satisfies its predicates. Its probability is not drawn: the user chose it.
  std::string fire(TransitionId t);
  /// Starts coloured transition `t` now in binding `b` (its variables' values, in the order
  /// of Colouring::of(t)->variables): the user's "fire this binding". As fire(t), and "" when
  /// it started; refused, with why, when `b` is not among bindings(t) (the binding is named:
  /// "binding (p = ph1) of 'take' is not enabled") or `t` has no variables.
  std::string fire(TransitionId t, const Binding& b);
  /// Steps taken since start, with the net on or off; now() == steps() * dt.
  [[nodiscard]] std::int64_t steps() const { return step_ + idle_; }
  /// The time at the end of the current step, seconds.
  [[nodiscard]] double now() const { return static_cast<double>(steps()) * dt_; }
  /// The step length, seconds.
  [[nodiscard]] double dt() const { return dt_; }
  /// Whole steps an occurrence of `seconds` lasts: max(1, ceil(seconds / dt)).
  [[nodiscard]] std::int64_t durationSteps(double seconds) const;

  /// Tokens on place slot `ps`.
  [[nodiscard]] std::int64_t marking(PlaceSlotId ps) const { return slots_[ps].m; }
  /// Capacity promised to occurring transitions on place slot `ps`.
  [[nodiscard]] std::int64_t reserve(PlaceSlotId ps) const { return slots_[ps].r; }
  /// Tokens on all slots of place `p`.
  [[nodiscard]] std::int64_t placeTokens(PlaceId p) const;
  /// The node tokens on node slot `ps`, first to leave first (empty for control slots).
  [[nodiscard]] std::vector<NodeRef> nodes(PlaceSlotId ps) const;
  /// True when `t` may start now (all its terms hold and a server of it is free).
  [[nodiscard]] bool enabled(TransitionId t) const { return tr_[t].unsat == 0; }
  /// Whether `t` can start, as the kernel last found it: its terms now, and what the last
  /// attempt to start it found of its guard, predicates and draw. Reads what the kernel keeps
  /// (no script runs); its cost is that of `t`'s terms.
  [[nodiscard]] Readiness readiness(TransitionId t) const;
  /// readiness(t) in words: "able to start", "guard false", "condition of arc 'P' -> 'T'
  /// false", "'P' a0 holds 0 of the 1 it needs" and the like.
  [[nodiscard]] std::string readinessText(TransitionId t) const;
  /// True while an occurrence of `t` runs.
  [[nodiscard]] bool occurring(TransitionId t) const { return tr_[t].end_step >= 0; }
  /// How many occurrences of `t` run now (at most its servers).
  [[nodiscard]] std::size_t occurrences(TransitionId t) const;
  /// How many occurrences of `t` may run at once; 0 (kUnlimitedServers) for any number.
  [[nodiscard]] std::uint32_t servers(TransitionId t) const { return net_->transitions()[t].servers; }
  /// Step at which the current occurrence of `t` started; when it is not occurring, the last
  /// one. (Steps with the net off before now count as if the occurrence had started after
  /// them.) With servers, the current occurrence is the one whose script runs now, else the
  /// oldest one running; so for endStep() and held().
  [[nodiscard]] std::int64_t startStep(TransitionId t) const;
  /// Step at which the current occurrence of `t` completes (-1 when not occurring).
  [[nodiscard]] std::int64_t endStep(TransitionId t) const;
  /// The node tokens the current occurrence of `t` holds, with their slots, in the order taken.
  [[nodiscard]] std::span<const std::pair<SlotId, NodeRef>> held(TransitionId t) const;
  /// The values on value slot `ps` (empty for other slots).
  [[nodiscard]] const Multiset& values(PlaceSlotId ps) const;
  /// The binding of the current occurrence of `t` and what its arcs take and put (as held());
  /// null when `t` has no variables or is not occurring.
  [[nodiscard]] const BoundOccurrence* binding(TransitionId t) const;
  /// The bindings of `t` enabled now, in the canonical order (at most `most`): what a firing
  /// phase chooses from. Empty for a transition without inscriptions.
  [[nodiscard]] std::vector<BoundOccurrence> bindings(TransitionId t, std::size_t most = SIZE_MAX) const;
  /// Sets the marking of control slot `ps` to `count` (a script's `set`). Returns "" or why
  /// not: a node slot, a negative count, or no room (count + reserve > capacity). Observers
  /// see the change as a deposit or a removal; on_deposit/on_remove scripts do not run.
  std::string setMarking(PlaceSlotId ps, std::int64_t count);
  /// The capacity of place slot `ps`, tokens (kUnbounded when none).
  [[nodiscard]] std::int64_t capacity(PlaceSlotId ps) const { return slots_[ps].capacity; }
  /// The amount on continuous place `p`, in its unit (0 for a discrete place).
  [[nodiscard]] double amount(PlaceId p) const;
  /// The room on continuous place `p` promised to occurring transitions, in its unit.
  [[nodiscard]] double amountReserved(PlaceId p) const;
  /// Sets the amount on continuous place `p` (a script's, the contents view's). Returns "" or
  /// why not: a discrete place, a number below 0 or not finite, or more than its capacity less
  /// the room promised. Observers see the change as a deposit or a removal of the difference.
  std::string setAmount(PlaceId p, double amount);
  /// Sets the value of Fluid::reads[`i`] (a number of the plant a rate reads), held until set again.
  void setFluidInput(std::size_t i, double value);
  /// The effective rate of continuous transition `t` now, units per second (0 for a discrete one).
  [[nodiscard]] double flowRate(TransitionId t) const;
  /// The rate continuous transition `t` would flow at without the first-order rules' cuts.
  [[nodiscard]] double nominalRate(TransitionId t) const;
  /// What the continuous part did over the run so far (amounts' extremes and areas, flows'
  /// amounts moved and time flowing; per Fluid::places and Fluid::flows); null without one.
  [[nodiscard]] const FluidTally* fluidTally() const { return fluid_ ? &fluid_run_->solver.tally() : nullptr; }
  /// True while some continuous transition moves an amount (a dead net may still flow).
  [[nodiscard]] bool flowing() const;
  /// Sets the capacity of place slot `ps` (a script's `capacity = n`; kUnbounded for none).
  /// Returns "" or why not: a slot the model left unbounded, a negative capacity, or less than
  /// the tokens there and the room promised to occurring transitions. Transitions waiting for room are re-examined.
  std::string setCapacity(PlaceSlotId ps, std::int64_t capacity);
  /// Sets whether condition term `term` holds (the sensor layer evaluates conditions when
  /// their sensor changes). Conditions start out not holding.
  void setCondition(TermId term, bool holds);
  /// Whether condition term `term` holds now.
  [[nodiscard]] bool condition(TermId term) const { return term < cond_.size() && cond_[term]; }
  /// Puts node token `ref` at the end of node slot `ps` (a script's `add`). Returns "" or why
  /// not: a control slot, or no room. Observers see a deposit; on_deposit does not run.
  std::string addNode(PlaceSlotId ps, NodeRef ref);
  /// Removes every node token for which `gone(ref)` is true, from the places (observers see
  /// removals) and from what occurring transitions hold (they deposit fewer). Returns how many.
  std::size_t dropNodes(const std::function<bool(NodeRef)>& gone);
  /// Number of occurrences running now (one per occurring transition, unless it has servers).
  [[nodiscard]] std::size_t occurringCount() const { return occurring_count_; }
  /// Number of transitions enabled now.
  [[nodiscard]] std::size_t enabledCount() const { return enabled_count_; }
  /// Occurrences started since construction.
  [[nodiscard]] std::uint64_t startCount() const { return start_count_; }
  /// True when nothing occurs and nothing is enabled: without outside input the net is dead.
  /// (A transition whose last attempt found no binding of its values counts as not enabled:
  /// only a change of the marking, which nothing inside the net can make now, could give it one.)
  [[nodiscard]] bool dead() const {
    return occurring_count_ == 0 && (enabled_count_ == 0 || (colouring_ && onlyUnbound())) && !(fluid_ && flowing());
  }
  /// The model's random generator (all draws of a run come from it, in a fixed order).
  core::Random& random() { return random_; }
  /// The frozen net.
  [[nodiscard]] const Net& net() const { return *net_; }
  /// Approximate heap bytes of the changing state.
  [[nodiscard]] std::size_t memoryBytes() const;

 private:
  struct alignas(64) TransitionState {  // all a firing needs of one transition: one cache line
    std::uint32_t terms_begin, inputs_end, conditions_end, terms_end;
    std::uint32_t rank : 23;      // priority rank, 0 highest
    std::uint32_t multi : 1;      // more than one server: its occurrences are kept in occ_
    std::uint32_t scripts : 8;    // TransitionScript bits
    std::int32_t held;            // index in held_, -1 when no node slot passes through
    std::uint32_t unsat;          // terms that do not hold, +1 while occurring (all servers busy)
    std::int32_t fixed_steps;     // -1 when the duration is drawn (or too long for 31 bits)
    double probability;
    std::int64_t enabled_step;    // when unsat last became 0
    std::int64_t start_step;      // current occurrence (with servers: the last started)
    std::int64_t end_step;        // -1 when not occurring (with servers: the oldest's end)
  };
  static_assert(sizeof(TransitionState) == 64);
  struct Watch {  // one term that watches a place slot
    TransitionId transition;
    std::int32_t weight;
    std::int32_t take;
    TermKind kind;
    std::uint8_t holds;           // whether the term held when last examined
  };
  struct alignas(64) SlotState {  // one place slot: one cache line, with its first watcher
    std::int64_t m, r, capacity;
    std::uint32_t watch_begin;    // further watchers: watch_[watch_begin, watch_begin + watch_count - 1)
    std::int32_t fifo;            // index in fifos_, -1 for control slots
    std::uint32_t watch_count;    // all watchers, the inline one included
    Watch first;                  // the first watcher, when watch_count > 0
    std::uint8_t scripts;         // SlotScript bits
    SlotId slot;                  // which slot of its place
  };
  static_assert(sizeof(SlotState) == 64);
  static_assert(sizeof(Watch) == 16);
  struct FiringTerm {  // what a start and a completion read of one term: 8 bytes, not the term's 20
    PlaceSlotId place_slot;
    std::int32_t weight;
  };
  struct RemoveCall {  // on_remove calls owed by a start: `count` times, for one node token or control
    PlaceSlotId ps;
    std::int64_t count;
    bool node;
    NodeRef token;
  };
  struct Carry {  // an enabled transition that did not start (probability), kept in order
    std::uint64_t key;
    std::int64_t step;
  };
  // the firing order: priority rank, then the step enabled, then declaration
  static bool candidateBefore(const Carry& a, const Carry& b) {
    return (a.key >> 32) != (b.key >> 32) ? (a.key >> 32) < (b.key >> 32) : a.step != b.step ? a.step < b.step : a.key < b.key;
  }

  // An occurrence, as the wheels and the in_fire list name it: a transition's index, or, for a
  // transition with servers, kOccurrenceBit | its occurrence's index in occ_.
  using Entry = std::uint32_t;
  static constexpr Entry kOccurrenceBit = 0x80000000u;
  static constexpr Entry kNoEntry = 0xffffffffu;
  static constexpr std::uint32_t kNoOccurrence = 0xffffffffu;
  struct Occurrence {  // one occurrence of a transition with servers
    TransitionId t;
    std::uint32_t prev, next;           // its transition's running occurrences, by start
    std::int64_t start_step, end_step;  // end_step -1 once completed
    std::int64_t start_idle;            // idle_ when it started
    std::uint64_t seq;                  // start_count_ at its start, when it has in_fire
    std::vector<std::pair<SlotId, NodeRef>> held;
  };
  struct Servers {  // a transition with servers
    std::uint32_t limit;  // 0: unlimited
    std::uint32_t busy;
    std::uint32_t oldest, newest;  // its running occurrences (kNoOccurrence: none)
  };
  [[nodiscard]] TransitionId transitionOf(Entry e) const {
    return e & kOccurrenceBit ? occ_[e & ~kOccurrenceBit].t : TransitionId{e};
  }
  [[nodiscard]] std::int64_t endOf(Entry e) const {
    return e & kOccurrenceBit ? occ_[e & ~kOccurrenceBit].end_step : tr_[e].end_step;
  }
  [[nodiscard]] std::uint64_t seqOf(Entry e) const {
    return e & kOccurrenceBit ? occ_[e & ~kOccurrenceBit].seq : start_seq_.empty() ? 0 : start_seq_[e];
  }
  template <bool kServers>
  std::vector<std::pair<SlotId, NodeRef>>& heldOf(Entry e) {
    if constexpr (kServers) return occ_[e & ~kOccurrenceBit].held;
    else return held_[static_cast<std::size_t>(tr_[e].held)];
  }
  // the occurrence of `t` a question means: the one whose script runs, else the oldest (nullptr: none)
  [[nodiscard]] const Occurrence* currentOccurrence(TransitionId t) const;
  Entry startOccurrence(TransitionId t, std::int64_t end);  // the bookkeeping of begin() for servers
  void endOccurrence(Entry e);                               // and of finish()
  // puts `e`, ending at step `end`, in the far wheel (out of line: most occurrences are near)
  [[gnu::noinline]] void waitFar(Entry e, std::int64_t end);
  // moves the entries of `from` that end at step `end` to `to`, in order; returns how many
  std::size_t takeEnding(std::vector<Entry>& from, std::int64_t end, std::vector<Entry>& to) const;
  bool tryStart(TransitionId t, bool again);

  // the same entry: one enabling of one transition
  static bool sameEntry(const Carry& a, const Carry& b) { return a.key == b.key && a.step == b.step; }

  static bool holds(const SlotState& st, TermKind kind, std::int64_t weight, std::int64_t take);
  void update(PlaceSlotId ps);
  void examine(const SlotState& st, Watch& watch);
  template <class Get>
  void prefetchAhead(std::size_t i, std::size_t n, Get get) const;
  /// Fetches into the cache the terms of `t` (its state line in the cache already).
  void prefetchTerms(TransitionId t) const;
  /// Fetches into the cache the place slots the terms of `t` name (its terms in the cache).
  void prefetchSlots(TransitionId t) const;
  void markEnabled(TransitionId t);
  bool selectTokens(TransitionId t);
  // chooses the binding the next start of coloured transition `t` occurs in (bound_next_):
  // false when none is enabled
  bool selectBinding(TransitionId t);
  // fire(t), or fire(t, *chosen): the binding chosen by the user in place of selectBinding's
  std::string fireIn(TransitionId t, const Binding* chosen);
  // whether every enabled transition is held back because none of its bindings is enabled
  [[nodiscard]] bool onlyUnbound() const;
  // the size of what term `i` of a coloured transition moves in the occurrence `o`
  [[nodiscard]] std::int64_t boundCount(std::uint32_t i, const BoundOccurrence& o) const {
    return multisetSize(o.arcs[static_cast<std::size_t>(term_arc_[i])]);
  }
  void begin(TransitionId t);
  template <bool kServers>
  void beginAs(TransitionId t);
  void deposited(PlaceSlotId ps, const SlotState& st, std::int64_t count);
  void finish(Entry e);
  template <bool kServers>
  void finishAs(Entry e);
  std::int64_t drawSteps(TransitionId t);
  // each run of `candidates` (in order) tied on priority and time enabled, in a drawn order
  void shuffleTies(std::vector<Carry>& candidates);
  // the firing phase's starts over candidates_ and, as immediate occurrences enable them,
  // extra_: whether an immediate occurrence took a round. Compiled without the rounds for a
  // net with no immediate transition (kRounds false), where no occurrence completes in the phase.
  template <bool kRounds>
  bool startCandidates();
  // after an immediate occurrence of the entry `fired`: it (when still enabled) and what was
  // enabled since join the extras not yet taken
  void addExtras(const Carry& fired);
  struct Extra {  // an entry an immediate occurrence enabled, numbered as it came
    Carry c;
    std::uint64_t order;
  };
  // whether extra `x` is taken after extra `y` (the heap's order): the firing order, or, with
  // random ties, its group (priority, time enabled), then the order they came in
  [[nodiscard]] bool extraAfter(const Extra& x, const Extra& y) const {
    if (!random_ties_) return candidateBefore(y.c, x.c);
    if ((x.c.key >> 32) != (y.c.key >> 32)) return (y.c.key >> 32) < (x.c.key >> 32);
    return x.c.step != y.c.step ? y.c.step < x.c.step : y.order < x.order;
  }
  // whether extra entry `x` goes before candidate `c`: in the firing order, or, with random
  // ties, only before a candidate of a later (priority, time enabled) group
  [[nodiscard]] bool extraBefore(const Carry& x, const Carry& c) const {
    if (!random_ties_) return candidateBefore(x, c);
    return (x.key >> 32) != (c.key >> 32) ? (x.key >> 32) < (c.key >> 32) : x.step < c.step;
  }

  std::shared_ptr<const Net> net_;
  const Term* terms_ = nullptr;
  // the continuous part (hybrid nets): amounts, promised room, reads, and the solver
  struct FluidRun {
    std::vector<double> x, reserved, inputs;
    std::vector<std::uint8_t> on;  // per flow: its discrete terms hold
    FluidSolver solver;
    std::vector<Crossing> crossed;
    std::vector<double> before;    // the amounts at the step's start
  };
  const Fluid* fluid_ = nullptr;
  std::optional<FluidRun> fluid_run_;
  void fluidInit();
  void fluidBegin(TransitionId t);   // a start's jumps: takes amounts, promises room
  void fluidFinish(TransitionId t);  // a completion's: puts amounts
  void fluidRefresh(std::uint32_t place);  // the terms on fluid place `place`, examined again
  void fluidRates();                 // the flows' rates at the amounts as they are
  [[nodiscard]] bool fluidTermHolds(std::uint32_t k) const;
  // value tokens (none when the net has no colouring)
  const Colouring* colouring_ = nullptr;
  std::vector<Multiset> values_;            // per place slot
  std::vector<std::int32_t> term_arc_;      // per term: its arc in its coloured transition, -1 for others
  BoundOccurrence bound_next_;              // what selectBinding chose for the next begin()
  // per coloured transition: its binding search, planned once (shared by copies: it only reads the net)
  std::shared_ptr<const std::vector<BindingSearch>> searches_;
  std::map<Entry, BoundOccurrence> bound_;  // per running occurrence of a coloured transition
  /// Per term (same index): its place slot and weight, all that firings read of it. A ring's
  /// firing reads 16 bytes of them rather than 40, a quarter of a cache line at 10^6 terms.
  std::vector<FiringTerm> firing_terms_;
  double dt_;
  core::Random random_;
  std::int64_t step_ = 0;  // steps with the net on: the clock of occurrences and enabling
  std::int64_t idle_ = 0;  // steps with the net off
  bool in_firing_ = false;
  // the step's firing phase is over: a transition enabled now (a marking set from outside
  // between steps) is a candidate of the next step's, and is stamped with that step
  bool settled_ = false;
  bool random_ties_ = false;
  bool immediate_fired_ = false;  // an immediate occurrence completed in this round
  bool immediates_ = false;       // some transition is immediate
  /// The net's state outgrows the caches close to the core (4 MiB and more): a firing fetches
  /// what the next ones read ahead of them.
  bool big_ = false;
  /// Occurrences running at once up to which what a completion reads (its transition, terms
  /// and place slots, touched as it started) is likely still in the second-level cache: a
  /// quarter of that cache at four lines an occurrence. Up to it, the loop over completions
  /// fetches nothing ahead; its fetches would only read lines already there.
  std::size_t warm_occurrences_ = 0;
  /// Rounds of immediate occurrences one firing phase takes at most, beyond 4 per transition
  /// of the net (a cycle of immediate transitions would never end); what is left waits for
  /// the next step.
  static constexpr std::int64_t kImmediateRounds = 10000;
  /// Starts of one transition with servers in one turn of the firing phase, at most (scripts
  /// that keep refilling its inputs would never end it); it goes on in the next phase.
  static constexpr std::uint32_t kStartsPerTurn = 1'000'000;

  std::vector<TransitionState> tr_;
  std::vector<SlotState> slots_;                  // one more than there are slots: a sentinel
  std::vector<Watch> watch_;                      // grouped by place slot (SlotState::watch_begin)
  std::vector<std::deque<NodeRef>> fifos_;
  std::vector<std::vector<std::pair<SlotId, NodeRef>>> held_;  // node tokens inside a transition
  std::size_t occurring_count_ = 0, enabled_count_ = 0;
  std::uint64_t start_count_ = 0;

  std::vector<std::uint64_t> fresh_, late_, late_now_, scratch_;  // keys: rank << 32 | t
  std::vector<Carry> carry_, carry_next_;
  std::vector<Carry> candidates_;  // one firing phase's candidates, in order
  std::vector<Extra> extra_;       // entries immediate occurrences enabled in this phase: a heap
  std::uint64_t extra_count_ = 0;
  std::uint64_t phase_ = 0;        // firing phases begun
  std::vector<std::uint64_t> taken_phase_;  // with random ties: per transition, the phase it was last taken in
  std::vector<std::int64_t> taken_step_;    // and the step enabled of the entry taken
  std::vector<Carry> next_;        // addExtras()'s new entries
  std::vector<std::int64_t> drawn_;  // per transition: the step of its last probability draw (-1: none)
  // per transition: a Readiness that the last attempt to start it found, Untried since it was
  // enabled, or kFree for one nothing but its terms can hold back (no guard, predicate or
  // draw). Empty when every transition is free: a net without scripts pays nothing.
  static constexpr std::uint8_t kFree = 0xff;
  std::vector<std::uint8_t> verdict_;
  // records that the attempt to start `t` found `r`; returns false (it did not start)
  bool heldBy(TransitionId t, Readiness r) {
    if (!verdict_.empty() && verdict_[t] != kFree) verdict_[t] = static_cast<std::uint8_t>(r);
    return false;
  }
  // why term `i` does not hold, after "'T' is not enabled: " ("'P' a0 holds 0 of the 1 it needs")
  [[nodiscard]] std::string termText(std::uint32_t i) const;
  // an entry that still stands: its transition enabled since the step it names
  [[nodiscard]] bool valid(const Carry& c) const {
    const auto& tr = tr_[static_cast<std::uint32_t>(c.key)];
    return tr.unsat == 0 && tr.enabled_step == c.step;
  }
  std::vector<std::vector<Entry>> wheel_;  // completions due by near_end_, by end step modulo its size
  std::vector<std::vector<Entry>> far_;    // later completions, by end step modulo its size
  std::int64_t near_end_ = 0;              // the last end step whose completions wait in wheel_
  std::size_t far_count_ = 0;              // completions waiting in far_
  std::vector<Entry> due_;
  std::vector<NodeRef> moved_;  // node tokens of one event, reused
  ScriptHooks* hooks_ = nullptr;
  std::vector<std::uint8_t> cond_;                // per term: a condition that holds
  std::vector<std::uint64_t> start_seq_;        // per transition, when the net has in_fire scripts
  std::vector<Entry> in_fire_;                  // occurrences with in_fire, in start order
  std::vector<Entry> in_fire_next_;
  std::vector<Occurrence> occ_;                 // occurrences of transitions with servers
  std::vector<std::uint32_t> occ_free_;         // indices in occ_ to reuse
  std::vector<std::int64_t> start_idle_;        // per transition: idle_ at its start (empty until an idle step)
  std::vector<Servers> servers_;
  std::vector<std::int32_t> servers_of_;        // per transition: index in servers_, -1 for one (empty: none has more)
  Entry current_ = kNoEntry;                    // the occurrence whose scripts run now
  std::vector<std::vector<std::size_t>> chosen_;  // per input term of the candidate: FIFO positions picked by predicates
  std::vector<NetObserver*> observers_;
};

}  // namespace gdpn::net
