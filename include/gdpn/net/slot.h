#pragma once
/// \file
/// Slots: the named members of a colour set (semantics §2). Names follow the IDE's 4 x 8
/// grid, a row letter a-d and a column digit 0-7 ("a0" ... "d7").

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace gdpn::net {

/// Index of a slot, 0..31 ("a0" is 0, "a1" is 1, ..., "d7" is 31).
using SlotId = std::uint8_t;
/// Number of slots in a colour set.
inline constexpr int kSlotCount = 32;
/// The slot used when an arc, a marking or a capacity names none.
inline constexpr SlotId kDefaultSlot = 0;

/// What a slot holds.
enum class SlotKind : std::uint8_t {
  Control,  ///< a count of indistinguishable tokens
  Node,     ///< an ordered multiset of references to scene nodes (FIFO by arrival)
  Sensor,   ///< a variable bound to a sensor node
  Value,    ///< a multiset of values of a colour set (value tokens: semantics, *Value tokens*)
  Continuous,  ///< a continuous place's only slot (a0): a real amount (hybrid nets), kept apart from tokens
};

/// Parses "a0" ... "d7"; nullopt for anything else.
std::optional<SlotId> parseSlot(std::string_view name);
/// "a0" ... "d7".
std::string slotName(SlotId slot);
/// "control", "node", "sensor", "value" or "continuous".
const char* slotKindName(SlotKind kind);
/// Parses "control", "node", "sensor" or "value" (a place is made continuous otherwise: `continuous`).
std::optional<SlotKind> parseSlotKind(std::string_view name);

}  // namespace gdpn::net
