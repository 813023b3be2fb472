// The Model Checking Contest's property files: XML formulas over the PNML ids of a net's
// places and transitions, read into the same formulas as the text form.

#include <unordered_map>

#include "detail/xml.h"
#include "gdpn/net/pnml.h"
#include "gdpn/net/query.h"

namespace gdpn::net {
namespace {

using detail::XmlElement;

/// Names by their last part (a PNML id under its net's or page's path), none when several
/// share it; `lastPart(id)` gives the last part of construct id's name.
template <class IdType>
std::unordered_map<std::string_view, std::optional<IdType>> byLastPart(IdRange<IdType> ids, const auto& lastPart) {
  std::unordered_map<std::string_view, std::optional<IdType>> out;
  for (const IdType i : ids) {
    const auto [at, added] = out.emplace(lastPart(i), i);
    if (!added) at->second.reset();
  }
  return out;
}

/// A construct looked up by its PNML id: its id, or none (`shared` when several have its name).
template <class IdType>
struct Found {
  std::optional<IdType> id;
  bool shared = false;
};

class Reader {
 public:
  Reader(const Net& net, core::Diagnostics& diags, const NameExpansion* names)
      : net_(net),
        diags_(diags),
        names_(names),
        places_(byLastPart(net.placeIds(), [&](PlaceId p) { return net.placeLocalName(p); })),
        transitions_(byLastPart(net.transitionIds(), [&](TransitionId t) { return net.transitionLocalName(t); })) {}

  std::optional<Formula> formula(const XmlElement& e, std::size_t depth = 0) {
    if (depth > kMaxDepth) return fail(e, "the formula is nested more than 100 levels deep");
    Formula f;
    f.column = static_cast<std::size_t>(std::max(1, e.loc.column));
    const std::string& n = e.name;
    static const std::pair<const char*, FormulaKind> kUnary[] = {
        {"negation", FormulaKind::Not},      {"exists-path", FormulaKind::Exists}, {"all-paths", FormulaKind::All},
        {"finally", FormulaKind::Future},    {"globally", FormulaKind::Globally},  {"next", FormulaKind::Next},
        {"conjunction", FormulaKind::And},   {"disjunction", FormulaKind::Or}};
    for (const auto& [name, kind] : kUnary) {
      if (n != name) continue;
      f.kind = kind;
      const bool many = kind == FormulaKind::And || kind == FormulaKind::Or;
      if (e.children.empty() || (!many && e.children.size() != 1)) {
        return fail(e, "<" + n + "> takes " + (many ? "one formula or more" : "one formula"));
      }
      for (const auto& c : e.children) {
        auto sub = formula(*c, depth + 1);
        if (!sub) return std::nullopt;
        f.operands.push_back(std::move(*sub));
      }
      if (many && f.operands.size() == 1) return std::move(f.operands[0]);
      return f;
    }
    if (n == "until") {
      const XmlElement* before = e.child("before");
      const XmlElement* reach = e.child("reach");
      if (!before || !reach || before->children.size() != 1 || reach->children.size() != 1) {
        return fail(e, "<until> takes <before> and <reach>, one formula each");
      }
      f.kind = FormulaKind::Until;
      for (const XmlElement* side : {before, reach}) {
        auto sub = formula(*side->children[0], depth + 1);
        if (!sub) return std::nullopt;
        f.operands.push_back(std::move(*sub));
      }
      return f;
    }
    if (n == "true" || n == "false" || n == "deadlock") {
      f.kind = n == "true" ? FormulaKind::True : n == "false" ? FormulaKind::False : FormulaKind::Deadlock;
      return f;
    }
    if (n == "is-fireable") {
      f.kind = FormulaKind::Fireable;
      for (const auto& c : e.children) {
        if (c->name != "transition") return fail(*c, "<is-fireable> holds <transition> elements, not <" + c->name + ">");
        if (auto many = expansion(c->text, false)) {
          for (const std::string& name : *many) {
            if (auto id = net_.findTransition(name)) f.transitions.push_back(*id);
          }
          continue;
        }
        const auto t = find(net_.findTransition(c->text), transitions_, c->text);
        if (!t.id) return fail(*c, "no transition is called '" + c->text + "'" + (t.shared ? " for certain (two PNML ids share its name)" : ""));
        f.transitions.push_back(*t.id);
      }
      return f;
    }
    static const std::pair<const char*, Comparison> kCompare[] = {
        {"integer-le", Comparison::LessEqual}, {"integer-lt", Comparison::Less}, {"integer-eq", Comparison::Equal},
        {"integer-ne", Comparison::NotEqual},  {"integer-ge", Comparison::GreaterEqual},
        {"integer-gt", Comparison::Greater}};
    for (const auto& [name, cmp] : kCompare) {
      if (n != name) continue;
      if (e.children.size() != 2) return fail(e, "<" + n + "> compares two integer expressions");
      f.kind = FormulaKind::Compare;
      f.compare = cmp;
      if (!sum(*e.children[0], f.left) || !sum(*e.children[1], f.right)) return std::nullopt;
      return f;
    }
    if (n == "place-bound") {
      f.kind = FormulaKind::Bound;
      if (!places(e, f.left)) return std::nullopt;
      if (depth != 0) return fail(e, "<place-bound> is a number: it is a formula of its own");
      return f;
    }
    return fail(e, "<" + n + "> is not part of the contest's property language");
  }

 private:
  static constexpr std::size_t kMaxDepth = 100;
  std::nullopt_t fail(const XmlElement& e, std::string message) {
    diags_.error(e.loc, std::move(message));
    return std::nullopt;
  }
  // the name itself, else the one place (or transition) whose name's last part is the PNML id
  // as gdpn reads it (pnmlName: "t8.2" becomes "t8_2"); -2 when that could be another's
  template <class IdType>
  static Found<IdType> find(std::optional<IdType> exact,
                            const std::unordered_map<std::string_view, std::optional<IdType>>& by, const std::string& id) {
    if (exact) return {exact};
    const std::string name = pnmlName(id);
    const auto at = by.find(name);
    if (at == by.end()) return {};
    if (name != id && by.contains(name + "_")) return {std::nullopt, true};  // two ids gave this name
    return {at->second, !at->second};
  }
  /// What the name expansion lists for PNML id `id` (the place or transition it names, by its
  /// last part, as gdpn reads the id), or null.
  const std::vector<std::string>* expansion(const std::string& id, bool place) const {
    if (!names_) return nullptr;
    const auto& table = place ? names_->places : names_->transitions;
    for (const std::string& n : {id, pnmlName(id)}) {
      if (const auto at = table.find(n); at != table.end()) return &at->second;
      const std::vector<std::string>* found = nullptr;
      bool several = false;
      for (const auto& [key, names] : table) {
        if (key.size() > n.size() && key.ends_with(n) && key[key.size() - n.size() - 1] == '/') {
          several = several || found;
          found = &names;
        }
      }
      if (found && !several) return found;
    }
    return nullptr;
  }
  bool places(const XmlElement& e, TokenSum& out) {
    for (const auto& c : e.children) {
      if (c->name != "place") {
        fail(*c, "<" + e.name + "> holds <place> elements, not <" + c->name + ">");
        return false;
      }
      if (auto many = expansion(c->text, true)) {
        for (const std::string& name : *many) {
          const auto id = net_.findPlace(name);
          if (!id) continue;
          const Place& place = net_.places()[*id];
          for (auto k = place.slots_begin; k < place.slots_end; ++k) out.slots.emplace_back(k);
        }
        continue;
      }
      const auto p = find(net_.findPlace(c->text), places_, c->text);
      if (!p.id) {
        fail(*c, "no place is called '" + c->text + "'" + (p.shared ? " for certain (two PNML ids share its name)" : ""));
        return false;
      }
      const Place& place = net_.places()[*p.id];
      for (auto k = place.slots_begin; k < place.slots_end; ++k) out.slots.emplace_back(k);
    }
    return true;
  }
  bool sum(const XmlElement& e, TokenSum& out) {
    if (e.name == "tokens-count") return places(e, out);
    if (e.name == "integer-constant") {
      try {
        std::size_t used = 0;
        out.constant = std::stoll(e.text, &used);
        if (used == e.text.size() && out.constant >= -kMostConstant && out.constant <= kMostConstant) return true;
      } catch (const std::exception&) {
      }
      fail(e, "'" + e.text + "' is not a whole number of at most 2^60 in magnitude");
      return false;
    }
    fail(e, "<" + e.name + "> is not an integer expression (<tokens-count> or <integer-constant>)");
    return false;
  }

  const Net& net_;
  core::Diagnostics& diags_;
  const NameExpansion* names_;
  std::unordered_map<std::string_view, std::optional<PlaceId>> places_;
  std::unordered_map<std::string_view, std::optional<TransitionId>> transitions_;
};

}  // namespace

std::optional<std::vector<Property>> readMccProperties(const Net& net, const std::string& text,
                                                       const std::string& file, core::Diagnostics& diags,
                                                       const NameExpansion* names) {
  const auto root = detail::parseXml(text, file, diags);
  if (!root) return std::nullopt;
  if (root->name != "property-set") {
    diags.error(root->loc, "a property file holds a <property-set>, not <" + root->name + ">");
    return std::nullopt;
  }
  Reader reader(net, diags, names);
  std::vector<Property> out;
  bool ok = true;
  for (const auto& p : root->children) {
    if (p->name != "property") continue;
    const XmlElement* id = p->child("id");
    const XmlElement* formula = p->child("formula");
    if (!id || !formula || formula->children.size() != 1) {
      diags.error(p->loc, "a <property> holds an <id> and a <formula> of one element");
      ok = false;
      continue;
    }
    auto f = reader.formula(*formula->children[0]);
    if (!f) {
      ok = false;
      continue;
    }
    out.push_back({id->text, std::move(*f)});
  }
  if (!ok) return std::nullopt;
  return out;
}

}  // namespace gdpn::net
