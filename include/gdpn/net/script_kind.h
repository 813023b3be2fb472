#pragma once
/// \file
/// The kinds of script a net's constructs carry (semantics §8), described once: the model
/// file's key, the construct that owns it, whether it is an expression, and its place among
/// its owner's scripts. The loader, the writer, the compiler and the script engine all read
/// this one table.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace gdpn::net {

/// Each kind of script. Transition scripts come first, then slot scripts, each group in the
/// order of its owner's scripts (ScriptIndex).
enum class ScriptKind : std::uint8_t {
  Guard,      ///< transition: may it start? (expression)
  PreFire,    ///< transition: when an occurrence starts
  InFire,     ///< transition: every step while it occurs
  PostFire,   ///< transition: when an occurrence completes
  OnDeposit,  ///< place slot: per token deposited
  OnRemove,   ///< place slot: per token removed
  OnEnter,    ///< sensor slot: per item that entered a Region
  OnExit,     ///< sensor slot: per item that left a Region
  OnSample,   ///< sensor slot: every step while the sensor reports anything
  OnChange,   ///< sensor slot: when the sensor's value changes
  Predicate,  ///< arc: may this node token be taken? (expression)
  Condition,  ///< arc from a sensor slot: does the reading allow a start? (expression)
  Globals,    ///< the model's globals, run once
};

/// Which construct a script belongs to.
enum class ScriptOwner : std::uint8_t { Transition, PlaceSlot, Arc, Model };

/// The description of one script kind.
struct ScriptKindInfo {
  ScriptKind kind;          ///< the kind described
  std::string_view key;     ///< its key in the model file ("pre_fire"), and its name in messages
  ScriptOwner owner;        ///< the construct it belongs to
  bool expression;          ///< an expression whose value counts, rather than statements
  std::uint8_t position;    ///< its index among its owner's scripts
};

/// Every script kind, indexed by ScriptKind.
inline constexpr std::array<ScriptKindInfo, 13> kScriptKinds = {{
    {ScriptKind::Guard, "guard", ScriptOwner::Transition, true, 0},
    {ScriptKind::PreFire, "pre_fire", ScriptOwner::Transition, false, 1},
    {ScriptKind::InFire, "in_fire", ScriptOwner::Transition, false, 2},
    {ScriptKind::PostFire, "post_fire", ScriptOwner::Transition, false, 3},
    {ScriptKind::OnDeposit, "on_deposit", ScriptOwner::PlaceSlot, false, 0},
    {ScriptKind::OnRemove, "on_remove", ScriptOwner::PlaceSlot, false, 1},
    {ScriptKind::OnEnter, "on_enter", ScriptOwner::PlaceSlot, false, 2},
    {ScriptKind::OnExit, "on_exit", ScriptOwner::PlaceSlot, false, 3},
    {ScriptKind::OnSample, "on_sample", ScriptOwner::PlaceSlot, false, 4},
    {ScriptKind::OnChange, "on_change", ScriptOwner::PlaceSlot, false, 5},
    {ScriptKind::Predicate, "predicate", ScriptOwner::Arc, true, 0},
    {ScriptKind::Condition, "condition", ScriptOwner::Arc, true, 0},
    {ScriptKind::Globals, "globals", ScriptOwner::Model, false, 0},
}};

/// The description of `kind`.
constexpr const ScriptKindInfo& info(ScriptKind kind) { return kScriptKinds[static_cast<std::size_t>(kind)]; }

/// A transition's scripts, in ScriptIndex order.
inline constexpr std::array<ScriptKind, 4> kTransitionScripts = {ScriptKind::Guard, ScriptKind::PreFire,
                                                                 ScriptKind::InFire, ScriptKind::PostFire};
/// A place slot's scripts, in ScriptIndex order.
inline constexpr std::array<ScriptKind, 6> kSlotScripts = {ScriptKind::OnDeposit, ScriptKind::OnRemove,
                                                           ScriptKind::OnEnter,   ScriptKind::OnExit,
                                                           ScriptKind::OnSample,  ScriptKind::OnChange};

/// The kind whose key is `key` and whose owner is `owner`, or nullopt.
constexpr std::optional<ScriptKind> parseScriptKind(std::string_view key, ScriptOwner owner) {
  for (const auto& k : kScriptKinds) {
    if (k.key == key && k.owner == owner) return k.kind;
  }
  return std::nullopt;
}

static_assert([] {
  for (std::size_t i = 0; i < kScriptKinds.size(); ++i) {
    if (static_cast<std::size_t>(kScriptKinds[i].kind) != i) return false;
  }
  for (std::size_t i = 0; i < kTransitionScripts.size(); ++i) {
    if (info(kTransitionScripts[i]).position != i) return false;
  }
  for (std::size_t i = 0; i < kSlotScripts.size(); ++i) {
    if (info(kSlotScripts[i]).position != i) return false;
  }
  return true;
}(), "the script table is indexed by kind, and positions follow each owner's order");

}  // namespace gdpn::net
