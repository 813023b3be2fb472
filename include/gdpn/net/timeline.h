#pragma once
/// \file
/// What a run did over time, kept for plots (the HTML report): each occurrence's start and
/// completion, and each place's tokens after each change. Kept up to a budget of records, so
/// a long run of a large net costs bounded memory; what came later is counted, not kept.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "gdpn/net/observer.h"

namespace gdpn::net {

/// Records a kernel's occurrences and place tokens over steps; attach it with
/// Kernel::addObserver before the run starts.
class Timeline final : public NetObserver {
 public:
  /// One occurrence of a transition.
  struct Occurrence {
    TransitionId transition{0};  ///< which
    std::int64_t start = 0;       ///< step it started
    std::int64_t end = -1;        ///< step it completed (-1: still occurring when the run ended)
  };
  /// A place's tokens (all its slots) from a step on.
  struct Change {
    std::int64_t step = 0;    ///< from this step
    std::int64_t tokens = 0;  ///< the tokens after the step's changes
    friend bool operator==(const Change&, const Change&) = default;
  };

  /// Starts from the initial marking of `net` at step 0 and keeps at most `budget` records
  /// (occurrences and changes together; the initial tokens are not counted).
  explicit Timeline(const Net& net, std::size_t budget = kDefaultBudget);
  void onStart(TransitionId t, std::int64_t step) override;
  void onComplete(TransitionId t, std::int64_t step, std::int64_t started) override;
  void onRemove(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef> nodes, std::int64_t step) override;
  void onDeposit(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef> nodes, std::int64_t step) override;

  /// Every occurrence kept, in the order they started.
  [[nodiscard]] const std::vector<Occurrence>& occurrences() const { return occurrences_; }
  /// Per place (indexed like Net::places()), its tokens at step 0 and after each change kept;
  /// changes within one step are merged into one.
  [[nodiscard]] const std::vector<std::vector<Change>>& places() const { return places_; }
  /// The step from which records were no longer kept (-1: all were kept).
  [[nodiscard]] std::int64_t cutAt() const { return cut_at_; }
  /// Records the budget did not keep.
  [[nodiscard]] std::int64_t dropped() const { return dropped_; }

  /// Records kept by default: about 24 MB at most.
  static constexpr std::size_t kDefaultBudget = 1'000'000;

 private:
  bool keep(std::int64_t step);  // false (and counted) once the budget is spent
  void change(PlaceSlotId ps, std::int64_t delta, std::int64_t step);
  const Net& net_;
  std::size_t budget_;
  std::size_t kept_ = 0;
  std::int64_t cut_at_ = -1;
  std::int64_t dropped_ = 0;
  std::vector<Occurrence> occurrences_;
  std::vector<std::deque<std::size_t>> open_;  // per transition: occurrences kept, by start (closed ones until at the front)
  std::vector<std::int64_t> tokens_;           // per place: tokens now (kept or not)
  std::vector<std::vector<Change>> places_;
};

}  // namespace gdpn::net
