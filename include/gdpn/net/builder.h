#pragma once
/// \file
/// NetBuilder: the low-level way to make a flat Net. `compile()` uses it after checking a
/// NetSpec; tests and benchmarks use it directly to build large nets quickly. It checks
/// nothing about the semantics: give it a net that `compile()` would accept.

#include <memory>
#include <string>
#include <vector>

#include "gdpn/net/net.h"

namespace gdpn::net {

/// Collects places, transitions and arcs, then freezes them into a Net.
class NetBuilder {
 public:
  /// Adds a place; its slots are made by setSlot() or by arcs.
  PlaceId addPlace(std::string name, SourceLoc loc = {});
  /// Sets the kind, capacity and initial marking of one slot of `place`.
  void setSlot(PlaceId place, SlotId slot, SlotKind kind, std::int64_t capacity,
               std::int64_t initial);
  /// Sets the initial node tokens of node slot `slot` of `place` (FIFO order); makes it a node slot.
  void setNodes(PlaceId place, SlotId slot, const std::vector<std::string>& nodes);
  /// Adds a transition; `duration` in seconds.
  TransitionId addTransition(std::string name, Duration duration = {}, std::int64_t priority = 0,
                             double probability = 1.0, SourceLoc loc = {});
  /// Adds an input arc term: place -> transition at `slot`.
  void addInput(PlaceId place, TransitionId transition, SlotId slot = kDefaultSlot,
                std::int32_t weight = 1, ArcKind kind = ArcKind::Normal);
  /// Adds an output arc term: transition -> place at `slot`.
  void addOutput(TransitionId transition, PlaceId place, SlotId slot = kDefaultSlot,
                 std::int32_t weight = 1);
  /// Number of places added so far.
  [[nodiscard]] std::size_t placeCount() const { return places_.size(); }
  /// Freezes everything into an immutable Net. The builder is left empty.
  std::shared_ptr<const Net> freeze();

 private:
  struct BuildSlot {
    SlotId slot = kDefaultSlot;
    SlotKind kind = SlotKind::Control;
    std::int64_t capacity = kUnbounded;
    std::int64_t initial = 0;
    std::vector<std::uint32_t> nodes;
  };
  struct BuildPlace {
    std::string name;
    SourceLoc loc;
    std::vector<BuildSlot> slots;
  };
  struct BuildArc {
    PlaceId place;
    TransitionId transition;
    SlotId slot;
    TermKind kind;
    std::int32_t weight;
  };
  BuildSlot& slotOf(PlaceId place, SlotId slot);

  std::vector<BuildPlace> places_;
  std::vector<Transition> transitions_;
  std::vector<BuildArc> arcs_;
  std::vector<std::string> node_names_;
  std::unordered_map<std::string, std::uint32_t> node_index_;
};

}  // namespace gdpn::net
