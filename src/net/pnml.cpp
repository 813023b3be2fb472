// PNML in: a place/transition net read into a NetSpec, its pages as pages, its reference
// nodes as the nodes they stand for, and gdpn's tool-specific parts read back (pnml.h; the
// format is in docs/format.md, "PNML").

#include "gdpn/net/pnml.h"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "detail/pnml_colour.h"
#include "detail/pnml_tool.h"
#include "detail/xml.h"
#include "gdpn/core/file.h"
#include "gdpn/core/text.h"

namespace gdpn::net {
namespace {

using detail::isIdNote;
using detail::kIdNote;
using detail::XmlElement;

/// The text of <name><text>..</text></name> (or of any such pair), trimmed.
std::string textOf(const XmlElement* el) {
  if (!el) return {};
  const XmlElement* t = el->child("text");
  std::string s = t ? t->text : el->text;
  const auto b = s.find_first_not_of(" \t\r\n"), e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

}  // namespace

std::string pnmlName(const std::string& id) {
  if (core::isIdentifier(id)) return id;
  std::string n;
  for (char c : id) n += (std::isalnum(static_cast<unsigned char>(c)) || c == '_') ? c : '_';
  if (n.empty() || std::isdigit(static_cast<unsigned char>(n[0]))) n = "n" + n;
  return n;
}

namespace {

/// A PNML <page> (or the net itself, for nodes written outside any page).
struct Page {
  const XmlElement* el = nullptr;
  int parent = -1;       // the page it lies inside; -1 for a top-level page
  int host = 0;          // the page it is read as part of: itself, unless made one with another
  bool named = false;    // gdpn's part named it
  PageSpec spec;         // name, loc, description, references; its nodes and arcs come at the end
  InstanceSpec instance; // inside another page: the instance it is there
};

/// A place, transition or reference node of the file.
struct Node {
  enum class Kind : std::uint8_t { Place, Transition, ReferencePlace, ReferenceTransition };
  Kind kind = Kind::Place;
  int page = 0;            // where it is written
  std::size_t index = 0;   // into places_ or transitions_ (places and transitions)
  const XmlElement* el = nullptr;
};

/// An arc of the file, its ends still PNML ids.
struct RawArc {
  int page = 0;
  const XmlElement* el = nullptr;
  ArcSpec spec;            // all but its ends
  std::string place, transition;  // the ids of the place and transition it joins, references followed
  std::string via;                // the referencePlace it names for its place, if it names one
  bool from_place = true;
};

/// What an element's tag is called in messages: "referencePlace 'r'".
std::string what(const XmlElement& el) {
  const std::string* id = el.attr("id");
  return "<" + el.name + ">" + (id ? " '" + *id + "'" : "");
}

class PnmlReader {
 public:
  PnmlReader(const std::string& file, core::Diagnostics& diags) : file_(file), diags_(diags) {}

  std::optional<NetSpec> read(const XmlElement& root, std::string* net_name) {
    if (root.name != "pnml") {
      diags_.error(root.loc, "a PNML file starts with <pnml>, this one with <" + root.name + ">");
      return std::nullopt;
    }
    const XmlElement* net = root.child("net");
    if (!net) {
      diags_.error(root.loc, "the PNML file holds no <net>");
      return std::nullopt;
    }
    const std::string* type = net->attr("type");
    symmetric_ = type && detail::isSymmetricNet(*type);
    if (type && type->find("ptnet") == std::string::npos && !symmetric_) {
      diags_.error(net->loc, "only place/transition nets (ptnet) and symmetric nets (symmetricnet) are supported; "
                             "this net is '" + *type + "'");
      return std::nullopt;
    }
    if (net_name) {
      *net_name = textOf(net->child("name"));
      if (net_name->empty() && net->attr("id")) *net_name = *net->attr("id");
    }
    NetSpec spec;
    if (symmetric_) colour_.declarations(*net, spec);
    if (const XmlElement* tool = gdpnPart(*net)) {
      for (const auto& c : tool->children) {
        if (c->name == "globals") spec.globals = script(*c);
        else if (c->name == "fusion") fusionSet(*c);
        else unknown(*c, "the net");
      }
    }
    collect(*net, -1);
    namePages();
    resolveReferences();
    for (auto& a : arcs_) readEnds(a);
    placeArcs();
    if (diags_.hasErrors()) return std::nullopt;
    build(spec);
    spec.fusions = std::move(fusions_);
    return spec;
  }

 private:
  // ---- the tool-specific part -------------------------------------------------------------

  /// `el`'s tool-specific part written by gdpn, or null; one of another version is warned of.
  const XmlElement* gdpnPart(const XmlElement& el) {
    for (const auto& c : el.children) {
      if (c->name != "toolspecific" || !c->attr("tool") || *c->attr("tool") != detail::kPnmlTool) continue;
      const std::string* version = c->attr("version");
      if (!version || *version != detail::kPnmlToolVersion) {
        diags_.warning(c->loc, "gdpn's tool-specific part of version '" + (version ? *version : std::string()) +
                                   "' is not read: this gdpn reads version " + std::string(detail::kPnmlToolVersion));
        return nullptr;
      }
      return c.get();
    }
    return nullptr;
  }

  void unknown(const XmlElement& el, const std::string& owner) {
    diags_.error(el.loc, "<" + el.name + "> is nothing gdpn's tool-specific part of " + owner + " holds");
  }

  /// A script: the element's text as written, or its `file` and `function`.
  static ScriptSpec script(const XmlElement& el) {
    ScriptSpec s;
    if (const std::string* file = el.attr("file")) {
      s.file = *file;
      if (const std::string* f = el.attr("function")) s.function = *f;
    } else {
      s.code = el.text;
    }
    s.loc = el.loc;
    return s;
  }

  /// The slot the `slot` attribute of `el` names; a missing or bad one is an error.
  std::optional<SlotId> slotOf(const XmlElement& el, const char* key = "slot") {
    const std::string* s = el.attr(key);
    auto slot = s ? parseSlot(*s) : std::nullopt;
    if (!slot) {
      diags_.error(el.loc, "<" + el.name + "> needs " + key + "=\"a0\" ... \"d7\"" + (s ? ", got \"" + *s + "\"" : ""));
    }
    return slot;
  }

  /// A whole number (of tokens, a weight, a priority): the text `t` of `el`.
  std::optional<std::int64_t> integer(const XmlElement& el, const std::string& t, const char* what, bool sign = false) {
    std::int64_t v = 0;
    const char* b = t.data();
    const char* e = t.data() + t.size();
    if (sign && b != e && *b == '+') ++b;
    const auto [ptr, ec] = std::from_chars(b, e, v);
    if (t.empty() || ec != std::errc() || ptr != e || (!sign && (t[0] == '-' || v < 0))) {
      diags_.error(el.loc, std::string(what) + " expects a whole number" + (sign ? "" : " of tokens") + ", got \"" +
                               t.substr(0, 40) + "\"");
      return std::nullopt;
    }
    return v;
  }

  /// A finite number written as `t` in `el`.
  std::optional<double> number(const XmlElement& el, const std::string& t, const std::string& what) {
    auto v = core::parseNumber(t);
    if (!v || !std::isfinite(*v)) {
      diags_.error(el.loc, what + " expects a number, got \"" + t.substr(0, 40) + "\"");
      return std::nullopt;
    }
    return v;
  }

  /// `n` numbers separated by blanks, the attribute `key` of `el`.
  template <std::size_t N>
  std::optional<std::array<double, N>> numbers(const XmlElement& el, const char* key) {
    const std::string* s = el.attr(key);
    if (!s) return std::nullopt;
    const auto words = core::words(*s);
    std::array<double, N> v{};
    if (words.size() != N) {
      diags_.error(el.loc, std::string(key) + "=\"" + s->substr(0, 40) + "\" expects " + std::to_string(N) + " numbers");
      return std::nullopt;
    }
    for (std::size_t i = 0; i < N; ++i) {
      auto x = number(el, std::string(words[i]), key);
      if (!x) return std::nullopt;
      v[i] = *x;
    }
    return v;
  }

  /// The text of a tool-specific element, trimmed (a count, a number).
  static std::string trimmed(const XmlElement& el) { return textOf(&el); }

  SlotScripts& slotScripts(std::vector<SlotScripts>& all, SlotId slot) {
    for (auto& s : all) {
      if (s.slot == slot) return s;
    }
    all.push_back({});
    all.back().slot = slot;
    return all.back();
  }

  /// A fusion set the net's part declares: `<fusion name="pool" scope="global"/>`.
  void fusionSet(const XmlElement& el) {
    const std::string* name = el.attr("name");
    const std::string* scope = el.attr("scope");
    const auto parsed = scope ? parseFusionScope(*scope) : std::optional<FusionScope>(FusionScope::Global);
    if (!name || !parsed) {
      diags_.error(el.loc, "<fusion> needs name=\"a set\" and scope=\"global\" or \"instance\"");
      return;
    }
    fusions_.push_back({*name, *parsed, el.loc});
    fusion_names_.insert(*name);
  }

  void placePart(const XmlElement& tool, PlaceSpec& p) {
    bool tokens = false;
    for (const auto& cp : tool.children) {
      const XmlElement& c = *cp;
      const std::string owner = "place '" + p.name + "'";
      if (c.name == "name" || c.name == "description") continue;
      if (c.name == "fusion") {
        if (const std::string* set = c.attr("name")) p.fusion = *set, p.fusion_loc = c.loc;
        else diags_.error(c.loc, "<fusion> needs name=\"the set\" the place is a member of");
      } else if (c.name == "slot") {
        auto slot = slotOf(c, "name");
        const std::string* k = c.attr("kind");
        auto kind = k ? parseSlotKind(*k) : std::nullopt;
        if (!kind) diags_.error(c.loc, "<slot> needs kind=\"control\", \"node\" or \"sensor\"");
        if (slot && kind) p.kinds.push_back({*slot, *kind, c.loc});
      } else if (c.name == "tokens" || c.name == "capacity") {
        auto slot = slotOf(c);
        auto n = integer(c, trimmed(c), c.name == "tokens" ? "a marking" : "a capacity");
        if (!tokens && c.name == "tokens") p.tokens.clear();  // the list replaces the initial marking
        tokens = tokens || c.name == "tokens";
        if (slot && n) (c.name == "tokens" ? p.tokens : p.capacity).push_back({*slot, *n, c.loc, {}});
      } else if (c.name == "nodes") {
        SlotNodes n;
        n.loc = c.loc;
        auto slot = slotOf(c);
        for (const auto& node : c.children) {
          if (node->name == "node") n.nodes.push_back(node->text);
          else unknown(*node, owner);
        }
        if (slot) {
          n.slot = *slot;
          p.nodes.push_back(std::move(n));
        }
      } else if (c.name == "sensor") {
        if (auto slot = slotOf(c)) p.sensors.push_back({*slot, c.text, c.loc});
      } else if (c.name == "scripts") {
        if (auto slot = slotOf(c)) slotScripts(p.scripts, *slot);
      } else if (auto kind = parseScriptKind(c.name, ScriptOwner::PlaceSlot)) {
        if (auto slot = slotOf(c)) scriptOf(slotScripts(p.scripts, *slot), *kind) = script(c);
      } else {
        unknown(c, owner);
      }
    }
  }

  void transitionPart(const XmlElement& tool, TransitionSpec& t) {
    for (const auto& cp : tool.children) {
      const XmlElement& c = *cp;
      if (c.name == "name" || c.name == "description") continue;
      if (c.name == "duration") {
        const std::string* law = c.attr("law");
        std::size_t k = 0;
        while (law && k < std::size(detail::kLawNames) && detail::kLawNames[k] != *law) ++k;
        if (!law || k == std::size(detail::kLawNames)) {
          diags_.error(c.loc, "<duration> needs law=\"fixed\", \"uniform\", \"normal\", \"exponential\" or \"immediate\"");
          continue;
        }
        t.duration = Duration(static_cast<DurationLaw::Law>(k), 0.0, 0.0, c.loc);
        if (const std::string* a = c.attr("a")) t.duration.a = number(c, *a, "a duration").value_or(0.0);
        if (const std::string* b = c.attr("b")) t.duration.b = number(c, *b, "a duration").value_or(0.0);
      } else if (c.name == "priority") {
        t.priority = integer(c, trimmed(c), "a priority", true).value_or(0);
      } else if (c.name == "probability") {
        t.probability = number(c, trimmed(c), "a probability").value_or(1.0);
        t.probability_loc = c.loc;
      } else if (c.name == "servers") {
        const std::string s = trimmed(c);
        t.servers = s == "unlimited" ? kUnlimitedServers : integer(c, s, "servers").value_or(1);
        t.servers_loc = c.loc;
      } else if (auto kind = parseScriptKind(c.name, ScriptOwner::Transition)) {
        scriptOf(t, *kind) = script(c);
      } else {
        unknown(c, "transition '" + t.name + "'");
      }
    }
  }

  void arcPart(const XmlElement& tool, ArcSpec& a, const XmlElement& arc) {
    bool weights = false;
    for (const auto& cp : tool.children) {
      const XmlElement& c = *cp;
      if (c.name == "weight") {
        if (!weights) a.weights.clear();  // the list replaces the inscription
        weights = true;
        auto slot = slotOf(c);
        auto n = integer(c, trimmed(c), "an arc weight");
        if (slot && n) a.weights.push_back({*slot, *n, c.loc, {}});
      } else if (c.name == "predicate" || c.name == "condition") {
        if (auto slot = slotOf(c)) (c.name == "predicate" ? a.predicates : a.conditions).push_back({*slot, script(c)});
      } else {
        unknown(c, "arc " + what(arc));
      }
    }
  }

  void pagePart(const XmlElement& tool, Page& page) {
    for (const auto& cp : tool.children) {
      const XmlElement& c = *cp;
      if (c.name == "name") {
        page.spec.name = c.text;
        page.named = true;
      } else if (c.name == "description") {
        page.spec.description = c.text;
      } else if (c.name == "instance" && page.parent >= 0) {
        InstanceSpec& i = page.instance;
        if (const std::string* type = c.attr("type")) i.type = *type;
        if (auto at = numbers<2>(c, "at")) i.position = *at;
        if (auto t = numbers<3>(c, "translation")) i.translation = *t;
        if (auto r = numbers<4>(c, "rotation")) i.rotation = *r;
        if (const std::string* part = c.attr("part")) i.part = *part, i.part_loc = c.loc;
        for (const auto& s : c.children) {
          const std::string* key = s->attr(s->name == "param" ? "name" : "role");
          if ((s->name != "param" && s->name != "use") || !key) {
            diags_.error(s->loc, "<instance> holds <param name=..> and <use role=..>, not <" + s->name + ">");
          } else if (s->name == "param") {
            if (auto v = number(*s, trimmed(*s), "a parameter")) i.params.push_back({*key, *v, s->loc});
          } else {
            i.uses.push_back({*key, s->text, s->loc});
          }
        }
      } else if (c.name == "reference" && page.parent >= 0) {
        page.spec.references.push_back({c.text, c.loc});
      } else {
        unknown(c, "a page");
      }
    }
  }

  // ---- places, transitions, pages --------------------------------------------------------

  /// A symmetric net's place: its `<type>` makes slot a0 a value slot of that set, and its
  /// `<hlinitialMarking>` the slot's initial values; one without a type is a plain place.
  void highLevelPlace(const XmlElement& el, PlaceSpec& p) {
    const XmlElement* type = el.child("type");
    if (!type) return;  // a plain place (as gdpn writes a net's places without values)
    auto set = colour_.placeSort(*type);
    if (!set) return;
    p.colours.push_back({kDefaultSlot, *set, type->loc});
    if (const XmlElement* m = el.child("hlinitialMarking")) {
      if (auto text = colour_.term(*m)) p.values.push_back({kDefaultSlot, *text, m->loc});
    }
  }

  /// The description of a place or transition read as `name` from PNML id `id`: gdpn's own
  /// when its part has one, else the id note when it was renamed, else its name label when
  /// that differs from the name. A label that reads like an id note is dropped, since a save
  /// would take it for one.
  static std::string describe(const XmlElement& el, const XmlElement* tool, const std::string& name,
                              const std::string& id) {
    if (const XmlElement* d = tool ? tool->child("description") : nullptr) return d->text;
    if (name != id) return std::string(kIdNote) + id;
    const std::string label = textOf(el.child("name"));
    return label == name || isIdNote(label) ? std::string() : label;
  }

  /// A name for PNML id `id`: gdpn's own when its part has one, else the id itself when it is
  /// an identifier, else a cleaned copy no other construct has.
  std::string nameFor(const std::string& id, const XmlElement* tool = nullptr) {
    if (const XmlElement* n = tool ? tool->child("name") : nullptr) {
      used_.insert(n->text);
      return n->text;
    }
    std::string n = pnmlName(id);
    if (n != id) {
      while (used_.count(n)) n += "_";
    }
    used_.insert(n);
    return n;
  }

  std::optional<std::string> idOf(const XmlElement& el) {
    const std::string* id = el.attr("id");
    if (!id || id->empty()) {
      diags_.error(el.loc, "<" + el.name + "> has no id");
      return std::nullopt;
    }
    if (ids_.count(*id)) {
      diags_.error(el.loc, "id '" + *id + "' is used twice");
      return std::nullopt;
    }
    return *id;
  }

  /// The point `x`, `y` of a graphics element (`<position>`, `<offset>`): finite numbers, else nullopt.
  static std::optional<EditorPos> point(const XmlElement* p) {
    if (!p || !p->attr("x") || !p->attr("y")) return std::nullopt;
    auto x = core::parseNumber(*p->attr("x")), y = core::parseNumber(*p->attr("y"));
    if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y)) return std::nullopt;
    return EditorPos{*x, *y};
  }

  std::optional<EditorPos> position(const XmlElement& el) {
    const XmlElement* g = el.child("graphics");
    return point(g ? g->child("position") : nullptr);
  }

  /// An arc's route: each `<position>` of its `<graphics>` is a bend point, in order (PNML's
  /// standard); one that is no point is left out, with a warning.
  std::vector<EditorPos> route(const XmlElement& arc) {
    std::vector<EditorPos> via;
    const XmlElement* g = arc.child("graphics");
    if (!g) return via;
    for (const auto& c : g->children) {
      if (c->name != "position") continue;
      if (auto at = point(c.get())) via.push_back(*at);
      else diags_.warning(c->loc, "a bend point needs finite numbers x and y; this one is left out");
    }
    return via;
  }

  /// The page nodes written directly in `el` (the net) belong to: one made for them.
  int pageFor(const XmlElement& el, int page) {
    if (page >= 0) return page;
    if (loose_ < 0) {
      loose_ = static_cast<int>(pages_.size());
      pages_.push_back({});
      pages_.back().el = &el;
      pages_.back().host = loose_;
      pages_.back().spec.loc = el.loc;
    }
    return loose_;
  }

  /// Reads the nodes, arcs and pages inside `el`, which is the page `page` (or the net: -1).
  void collect(const XmlElement& el, int page) {
    for (const auto& cp : el.children) {
      const XmlElement& c = *cp;
      if (c.name == "page") {
        const int index = static_cast<int>(pages_.size());
        pages_.push_back({});
        Page& p = pages_.back();
        p.el = &c;
        p.parent = page;
        p.host = index;
        p.spec.loc = p.instance.loc = p.instance.type_loc = c.loc;
        if (const XmlElement* tool = gdpnPart(c)) pagePart(*tool, pages_[static_cast<std::size_t>(index)]);
        collect(c, index);
      } else if (c.name == "place" || c.name == "transition" || (c.name == "referencePlace" && isMember(c))) {
        auto id = idOf(c);
        if (!id) continue;
        const XmlElement* tool = gdpnPart(c);
        const bool is_place = c.name != "transition";
        Node node{is_place ? Node::Kind::Place : Node::Kind::Transition, pageFor(el, page), 0, &c};
        if (is_place) {
          PlaceSpec p;
          p.name = nameFor(*id, tool);
          p.loc = c.loc;
          p.description = describe(c, tool, p.name, *id);
          if (const XmlElement* m = c.child("initialMarking")) {
            if (auto n = integer(*m, textOf(m), "an initial marking"); n && *n > 0) {
              p.tokens.push_back({kDefaultSlot, *n, m->loc, {}});
            }
          }
          if (symmetric_) highLevelPlace(c, p);
          p.position = position(c);
          if (tool) placePart(*tool, p);
          node.index = places_.size();
          places_.push_back(std::move(p));
        } else {
          TransitionSpec t;
          t.name = nameFor(*id, tool);
          t.loc = t.duration.loc = t.probability_loc = t.servers_loc = c.loc;
          t.description = describe(c, tool, t.name, *id);
          t.position = position(c);
          if (const XmlElement* when = symmetric_ ? c.child("condition") : nullptr) {
            if (auto text = colour_.term(*when)) t.when = {kDefaultSlot, *text, when->loc};
          }
          if (tool) transitionPart(*tool, t);
          node.index = transitions_.size();
          transitions_.push_back(std::move(t));
        }
        ids_[*id] = node;
      } else if (c.name == "referencePlace" || c.name == "referenceTransition") {
        auto id = idOf(c);
        if (!id) continue;
        ids_[*id] = {c.name == "referencePlace" ? Node::Kind::ReferencePlace : Node::Kind::ReferenceTransition,
                     pageFor(el, page), 0, &c};
        references_.push_back(*id);
      } else if (c.name == "arc") {
        RawArc a;
        a.page = pageFor(el, page);
        a.el = &c;
        arcs_.push_back(std::move(a));
      }
    }
  }

  /// True for a referencePlace that gdpn wrote for a member of a fusion set (its part names the
  /// set): a place of its own page, one with the place it refers to.
  bool isMember(const XmlElement& el) {
    for (const auto& c : el.children) {
      if (c->name != "toolspecific" || !c->attr("tool") || *c->attr("tool") != detail::kPnmlTool) continue;
      if (c->child("fusion")) return true;
    }
    return false;
  }

  /// Gives every page its name: gdpn's own; `net` for the one page of a net; else its id, cleaned.
  void namePages() {
    for (auto& p : pages_) {
      if (!p.named) {
        const std::string* id = p.el->attr("id");
        p.spec.name = pages_.size() == 1 ? "net" : nameFor(p.el->name == "page" && id ? *id : "net");
      }
      p.instance.name = p.spec.name;
      if (p.instance.type.empty()) p.instance.type = p.spec.name;
    }
  }

  // ---- references and arcs ----------------------------------------------------------------

  /// Follows every reference node to the place or transition it stands for; a reference to
  /// nothing, to a node of the other kind, or in a cycle of references is an error.
  void resolveReferences() {
    for (const auto& start : references_) {
      if (target_.count(start)) continue;
      std::vector<std::string> chain{start};
      std::string found;  // the place or transition at the end; "" when there is none
      for (std::string cur = start;;) {
        const Node& node = ids_.at(cur);
        if (node.kind == Node::Kind::Place || node.kind == Node::Kind::Transition) {
          found = cur;
          break;
        }
        const std::string* to = node.el->attr("ref");
        if (!to) {
          diags_.error(node.el->loc, what(*node.el) + " has no ref (the id of the node it stands for)");
          break;
        }
        if (auto known = target_.find(*to); known != target_.end()) {
          found = known->second;
          break;
        }
        if (!ids_.count(*to)) {
          diags_.error(node.el->loc, what(*node.el) + " refers to '" + *to + "', which is no node of the net");
          break;
        }
        if (auto again = std::find(chain.begin(), chain.end(), *to); again != chain.end()) {
          std::string cycle;
          for (auto it = again; it != chain.end(); ++it) cycle += "'" + *it + "' -> ";
          diags_.error(ids_.at(*to).el->loc, "the references " + cycle + "'" + *to +
                                                 "' form a cycle: none of them reaches a place or transition");
          break;
        }
        chain.push_back(*to);
        cur = *to;
      }
      for (const auto& c : chain) target_[c] = found;
    }
    // a reference stands for a node of its own kind
    for (const auto& r : references_) {
      const Node& ref = ids_.at(r);
      const std::string& to = target_.at(r);
      if (to.empty()) continue;
      const bool place = ref.kind == Node::Kind::ReferencePlace;
      if (place != (ids_.at(to).kind == Node::Kind::Place)) {
        diags_.error(ref.el->loc, what(*ref.el) + " stands for " + (place ? "transition" : "place") + " '" + to +
                                      "'; a " + ref.el->name + " stands for a " + (place ? "place" : "transition"));
        target_[r].clear();
      }
    }
  }

  /// Reads an arc: its kind, weight and gdpn's part, and the place and transition it joins.
  void readEnds(RawArc& raw) {
    const XmlElement& el = *raw.el;
    ArcSpec& a = raw.spec;
    a.loc = a.from_loc = a.to_loc = el.loc;
    std::string kind = el.attr("type") ? *el.attr("type") : "";
    if (const XmlElement* ty = el.child("type"); ty && ty->attr("value")) kind = *ty->attr("value");
    if (kind == "inhibitor") a.kind = ArcKind::Inhibitor;
    else if (kind == "test" || kind == "read") a.kind = ArcKind::Test;
    if (const XmlElement* w = el.child("inscription")) {
      if (auto n = integer(*w, textOf(w), "an arc inscription"); n && *n != 1) a.weights.push_back({kDefaultSlot, *n, w->loc, {}});
      // where the inscription stands: PNML's offset from its arc
      const XmlElement* g = w->child("graphics");
      a.label_at = point(g ? g->child("offset") : nullptr);
    }
    if (const XmlElement* h = symmetric_ ? el.child("hlinscription") : nullptr) {
      if (auto text = colour_.term(*h)) a.inscriptions.push_back({kDefaultSlot, *text, h->loc});
      const XmlElement* g = h->child("graphics");
      a.label_at = point(g ? g->child("offset") : nullptr);
    }
    a.via = route(el);
    if (const XmlElement* tool = gdpnPart(el)) arcPart(*tool, a, el);

    const std::string* src = el.attr("source");
    const std::string* dst = el.attr("target");
    if (!el.attr("id")) diags_.error(el.loc, "<arc> has no id");
    if (!src || !dst) {
      diags_.error(el.loc, "<arc> needs a source and a target");
      return;
    }
    auto s = ids_.find(*src), t = ids_.find(*dst);
    if (s == ids_.end()) diags_.error(el.loc, "arc source '" + *src + "' names no place or transition (nor a reference to one)");
    if (t == ids_.end()) diags_.error(el.loc, "arc target '" + *dst + "' names no place or transition (nor a reference to one)");
    if (s == ids_.end() || t == ids_.end()) return;
    const std::string from = real(*src), to = real(*dst);
    if (from.empty() || to.empty()) return;  // a broken reference, reported
    const bool from_place = ids_.at(from).kind == Node::Kind::Place;
    const std::string& written = from_place ? *src : *dst;
    if (ids_.at(written).kind == Node::Kind::ReferencePlace) raw.via = written;
    if (from_place == (ids_.at(to).kind == Node::Kind::Place)) {
      diags_.error(el.loc, "arc '" + *src + "' -> '" + *dst + "' joins two " + (from_place ? "places" : "transitions"));
      return;
    }
    raw.from_place = from_place;
    raw.place = from_place ? from : to;
    raw.transition = from_place ? to : from;
  }

  /// The place or transition id `id` stands for (itself, or what a reference leads to; "" for none).
  std::string real(const std::string& id) const {
    auto t = target_.find(id);
    return t == target_.end() ? id : t->second;
  }

  int host(int page) {
    while (pages_[static_cast<std::size_t>(page)].host != page) page = pages_[static_cast<std::size_t>(page)].host;
    return page;
  }
  /// The page that `h` (a host) lies inside, as read; -1 for a top-level one.
  int parentOf(int h) {
    const int p = pages_[static_cast<std::size_t>(h)].parent;
    return p < 0 ? -1 : host(p);
  }
  int depth(int h) {
    int d = 0;
    for (int p = parentOf(h); p >= 0; p = parentOf(p)) ++d;
    return d;
  }

  /// True when an arc of transition `transition` reaches place `place` as gdpn draws arcs:
  /// on the transition's page, or as a link to a page directly inside it.
  bool linkable(const RawArc& a) {
    const int t = host(ids_.at(a.transition).page), p = host(ids_.at(a.place).page);
    return t == p || parentOf(p) == t;
  }
  /// True when arc `a` reaches its place through a referencePlace on its transition's page,
  /// which can be a member of a fusion set with the place.
  bool viaReference(const RawArc& a) {
    return !a.via.empty() && host(ids_.at(a.via).page) == host(ids_.at(a.transition).page);
  }

  /// An arc that reaches a place of another page through a referencePlace on its own page makes
  /// that reference a member of a fusion set with the place. The pages of other arcs that gdpn
  /// cannot draw on one page are made one: an arc lies on its transition's page and reaches
  /// places of that page and, as links, of pages directly inside it.
  void placeArcs() {
    for (bool changed = true; changed;) {
      changed = false;
      for (const auto& a : arcs_) {
        if (a.place.empty() || linkable(a) || viaReference(a)) continue;
        const int t = host(ids_.at(a.transition).page), p = host(ids_.at(a.place).page);
        // the deeper page goes into the one around it; of two top-level pages, the later into the earlier
        int from = 0, into = 0;
        if (parentOf(t) < 0 && parentOf(p) < 0) {
          from = std::max(t, p), into = std::min(t, p);
        } else if (parentOf(t) >= 0 && depth(t) >= depth(p)) {
          from = t, into = parentOf(t);
        } else {
          from = p, into = parentOf(p);
        }
        diags_.warning(a.el->loc, "page '" + name(from) + "' is read as part of page '" + name(into) + "': arc '" +
                                      (a.el->attr("id") ? *a.el->attr("id") : std::string()) + "' joins transition '" +
                                      transitions_[ids_.at(a.transition).index].name + "' of page '" + name(t) +
                                      "' and place '" + places_[ids_.at(a.place).index].name + "' of page '" + name(p) +
                                      "', and a transition's arcs reach only places of its own page and of pages "
                                      "directly inside it (or a referencePlace on its page, a fusion place)");
        pages_[static_cast<std::size_t>(from)].host = into;
        changed = true;
      }
    }
    for (auto& a : arcs_) {
      if (a.place.empty() || linkable(a)) continue;
      a.place = member(a.via, a.place);
    }
  }

  /// Makes referencePlace `ref` a place of its page, a member of the fusion set of place
  /// `target` (one named after it, global, where it is in none); returns `ref`.
  const std::string& member(const std::string& ref, const std::string& target) {
    Node& node = ids_.at(ref);
    if (node.kind == Node::Kind::Place) return ref;  // made a member by an arc before
    PlaceSpec& declarer = places_[ids_.at(target).index];
    if (declarer.fusion.empty()) {
      std::string set = declarer.name;
      for (int n = 2; fusion_names_.count(set); ++n) set = declarer.name + "_" + std::to_string(n);
      fusion_names_.insert(set);
      fusions_.push_back({set, FusionScope::Global, declarer.loc});
      declarer.fusion = set;
      declarer.fusion_loc = declarer.loc;
    }
    PlaceSpec p;
    const XmlElement& el = *node.el;
    const XmlElement* tool = gdpnPart(el);
    p.name = nameFor(ref, tool);
    p.loc = p.fusion_loc = el.loc;
    p.description = describe(el, tool, p.name, ref);
    p.position = position(el);
    p.fusion = places_[ids_.at(target).index].fusion;
    node.kind = Node::Kind::Place;
    node.index = places_.size();
    places_.push_back(std::move(p));
    return ref;
  }

  const std::string& name(int page) const { return pages_[static_cast<std::size_t>(page)].spec.name; }

  /// Moves everything read into `spec`: top-level pages as pages, pages inside others as page
  /// types instantiated once, places, transitions and arcs on their pages.
  void build(NetSpec& spec) {
    // arcs on their transitions' pages, named before the nodes move
    for (auto& a : arcs_) {
      const Node& pn = ids_.at(a.place);
      const Node& tn = ids_.at(a.transition);
      const int t = host(tn.page), p = host(pn.page);
      const std::string& place = places_[pn.index].name;
      std::string end = place;
      if (p != t) {
        // a link to a place of the page inside, which its type publishes
        Page& inner = pages_[static_cast<std::size_t>(p)];
        end = inner.instance.name + "/" + place;
        auto& refs = inner.spec.references;
        if (std::none_of(refs.begin(), refs.end(), [&](const ReferenceSpec& r) { return r.place == place; })) {
          refs.push_back({place, a.el->loc});
        }
      }
      const std::string& transition = transitions_[tn.index].name;
      a.spec.from = a.from_place ? end : transition;
      a.spec.to = a.from_place ? transition : end;
      pages_[static_cast<std::size_t>(t)].spec.arcs.push_back(std::move(a.spec));
    }
    // places and transitions in document order, each on its page
    std::vector<int> place_page(places_.size()), transition_page(transitions_.size());
    for (const auto& [id, n] : ids_) {
      if (n.kind == Node::Kind::Place) place_page[n.index] = n.page;
      if (n.kind == Node::Kind::Transition) transition_page[n.index] = n.page;
    }
    for (std::size_t i = 0; i < places_.size(); ++i) {
      pages_[static_cast<std::size_t>(host(place_page[i]))].spec.places.push_back(std::move(places_[i]));
    }
    for (std::size_t i = 0; i < transitions_.size(); ++i) {
      pages_[static_cast<std::size_t>(host(transition_page[i]))].spec.transitions.push_back(std::move(transitions_[i]));
    }
    // pages in document order; one inside another is a page type, instantiated on the page around it
    for (std::size_t i = 0; i < pages_.size(); ++i) {
      Page& p = pages_[i];
      if (p.host != static_cast<int>(i) || p.parent < 0) continue;
      p.spec.name = p.instance.type;
      pages_[static_cast<std::size_t>(parentOf(static_cast<int>(i)))].spec.instances.push_back(p.instance);
    }
    for (std::size_t i = 0; i < pages_.size(); ++i) {
      Page& p = pages_[i];
      if (p.host == static_cast<int>(i)) (p.parent < 0 ? spec.pages : spec.page_types).push_back(std::move(p.spec));
    }
  }

  std::string file_;
  core::Diagnostics& diags_;
  bool symmetric_ = false;              // a symmetric net: its high-level parts are read
  detail::PnmlColourReader colour_{diags_};
  std::vector<Page> pages_;
  int loose_ = -1;                      // the page made for nodes outside any page, if any
  std::vector<PlaceSpec> places_;       // in document order
  std::vector<TransitionSpec> transitions_;
  std::vector<RawArc> arcs_;
  std::unordered_map<std::string, Node> ids_;          // every node by id
  std::vector<std::string> references_;                // reference nodes' ids, in document order
  std::unordered_map<std::string, std::string> target_;  // reference id -> the node it stands for ("" for none)
  std::unordered_set<std::string> used_;               // names given so far
  std::vector<FusionSpec> fusions_;                     // fusion sets, declared or made for references
  std::unordered_set<std::string> fusion_names_;        // their names
};

}  // namespace

std::optional<NetSpec> parsePnml(const std::string& text, const std::string& file, core::Diagnostics& diags,
                                 std::string* net_name) {
  if (!core::checkUtf8(text, file, diags)) return std::nullopt;
  auto root = detail::parseXml(text, file, diags);
  if (!root) return std::nullopt;
  return PnmlReader(file, diags).read(*root, net_name);
}

std::optional<NetSpec> loadPnml(const std::string& path, core::Diagnostics& diags, std::string* net_name) {
  auto text = core::readFile(path, diags);
  return text ? parsePnml(*text, path, diags, net_name) : std::nullopt;
}

}  // namespace gdpn::net
