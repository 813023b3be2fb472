#pragma once
/// \file
/// Completion for the script editor: what may follow the cursor (`sim.`, `self.`, a slot, a
/// node token's fields and methods, the model's globals), each name with one line that says
/// what it is. The names of gdpn's views come from their Python bindings (script/api.h), a
/// node's fields from its type's description (scene/types.h), the slots from the construct as
/// the model writes it, the globals from the globals script read by Python's ast. No ImGui: the
/// contents view shows the list.

#include <cstddef>
#include <functional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "gdpn/net/script_kind.h"
#include "gdpn/net/slot.h"
#include "gdpn/script/api.h"

namespace gdpn::model {
struct Model;
}
namespace gdpn::scene {
struct NodeType;
}

namespace gdpn::ide {

struct TokenTypes;

/// One slot of the construct a script belongs to, as completion offers it (`self.d0`).
struct ScopeSlot {
  net::SlotId slot = net::kDefaultSlot;          ///< which slot
  net::SlotKind kind = net::SlotKind::Control;   ///< what it holds
  std::set<std::string> types;                   ///< a node slot's node types (names), when known
  std::string sensor;                            ///< a sensor slot's sensor node (its path)
  const scene::NodeType* sensor_type = nullptr;  ///< that node's type, when found
};

/// What a script sees besides Python's builtins: the names completion may offer and what they
/// stand for. Made by scopeOf() from the document's model.
struct ScriptScope {
  net::ScriptKind kind = net::ScriptKind::Globals;  ///< the script's kind: says what `self` is and which names it sees
  std::vector<ScopeSlot> slots;                     ///< `self`'s slots (a transition's, or a place's)
  std::set<std::string> token_types;                ///< the node types of `token` / `item` (their slot's)
  std::vector<script::GlobalName> globals;          ///< the names the globals bind
  std::vector<std::pair<std::string, std::string>> params;  ///< the model's parameters: name, and a line (value, unit)
  /// The type of the scene node at a path (`sim.node("belt")`), or null.
  std::function<const scene::NodeType*(const std::string& path)> node_type;
  /// The slots of the place or transition a qualified name names (`sim.place("main/belt")`).
  std::function<std::vector<ScopeSlot>(const std::string& name, bool place)> slots_of;
};

/// The scope of a script of kind `kind` of construct `construct` ("" for the globals) on page
/// (or page type) `page`, slot `slot` for a place slot's script, in `model`; `types` is the
/// document's propagation of node types (App::tokenTypes()).
ScriptScope scopeOf(const model::Model& model, const TokenTypes& types, const std::string& page,
                    const std::string& construct, net::ScriptKind kind, net::SlotId slot);

/// One name completion offers.
struct Completion {
  std::string name;    ///< what is inserted
  std::string kind;    ///< "attribute", "method", "field", "slot", "name", "function", "class", "variable", "import", "parameter", "channel"
  std::string detail;  ///< one line: what it is (a field's kind and unit first)
  std::string signature;  ///< a method's parameters, "(reason='stopped by a script')"; "" for any other name
};

/// What may follow the cursor.
struct CompletionQuery {
  std::string context;    ///< the expression before the dot ("sim", "self.d0"), "" at the start of a name
  std::string prefix;     ///< the part of the name typed so far
  std::size_t start = 0;  ///< where that part begins in the code (bytes): an accepted name replaces [start, cursor)
  bool member = false;    ///< after a dot: the names of what `context` stands for
  std::vector<Completion> names;  ///< those that begin with `prefix`, in order to offer them
};

/// The names that may complete the word at `cursor` (a byte offset) in `code` under `scope`;
/// none in a comment or a string, or after an expression whose kind is unknown.
CompletionQuery complete(const ScriptScope& scope, std::string_view code, std::size_t cursor);

}  // namespace gdpn::ide
