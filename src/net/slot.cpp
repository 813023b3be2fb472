#include "gdpn/net/slot.h"

namespace gdpn::net {

std::optional<SlotId> parseSlot(std::string_view name) {
  if (name.size() != 2) return std::nullopt;
  if (name[0] < 'a' || name[0] > 'd' || name[1] < '0' || name[1] > '7') return std::nullopt;
  return static_cast<SlotId>((name[0] - 'a') * 8 + (name[1] - '0'));
}

std::string slotName(SlotId slot) {
  return {static_cast<char>('a' + slot / 8), static_cast<char>('0' + slot % 8)};
}

const char* slotKindName(SlotKind kind) {
  switch (kind) {
    case SlotKind::Control: return "control";
    case SlotKind::Node: return "node";
    case SlotKind::Sensor: return "sensor";
    case SlotKind::Value: return "value";
    case SlotKind::Continuous: return "continuous";
  }
  return "?";
}

std::optional<SlotKind> parseSlotKind(std::string_view name) {
  if (name == "control") return SlotKind::Control;
  if (name == "node") return SlotKind::Node;
  if (name == "sensor") return SlotKind::Sensor;
  if (name == "value") return SlotKind::Value;
  return std::nullopt;
}

}  // namespace gdpn::net
