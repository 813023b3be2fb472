#pragma once
/// \file
/// The runtime kernel (semantics §5-§7): markings, reserves, occurrences and the incremental
/// enabling of the dissertation's kernel. A change at one place slot re-examines only the arc
/// terms that watch it; each transition counts its unsatisfied terms; the ready set is kept
/// in order of priority, time enabled and declaration. The cost of a step grows with what
/// changed in it, not with the size of the net.

#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "gdpn/core/random.h"
#include "gdpn/net/net.h"
#include "gdpn/net/observer.h"

namespace gdpn::net {

/// How a kernel runs.
struct KernelSettings {
  double dt = 1.0 / 60.0;   ///< length of a step, seconds (> 0)
  std::uint64_t seed = 1;   ///< seed of the model's random generator
};

/// The changing state of one frozen Net, and the step loop's net phases.
class Kernel {
 public:
  /// A kernel in the initial marking, at step 0, not yet started.
  Kernel(std::shared_ptr<const Net> net, KernelSettings settings);

  /// Subscribes `observer` (not owned; it must outlive the kernel's use of it).
  void addObserver(NetObserver* observer);
  /// Runs phase 4 (firing) once at time 0. Call once, before the first step().
  void start();
  /// One whole step for a net without a plant: advance the clock, complete, fire.
  void step();

  /// Phase 0: the clock moves to the end of the next step.
  void beginStep() { ++step_; }
  /// Phase 3: occurring transitions whose duration has elapsed complete, in start order.
  void completeOccurrences();
  /// Phase 4: enabled transitions start, by priority, then time enabled, then declaration.
  void fireEnabled();

  /// Steps taken since start; now() == steps() * dt.
  [[nodiscard]] std::int64_t steps() const { return step_; }
  /// The time at the end of the current step, seconds.
  [[nodiscard]] double now() const { return static_cast<double>(step_) * dt_; }
  /// The step length, seconds.
  [[nodiscard]] double dt() const { return dt_; }
  /// Whole steps an occurrence of `seconds` lasts: max(1, ceil(seconds / dt)).
  [[nodiscard]] std::int64_t durationSteps(double seconds) const;

  /// Tokens on place slot `ps`.
  [[nodiscard]] std::int64_t marking(PlaceSlotId ps) const { return m_[ps]; }
  /// Capacity promised to occurring transitions on place slot `ps`.
  [[nodiscard]] std::int64_t reserve(PlaceSlotId ps) const { return r_[ps]; }
  /// Tokens on all slots of place `p`.
  [[nodiscard]] std::int64_t placeTokens(PlaceId p) const;
  /// The node tokens on node slot `ps`, first to leave first (empty for control slots).
  [[nodiscard]] std::vector<NodeRef> nodes(PlaceSlotId ps) const;
  /// True when `t` may start now (all its terms hold and it is not occurring).
  [[nodiscard]] bool enabled(TransitionId t) const { return unsat_[t] == 0; }
  /// True while `t` is occurring.
  [[nodiscard]] bool occurring(TransitionId t) const { return end_step_[t] >= 0; }
  /// Step at which the current occurrence of `t` started (only while occurring).
  [[nodiscard]] std::int64_t startStep(TransitionId t) const { return start_step_[t]; }
  /// Number of transitions occurring now.
  [[nodiscard]] std::size_t occurringCount() const { return occurring_count_; }
  /// Number of transitions enabled now.
  [[nodiscard]] std::size_t enabledCount() const { return enabled_count_; }
  /// True when nothing occurs and nothing is enabled: without outside input the net is dead.
  [[nodiscard]] bool dead() const { return occurring_count_ == 0 && enabled_count_ == 0; }
  /// The model's random generator (all draws of a run come from it, in a fixed order).
  core::Random& random() { return random_; }
  /// The frozen net.
  [[nodiscard]] const Net& net() const { return *net_; }
  /// Approximate heap bytes of the changing state.
  [[nodiscard]] std::size_t memoryBytes() const;

 private:
  struct Hot {  // what firing needs of a transition, packed
    std::uint32_t terms_begin, inputs_end, conditions_end, terms_end;
    std::uint32_t rank;
    std::int32_t held;         // index in held_, -1 when no node slot passes through
    std::int64_t fixed_steps;  // -1 when the duration is drawn
    double probability;
  };
  struct Carry {  // an enabled transition that did not start (probability), kept in order
    std::uint64_t key;
    std::int64_t step;
  };

  bool holds(const Term& term) const;
  void update(PlaceSlotId ps);
  void markEnabled(TransitionId t);
  void begin(TransitionId t);
  void finish(TransitionId t);
  std::int64_t drawSteps(TransitionId t);

  std::shared_ptr<const Net> net_;
  const Term* terms_ = nullptr;
  double dt_;
  core::Random random_;
  std::int64_t step_ = 0;
  bool in_firing_ = false;

  std::vector<Hot> hot_;
  std::vector<std::int64_t> m_, r_, cap_;
  std::vector<std::int32_t> fifo_of_;            // place slot -> index in fifos_, -1 for control
  std::vector<std::deque<NodeRef>> fifos_;
  std::vector<std::uint8_t> holds_;              // per term
  std::vector<std::uint32_t> unsat_;             // per transition; +1 while occurring
  std::vector<std::int64_t> enabled_step_, considered_, start_step_, end_step_;
  std::vector<std::vector<std::pair<SlotId, NodeRef>>> held_;  // node tokens inside a transition
  std::size_t occurring_count_ = 0, enabled_count_ = 0;

  std::vector<std::uint64_t> fresh_, late_, late_now_, scratch_;  // keys: rank << 32 | t
  std::vector<Carry> carry_, carry_next_;
  std::vector<std::vector<TransitionId>> wheel_;  // completions, by end step modulo its size
  std::vector<TransitionId> due_;
  std::vector<NetObserver*> observers_;
};

}  // namespace gdpn::net
