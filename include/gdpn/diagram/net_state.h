#pragma once
/// \file
/// What the net view shows of a running net: per place slot its kind, tokens and token
/// names; per transition whether it is idle, enabled, held back (its marking suffices, its
/// guard, a predicate or a condition does not) or occurring; per arc whether its condition
/// holds; per continuous place its amount and per continuous transition its rate (hybrid
/// nets: a flow is enabled while its effective rate is not 0, idle otherwise). Made from the kernel at its current time; plain data, so the IDE and the
/// CLI draw the same thing.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/diagram/layout.h"
#include "gdpn/net/kernel.h"

namespace gdpn::diagram {

/// The marking of one place slot.
struct SlotMarking {
  net::SlotId slot = net::kDefaultSlot;        ///< which slot
  net::SlotKind kind = net::SlotKind::Control; ///< control, node or sensor
  std::int64_t count = 0;                      ///< tokens (a sensor slot: 1, its variable)
  std::vector<std::string> names;              ///< node tokens' names, first to leave first
};

/// What a transition is doing, as the kernel last found it (net::Kernel::readiness()).
enum class Activity : std::uint8_t {
  Idle,       ///< neither enabled nor occurring: its marking or a capacity does not allow it
  Enabled,    ///< the last firing phase found it able to start (or nothing but its arcs can stop it)
  Waiting,    ///< its arcs allow it; no firing phase has tried its guard, predicates or draw yet
  HeldBack,   ///< its marking suffices, but its guard, a predicate, a condition or its draw held it back
  Occurring,  ///< started, not yet completed
};

/// The activity a transition in `readiness` shows when it is not occurring.
[[nodiscard]] Activity activityOf(net::Readiness readiness);

/// The state of one page's constructs, indexed as the PageSpec's vectors are.
struct NetState {
  double time = 0.0;                              ///< model time, seconds
  std::vector<std::vector<SlotMarking>> places;   ///< per place: its slots in use (empty slots left out)
  std::vector<Activity> transitions;              ///< per transition
  /// Per transition: why it can or cannot start (net::Readiness::Tokens for one the net lacks).
  std::vector<net::Readiness> readiness;
  std::vector<std::uint32_t> occurrences;         ///< per transition: its occurrences running now
  std::vector<std::optional<bool>> arcs;          ///< per arc of PageSpec::arcs: whether it holds (nullopt: unknown)
  /// Per place: a continuous place's amount now, in its unit (nullopt: a discrete place, or
  /// one the net lacks). Hybrid nets.
  std::vector<std::optional<double>> amounts{};
  /// Per place: a continuous place's capacity, in its unit (net::kNoBound: unbounded).
  std::vector<double> capacities{};
  /// Per transition: a continuous transition's effective rate now, units of its places per
  /// second (nullopt: a discrete transition, or one the net lacks). Hybrid nets.
  std::vector<std::optional<double>> flow_rates{};
};

/// Names a node token (the kernel knows only references).
using NodeNamer = std::function<std::string(net::NodeRef)>;

/// Where a page view's constructs are in a compiled net, found once by their qualified names
/// (`view.prefix` + "/" + name), so that their state can be read at every frame without a
/// name lookup. None where the net lacks one (a page type seen alone).
struct PageBinding {
  std::vector<std::optional<net::PlaceId>> places;            ///< per place of the page
  std::vector<std::optional<net::TransitionId>> transitions;  ///< per transition of the page
  /// An arc's transition and place, and which way it runs.
  struct Arc {
    std::optional<net::TransitionId> transition;  ///< its transition in the net
    std::optional<net::PlaceId> place;            ///< its place in the net
    bool output = false;                          ///< from the transition to the place
  };
  std::vector<Arc> arcs;  ///< per arc of PageSpec::arcs
};

/// Finds `view`'s constructs in `net`.
PageBinding bindPage(const net::Net& net, const PageView& view);

/// The state in `kernel` now of the constructs `binding` found (bindPage on kernel's net).
NetState netStateOf(const net::Kernel& kernel, const PageBinding& binding, const NodeNamer& names = {});

/// The state of `view`'s constructs in `kernel` now. Constructs are found by their qualified
/// names (`view.prefix` + "/" + name); those the net lacks (a page type seen alone) stay
/// empty and idle. An arc holds when every term it makes holds: inputs and tests have their
/// tokens, inhibitors are below their weight, outputs have room, conditions are true. Node
/// tokens are named by `names`, or by the net's initial node names when it is empty.
NetState netStateOf(const net::Kernel& kernel, const PageView& view, const NodeNamer& names = {});

}  // namespace gdpn::diagram
