#pragma once
/// \file
/// Round trips of one token through a state machine with choices (a station that either skips
/// a box or works on it), recorded while the net runs: each path the token took from its home
/// place and back, how often, and how long each took.

#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include "gdpn/net/net.h"
#include "gdpn/net/observer.h"

namespace gdpn::net {

/// Watches tokens' round trips; attach it to a kernel (Kernel::addObserver) before the run.
class RoundTrips final : public NetObserver {
 public:
  /// One path a token took, start to start.
  struct Circuit {
    std::vector<TransitionId> transitions;  ///< in the order they started; the first takes the token from home
    std::int64_t trips = 0;                 ///< times it was taken
    std::int64_t steps = 0;                 ///< kernel steps spent on it in all, each from the trip's first start to the next trip's
  };

  /// The longest trip kept (transitions); a longer one is counted in overlong() instead.
  static constexpr std::size_t kMostTransitions = 1000;
  /// The most distinct circuits kept per watch; trips on further ones are counted in overlong().
  static constexpr std::size_t kMostCircuits = 64;

  /// Ready for a net of `transitions` transitions.
  explicit RoundTrips(std::size_t transitions) : of_(transitions) {}

  /// Watches the token of `net` that leaves place slot `home` through `transitions` (those
  /// taking from the invariant that carries it): a trip begins each time a transition takes
  /// from `home` and ends when the next one does. Returns the watch's index.
  std::size_t watch(const Net& net, PlaceSlotId home, std::span<const TransitionId> transitions);

  void onStart(TransitionId t, std::int64_t step) override;

  /// The circuits watch `w` saw completed, in the order each was first completed.
  [[nodiscard]] const std::vector<Circuit>& circuits(std::size_t w) const { return watches_[w].seen; }
  /// Trips of watch `w` not kept: longer than kMostTransitions, or past kMostCircuits circuits.
  [[nodiscard]] std::int64_t overlong(std::size_t w) const { return watches_[w].overlong; }

 private:
  struct Watch {
    std::vector<TransitionId> current;  // the trip under way
    bool too_long = false;              // it passed kMostTransitions
    std::int64_t departed = -1;         // the step it began (-1: none yet)
    std::vector<Circuit> seen;
    std::map<std::vector<TransitionId>, std::size_t> index;  // a circuit's place in `seen`
    std::int64_t overlong = 0;
  };
  struct Role {
    std::uint32_t watch;
    bool leaves_home;
  };
  std::vector<Watch> watches_;
  std::vector<std::vector<Role>> of_;  // per transition, the watches it belongs to
};

}  // namespace gdpn::net
