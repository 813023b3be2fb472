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
  /// Makes room for `places` places (with about one slot each), `transitions` transitions and
  /// `terms` arc terms, so that building a large net does not move what it has built.
  void reserve(std::size_t places, std::size_t transitions, std::size_t terms);
  /// Adds a place called `name` (qualified: its scope is the part before the last '/');
  /// its slots are made by setSlot() or by arcs.
  PlaceId addPlace(std::string name, SourceLoc loc = {});
  /// Adds place `local` of the table of `scope` (made with names()); compile() uses this, so
  /// that a page type's names and locations are stored once for all its instances.
  PlaceId addScopedPlace(std::uint32_t scope, std::uint32_t local);
  /// Sets the kind, capacity and initial marking of one slot of `place`.
  void setSlot(PlaceId place, SlotId slot, SlotKind kind, std::int64_t capacity,
               std::int64_t initial);
  /// Sets the initial node tokens of node slot `slot` of `place` (FIFO order); makes it a node slot.
  void setNodes(PlaceId place, SlotId slot, const std::vector<std::string>& nodes);
  /// Adds a transition called `name` (qualified, as for addPlace); `duration` in seconds.
  TransitionId addTransition(std::string name, const Duration& duration = {}, std::int64_t priority = 0,
                             double probability = 1.0, SourceLoc loc = {});
  /// Adds transition `local` of the table of `scope` (made with names()); `duration` in seconds.
  TransitionId addScopedTransition(std::uint32_t scope, std::uint32_t local, const DurationLaw& duration,
                                   std::int64_t priority, double probability);
  /// The tables and scopes of the net being built: compile() adds a table per page type and a
  /// scope per instantiated page here before adding their places and transitions.
  [[nodiscard]] Names& names() { return names_; }
  /// Adds an input arc term: place -> transition at `slot`.
  void addInput(PlaceId place, TransitionId transition, SlotId slot = kDefaultSlot,
                std::int32_t weight = 1, ArcKind kind = ArcKind::Normal);
  /// Adds an output arc term: transition -> place at `slot`.
  void addOutput(TransitionId transition, PlaceId place, SlotId slot = kDefaultSlot,
                 std::int32_t weight = 1);
  /// Adds a script and returns its index for the set*Script calls.
  std::int32_t addScript(ScriptSpec script);
  /// Lets `servers` occurrences of transition `t` run at once (0, kUnlimitedServers: any number).
  void setServers(TransitionId t, std::uint32_t servers);
  /// Gives transition `t` script `index` as its script of kind `kind` (one of kTransitionScripts).
  void setTransitionScript(TransitionId t, ScriptKind kind, std::int32_t index);
  /// Gives slot `slot` of `place` script `index` as its script of kind `kind` (one of kSlotScripts).
  void setSlotScript(PlaceId place, SlotId slot, ScriptKind kind, std::int32_t index);
  /// Makes slot `slot` of `place` a sensor slot reading the sensor at `path`.
  void setSensor(PlaceId place, SlotId slot, std::string path);
  /// Makes slot `slot` of `place` a value slot of set `set` holding `initial` (its count is
  /// the multiset's size).
  void setValues(PlaceId place, SlotId slot, ColourId set, Multiset initial);
  /// Gives the net value tokens: `colouring` without its per-slot parts (slot_set, initial),
  /// which freeze() fills from setValues, and without arc_terms, which freeze() fills from
  /// `arcs`: per coloured transition, per arc, the index among the terms added for the
  /// transition (addInput, addOutput, addCondition, in the order added) of the arc's term.
  void setColouring(Colouring colouring, std::vector<std::vector<std::uint32_t>> arcs);
  /// Adds a condition term: the transition may start only while script `index` (an
  /// expression over the sensor slot `slot` of `place`) is true.
  void addCondition(PlaceId place, TransitionId transition, SlotId slot, std::int32_t index);
  /// Adds a term of discrete transition `transition` on continuous place `place` (its slot a0):
  /// a condition the amount decides. Returns its number among the arcs added (for setFluid).
  std::uint32_t addFluidTerm(PlaceId place, TransitionId transition);
  /// Gives the net a continuous part: `fluid` without its `terms[k].term` and `of_term`, which
  /// freeze() fills, `fluid_arcs[k]` being what addFluidTerm returned for terms[k].
  void setFluid(Fluid fluid, std::vector<std::uint32_t> fluid_arcs);
  /// Gives the most recently added arc term a predicate, script `index`.
  void setLastPredicate(std::int32_t index);
  /// Marks script `index` as the model's globals.
  void setGlobalsScript(std::int32_t index) { globals_script_ = index; }
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
    std::array<std::int32_t, 6> scripts{-1, -1, -1, -1, -1, -1};
    std::int32_t nodes = -1;       // its initial node tokens in nodes_, if it has any
    std::int32_t sensor = -1;      // its sensor's path in sensors_, if it reads one
    std::int32_t set = -1;         // a value slot's colour set
    std::int32_t values = -1;      // its initial values in values_
    std::uint32_t next = kNoSlot;  // the place's next slot in slots_
  };
  static constexpr std::uint32_t kNoSlot = 0xffffffffu;
  struct BuildArc {
    PlaceId place;
    TransitionId transition;
    SlotId slot;
    TermKind kind;
    std::int32_t weight;
    std::int32_t predicate = -1;
  };
  BuildSlot& slotOf(PlaceId place, SlotId slot);

  Names names_;                             // moved into the Net, with its indexes built
  std::vector<Place> places_;               // moved into the Net as they are
  std::vector<std::uint32_t> first_slot_;  // per place: its first slot in slots_ (a chain, no vector per place)
  std::vector<BuildSlot> slots_;
  std::vector<std::vector<std::uint32_t>> nodes_;  // node slots' initial tokens (few slots have them)
  std::vector<std::string> sensors_;               // sensor slots' paths
  std::vector<Transition> transitions_;
  std::vector<BuildArc> arcs_;
  std::vector<std::string> node_names_;
  std::unordered_map<std::string, std::uint32_t> node_index_;
  std::vector<ScriptSpec> scripts_;
  std::vector<std::array<std::int32_t, 4>> transition_scripts_;
  std::int32_t globals_script_ = -1;
  std::vector<Multiset> values_;                          // value slots' initial values
  std::optional<Colouring> colouring_;                    // see setColouring
  std::vector<std::vector<std::uint32_t>> colour_arcs_;   // see setColouring
  std::optional<Fluid> fluid_;                            // see setFluid
  std::vector<std::uint32_t> fluid_arcs_;                 // see setFluid
};

}  // namespace gdpn::net
