// Completion for the script editor: the expression before the cursor read backwards, what it
// stands for found from the scope, and the names that thing offers.

#include "gdpn/ide/script_completion.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "gdpn/core/text.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/ide/token_types.h"
#include "gdpn/model/model.h"
#include "gdpn/scene/node.h"
#include "gdpn/sensors/sensor_kind.h"

namespace gdpn::ide {
namespace {

using script::ViewClass;

// ---- the scope ----

/// The slots an arc carries: its weights', its predicates' and its conditions' (a0 when it
/// names none).
std::vector<net::SlotId> arcSlots(const net::ArcSpec& a) {
  std::vector<net::SlotId> out;
  for (const auto& w : a.weights) out.push_back(w.slot);
  for (const auto& p : a.predicates) out.push_back(p.slot);
  for (const auto& c : a.conditions) out.push_back(c.slot);
  if (out.empty()) out.push_back(net::kDefaultSlot);
  return out;
}

const net::PlaceSpec* placeOn(const net::PageSpec& page, const std::string& name) {
  const auto it = std::find_if(page.places.begin(), page.places.end(), [&](const auto& p) { return p.name == name; });
  return it == page.places.end() ? nullptr : &*it;
}

/// What slot `slot` of `place` is: its kind, and the sensor it reads.
ScopeSlot slotOfPlace(const net::PlaceSpec& place, net::SlotId slot) {
  ScopeSlot s;
  s.slot = slot;
  s.kind = slotKindOf(place, slot);
  for (const auto& b : place.sensors) {
    if (b.slot == slot) s.sensor = b.path;
  }
  return s;
}

/// The slots of the place or transition `name` on `page`, sorted, each once.
std::vector<ScopeSlot> slotsOn(const net::PageSpec& page, const std::string& name, bool is_place) {
  std::map<net::SlotId, ScopeSlot> found;
  const auto note = [&](ScopeSlot s) { found.try_emplace(s.slot, std::move(s)); };
  if (is_place) {
    const auto* place = placeOn(page, name);
    if (place == nullptr) return {};
    note(slotOfPlace(*place, net::kDefaultSlot));
    for (const auto& d : place->kinds) note(slotOfPlace(*place, d.slot));
    for (const auto& c : place->tokens) note(slotOfPlace(*place, c.slot));
    for (const auto& n : place->nodes) note(slotOfPlace(*place, n.slot));
    for (const auto& c : place->capacity) note(slotOfPlace(*place, c.slot));
    for (const auto& s : place->scripts) note(slotOfPlace(*place, s.slot));
    for (const auto& b : place->sensors) note(slotOfPlace(*place, b.slot));
    for (const auto& a : page.arcs) {
      if (a.from != name && a.to != name) continue;
      for (const auto slot : arcSlots(a)) note(slotOfPlace(*place, slot));
    }
  } else {
    // a transition's slots are those its arcs carry, of the kind their place gives them
    for (const auto& a : page.arcs) {
      if (a.from != name && a.to != name) continue;
      const auto* place = placeOn(page, a.from == name ? a.to : a.from);
      for (const auto slot : arcSlots(a)) {
        if (place != nullptr) {
          note(slotOfPlace(*place, slot));
        } else {
          ScopeSlot s;  // a link into an instance: its kind is the instance's
          s.slot = slot;
          note(s);
        }
      }
    }
  }
  std::vector<ScopeSlot> out;
  for (auto& [slot, s] : found) out.push_back(std::move(s));
  return out;
}

/// The text of the model's globals script: inline, or its .py file beside the model.
std::string globalsText(const model::Model& model) {
  const auto& g = model.net.globals;
  if (g.file.empty()) return g.code;
  const auto dir = std::filesystem::path(model.path).parent_path();
  std::ifstream in(dir / g.file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// ---- what the code before the cursor says ----

bool wordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

/// True when offset `at` of `code` lies in a comment or a string.
bool inCommentOrString(std::string_view code, std::size_t at) {
  char quote = 0;
  bool triple = false;
  for (std::size_t i = 0; i < at && i < code.size(); ++i) {
    const char c = code[i];
    if (quote != 0) {
      if (c == '\\') {
        ++i;
      } else if (c == '\n' && !triple) {
        quote = 0;  // an unclosed one-line string ends with its line
      } else if (c == quote) {
        if (!triple) {
          quote = 0;
        } else if (code.substr(i, 3) == std::string(3, quote)) {
          quote = 0;
          i += 2;
        }
      }
    } else if (c == '#') {
      const auto nl = code.find('\n', i);
      if (nl == std::string_view::npos || nl >= at) return true;
      i = nl;
    } else if (c == '"' || c == '\'') {
      quote = c;
      triple = code.substr(i, 3) == std::string(3, c);
      if (triple) i += 2;
    }
  }
  return quote != 0;
}

/// One link of a dotted expression: a name and what follows it (calls and subscripts).
struct Segment {
  std::string name;
  bool called = false;    ///< `name(...)`
  std::string argument;   ///< a call's argument when it is one string literal (`sim.node("belt")`)
  int indexed = 0;        ///< how many `[...]` follow
};

/// The text inside a string literal `text`, or nullopt when it is not one.
std::optional<std::string> stringLiteral(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  if (text.size() < 2 || (text.front() != '"' && text.front() != '\'') || text.back() != text.front()) return std::nullopt;
  const auto inner = text.substr(1, text.size() - 2);
  if (inner.find(text.front()) != std::string_view::npos) return std::nullopt;
  return std::string(inner);
}

/// The dotted expression that ends just before offset `end` (where its last name ends), read
/// backwards: `sim.node("a").parent` gives sim, node("a"), parent. Empty when what stands there
/// is no such chain (a literal, a bracketed expression).
std::vector<Segment> chainBefore(std::string_view code, std::size_t end) {
  std::vector<Segment> out;
  std::size_t p = end;
  for (;;) {
    Segment seg;
    // the calls and subscripts after the name, last first
    while (p > 0 && (code[p - 1] == ')' || code[p - 1] == ']')) {
      const char close = code[p - 1];
      const char open = close == ')' ? '(' : '[';
      int depth = 0;
      std::size_t q = p;
      while (q > 0) {
        --q;
        if (code[q] == close) ++depth;
        if (code[q] == open && --depth == 0) break;
      }
      if (depth != 0) return {};
      if (close == ')') {
        if (!seg.called) {  // the first call after the name is the last one read
          seg.argument = stringLiteral(code.substr(q + 1, p - 1 - (q + 1))).value_or("");
        }
        seg.called = true;
      } else {
        ++seg.indexed;
      }
      p = q;
    }
    std::size_t b = p;
    while (b > 0 && wordChar(code[b - 1])) --b;
    if (b == p || std::isdigit(static_cast<unsigned char>(code[b])) != 0) return {};
    seg.name = std::string(code.substr(b, p - b));
    out.push_back(std::move(seg));
    if (b > 0 && code[b - 1] == '.') {
      p = b - 1;
      continue;
    }
    break;
  }
  std::reverse(out.begin(), out.end());
  return out;
}

// ---- what an expression stands for ----

/// What an expression is, as far as completion can tell.
struct Thing {
  enum class Is { Unknown, Class, Slot, Node, Sensor };
  Is is = Is::Unknown;
  ViewClass view = ViewClass::Sim;     ///< for Class: which view
  std::vector<ScopeSlot> slots;        ///< a transition's or place's slots
  ScopeSlot slot;                      ///< for Slot
  std::set<std::string> types;         ///< a node's types, when known
  const scene::NodeType* sensor = nullptr;  ///< for Sensor: its type, when known
};

Thing view(ViewClass c, std::vector<ScopeSlot> slots = {}) {
  Thing t;
  t.is = Thing::Is::Class;
  t.view = c;
  t.slots = std::move(slots);
  return t;
}

Thing node(std::set<std::string> types = {}) {
  Thing t;
  t.is = Thing::Is::Node;
  t.types = std::move(types);
  return t;
}

Thing sensorThing(const scene::NodeType* type) {
  Thing t;
  t.is = Thing::Is::Sensor;
  t.sensor = type;
  return t;
}

Thing slotThing(const ScopeSlot& s) {
  Thing t;
  t.is = Thing::Is::Slot;
  t.slot = s;
  return t;
}

/// The first name of an expression.
Thing first(const ScriptScope& scope, const Segment& seg) {
  const auto owner = net::info(scope.kind).owner;
  if (seg.name == "sim") return view(ViewClass::Sim);
  if (seg.name == "self") {
    switch (owner) {
      case net::ScriptOwner::Transition:
      case net::ScriptOwner::Arc: return view(ViewClass::Transition, scope.slots);
      case net::ScriptOwner::PlaceSlot: return view(ViewClass::Place, scope.slots);
      case net::ScriptOwner::Model: return {};
    }
  }
  if (seg.name == "token" || seg.name == "item") return node(scope.token_types);
  if (scope.kind == net::ScriptKind::Condition) {  // a condition sees its sensor slot by its name
    for (const auto& s : scope.slots) {
      if (net::slotName(s.slot) == seg.name && s.kind == net::SlotKind::Sensor) return sensorThing(s.sensor_type);
    }
  }
  return {};
}

/// The type names of the node at `path`, when found.
std::set<std::string> typesAt(const ScriptScope& scope, const std::string& path) {
  const auto* type = scope.node_type && !path.empty() ? scope.node_type(path) : nullptr;
  if (type == nullptr) return {};
  return {type->name};
}

/// What `name` of `of` stands for.
Thing member(const ScriptScope& scope, const Thing& of, const Segment& seg) {
  switch (of.is) {
    case Thing::Is::Unknown: return {};
    case Thing::Is::Class:
      switch (of.view) {
        case ViewClass::Sim:
          if (seg.name == "random") return view(ViewClass::Random);
          if (seg.name == "params") return view(ViewClass::Params);
          if (seg.name == "part") return view(ViewClass::Part);
          if (seg.name == "node") return node(typesAt(scope, seg.argument));
          if (seg.name == "place" || seg.name == "transition") {
            const bool place = seg.name == "place";
            auto slots = scope.slots_of && !seg.argument.empty() ? scope.slots_of(seg.argument, place) : std::vector<ScopeSlot>{};
            return view(place ? ViewClass::Place : ViewClass::Transition, std::move(slots));
          }
          return {};
        case ViewClass::Transition:
        case ViewClass::Place:
          for (const auto& s : of.slots) {
            if (net::slotName(s.slot) == seg.name) return slotThing(s);
          }
          if (seg.name == "instance") return node();
          if (seg.name == "part") return view(ViewClass::Part);
          if (seg.name == "params") return view(ViewClass::Params);
          return {};
        case ViewClass::Part:
          if (seg.name == "node") return node();
          if (seg.name == "params") return view(ViewClass::Params);
          return {};
        case ViewClass::Slot:
        case ViewClass::Node:
        case ViewClass::Sensor:
        case ViewClass::Random:
        case ViewClass::Params:
        case ViewClass::Data: return {};
      }
      return {};
    case Thing::Is::Slot:
      if (of.slot.kind == net::SlotKind::Node) return member(scope, node(of.slot.types), seg);
      return {};
    case Thing::Is::Node:
      if (seg.name == "parent" || seg.name == "prev" || seg.name == "next" || seg.name == "find" || seg.name == "spawn") {
        return node();
      }
      if (seg.name == "children") return seg.indexed > 0 ? node() : Thing{};
      if (seg.name == "data") return view(ViewClass::Data);
      return {};
    case Thing::Is::Sensor: return {};
  }
  return {};
}

/// What the whole chain stands for.
Thing resolve(const ScriptScope& scope, const std::vector<Segment>& chain) {
  if (chain.empty()) return {};
  Thing t = first(scope, chain.front());
  if (chain.front().called || chain.front().indexed > 0) {
    // `self.d0[0]`'s form on a first name: only a slot's subscript gives a node
    if (t.is == Thing::Is::Slot && chain.front().indexed > 0) return node(t.slot.types);
    return {};
  }
  for (std::size_t i = 1; i < chain.size(); ++i) {
    const auto& seg = chain[i];
    Thing next = member(scope, t, seg);
    // a slot's subscript is one of its node tokens
    if (next.is == Thing::Is::Slot && seg.indexed > 0) {
      next = next.slot.kind == net::SlotKind::Node ? node(next.slot.types) : Thing{};
    } else if (seg.indexed > 0 && !(next.is == Thing::Is::Node && seg.name == "children")) {
      next = {};
    }
    t = std::move(next);
    if (t.is == Thing::Is::Unknown) break;
  }
  return t;
}

// ---- the names a thing offers ----

void addView(ViewClass c, std::vector<Completion>& out) {
  for (const auto& n : script::viewNames(c)) {
    out.push_back({n.name, n.method ? "method" : "attribute", n.doc, n.method ? "(" + n.arguments + ")" : ""});
  }
}

std::string slotLine(const ScopeSlot& s) {
  switch (s.kind) {
    case net::SlotKind::Control: return "control slot: a count of tokens";
    case net::SlotKind::Node: {
      std::string types;
      for (const auto& t : s.types) types += (types.empty() ? "" : " or ") + t;
      return "node slot" + (types.empty() ? std::string() : ": holds a " + types);
    }
    case net::SlotKind::Sensor:
      return "sensor slot: reads " + (s.sensor.empty() ? std::string("a sensor") : s.sensor) +
             (s.sensor_type != nullptr ? " (a " + s.sensor_type->name + ")" : "");
    case net::SlotKind::Value: return "value slot: a multiset of values of its colour set";
    case net::SlotKind::Continuous: return "continuous place: a real amount (`amount`)";
  }
  return {};
}

void addSlots(const std::vector<ScopeSlot>& slots, std::vector<Completion>& out) {
  for (const auto& s : slots) out.push_back({net::slotName(s.slot), "slot", slotLine(s), ""});
}

/// A node's own names and the fields of its types (each field once, the first type's line).
void addNode(const std::set<std::string>& types, std::vector<Completion>& out) {
  addView(ViewClass::Node, out);
  for (const auto& name : types) {
    const auto* type = scene::builtinTypes().find(name);
    if (type == nullptr) continue;
    for (const auto* f : type->fields) {
      std::string line = std::string(scene::fieldKindName(f->kind)) + (f->unit.empty() ? "" : ", " + f->unit);
      line += (types.size() > 1 ? " (" + type->name + ")" : std::string()) + ": " + f->doc;
      out.push_back({f->name, "field", line, ""});
    }
  }
}

/// A sensor's names: those every kind has, and its own kind's channels (every kind's when the
/// kind is unknown).
void addSensor(const scene::NodeType* type, std::vector<Completion>& out) {
  const auto* own = type != nullptr ? sensors::sensorKind(type->kind) : nullptr;
  std::set<std::string, std::less<>> channels;
  for (const auto* k : sensors::sensorKinds()) {
    for (const auto& c : k->channels) channels.insert(std::string(c.name));
  }
  for (const auto& n : script::viewNames(ViewClass::Sensor)) {
    if (own != nullptr && channels.count(n.name) > 0) {
      const auto c = std::find_if(own->channels.begin(), own->channels.end(), [&](const auto& x) { return x.name == n.name; });
      if (c == own->channels.end()) continue;  // another kind's
      if (n.name != "items") {
        out.push_back({n.name, "channel", std::string(c->help) + (c->unit.empty() ? "" : ", " + std::string(c->unit)), ""});
        continue;
      }
    }
    out.push_back({n.name, n.method ? "method" : "attribute", n.doc, n.method ? "(" + n.arguments + ")" : ""});
  }
}

std::vector<Completion> namesOf(const ScriptScope& scope, const Thing& t) {
  std::vector<Completion> out;
  switch (t.is) {
    case Thing::Is::Unknown: break;
    case Thing::Is::Class:
      if (t.view == ViewClass::Transition || t.view == ViewClass::Place) addSlots(t.slots, out);
      addView(t.view, out);
      if (t.view == ViewClass::Params) {
        for (const auto& [name, line] : scope.params) out.push_back({name, "parameter", line, ""});
      }
      break;
    case Thing::Is::Slot:
      addView(ViewClass::Slot, out);
      // a node slot reads its first token's attributes; a sensor slot its sensor's
      if (t.slot.kind == net::SlotKind::Node) addNode(t.slot.types, out);
      if (t.slot.kind == net::SlotKind::Sensor) addSensor(t.slot.sensor_type, out);
      break;
    case Thing::Is::Node: addNode(t.types, out); break;
    case Thing::Is::Sensor: addSensor(t.sensor, out); break;
  }
  return out;
}

/// The names a script sees before any dot.
std::vector<Completion> topNames(const ScriptScope& scope) {
  std::vector<Completion> out;
  out.push_back({"sim", "name", script::viewClassDoc(ViewClass::Sim), ""});
  const auto owner = net::info(scope.kind).owner;
  switch (owner) {
    case net::ScriptOwner::Transition:
    case net::ScriptOwner::Arc: out.push_back({"self", "name", script::viewClassDoc(ViewClass::Transition), ""}); break;
    case net::ScriptOwner::PlaceSlot: out.push_back({"self", "name", script::viewClassDoc(ViewClass::Place), ""}); break;
    case net::ScriptOwner::Model: break;
  }
  switch (scope.kind) {
    case net::ScriptKind::OnDeposit:
    case net::ScriptKind::OnRemove:
    case net::ScriptKind::Predicate: out.push_back({"token", "name", "the node token (None for a control token)", ""}); break;
    case net::ScriptKind::OnEnter:
    case net::ScriptKind::OnExit:
      out.push_back({"item", "name", "what entered (or left) first: its geometries; attributes read its node", ""});
      out.push_back({"items", "name", "every item that entered (or left) in this step", ""});
      break;
    case net::ScriptKind::OnChange:
    case net::ScriptKind::Condition: out.push_back({"value", "name", "the sensor's main number", ""}); break;
    case net::ScriptKind::Guard:
    case net::ScriptKind::PreFire:
    case net::ScriptKind::InFire:
    case net::ScriptKind::PostFire:
    case net::ScriptKind::OnSample:
    case net::ScriptKind::Globals: break;
  }
  if (scope.kind == net::ScriptKind::Condition) {
    for (const auto& s : scope.slots) {
      if (s.kind == net::SlotKind::Sensor) out.push_back({net::slotName(s.slot), "slot", slotLine(s), ""});
    }
  }
  for (const auto& g : scope.globals) out.push_back({g.name, g.kind, g.detail, ""});
  return out;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

ScriptScope scopeOf(const model::Model& model, const TokenTypes& types, const std::string& page,
                    const std::string& construct, net::ScriptKind kind, net::SlotId slot) {
  ScriptScope scope;
  scope.kind = kind;
  const scene::Scene* plant = model.scene.get();
  scope.node_type = [plant](const std::string& path) -> const scene::NodeType* {
    const auto* n = plant != nullptr ? plant->find(path) : nullptr;
    return n != nullptr ? &n->type() : nullptr;
  };
  const auto typed = [&types, plant](std::vector<ScopeSlot> slots, const std::string& key) {
    for (auto& s : slots) {
      if (const auto it = types.types.find({key, s.slot}); it != types.types.end()) s.types = it->second;
      if (!s.sensor.empty() && plant != nullptr) {
        if (const auto* n = plant->find(s.sensor)) s.sensor_type = &n->type();
      }
    }
    return slots;
  };
  const net::NetSpec* net = &model.net;
  scope.slots_of = [net, typed](const std::string& name, bool place) {
    const auto at = locateConstruct(*net, name);
    const auto* p = at ? findPage(*net, at->page) : nullptr;
    return p != nullptr ? typed(slotsOn(*p, at->name, place), at->page + "/" + at->name) : std::vector<ScopeSlot>{};
  };
  if (const auto* p = construct.empty() ? nullptr : findPage(model.net, page)) {
    const auto owner = net::info(kind).owner;
    const bool place = owner == net::ScriptOwner::PlaceSlot;
    scope.slots = typed(slotsOn(*p, construct, place), page + "/" + construct);
    if (place) {
      if (const auto it = types.types.find({page + "/" + construct, slot}); it != types.types.end()) {
        scope.token_types = it->second;
      }
    }
  }
  scope.globals = script::globalNames(globalsText(model));
  for (const auto& prm : model.params) {
    std::string line = "= " + core::formatDouble(prm.value) + (prm.unit.empty() ? "" : " " + prm.unit);
    if (!prm.description.empty()) line += ": " + prm.description;
    scope.params.emplace_back(prm.name, std::move(line));
  }
  return scope;
}

CompletionQuery complete(const ScriptScope& scope, std::string_view code, std::size_t cursor) {
  CompletionQuery q;
  cursor = std::min(cursor, code.size());
  std::size_t start = cursor;
  while (start > 0 && wordChar(code[start - 1])) --start;
  q.start = start;
  q.prefix = std::string(code.substr(start, cursor - start));
  if (!q.prefix.empty() && std::isdigit(static_cast<unsigned char>(q.prefix.front())) != 0) return q;  // a number
  if (inCommentOrString(code, cursor)) return q;
  std::vector<Completion> all;
  if (start > 0 && code[start - 1] == '.') {
    q.member = true;
    const auto chain = chainBefore(code, start - 1);
    if (chain.empty()) return q;
    for (const auto& seg : chain) {
      if (!q.context.empty()) q.context += '.';
      q.context += seg.name + (seg.called ? "(" + (seg.argument.empty() ? "" : "\"" + seg.argument + "\"") + ")" : "");
      for (int i = 0; i < seg.indexed; ++i) q.context += "[]";
    }
    all = namesOf(scope, resolve(scope, chain));
  } else {
    all = topNames(scope);
  }
  // those that begin with what was typed (in any case), each once; the ones that match its case
  // first, then by name
  const auto typed = lower(q.prefix);
  std::set<std::string> seen;
  for (auto& c : all) {
    if (!lower(c.name).starts_with(typed) || !seen.insert(c.name).second) continue;
    q.names.push_back(std::move(c));
  }
  std::stable_sort(q.names.begin(), q.names.end(), [&](const Completion& a, const Completion& b) {
    const bool ea = a.name.starts_with(q.prefix), eb = b.name.starts_with(q.prefix);
    if (ea != eb) return ea;
    return lower(a.name) < lower(b.name);
  });
  return q;
}

}  // namespace gdpn::ide
