#include "gdpn/net/coloured_invariants.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <numeric>
#include <set>

// Why what is found here is an invariant (semantics: *Invariants of a coloured net*).
//
// Take a finite colour set D of n values (or none: invariants over counts, n = 1). Each place
// slot gets one or more groups, each a way of reading its tokens as numbers per value of D:
// Value (the slot's set is D: the tokens of value d), Component j (the slot's set is a product
// or record whose component j is D: the tokens whose component j is d), or Count (every token,
// one number). A row is a group with an offset k (in a cyclic D, 0 <= k < n; else 0); for a
// member x of D, row (g, k) stands for the number g reads at d = x + k (the k-th successor).
//
// A binding b of transition t changes what group g reads at d by Δg(t, b)(d). The projection
// of an arc's inscription onto g is computed from the inscription's form (sums, n'e, tuples,
// `all`, if-then-else, a value) with only t's variables of set D bound (b_D): a part that
// would need another variable makes the group inexact for D, and every row of an inexact
// group is left out (weight 0). So for every exact group, Δg(t, b) = Δg(t, b_D) whatever the
// other variables are. Each transition contributes one column per b_D in D^k (its k variables
// of D, all combinations, the condition dropping only those it refutes from b_D alone): a
// superset of the bindings that occur, which only adds equations. A transition without
// inscriptions contributes one column of its terms' weights (Count groups).
//
// The equations: for every column (t, b_D) and every x in D, Σ_rows y(g, k)·Δg(t, b_D)(x + k)
// = 0. A semi-positive solution y gives, for each x, the weights
//     W_x(p, v) = Σ over rows (g, k) of p's groups that read v at x + k: y(g, k)
// on the unfolded net's places (p, v); W_x·Δ(t, b) is the equation at (t, b_D, x), so 0 for
// every occurring binding: each W_x is a P-invariant of the unfolded net, and the weighted sum
// W_x·M is the same in every reachable marking M. The Farkas algorithm (semiflowsOf) gives the
// minimal semi-positive solutions; in a cyclic D each family comes once per rotation, and is
// kept once. Nothing is found by unfolding: the rows number (groups x offsets), the equations
// (columns x n) before equal ones are merged.

namespace gdpn::net {
namespace {

using Sparse = std::vector<std::pair<std::uint32_t, std::int64_t>>;

/// One way of reading a place slot's tokens as numbers per value of D.
struct Group {
  PlaceSlotId ps{0u};
  Projection projection = Projection::Count;
  std::uint32_t component = 0;
  bool exact = true;
  std::string why;  // when not exact: the first reason
};

/// Projects inscriptions onto one group with only some variables bound.
class Projector {
 public:
  Projector(const Colours& colours, std::optional<ColourId> d) : colours_(colours), d_(d) {
    if (d_) values_ = colours_.values(*d_);
  }
  /// How many numbers a projection has: |D|, or 1 for Count.
  [[nodiscard]] std::size_t width(Projection p) const { return p == Projection::Count ? 1 : values_.size(); }
  /// The index of `v` among D's values.
  [[nodiscard]] std::optional<std::size_t> indexOf(const Value& v) const {
    const auto it = std::lower_bound(values_.begin(), values_.end(), v);
    if (it == values_.end() || !(*it == v)) return std::nullopt;
    return static_cast<std::size_t>(it - values_.begin());
  }
  [[nodiscard]] const std::vector<Value>& values() const { return values_; }

  /// The variables bound (by index): the rest must not be read.
  void setKnown(std::vector<bool> known) { known_ = std::move(known); }

  /// True when `e` reads only bound variables.
  [[nodiscard]] bool knownOnly(const Expr& e) const {
    if (e.op == Expr::Op::Var && (e.index < 0 || static_cast<std::size_t>(e.index) >= known_.size() ||
                                  !known_[static_cast<std::size_t>(e.index)])) {
      return false;
    }
    return std::all_of(e.args.begin(), e.args.end(), [&](const Expr& a) { return knownOnly(a); });
  }

  /// Adds `scale` times the projection of `e` (a multiset of, or one value of, set `set`) under
  /// `b` onto (`p`, `component`) to `out` (width(p) numbers). False when it is not a function
  /// of the bound variables alone, has no value there, or overflows.
  bool project(const Expr& e, ColourId set, Projection p, std::uint32_t component, const Binding& b,
               std::int64_t scale, std::vector<std::int64_t>& out) const {
    if (scale == 0) return true;
    switch (e.op) {
      case Expr::Op::Sum:
        return project(e.args[0], set, p, component, b, scale, out) &&
               project(e.args[1], set, p, component, b, scale, out);
      case Expr::Op::Times: {
        if (!knownOnly(e.args[0])) return false;
        const auto n = evaluate(e.args[0], b, colours_);
        std::int64_t t = 0;
        if (!n || n->tag != Value::Tag::Int || n->i < 0 || __builtin_mul_overflow(scale, n->i, &t)) return false;
        return project(e.args[1], set, p, component, b, t, out);
      }
      case Expr::Op::Empty: return true;
      case Expr::Op::If: {
        if (!knownOnly(e.args[0])) return !e.multiset && p == Projection::Count && add(out, 0, scale);
        const auto c = evaluate(e.args[0], b, colours_);
        if (!c || c->tag != Value::Tag::Bool) return false;
        return project(e.args[c->i != 0 ? 1 : 2], set, p, component, b, scale, out);
      }
      case Expr::Op::All: return all(set, p, component, scale, out);
      case Expr::Op::Tuple:
      case Expr::Op::Record:
        if (e.multiset) {
          if (p != Projection::Value) return combinations(e, set, p, component, b, scale, out);
          break;  // D is the product itself: evaluated whole below
        }
        if (p == Projection::Component) {
          const auto arg = argOf(e, component);
          if (!arg || !knownOnly(*arg)) return false;
          const auto v = evaluate(*arg, b, colours_);
          return v && addValue(out, *v, scale);
        }
        break;
      case Expr::Op::Const:
      case Expr::Op::Name:
      case Expr::Op::Var:
      case Expr::Op::Field:
      case Expr::Op::Neg:
      case Expr::Op::Not:
      case Expr::Op::Add:
      case Expr::Op::Sub:
      case Expr::Op::Mul:
      case Expr::Op::Div:
      case Expr::Op::Mod:
      case Expr::Op::Eq:
      case Expr::Op::Ne:
      case Expr::Op::Lt:
      case Expr::Op::Le:
      case Expr::Op::Gt:
      case Expr::Op::Ge:
      case Expr::Op::And:
      case Expr::Op::Or:
      case Expr::Op::Succ:
      case Expr::Op::Pred: break;
    }
    // one value counts one token; else the whole is evaluated, which needs every variable it reads
    if (!e.multiset && p == Projection::Count) return add(out, 0, scale);
    if (!knownOnly(e)) return false;
    if (!e.multiset) {
      const auto v = evaluate(e, b, colours_);
      return v && colours_.contains(set, *v) && addProjected(out, *v, p, component, scale);
    }
    Multiset m;
    if (!evaluateInto(e, b, colours_, set, m)) return false;
    for (const auto& [v, k] : m) {
      std::int64_t t = 0;
      if (__builtin_mul_overflow(scale, k, &t) || !addProjected(out, v, p, component, t)) return false;
    }
    return true;
  }

 private:
  static bool add(std::vector<std::int64_t>& out, std::size_t at, std::int64_t n) {
    return !__builtin_add_overflow(out[at], n, &out[at]);
  }
  bool addValue(std::vector<std::int64_t>& out, const Value& v, std::int64_t n) const {
    const auto at = indexOf(v);
    return at && add(out, *at, n);
  }
  bool addProjected(std::vector<std::int64_t>& out, const Value& v, Projection p, std::uint32_t component,
                    std::int64_t n) const {
    switch (p) {
      case Projection::Count: return add(out, 0, n);
      case Projection::Value: return addValue(out, v, n);
      case Projection::Component: return component < v.items.size() && addValue(out, v.items[component], n);
    }
    return false;
  }

  /// The argument of tuple or record `e` that gives component `k` of its value.
  const Expr* argOf(const Expr& e, std::size_t k) const {
    if (e.op == Expr::Op::Tuple) return k < e.args.size() ? &e.args[k] : nullptr;
    if (e.type >= colours_.sets().size()) return nullptr;
    const auto& fields = colours_.at(e.type).fields;
    if (k >= fields.size()) return nullptr;
    const auto it = std::find(e.fields.begin(), e.fields.end(), fields[k]);
    if (it == e.fields.end()) return nullptr;
    return &e.args[static_cast<std::size_t>(it - e.fields.begin())];
  }

  /// `all` of `set`: every value once.
  bool all(ColourId set, Projection p, std::uint32_t component, std::int64_t scale,
           std::vector<std::int64_t>& out) const {
    const auto size = colours_.at(set).size;
    if (!size) return false;
    switch (p) {
      case Projection::Count: {
        std::int64_t t = 0;
        return !__builtin_mul_overflow(scale, *size, &t) && add(out, 0, t);
      }
      case Projection::Value:
        for (std::size_t i = 0; i < out.size(); ++i) {
          if (!add(out, i, scale)) return false;
        }
        return true;
      case Projection::Component: {
        // a product's values: each value of one component as often as the others combine
        const auto& s = colours_.at(set);
        if (component >= s.components.size()) return false;
        std::int64_t others = 1;
        for (std::size_t k = 0; k < s.components.size(); ++k) {
          if (k == component) continue;
          const auto n = colours_.at(s.components[k]).size;
          if (!n || __builtin_mul_overflow(others, *n, &others)) return false;
        }
        std::int64_t t = 0;
        if (__builtin_mul_overflow(scale, others, &t)) return false;
        for (std::size_t i = 0; i < out.size(); ++i) {
          if (!add(out, i, t)) return false;
        }
        return true;
      }
    }
    return false;
  }

  /// A tuple or record with a multiset among its components: every combination.
  bool combinations(const Expr& e, ColourId set, Projection p, std::uint32_t component, const Binding& b,
                    std::int64_t scale, std::vector<std::int64_t>& out) const {
    const auto& s = colours_.at(set);
    if ((s.kind != ColourKind::Product && s.kind != ColourKind::Record) || s.components.size() != e.args.size()) {
      return false;
    }
    // how many values each component other than the projected one has: a number alone
    std::int64_t others = 1;
    for (std::size_t k = 0; k < s.components.size(); ++k) {
      if (p == Projection::Component && k == component) continue;
      const Expr* arg = argOf(e, k);
      std::vector<std::int64_t> n(1, 0);
      if (arg == nullptr || !project(*arg, s.components[k], Projection::Count, 0, b, 1, n) ||
          __builtin_mul_overflow(others, n[0], &others)) {
        return false;
      }
    }
    std::int64_t t = 0;
    if (__builtin_mul_overflow(scale, others, &t)) return false;
    switch (p) {
      case Projection::Count: return add(out, 0, t);
      case Projection::Component: {
        const Expr* arg = argOf(e, component);
        return arg != nullptr && component < s.components.size() &&
               project(*arg, s.components[component], Projection::Value, 0, b, t, out);
      }
      case Projection::Value: break;  // not called so
    }
    return false;
  }

  const Colours& colours_;
  std::optional<ColourId> d_;
  std::vector<Value> values_;
  std::vector<bool> known_;
};

/// The greatest common divisor of a row's values made 1, its first value positive.
void normalise(Sparse& row) {
  std::int64_t g = 0;
  for (const auto& [k, v] : row) g = std::gcd(g, v < 0 ? -v : v);
  const std::int64_t sign = row.front().second < 0 ? -1 : 1;
  for (auto& [k, v] : row) v = v / g * sign;
}

/// The invariants over D (none: over counts) of `net`, into `out`.
void solve(const Net& net, std::optional<ColourId> d, const ColouredInvariantOptions& options,
           ColouredInvariants& out) {
  const Colouring* colouring = net.colouring();
  static const Colours kBuiltins;
  const Colours& colours = colouring != nullptr ? colouring->colours : kBuiltins;
  Projector projector(colours, d);
  const std::size_t n = d ? projector.values().size() : 1;
  const bool cyclic = d && colours.at(*d).kind == ColourKind::Enum && colours.at(*d).cyclic;
  const std::string over = d ? "over " + colours.at(*d).name + ": " : std::string("over counts: ");

  // the groups of each place slot
  std::vector<Group> groups;
  std::vector<std::vector<std::uint32_t>> groups_of(net.placeSlots().size());
  for (PlaceSlotId ps : net.placeSlotIds()) {
    const auto set = colouring != nullptr ? colouring->setOf(ps) : std::nullopt;
    auto adopt = [&](Projection p, std::uint32_t component) {
      groups_of[ps].push_back(static_cast<std::uint32_t>(groups.size()));
      groups.push_back({ps, p, component, true, {}});
    };
    if (d && set && *set == *d) {
      adopt(Projection::Value, 0);
    } else if (d && set) {
      const auto& s = colours.at(*set);
      if (s.kind == ColourKind::Product || s.kind == ColourKind::Record) {
        for (std::uint32_t k = 0; k < s.components.size(); ++k) {
          if (s.components[k] == *d) adopt(Projection::Component, k);
        }
      }
    }
    if (groups_of[ps].empty()) adopt(Projection::Count, 0);
  }
  auto inexact = [&](std::uint32_t g, std::string why) {
    if (groups[g].exact) groups[g].why = std::move(why);
    groups[g].exact = false;
  };

  // the columns: per transition and binding of its variables of D, each group's change
  using Column = std::map<std::uint32_t, std::vector<std::int64_t>>;
  std::vector<Column> columns;
  for (TransitionId t : net.transitionIds()) {
    const TransitionInscriptions* ti = colouring != nullptr ? colouring->of(t) : nullptr;
    const std::string name = "'" + net.transitionName(t) + "'";
    // what the terms of slots without values do (the same in every binding)
    Column fixed;
    for (const Term& term : net.termsOf(t)) {
      if (term.kind != TermKind::Input && term.kind != TermKind::Output) continue;
      if (colouring != nullptr && colouring->setOf(term.place_slot)) {
        if (ti == nullptr) {
          for (auto g : groups_of[term.place_slot]) inexact(g, "transition " + name + " has a weight on it");
        }
        continue;
      }
      for (auto g : groups_of[term.place_slot]) {
        auto& v = fixed.try_emplace(g, projector.width(groups[g].projection), 0).first->second;
        v[0] += term.kind == TermKind::Input ? -std::int64_t{term.weight} : std::int64_t{term.weight};
      }
    }
    if (ti == nullptr) {
      columns.push_back(std::move(fixed));
      continue;
    }
    const auto c = static_cast<std::size_t>(colouring->of_transition[t]);
    std::vector<std::size_t> mine;  // the variables of D
    std::vector<bool> known(ti->variables.size(), false);
    for (std::size_t k = 0; k < ti->sets.size(); ++k) {
      if (d && ti->sets[k] == *d) {
        mine.push_back(k);
        known[k] = true;
      }
    }
    projector.setKnown(known);
    const bool judge = ti->when && projector.knownOnly(*ti->when);
    Binding b(ti->variables.size());
    std::vector<std::size_t> at(mine.size(), 0);
    for (bool more = true; more;) {
      for (std::size_t k = 0; k < mine.size(); ++k) b[mine[k]] = projector.values()[at[k]];
      // the next combination (the last variable fastest)
      more = false;
      for (std::size_t k = mine.size(); k-- > 0;) {
        if (++at[k] < n) {
          more = true;
          break;
        }
        at[k] = 0;
      }
      if (judge) {
        const auto holds = evaluate(*ti->when, b, colours);
        if (holds && holds->tag == Value::Tag::Bool && holds->i == 0) continue;
      }
      Column col = fixed;
      for (std::size_t a = 0; a < ti->arcs.size(); ++a) {
        const ArcInscription& arc = ti->arcs[a];
        const std::int64_t sign = arc.role == ArcRole::Take ? -1 : arc.role == ArcRole::Put ? 1 : 0;
        if (sign == 0) continue;
        const PlaceSlotId ps = net.terms()[colouring->arc_terms[c][a]].place_slot;
        for (auto g : groups_of[ps]) {
          if (!groups[g].exact) continue;
          auto& v = col.try_emplace(g, projector.width(groups[g].projection), 0).first->second;
          if (!projector.project(arc.expr, arc.set, groups[g].projection, groups[g].component, b, sign, v)) {
            inexact(g, d ? "what an inscription of transition " + name + " moves there is not a function of its " +
                               colours.at(*d).name + " variables alone (or has no value)"
                         : "how many tokens an inscription of transition " + name + " moves depends on the binding");
          }
        }
      }
      columns.push_back(std::move(col));
    }
  }

  // the rows: each exact group with each offset (a slot no arc reaches is left out: it keeps
  // what it has, and the unfolded net has no such place)
  std::vector<bool> reached(net.placeSlots().size(), false);
  for (const Term& term : net.terms()) reached[term.place_slot] = true;
  std::vector<std::pair<std::uint32_t, std::int64_t>> rows;  // (group, offset)
  std::vector<std::vector<std::uint32_t>> row_of(groups.size());
  for (std::uint32_t g = 0; g < groups.size(); ++g) {
    if (!reached[groups[g].ps]) continue;
    if (!groups[g].exact) {
      out.notes.push_back(over + "'" + placeSlotName(net, groups[g].ps) + "' is left out: " + groups[g].why);
      continue;
    }
    std::vector<std::int64_t> offsets{0};
    if (cyclic && groups[g].projection != Projection::Count) {
      // every offset in small sets; x's neighbours in larger ones
      offsets = n <= 8 ? std::vector<std::int64_t>(n) : std::vector<std::int64_t>{0, 1, static_cast<std::int64_t>(n) - 1};
      if (n <= 8) std::iota(offsets.begin(), offsets.end(), 0);
    }
    for (auto k : offsets) {
      row_of[g].push_back(static_cast<std::uint32_t>(rows.size()));
      rows.emplace_back(g, k);
    }
  }

  // the equations: per column and x, each row's change at x + offset; equal ones once
  std::set<Sparse> equations;
  for (const Column& col : columns) {
    for (std::size_t x = 0; x < n; ++x) {
      Sparse eq;
      for (const auto& [g, change] : col) {
        if (!groups[g].exact) continue;
        for (auto r : row_of[g]) {
          const auto k = rows[r].second;
          const std::int64_t v = groups[g].projection == Projection::Count
                                     ? change[0]
                                     : change[(x + static_cast<std::size_t>(k)) % n];
          if (v != 0) eq.emplace_back(r, v);
        }
      }
      if (eq.empty()) continue;
      std::sort(eq.begin(), eq.end());
      normalise(eq);
      equations.insert(std::move(eq));
    }
  }
  std::vector<Sparse> matrix(rows.size());
  std::uint32_t column = 0;
  for (const Sparse& eq : equations) {
    for (const auto& [r, v] : eq) matrix[r].emplace_back(column, v);
    ++column;
  }
  ExploreStop stop = ExploreStop::Done;
  const auto found = semiflowsOf(matrix, equations.size(), options.limits, &stop);
  if (stop != ExploreStop::Done) {
    out.complete = false;
    if (out.stop == ExploreStop::Done) out.stop = stop;
  }

  // each solution as terms; a family once (its rotation of least offsets)
  std::set<std::vector<ColouredTerm>> seen;
  std::vector<ColouredInvariant> made;
  for (const Invariant& y : found) {
    std::vector<ColouredTerm> terms;
    for (const auto& [r, w] : y.weights) {
      const Group& g = groups[rows[r].first];
      terms.push_back({g.ps, g.projection, g.component, rows[r].second, w});
    }
    const bool counts = std::all_of(terms.begin(), terms.end(),
                                    [](const ColouredTerm& t) { return t.projection == Projection::Count; });
    if (d.has_value() == counts) continue;  // over D, those over counts are found without D
    if (cyclic) {
      // the rotation whose offsets are least (pred(x) counts 1, as succ(x) does)
      auto cost = [&](const std::vector<ColouredTerm>& ts) {
        std::int64_t s = 0;
        for (const auto& t : ts) s += std::min(t.offset, static_cast<std::int64_t>(n) - t.offset);
        return s;
      };
      std::vector<ColouredTerm> best;
      std::int64_t best_cost = 0;
      for (std::size_t r = 0; r < n; ++r) {
        auto turned = terms;
        for (auto& t : turned) {
          if (t.projection != Projection::Count) t.offset = (t.offset + static_cast<std::int64_t>(r)) % static_cast<std::int64_t>(n);
        }
        std::sort(turned.begin(), turned.end());
        const auto c = cost(turned);
        if (best.empty() || c < best_cost || (c == best_cost && turned < best)) {
          best = std::move(turned);
          best_cost = c;
        }
      }
      terms = std::move(best);
      // every value of each group's place alike: a sum over counts, not of x
      std::map<std::pair<std::uint32_t, std::uint32_t>, std::set<std::int64_t>> offsets;
      std::map<std::pair<std::uint32_t, std::uint32_t>, std::set<std::int64_t>> weights;
      for (const auto& t : terms) {
        if (t.projection == Projection::Count) continue;
        offsets[{t.place_slot, t.component}].insert(t.offset);
        weights[{t.place_slot, t.component}].insert(t.weight);
      }
      bool flat = true;
      for (const auto& [key, o] : offsets) flat = flat && o.size() == n && weights[key].size() == 1;
      if (flat) continue;
    }
    std::sort(terms.begin(), terms.end());
    if (!seen.insert(terms).second) continue;
    ColouredInvariant inv;
    inv.over = d;
    inv.terms = std::move(terms);
    made.push_back(std::move(inv));
  }
  // the sums in the initial marking
  for (auto& inv : made) {
    for (std::size_t x = 0; x < n; ++x) {
      std::int64_t sum = 0;
      for (PlaceSlotId ps : net.placeSlotIds()) {
        const Multiset* values = colouring != nullptr && colouring->setOf(ps) ? &colouring->initial[ps] : nullptr;
        if (values == nullptr) {
          sum += colouredWeight(net, inv, x, ps, nullptr) * net.placeSlots()[ps].initial;
          continue;
        }
        for (const auto& [v, k] : *values) sum += colouredWeight(net, inv, x, ps, &v) * k;
      }
      inv.tokens.push_back(sum);
    }
    out.invariants.push_back(std::move(inv));
  }
}

/// `x` shifted `k` times by succ (k > 0) or pred, as the language writes it.
std::string shifted(std::int64_t k, std::int64_t n) {
  std::string s = "x";
  const bool back = k > n / 2;
  for (std::int64_t i = 0; i < (back ? n - k : k); ++i) s = std::string(back ? "pred(" : "succ(") + s + ")";
  return s;
}

}  // namespace

ColouredInvariants colouredInvariants(const Net& net, const ColouredInvariantOptions& options) {
  ColouredInvariants out;
  solve(net, std::nullopt, options, out);
  const Colouring* colouring = net.colouring();
  if (colouring == nullptr) return out;
  // the sets D: every finite set of 2 to most_values values a value slot has or has as a
  // component, and some transition has a variable of (else no value of D moves but constants)
  std::set<ColourId> slots, variables;
  for (const auto s : colouring->slot_set) {
    if (s < 0) continue;
    const auto& set = colouring->colours.at(static_cast<ColourId>(s));
    slots.insert(static_cast<ColourId>(s));
    if (set.kind == ColourKind::Product || set.kind == ColourKind::Record) {
      slots.insert(set.components.begin(), set.components.end());
    }
  }
  for (const auto& ti : colouring->transitions) variables.insert(ti.sets.begin(), ti.sets.end());
  std::vector<ColourId> candidates;
  std::set_intersection(slots.begin(), slots.end(), variables.begin(), variables.end(), std::back_inserter(candidates));
  for (const ColourId d : candidates) {
    const auto& set = colouring->colours.at(d);
    if (!set.size || *set.size < 2 || *set.size > options.most_values) continue;
    // the bindings of the variables of D, all transitions together
    std::size_t bindings = 0;
    for (const auto& ti : colouring->transitions) {
      std::size_t k = 1;
      for (const auto s : ti.sets) {
        if (s != d) continue;
        k = __builtin_mul_overflow(k, static_cast<std::size_t>(*set.size), &k) ? SIZE_MAX : k;
      }
      bindings = __builtin_add_overflow(bindings, k, &bindings) ? SIZE_MAX : bindings;
    }
    if (bindings > options.most_bindings) {
      out.notes.push_back("over " + set.name + ": not tried: its variables have " +
                          (bindings == SIZE_MAX ? std::string("too many") : std::to_string(bindings)) +
                          " bindings, more than " + std::to_string(options.most_bindings));
      continue;
    }
    solve(net, d, options, out);
  }
  return out;
}

std::int64_t colouredWeight(const Net& net, const ColouredInvariant& inv, std::size_t x, PlaceSlotId ps,
                            const Value* value) {
  const Colouring* colouring = net.colouring();
  std::vector<Value> values;
  if (inv.over && colouring != nullptr) values = colouring->colours.values(*inv.over);
  std::int64_t w = 0;
  for (const auto& t : inv.terms) {
    if (t.place_slot != ps) continue;
    if (t.projection == Projection::Count) {
      w += t.weight;
      continue;
    }
    if (value == nullptr || values.empty()) continue;
    const Value& want = values[(x + static_cast<std::size_t>(t.offset)) % values.size()];
    const Value* got = value;
    if (t.projection == Projection::Component) got = t.component < value->items.size() ? &value->items[t.component] : nullptr;
    if (got != nullptr && *got == want) w += t.weight;
  }
  return w;
}

std::string colouredInvariantText(const Net& net, const ColouredInvariant& inv) {
  const Colouring* colouring = net.colouring();
  std::string s;
  const auto n = inv.over && colouring != nullptr ? colouring->colours.at(*inv.over).size.value_or(1) : 1;
  for (const auto& t : inv.terms) {
    if (!s.empty()) s += " + ";
    if (t.weight != 1) s += std::to_string(t.weight) + "*";
    const std::string place = placeSlotName(net, t.place_slot);
    const std::string x = shifted(t.offset, n);
    switch (t.projection) {
      case Projection::Count: s += "|" + place + "|"; break;
      case Projection::Value: s += place + "(" + x + ")"; break;
      case Projection::Component: {
        const auto set = colouring != nullptr ? colouring->setOf(t.place_slot) : std::nullopt;
        const ColourSet* product = set ? &colouring->colours.at(*set) : nullptr;
        if (product != nullptr && product->kind == ColourKind::Record && t.component < product->fields.size()) {
          s += place + "{" + product->fields[t.component] + " = " + x + "}";
          break;
        }
        s += place + "(";
        const std::size_t parts = product != nullptr ? product->components.size() : t.component + 1;
        for (std::size_t k = 0; k < parts; ++k) s += (k > 0 ? ", " : "") + (k == t.component ? x : std::string("_"));
        s += ")";
        break;
      }
    }
  }
  if (!inv.over || colouring == nullptr) return s + " = " + (inv.tokens.empty() ? std::string("?") : std::to_string(inv.tokens[0]));
  // the sum per x: one number, or the values of each but the most common
  const auto& set = colouring->colours.at(*inv.over);
  const auto values = colouring->colours.values(*inv.over);
  std::map<std::int64_t, std::vector<std::size_t>> by_sum;
  for (std::size_t x = 0; x < inv.tokens.size(); ++x) by_sum[inv.tokens[x]].push_back(x);
  if (by_sum.size() <= 1) {
    return s + " = " + (by_sum.empty() ? std::string("?") : std::to_string(by_sum.begin()->first)) + " for every x in " +
           set.name;
  }
  auto most = by_sum.begin();
  for (auto it = by_sum.begin(); it != by_sum.end(); ++it) {
    if (it->second.size() > most->second.size()) most = it;
  }
  s += " =";
  std::string sep = " ";
  for (const auto& [sum, xs] : by_sum) {
    if (sum == most->first) continue;
    s += sep + std::to_string(sum) + " for x = ";
    for (std::size_t i = 0; i < xs.size(); ++i) s += (i > 0 ? ", " : "") + colouring->colours.text(*inv.over, values[xs[i]]);
    sep = "; ";
  }
  return s + sep + std::to_string(most->first) + " for every other x in " + set.name;
}

}  // namespace gdpn::net
