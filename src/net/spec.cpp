#include "gdpn/net/spec.h"

#include <algorithm>

#include "gdpn/core/assert.h"

namespace gdpn::net {

SourceLoc SlotText::where(const SourceLoc& in_text) const {
  if (in_text.line < 1) return loc;
  std::size_t offset = 0;
  int line = 1;
  for (; line < in_text.line && offset < text.size(); ++line) {
    const auto nl = text.find('\n', offset);
    if (nl == std::string::npos) break;
    offset = nl + 1;
  }
  const auto column = static_cast<std::size_t>(std::max(in_text.column, 1) - 1);
  if (!layout.empty()) {
    const auto& [l, c] = layout[std::min(offset + column, layout.size() - 1)];
    return {loc.file, l, c};
  }
  // laid out from loc: the first line from its column, the others from their first column
  if (line == 1) return {loc.file, loc.line, loc.column + static_cast<int>(column)};
  return {loc.file, loc.line + line - 1, static_cast<int>(column) + 1};
}

const ScriptSpec& scriptOf(const SlotScripts& s, ScriptKind kind) {
  switch (kind) {
    case ScriptKind::OnDeposit: return s.on_deposit;
    case ScriptKind::OnRemove: return s.on_remove;
    case ScriptKind::OnEnter: return s.on_enter;
    case ScriptKind::OnExit: return s.on_exit;
    case ScriptKind::OnSample: return s.on_sample;
    case ScriptKind::OnChange: return s.on_change;
    case ScriptKind::Guard:
    case ScriptKind::PreFire:
    case ScriptKind::InFire:
    case ScriptKind::PostFire:
    case ScriptKind::Predicate:
    case ScriptKind::Condition:
    case ScriptKind::Globals: break;
  }
  GDPN_ASSERT(false, "a slot's script is asked for by a slot script kind");
  return s.on_deposit;
}

const ScriptSpec& scriptOf(const TransitionSpec& t, ScriptKind kind) {
  switch (kind) {
    case ScriptKind::Guard: return t.guard;
    case ScriptKind::PreFire: return t.pre_fire;
    case ScriptKind::InFire: return t.in_fire;
    case ScriptKind::PostFire: return t.post_fire;
    case ScriptKind::OnDeposit:
    case ScriptKind::OnRemove:
    case ScriptKind::OnEnter:
    case ScriptKind::OnExit:
    case ScriptKind::OnSample:
    case ScriptKind::OnChange:
    case ScriptKind::Predicate:
    case ScriptKind::Condition:
    case ScriptKind::Globals: break;
  }
  GDPN_ASSERT(false, "a transition's script is asked for by a transition script kind");
  return t.guard;
}

const char* fusionScopeName(FusionScope scope) {
  switch (scope) {
    case FusionScope::Global: return "global";
    case FusionScope::Instance: return "instance";
  }
  return "?";
}

std::optional<FusionScope> parseFusionScope(std::string_view word) {
  for (const FusionScope s : {FusionScope::Global, FusionScope::Instance}) {
    if (word == fusionScopeName(s)) return s;
  }
  return std::nullopt;
}

}  // namespace gdpn::net
