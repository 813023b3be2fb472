// Node types propagated along the arcs, slot by slot, and the scripts checked against them.

#include "gdpn/ide/token_types.h"

#include <algorithm>
#include <deque>
#include <regex>

namespace gdpn::ide {

namespace {

/// The slots an arc carries: its weights' slots (a0 when it has none).
std::vector<net::SlotId> slotsOf(const net::ArcSpec& a) {
  std::vector<net::SlotId> out;
  for (const auto& w : a.weights) out.push_back(w.slot);
  if (out.empty()) out.push_back(net::kDefaultSlot);
  return out;
}

/// What every node offers a script besides its fields (the node view's methods and properties).
bool nodeApi(const std::string& name) {
  static const std::set<std::string> kApi = {
      "add_force", "attach", "children", "delete", "detach", "find", "name", "next", "parent", "path",
      "position", "prev", "rotation", "set_force", "set_torque", "set_velocity", "spawn", "type", "velocity",
      "angle", "items", "hit", "value", "ref", "active", "distance", "vector", "reading"};
  return kApi.count(name) > 0;
}

/// Flags the uses `pattern` finds in `code` (group 1 the slot, group 2 the field) whose field no
/// type of that slot has.
void checkUses(const std::string& code, const std::regex& pattern, const std::function<const std::set<std::string>*(const std::string&)>& typesOfSlot,
               const std::function<const scene::NodeType*(const std::string&)>& typeNamed, const std::string& construct,
               const std::string& script, std::vector<TokenTypes::UnknownField>& out) {
  int line = 1;
  std::size_t start = 0;
  while (start <= code.size()) {
    const auto end = code.find('\n', start);
    const std::string text = code.substr(start, end == std::string::npos ? std::string::npos : end - start);
    for (std::sregex_iterator it(text.begin(), text.end(), pattern), none; it != none; ++it) {
      const std::string slot = (*it)[1], field = (*it)[2];
      const auto* types = typesOfSlot(slot);
      if (types == nullptr || types->empty() || nodeApi(field)) continue;
      const bool known = std::any_of(types->begin(), types->end(), [&](const std::string& t) {
        const auto* type = typeNamed(t);
        return type == nullptr || type->fieldIndex(field) >= 0;
      });
      if (known) continue;
      std::string names;
      for (const auto& t : *types) names += (names.empty() ? "" : " or ") + t;
      out.push_back({construct, script, line, (*it)[0], "a " + names + " has no field or method '" + field + "'"});
    }
    if (end == std::string::npos) break;
    start = end + 1;
    ++line;
  }
}

}  // namespace

TokenTypes propagateTokenTypes(const net::NetSpec& net, const NodeTypeOf& typeOf) {
  TokenTypes out;
  std::map<std::string, const scene::NodeType*> named;  // the types met, by name
  for (const auto* list : {&net.pages, &net.page_types}) {
    for (const auto& page : *list) {
      const auto key = [&](const std::string& name, net::SlotId s) { return SlotKey{page.name + "/" + name, s}; };
      // the initial node tokens
      for (const auto& p : page.places) {
        for (const auto& slot : p.nodes) {
          for (const auto& path : slot.nodes) {
            if (const auto* type = typeOf(page.name, path)) {
              out.types[key(p.name, slot.slot)].insert(type->name);
              named[type->name] = type;
            }
          }
        }
      }
      // along the arcs: input place slot -> transition slot -> output place slot; a slot goes
      // back on the work list only when its set grew, so the cost is arcs times types, not
      // arcs times the length of the longest path
      std::map<SlotKey, std::vector<SlotKey>> next;
      for (const auto& a : page.arcs) {
        if (a.kind != net::ArcKind::Normal) continue;  // a test or inhibitor arc moves no token
        for (const auto s : slotsOf(a)) next[key(a.from, s)].push_back(key(a.to, s));
      }
      std::deque<SlotKey> work;
      for (const auto& [slot, types] : out.types) {
        if (slot.first.starts_with(page.name + "/")) work.push_back(slot);
      }
      while (!work.empty()) {
        const SlotKey at = work.front();
        work.pop_front();
        const auto edges = next.find(at);
        if (edges == next.end()) continue;
        const auto& types = out.types[at];  // a map's elements stay where they are as it grows
        for (const auto& to : edges->second) {
          if (to == at) continue;
          auto& into = out.types[to];
          const auto before = into.size();
          into.insert(types.begin(), types.end());
          if (into.size() != before) work.push_back(to);
        }
      }
      // conflicts: a place slot two types reach
      for (const auto& p : page.places) {
        for (int i = 0; i < net::kSlotCount; ++i) {
          const auto s = static_cast<net::SlotId>(i);
          const auto it = out.types.find(key(p.name, s));
          if (it == out.types.end() || it->second.size() < 2) continue;
          TokenTypes::Conflict c{it->first, it->second, {}};
          for (const auto& a : page.arcs) {
            const auto slots = slotsOf(a);
            if (a.to == p.name && std::find(slots.begin(), slots.end(), s) != slots.end()) c.from.push_back(page.name + "/" + a.from);
          }
          out.conflicts.push_back(std::move(c));
        }
      }
      // scripts reading fields: self.b0.field in a transition's, token.field in a place slot's
      const auto typeNamed = [&](const std::string& n) -> const scene::NodeType* {
        const auto it = named.find(n);
        return it == named.end() ? nullptr : it->second;
      };
      static const std::regex kSelf(R"(self\.([a-d][0-7])(?:\[[^\]]*\])?\.([A-Za-z_]\w*))");
      static const std::regex kToken(R"((token)\.([A-Za-z_]\w*))");
      for (const auto& t : page.transitions) {
        const auto slotTypes = [&](const std::string& slot) -> const std::set<std::string>* {
          const auto s = net::parseSlot(slot);
          if (!s) return nullptr;
          const auto it = out.types.find(key(t.name, *s));
          return it == out.types.end() ? nullptr : &it->second;
        };
        for (const auto k : net::kTransitionScripts) {
          checkUses(net::scriptOf(t, k).code, kSelf, slotTypes, typeNamed, page.name + "/" + t.name,
                    std::string(net::info(k).key), out.unknown);
        }
      }
      for (const auto& p : page.places) {
        for (const auto& scripts : p.scripts) {
          const auto slotTypes = [&](const std::string&) -> const std::set<std::string>* {
            const auto it = out.types.find(key(p.name, scripts.slot));
            return it == out.types.end() ? nullptr : &it->second;
          };
          for (const auto k : {net::ScriptKind::OnDeposit, net::ScriptKind::OnRemove}) {
            checkUses(net::scriptOf(scripts, k).code, kToken, slotTypes, typeNamed, page.name + "/" + p.name,
                      std::string(net::info(k).key) + " (" + net::slotName(scripts.slot) + ")", out.unknown);
          }
        }
      }
    }
  }
  return out;
}

std::vector<std::string> tokenPath(const net::PageSpec& page, const std::string& place, net::SlotId slot) {
  std::vector<std::string> order{place};
  std::set<std::string> seen{place};
  std::deque<std::string> queue{place};
  while (!queue.empty()) {
    const auto at = queue.front();
    queue.pop_front();
    for (const auto& a : page.arcs) {
      if (a.from != at || a.kind != net::ArcKind::Normal) continue;
      const auto slots = slotsOf(a);
      if (std::find(slots.begin(), slots.end(), slot) == slots.end()) continue;
      if (seen.insert(a.to).second) {
        order.push_back(a.to);
        queue.push_back(a.to);
      }
    }
  }
  return order;
}

}  // namespace gdpn::ide
