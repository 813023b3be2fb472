// The inscription language's type checker: bidirectional, each node checked against the set its
// context expects where there is one (an arc's place, a tuple's component, the other side of a
// comparison), its own set inferred where there is none.

#include <algorithm>

#include "gdpn/net/inscription.h"

namespace gdpn::net {
namespace {

// what a node's context asks of it
struct Want {
  std::optional<ColourId> set;  // the set it must be of, when known
  bool multiset = false;        // whether a multiset may stand here
};

class Checker {
 public:
  Checker(const InscriptionScope& scope, std::vector<std::uint32_t>& used, core::Diagnostics& diags)
      : scope_(scope), c_(*scope.colours), used_(used), diags_(diags) {}

  // checks `e` against `w`; false after reporting (once) what is wrong
  bool check(Expr& e, Want w) {
    switch (e.op) {
      case Expr::Op::Const: return literal(e, w);
      case Expr::Op::Name: return name(e, w);
      case Expr::Op::Var: return variable(e, w);
      case Expr::Op::Tuple: return tuple(e, w);
      case Expr::Op::Record: return record(e, w);
      case Expr::Op::Field: return field(e, w);
      case Expr::Op::Neg:
      case Expr::Op::Add:
      case Expr::Op::Sub:
      case Expr::Op::Mul:
      case Expr::Op::Div:
      case Expr::Op::Mod: return arithmetic(e, w);
      case Expr::Op::Not:
      case Expr::Op::And:
      case Expr::Op::Or: return logic(e, w);
      case Expr::Op::Eq:
      case Expr::Op::Ne:
      case Expr::Op::Lt:
      case Expr::Op::Le:
      case Expr::Op::Gt:
      case Expr::Op::Ge: return comparison(e, w);
      case Expr::Op::If: return conditional(e, w);
      case Expr::Op::Succ:
      case Expr::Op::Pred: return successor(e, w);
      case Expr::Op::Times: return times(e, w);
      case Expr::Op::Sum: return sum(e, w);
      case Expr::Op::All: return all(e, w);
      case Expr::Op::Empty: return empty(e, w);
    }
    return fail(e, "unknown kind of node");
  }

 private:
  bool fail(const Expr& e, std::string message) {
    diags_.error(e.loc, std::move(message));
    return false;
  }
  const ColourSet& set(ColourId id) const { return c_.at(id); }
  std::string nameOf(ColourId id) const { return set(id).name; }

  // two sets whose values can stand for each other: the same set; two integer sets (a range
  // is checked when a value is made); two sets of one simple kind (bool, dot, string); products
  // and records of such components
  bool compatible(ColourId a, ColourId b) const {
    if (a == b) return true;
    const ColourSet& x = set(a);
    const ColourSet& y = set(b);
    if (x.kind != y.kind) return false;
    switch (x.kind) {
      case ColourKind::Dot:
      case ColourKind::Bool:
      case ColourKind::Integer:
      case ColourKind::String: return true;
      case ColourKind::Enum: return false;
      case ColourKind::Product:
      case ColourKind::Record:
        if (x.components.size() != y.components.size() || x.fields != y.fields) return false;
        for (std::size_t k = 0; k < x.components.size(); ++k) {
          if (!compatible(x.components[k], y.components[k])) return false;
        }
        return true;
    }
    return false;
  }

  // the node holds one value of `found`: is that what the context wants?
  bool single(Expr& e, const Want& w, ColourId found) {
    if (w.set && !compatible(*w.set, found)) return fail(e, "expected " + nameOf(*w.set) + ", found " + nameOf(found));
    e.type = found;
    e.multiset = false;
    return true;
  }
  // the node is a multiset of `found`
  bool many(Expr& e, const Want& w, ColourId found) {
    if (!w.multiset) {
      return fail(e, w.set ? "expected a single value of " + nameOf(*w.set) + ", found a multiset"
                           : "expected a single value, found a multiset");
    }
    if (w.set && !compatible(*w.set, found)) {
      return fail(e, "expected " + nameOf(*w.set) + ", found a multiset of " + nameOf(found));
    }
    e.type = found;
    e.multiset = true;
    return true;
  }
  bool kindIs(std::optional<ColourId> id, ColourKind k) const { return id && set(*id).kind == k; }

  // a number, a string, true/false or dot: fits any set of its kind
  bool literal(Expr& e, const Want& w) {
    ColourKind kind = ColourKind::Dot;
    ColourId builtin = Colours::kDot;
    switch (e.value.tag) {
      case Value::Tag::Dot: break;
      case Value::Tag::Bool: kind = ColourKind::Bool, builtin = Colours::kBool; break;
      case Value::Tag::Int:
        // a constant resolved before (a tree checked twice) keeps its enumeration
        if (set(e.type).kind == ColourKind::Enum) return single(e, w, e.type);
        kind = ColourKind::Integer, builtin = Colours::kInt;
        break;
      case Value::Tag::String: kind = ColourKind::String, builtin = Colours::kString; break;
      case Value::Tag::Tuple:
        if (e.type < c_.sets().size() && c_.contains(e.type, e.value)) return single(e, w, e.type);
        return fail(e, "a tuple constant without its colour set");
    }
    return single(e, w, kindIs(w.set, kind) ? *w.set : builtin);
  }

  // a variable in scope or an enumeration's constant
  bool name(Expr& e, const Want& w) {
    const auto& names = scope_.variable_names;
    const auto it = std::find(names.begin(), names.end(), e.name);
    if (it != names.end()) {
      const auto v = static_cast<std::uint32_t>(it - names.begin());
      auto pos = std::find(used_.begin(), used_.end(), v);
      if (pos == used_.end()) {
        used_.push_back(v);
        pos = used_.end() - 1;
      }
      e.op = Expr::Op::Var;
      e.index = static_cast<std::int32_t>(pos - used_.begin());
      const ColourId found = v < scope_.variable_sets.size() ? scope_.variable_sets[v] : Colours::kDot;
      return single(e, w, found);
    }
    if (const auto k = c_.constant(e.name)) {
      e.op = Expr::Op::Const;
      e.value = Value::integer(k->second);
      return single(e, w, k->first);
    }
    return fail(e, "unknown name '" + e.name + "'");
  }
  // a variable resolved before: its set
  bool variable(Expr& e, const Want& w) {
    if (e.index < 0 || static_cast<std::size_t>(e.index) >= used_.size()) return fail(e, "a variable out of scope");
    const std::uint32_t v = used_[static_cast<std::size_t>(e.index)];
    return single(e, w, v < scope_.variable_sets.size() ? scope_.variable_sets[v] : Colours::kDot);
  }

  // the first product (or record, with `fields`) whose components fit `parts`
  std::optional<ColourId> findProduct(const std::vector<ColourId>& parts, const std::vector<std::string>* fields) const {
    for (ColourId id = 0; id < c_.sets().size(); ++id) {
      const ColourSet& s = set(id);
      if (s.kind != (fields != nullptr ? ColourKind::Record : ColourKind::Product)) continue;
      if (s.components.size() != parts.size()) continue;
      if (fields != nullptr && s.fields != *fields) continue;
      bool fits = true;
      for (std::size_t k = 0; k < parts.size() && fits; ++k) fits = compatible(s.components[k], parts[k]);
      if (fits) return id;
    }
    return std::nullopt;
  }

  // (a, b, ...): against a product, each component against its set; alone, the product its
  // components make
  bool tuple(Expr& e, const Want& w) {
    const Want part{std::nullopt, w.multiset};
    if (w.set) {
      const ColourSet& s = set(*w.set);
      if (s.kind != ColourKind::Product) return fail(e, "expected " + s.name + ", found a tuple");
      if (s.components.size() != e.args.size()) {
        return fail(e, "expected " + s.name + " (" + std::to_string(s.components.size()) + " components), found a tuple of " +
                           std::to_string(e.args.size()));
      }
      bool ok = true;
      bool anyMany = false;
      for (std::size_t k = 0; k < e.args.size(); ++k) {
        ok = check(e.args[k], Want{s.components[k], w.multiset}) && ok;
        anyMany = anyMany || e.args[k].multiset;
      }
      if (!ok) return false;
      e.type = *w.set;
      e.multiset = anyMany;
      return true;
    }
    std::vector<ColourId> parts;
    bool ok = true;
    bool anyMany = false;
    for (Expr& a : e.args) {
      ok = check(a, part) && ok;
      parts.push_back(a.type);
      anyMany = anyMany || a.multiset;
    }
    if (!ok) return false;
    const auto id = findProduct(parts, nullptr);
    if (!id) {
      std::string list;
      for (const ColourId p : parts) list += (list.empty() ? "" : ", ") + nameOf(p);
      return fail(e, "no colour set is a product of (" + list + ")");
    }
    e.type = *id;
    e.multiset = anyMany;
    return true;
  }

  // {f = a, ...}: against a record, every field once (in any order); alone, the record with
  // these fields
  bool record(Expr& e, const Want& w) {
    std::optional<ColourId> target = w.set;
    if (!target) {
      std::vector<std::string> sorted = e.fields;
      std::sort(sorted.begin(), sorted.end());
      for (ColourId id = 0; id < c_.sets().size() && !target; ++id) {
        std::vector<std::string> f = set(id).fields;
        std::sort(f.begin(), f.end());
        if (set(id).kind == ColourKind::Record && f == sorted) target = id;
      }
      if (!target) return fail(e, "no colour set is a record of these fields");
    }
    const ColourSet& s = set(*target);
    if (s.kind != ColourKind::Record) return fail(e, "expected " + s.name + ", found a record");
    bool ok = true;
    bool anyMany = false;
    std::vector<bool> given(s.fields.size(), false);
    for (std::size_t k = 0; k < e.args.size(); ++k) {
      const auto f = std::find(s.fields.begin(), s.fields.end(), e.fields[k]);
      if (f == s.fields.end()) {
        ok = fail(e.args[k], "record " + s.name + " has no field '" + e.fields[k] + "'") && ok;
        continue;
      }
      const auto at = static_cast<std::size_t>(f - s.fields.begin());
      if (given[at]) {
        ok = fail(e.args[k], "field '" + e.fields[k] + "' is given twice") && ok;
        continue;
      }
      given[at] = true;
      ok = check(e.args[k], Want{s.components[at], w.multiset}) && ok;
      anyMany = anyMany || e.args[k].multiset;
    }
    for (std::size_t k = 0; k < given.size() && ok; ++k) {
      if (!given[k]) ok = fail(e, "record " + s.name + " needs its field '" + s.fields[k] + "'");
    }
    if (!ok) return false;
    e.type = *target;
    e.multiset = anyMany;
    return true;
  }

  // r.f
  bool field(Expr& e, const Want& w) {
    if (!check(e.args[0], Want{})) return false;
    const ColourSet& s = set(e.args[0].type);
    if (s.kind != ColourKind::Record) return fail(e, "'." + e.name + "' needs a record, found " + s.name);
    const auto f = std::find(s.fields.begin(), s.fields.end(), e.name);
    if (f == s.fields.end()) return fail(e, "record " + s.name + " has no field '" + e.name + "'");
    e.index = static_cast<std::int32_t>(f - s.fields.begin());
    return single(e, w, s.components[static_cast<std::size_t>(e.index)]);
  }

  // an operand that must be a whole number (of any integer set)
  bool number(Expr& e, const char* what) {
    if (!check(e, Want{})) return false;
    if (set(e.type).kind != ColourKind::Integer) {
      return fail(e, std::string(what) + " needs a whole number, found " + nameOf(e.type));
    }
    return true;
  }
  // -a, a + b, ...: whole numbers; the result fits any integer set
  bool arithmetic(Expr& e, const Want& w) {
    bool ok = true;
    for (Expr& a : e.args) ok = number(a, "arithmetic") && ok;
    if (!ok) return false;
    return single(e, w, kindIs(w.set, ColourKind::Integer) ? *w.set : Colours::kInt);
  }
  // not, and, or: booleans
  bool logic(Expr& e, const Want& w) {
    bool ok = true;
    for (Expr& a : e.args) ok = check(a, Want{Colours::kBool, false}) && ok;
    if (!ok) return false;
    return single(e, w, kindIs(w.set, ColourKind::Bool) ? *w.set : Colours::kBool);
  }
  // a = b, a < b, ...: two single values of one type; an order on numbers, enumeration
  // constants and strings
  bool comparison(Expr& e, const Want& w) {
    // the side that knows its own set goes first: a tuple or record takes the other's
    const bool swap = (e.args[0].op == Expr::Op::Tuple || e.args[0].op == Expr::Op::Record) &&
                      e.args[1].op != Expr::Op::Tuple && e.args[1].op != Expr::Op::Record;
    Expr& first = e.args[swap ? 1 : 0];
    Expr& second = e.args[swap ? 0 : 1];
    if (!check(first, Want{})) return false;
    if (!check(second, Want{first.type, false})) return false;
    const bool order = e.op != Expr::Op::Eq && e.op != Expr::Op::Ne;
    const ColourKind k = set(first.type).kind;
    if (order && k != ColourKind::Integer && k != ColourKind::Enum && k != ColourKind::String) {
      return fail(e, "only numbers, enumeration constants and strings are ordered, not " + nameOf(first.type));
    }
    return single(e, w, kindIs(w.set, ColourKind::Bool) ? *w.set : Colours::kBool);
  }
  // if c then a else b: both branches of one type
  bool conditional(Expr& e, const Want& w) {
    bool ok = check(e.args[0], Want{Colours::kBool, false});
    if (!check(e.args[1], w)) return false;
    const Want other{w.set ? w.set : std::optional<ColourId>(e.args[1].type), w.multiset};
    if (!check(e.args[2], other)) return false;
    if (!ok) return false;
    e.type = w.set ? *w.set : e.args[1].type;
    e.multiset = e.args[1].multiset || e.args[2].multiset;
    return true;
  }
  // succ(x), pred(x): an enumeration or a number
  bool successor(Expr& e, const Want& w) {
    const bool hint = kindIs(w.set, ColourKind::Enum) || kindIs(w.set, ColourKind::Integer);
    if (!check(e.args[0], hint ? Want{w.set, false} : Want{})) return false;
    const ColourKind k = set(e.args[0].type).kind;
    if (k != ColourKind::Enum && k != ColourKind::Integer) {
      return fail(e, std::string(e.op == Expr::Op::Succ ? "'succ'" : "'pred'") +
                         " needs an enumeration or a number, found " + nameOf(e.args[0].type));
    }
    return single(e, w, e.args[0].type);
  }
  // n'v: n whole, v a value or a multiset
  bool times(Expr& e, const Want& w) {
    if (!w.multiset) return many(e, w, w.set.value_or(Colours::kDot));
    bool ok = check(e.args[0], Want{});
    if (ok && set(e.args[0].type).kind != ColourKind::Integer) {
      ok = fail(e.args[0], "the multiplicity of n'v needs a whole number, found " + nameOf(e.args[0].type));
    }
    if (!check(e.args[1], Want{w.set, true})) return false;
    if (!ok) return false;
    return many(e, w, e.args[1].type);
  }
  // a ++ b: multisets of one type
  bool sum(Expr& e, const Want& w) {
    if (!w.multiset) return many(e, w, w.set.value_or(Colours::kDot));
    if (!check(e.args[0], w)) return false;
    if (!check(e.args[1], Want{w.set ? w.set : std::optional<ColourId>(e.args[0].type), true})) return false;
    return many(e, w, w.set ? *w.set : e.args[0].type);
  }
  // all, all(S): every value of a finite set
  bool all(Expr& e, const Want& w) {
    std::optional<ColourId> s = w.set;
    if (!e.name.empty()) {
      s = c_.find(e.name);
      if (!s) return fail(e, "unknown colour set '" + e.name + "'");
    }
    if (!s) return fail(e, "'all' takes its colour set from its place here: write all(Set)");
    if (!set(*s).size) return fail(e, "'all' needs a finite colour set: " + nameOf(*s) + " is not");
    if (*set(*s).size > kMostValues) {
      return fail(e, "'all' of " + nameOf(*s) + " would be " + std::to_string(*set(*s).size) + " values, more than " +
                         std::to_string(kMostValues) + " (a range that large is for values bound by arcs)");
    }
    return many(e, w, *s);
  }
  // empty: the context says of what
  bool empty(Expr& e, const Want& w) {
    if (!w.set && w.multiset) return fail(e, "'empty' takes its colour set from its context, and there is none here");
    return many(e, w, w.set.value_or(Colours::kDot));
  }

  const InscriptionScope& scope_;
  const Colours& c_;
  std::vector<std::uint32_t>& used_;
  core::Diagnostics& diags_;
};

}  // namespace

bool checkInscription(Expr& e, ColourId set, Expect what, const InscriptionScope& scope, std::vector<std::uint32_t>& used,
                      core::Diagnostics& diags) {
  if (scope.colours == nullptr) {
    diags.error(e.loc, "an inscription checked without colour sets");
    return false;
  }
  Checker checker(scope, used, diags);
  switch (what) {
    case Expect::Tokens: return checker.check(e, {set, true});
    case Expect::Single: return checker.check(e, {set, false});
    case Expect::Condition: return checker.check(e, {Colours::kBool, false});
  }
  return false;
}

}  // namespace gdpn::net
