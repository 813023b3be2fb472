#pragma once
/// \file
/// Run statistics gathered from kernel events (semantics §10): per transition, occurrences,
/// cycle times and utilisation; per place, mean and max tokens and throughput. All counts are
/// kept in integer steps, so cycle times of whole-step durations come out exact.

#include <cstdint>
#include <vector>

#include "gdpn/net/observer.h"

namespace gdpn::net {

/// Figures of one transition over a run.
struct alignas(64) TransitionStats {
  std::int64_t starts = 0;        ///< occurrences started
  std::int64_t cycle_sum = 0;     ///< sum of the intervals between successive starts, steps
  std::int64_t cycle_min = 0;     ///< shortest interval, steps (0 when no cycle)
  std::int64_t cycle_max = 0;     ///< longest interval, steps
  std::int64_t busy = 0;          ///< steps spent occurring, summed over its occurrences
  std::int64_t last_start = -1;   ///< step of the latest start, -1 if none
  std::int64_t running = 0;       ///< occurrences started and not completed
  std::int64_t running_starts = 0;///< sum of their start steps
  /// Intervals measured between successive starts: one fewer than the starts.
  [[nodiscard]] std::int64_t cycles() const { return starts > 0 ? starts - 1 : 0; }
};

/// Figures of one place (all its slots together) over a run.
struct PlaceStats {
  std::int64_t tokens = 0;      ///< tokens now
  std::int64_t max = 0;         ///< most tokens at any time
  std::int64_t area = 0;        ///< integral of tokens over steps (for the mean)
  std::int64_t deposited = 0;   ///< tokens deposited (for throughput)
  std::int64_t since = 0;       ///< step of the last change
};

/// Collects TransitionStats and PlaceStats from a kernel it observes.
class StatsCollector : public NetObserver {
 public:
  /// Starts counting from the initial marking of `net` at step 0.
  explicit StatsCollector(const Net& net);
  void onStart(TransitionId t, std::int64_t step) override;
  void onComplete(TransitionId t, std::int64_t step, std::int64_t started) override;
  void onRemove(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef> nodes, std::int64_t step) override;
  void onDeposit(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef> nodes, std::int64_t step) override;

  /// Closes the books at `step`: areas are integrated up to it and running occurrences
  /// count as busy up to it. Call once, at the end of the run.
  void finish(std::int64_t step);
  /// Per transition, indexed like Net::transitions().
  [[nodiscard]] const std::vector<TransitionStats>& transitions() const { return transitions_; }
  /// Per place, indexed like Net::places().
  [[nodiscard]] const std::vector<PlaceStats>& places() const { return places_; }

 private:
  void change(PlaceId p, std::int64_t delta, std::int64_t step);
  // what a firing touches, each in one place: a transition's figures fill one cache line, and
  // the place of each slot is read from an array of its own (not from the net's slots)
  std::vector<TransitionStats> transitions_;
  std::vector<PlaceStats> places_;
  std::vector<PlaceId> place_of_;  // per place slot
};

}  // namespace gdpn::net
