#pragma once
/// \file
/// The frozen net: places, transitions and arcs flattened (hierarchy resolved) into
/// contiguous arrays indexed by integers. Built once by `compile()`, shared read-only.

#include <array>
#include <memory>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/colouring.h"
#include "gdpn/net/fluid.h"
#include "gdpn/net/id.h"
#include "gdpn/net/names.h"
#include "gdpn/net/slot.h"
#include "gdpn/net/spec.h"

namespace gdpn::net {

using NodeRef = std::uint64_t;       ///< an opaque reference to a scene node; the kernel never looks inside

/// Capacity of a slot that has none.
inline constexpr std::int64_t kUnbounded = std::numeric_limits<std::int64_t>::max();

/// What one (arc, slot) pair asks of its place slot.
enum class TermKind : std::uint8_t {
  Input,      ///< normal input: needs `weight` tokens and takes them
  Test,       ///< test input: needs `weight` tokens
  Inhibitor,  ///< needs fewer than `weight` tokens
  Output,     ///< needs room for `weight` tokens, deposits them on completion
  Condition,  ///< a sensor condition: holds while its expression is true (set from outside)
};

/// The largest arc weight, tokens (weights are 32-bit to keep terms small).
inline constexpr std::int64_t kMaxWeight = std::numeric_limits<std::int32_t>::max();

/// One (arc, slot) pair: the unit of incremental enabling. 20 bytes.
struct Term {
  TransitionId transition;      ///< the arc's transition
  PlaceSlotId place_slot;       ///< the arc's place, at this slot
  std::int32_t weight = 1;      ///< tokens, 1..kMaxWeight
  std::int32_t take = 0;        ///< for outputs: what the transition itself takes from this place slot
  TermKind kind = TermKind::Input;  ///< what the term asks of its place slot
  bool predicate = false;       ///< only tokens its predicate accepts count (node slots)
};

/// Bits of Transition::scripts.
enum TransitionScript : std::uint8_t { kGuard = 1, kPreFire = 2, kInFire = 4, kPostFire = 8 };
/// Bits of PlaceSlot::scripts.
enum SlotScript : std::uint8_t { kOnDeposit = 1, kOnRemove = 2, kOnEnter = 4, kOnExit = 8, kOnSample = 16, kOnChange = 32 };

/// Where each scripted construct's scripts are, as indices into Net::scripts() (-1: none).
struct ScriptIndex {
  std::vector<std::array<std::int32_t, 4>> transitions;  ///< guard, pre_fire, in_fire, post_fire
  std::vector<std::array<std::int32_t, 6>> slots;  ///< on_deposit, on_remove, on_enter, on_exit, on_sample, on_change
  std::vector<std::int32_t> predicates;            ///< per term: its predicate or condition
};

/// One slot of one place.
struct PlaceSlot {
  PlaceId place;                        ///< owning place
  SlotId slot = kDefaultSlot;           ///< which slot
  SlotKind kind = SlotKind::Control;    ///< control or node
  std::int64_t capacity = kUnbounded;   ///< tokens; kUnbounded when none
  std::int64_t initial = 0;             ///< initial marking count
  std::uint32_t nodes_begin = 0;        ///< initial node tokens: range in Net::initialNodes()
  std::uint32_t nodes_end = 0;          ///< end of that range
  std::uint8_t scripts = 0;             ///< SlotScript bits
};

/// A place after flattening. Its name and location are Net::placeName() and Net::placeLoc().
struct Place {
  std::uint32_t slots_begin = 0;  ///< its place slots: range in Net::placeSlots()
  std::uint32_t slots_end = 0;    ///< end of that range
  std::uint32_t scope = 0;        ///< the instantiated page it belongs to (Net::names())
  std::uint32_t local = 0;        ///< its index in that page's ConstructTable
};

/// A transition after flattening. Its terms lie in Net::terms() in the order: normal inputs,
/// tests and inhibitors, outputs. Its name and location are Net::transitionName() and
/// Net::transitionLoc().
struct Transition {
  std::uint32_t scope = 0;         ///< the instantiated page it belongs to (Net::names())
  std::uint32_t local = 0;         ///< its index in that page's ConstructTable
  DurationLaw duration;            ///< seconds
  std::int64_t priority = 0;       ///< higher first
  std::uint32_t priority_rank = 0; ///< 0 for the highest priority in the net, dense
  double probability = 1.0;        ///< chance to start in a step while enabled
  std::uint32_t servers = 1;       ///< occurrences at once; 0 (kUnlimitedServers) for no limit
  std::uint32_t terms_begin = 0;   ///< first term
  std::uint32_t inputs_end = 0;    ///< end of the normal inputs
  std::uint32_t conditions_end = 0;///< end of the tests and inhibitors
  std::uint32_t terms_end = 0;     ///< end of the outputs
  std::uint32_t node_slot_mask = 0;///< bit s set when slot s is a node slot on this transition
  std::uint8_t scripts = 0;        ///< TransitionScript bits
};

/// The frozen, flat net. Immutable after `compile()`; share it with `std::shared_ptr<const Net>`.
class Net {
 public:
  /// All places, in declaration order (pages first, instances expanded in place).
  [[nodiscard]] std::span<const Place> places() const { return places_; }
  /// All transitions, in declaration order; this order breaks ties when firing.
  [[nodiscard]] std::span<const Transition> transitions() const { return transitions_; }
  /// All (place, slot) pairs.
  [[nodiscard]] std::span<const PlaceSlot> placeSlots() const { return place_slots_; }
  /// The ids of all places, 0..places().size()-1.
  [[nodiscard]] IdRange<PlaceId> placeIds() const { return IdRange<PlaceId>(places_.size()); }
  /// The ids of all transitions, in their order.
  [[nodiscard]] IdRange<TransitionId> transitionIds() const { return IdRange<TransitionId>(transitions_.size()); }
  /// The ids of all place slots.
  [[nodiscard]] IdRange<PlaceSlotId> placeSlotIds() const { return IdRange<PlaceSlotId>(place_slots_.size()); }
  /// The ids of place `p`'s slots, in slot order.
  [[nodiscard]] IdRange<PlaceSlotId> placeSlotsOf(PlaceId p) const {
    return {places_[p].slots_begin, places_[p].slots_end};
  }
  /// All (arc, slot) conditions, grouped by transition.
  [[nodiscard]] std::span<const Term> terms() const { return terms_; }
  /// The terms of transition `t`.
  [[nodiscard]] std::span<const Term> termsOf(TransitionId t) const {
    const auto& tr = transitions_[t];
    return {terms_.data() + tr.terms_begin, tr.terms_end - tr.terms_begin};
  }
  /// The ids of the terms whose satisfaction depends on place slot `ps` (its watchers).
  [[nodiscard]] std::span<const TermId> watchers(PlaceSlotId ps) const {
    return {watchers_.data() + watch_begin_[ps], watch_begin_[ps + 1] - watch_begin_[ps]};
  }
  /// Names of the node tokens in initial markings; a NodeRef in a fresh kernel is an index here.
  [[nodiscard]] std::span<const std::string> nodeNames() const { return node_names_; }
  /// Indices into nodeNames(), referenced by PlaceSlot::nodes_begin/nodes_end.
  [[nodiscard]] std::span<const std::uint32_t> initialNodes() const { return initial_nodes_; }

  /// The qualified name of place `p` ("line/cellA/buffer"), built on request.
  [[nodiscard]] std::string placeName(PlaceId p) const;
  /// The qualified name of transition `t`, built on request.
  [[nodiscard]] std::string transitionName(TransitionId t) const;
  /// Appends the qualified name of place `p` to `out` (for loops that write many names).
  void appendPlaceName(std::string& out, PlaceId p) const;
  /// Appends the qualified name of transition `t` to `out`.
  void appendTransitionName(std::string& out, TransitionId t) const;
  /// The last part of place `p`'s qualified name ("buffer"), as declared in its page.
  [[nodiscard]] std::string_view placeLocalName(PlaceId p) const {
    return names_.table(names_.scope(places_[p].scope).table).places[places_[p].local];
  }
  /// The last part of transition `t`'s qualified name, as declared in its page.
  [[nodiscard]] std::string_view transitionLocalName(TransitionId t) const {
    return names_.table(names_.scope(transitions_[t].scope).table).transitions[transitions_[t].local];
  }
  /// Where place `p` was declared (its page type's declaration, for every instance).
  [[nodiscard]] const SourceLoc& placeLoc(PlaceId p) const {
    return names_.table(names_.scope(places_[p].scope).table).place_locs[places_[p].local];
  }
  /// Where transition `t` was declared (its page type's declaration, for every instance).
  [[nodiscard]] const SourceLoc& transitionLoc(TransitionId t) const {
    return names_.table(names_.scope(transitions_[t].scope).table).transition_locs[transitions_[t].local];
  }
  /// The tables of local names and locations, and the scopes (instantiated pages).
  [[nodiscard]] const Names& names() const { return names_; }
  /// The place called `qualified_name`, if there is one.
  [[nodiscard]] std::optional<PlaceId> findPlace(std::string_view qualified_name) const {
    return names_.findPlace(qualified_name);
  }
  /// The transition called `qualified_name`, if there is one.
  [[nodiscard]] std::optional<TransitionId> findTransition(std::string_view qualified_name) const {
    return names_.findTransition(qualified_name);
  }
  /// The place slot of `place` at `slot`; none when the place does not use that slot.
  [[nodiscard]] std::optional<PlaceSlotId> findPlaceSlot(PlaceId place, SlotId slot) const;
  /// The number of distinct priorities (ranks run 0..count-1).
  [[nodiscard]] std::uint32_t priorityLevels() const { return priority_levels_; }
  /// The distinct scripts of the net (a page type's scripts appear once for all its instances),
  /// followed by the model's globals script when there is one.
  [[nodiscard]] std::span<const ScriptSpec> scripts() const { return scripts_; }
  /// Which scripts each construct has; empty vectors when the net has no scripts.
  [[nodiscard]] const ScriptIndex& scriptIndex() const { return script_index_; }
  /// The sensor path a sensor slot reads ("" for other slots), per place slot.
  [[nodiscard]] const std::string& sensorPath(PlaceSlotId ps) const {
    static const std::string none;
    return ps < sensor_paths_.size() ? sensor_paths_[ps] : none;
  }
  /// The index of the globals script in scripts(), or -1.
  [[nodiscard]] std::int32_t globalsScript() const { return globals_script_; }
  /// True when any construct has a script.
  [[nodiscard]] bool scripted() const { return !scripts_.empty(); }
  /// Its value tokens: colour sets, value slots, coloured transitions; null when it has none.
  [[nodiscard]] const Colouring* colouring() const { return colouring_.get(); }
  /// Its continuous part (hybrid nets): continuous places and transitions; null when it has none.
  [[nodiscard]] const Fluid* fluid() const { return fluid_.get(); }
  /// True when transition `t` is continuous: it flows, and never fires.
  [[nodiscard]] bool continuous(TransitionId t) const { return fluid_ && fluid_->continuous(t); }
  /// True when place `p` is continuous: it holds an amount, not tokens.
  [[nodiscard]] bool continuousPlace(PlaceId p) const { return fluid_ && fluid_->of_place[p] >= 0; }
  /// True when its arc terms' weights are the tokens every occurrence moves (always, but for a
  /// value inscription whose size depends on the binding: Colouring::counts_exact).
  [[nodiscard]] bool countsExact() const { return !colouring_ || colouring_->counts_exact; }
  /// Approximate heap bytes held by this net.
  [[nodiscard]] std::size_t memoryBytes() const;

 private:
  friend class NetBuilder;
  std::vector<Place> places_;
  std::vector<Transition> transitions_;
  std::vector<PlaceSlot> place_slots_;
  std::vector<Term> terms_;
  std::vector<std::uint32_t> watch_begin_;
  std::vector<TermId> watchers_;
  std::vector<std::string> node_names_;
  std::vector<std::uint32_t> initial_nodes_;
  Names names_;  // names and locations, per page type, and the scopes that use them
  std::uint32_t priority_levels_ = 1;
  std::vector<ScriptSpec> scripts_;
  ScriptIndex script_index_;
  std::int32_t globals_script_ = -1;
  std::vector<std::string> sensor_paths_;
  std::shared_ptr<const Colouring> colouring_;
  std::shared_ptr<const Fluid> fluid_;
};

}  // namespace gdpn::net
