#pragma once
/// \file
/// The kernel reports what happens through this interface; the trace, the statistics and
/// (later) scripts subscribe. Nobody listening costs one branch per event.

#include <cstdint>
#include <span>

#include "gdpn/net/net.h"

namespace gdpn::net {

/// Receives the kernel's events in the order they happen. Steps are the kernel's integer
/// clock; the time in seconds is step * dt.
class NetObserver {
 public:
  virtual ~NetObserver() = default;
  /// `t` starts at `step`; its removals follow.
  virtual void onStart(TransitionId t, std::int64_t step) { (void)t, (void)step; }
  /// An occurrence of `t` that started at step `started` completes at `step`; its deposits
  /// follow. (With servers, occurrences of one transition may complete in another order than
  /// they started: `started` tells which one this is.)
  virtual void onComplete(TransitionId t, std::int64_t step, std::int64_t started) { (void)t, (void)step, (void)started; }
  /// `count` tokens left place slot `ps` (the node tokens, for a node slot).
  virtual void onRemove(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef> nodes,
                        std::int64_t step) {
    (void)ps, (void)count, (void)nodes, (void)step;
  }
  /// `count` tokens arrived on place slot `ps` (the node tokens, for a node slot).
  virtual void onDeposit(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef> nodes,
                         std::int64_t step) {
    (void)ps, (void)count, (void)nodes, (void)step;
  }
  /// The occurrence of `t` whose onStart came just before occurs in binding `b` (its values of
  /// the transition's variables, Colouring::transitions' order); only for a transition with
  /// variables, before its removals.
  virtual void onBinding(TransitionId t, const Binding& b, std::int64_t step) { (void)t, (void)b, (void)step; }
  /// The onRemove (`deposited` false) or onDeposit just before, on value slot `ps`, moved
  /// `values`.
  virtual void onValues(PlaceSlotId ps, const Multiset& values, bool deposited, std::int64_t step) {
    (void)ps, (void)values, (void)deposited, (void)step;
  }
  /// An amount `moved` (> 0) left (`deposited` false) or arrived on continuous place `p`, in
  /// one jump: a start's take, a completion's put, or a set; it holds `now` after it.
  virtual void onAmount(PlaceId p, double moved, bool deposited, double now, std::int64_t step) {
    (void)p, (void)moved, (void)deposited, (void)now, (void)step;
  }
  /// Continuous place `p` crossed (or reached) `level` at `time` seconds, within the step
  /// ending at `step`: from below when `rising`. Levels are 0, its capacity and its arcs' thresholds.
  virtual void onCross(PlaceId p, double level, double time, bool rising, std::int64_t step) {
    (void)p, (void)level, (void)time, (void)rising, (void)step;
  }
};

}  // namespace gdpn::net
