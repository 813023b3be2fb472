// The bindings of a coloured transition: matched against the values its input places hold,
// then enumerated over what finite sets leave free, then each checked against every arc and the
// condition. Also every binding whatever the marking (for unfolding).

#include <algorithm>
#include <set>

#include "gdpn/net/inscription.h"

namespace gdpn::net {
namespace {

// one term c'pattern of a normal or test input arc's sum: c a constant, the pattern a
// variable, a constant or a tuple (record) of them
struct Pattern {
  std::size_t arc = 0;
  std::int64_t times = 1;
  const Expr* expr = nullptr;
};

bool hasVar(const Expr& e) {
  if (e.op == Expr::Op::Var) return true;
  return std::any_of(e.args.begin(), e.args.end(), [](const Expr& a) { return hasVar(a); });
}

bool isPattern(const Expr& e) {
  switch (e.op) {
    case Expr::Op::Var:
    case Expr::Op::Const: return true;
    case Expr::Op::Tuple:
    case Expr::Op::Record:
      return !e.multiset && std::all_of(e.args.begin(), e.args.end(), [](const Expr& a) { return isPattern(a); });
    case Expr::Op::Name:
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
    case Expr::Op::If:
    case Expr::Op::Succ:
    case Expr::Op::Pred:
    case Expr::Op::Times:
    case Expr::Op::Sum:
    case Expr::Op::All:
    case Expr::Op::Empty: break;
  }
  return false;
}

// the pattern terms of sum `e` (on arc `arc`), each with its constant multiplicity
void collect(const Expr& e, std::size_t arc, std::int64_t times, const Colours& colours, std::vector<Pattern>& out) {
  if (e.op == Expr::Op::Sum) {
    collect(e.args[0], arc, times, colours, out);
    collect(e.args[1], arc, times, colours, out);
    return;
  }
  if (e.op == Expr::Op::Times) {
    if (hasVar(e.args[0])) return;
    const auto n = evaluate(e.args[0], {}, colours);
    if (!n || n->tag != Value::Tag::Int || n->i <= 0) return;
    std::int64_t t = 0;
    if (__builtin_mul_overflow(times, n->i, &t)) return;
    collect(e.args[1], arc, t, colours, out);
    return;
  }
  if (isPattern(e) && hasVar(e)) out.push_back({arc, times, &e});
}

std::vector<Pattern> patterns(const TransitionInscriptions& t, const Colours& colours) {
  std::vector<Pattern> out;
  for (std::size_t a = 0; a < t.arcs.size(); ++a) {
    const ArcRole role = t.arcs[a].role;
    if (role == ArcRole::Take || role == ArcRole::Test) collect(t.arcs[a].expr, a, 1, colours, out);
  }
  return out;
}

void markVars(const Expr& e, std::vector<bool>& matched) {
  if (e.op == Expr::Op::Var && e.index >= 0 && static_cast<std::size_t>(e.index) < matched.size()) {
    matched[static_cast<std::size_t>(e.index)] = true;
  }
  for (const Expr& a : e.args) markVars(a, matched);
}

using Partial = std::vector<std::optional<Value>>;

// matches `v` against pattern `p`, binding what is free (undone through `bound` by the caller);
// false when it does not match
bool unify(const Expr& p, const Value& v, const TransitionInscriptions& t, const Colours& colours, Partial& b,
           std::vector<std::size_t>& bound) {
  switch (p.op) {
    case Expr::Op::Const: return p.value == v;
    case Expr::Op::Var: {
      if (p.index < 0 || static_cast<std::size_t>(p.index) >= b.size()) return false;
      const auto k = static_cast<std::size_t>(p.index);
      if (b[k]) return *b[k] == v;
      if (k >= t.sets.size() || !colours.contains(t.sets[k], v)) return false;
      b[k] = v;
      bound.push_back(k);
      return true;
    }
    case Expr::Op::Tuple:
      if (v.tag != Value::Tag::Tuple || v.items.size() != p.args.size()) return false;
      for (std::size_t k = 0; k < p.args.size(); ++k) {
        if (!unify(p.args[k], v.items[k], t, colours, b, bound)) return false;
      }
      return true;
    case Expr::Op::Record: {
      // the value holds the fields in the set's order
      if (v.tag != Value::Tag::Tuple || p.type >= colours.sets().size()) return false;
      const auto& fields = colours.at(p.type).fields;
      if (fields.size() != p.args.size() || v.items.size() != fields.size()) return false;
      for (std::size_t k = 0; k < fields.size(); ++k) {
        const auto it = std::find(p.fields.begin(), p.fields.end(), fields[k]);
        if (it == p.fields.end()) return false;
        if (!unify(p.args[static_cast<std::size_t>(it - p.fields.begin())], v.items[k], t, colours, b, bound)) {
          return false;
        }
      }
      return true;
    }
    case Expr::Op::Name:
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
    case Expr::Op::If:
    case Expr::Op::Succ:
    case Expr::Op::Pred:
    case Expr::Op::Times:
    case Expr::Op::Sum:
    case Expr::Op::All:
    case Expr::Op::Empty: break;
  }
  return false;
}

// the condition holds and every arc has a value: the arcs' multisets, else nullopt
std::optional<std::vector<Multiset>> occurrence(const TransitionInscriptions& t, const Colours& colours,
                                                const Binding& b) {
  if (t.when) {
    const auto c = evaluate(*t.when, b, colours);
    if (!c || *c != Value::boolean(true)) return std::nullopt;
  }
  std::vector<Multiset> arcs(t.arcs.size());
  for (std::size_t a = 0; a < t.arcs.size(); ++a) {
    if (!evaluateInto(t.arcs[a].expr, b, colours, t.arcs[a].set, arcs[a])) return std::nullopt;
  }
  return arcs;
}

class Search {
 public:
  Search(const TransitionInscriptions& t, const Colours& colours, const ArcMarking& marking, const ArcRoom& room,
         std::size_t most)
      : t_(t), colours_(colours), marking_(marking), room_(room), most_(most), patterns_(patterns(t, colours)),
        partial_(t.variables.size()) {}

  std::vector<BoundOccurrence> run() {
    if (most_ > 0) match(0);
    std::vector<BoundOccurrence> out;
    out.reserve(found_.size());
    for (auto& [b, arcs] : found_) out.push_back({b, std::move(arcs)});
    return out;
  }

 private:
  bool full() const { return found_.size() >= most_; }

  // pattern `k` onwards, against the distinct values its place holds
  void match(std::size_t k) {
    if (full()) return;
    if (k == patterns_.size()) {
      enumerate(0);
      return;
    }
    const Pattern& p = patterns_[k];
    const Multiset& held = marking_(p.arc);
    for (const auto& [v, n] : held) {
      if (n < p.times) continue;  // this term alone needs times copies of its value
      std::vector<std::size_t> bound;
      if (unify(*p.expr, v, t_, colours_, partial_, bound)) match(k + 1);
      for (const std::size_t i : bound) partial_[i].reset();
      if (full()) return;
    }
  }

  // variables from `i` on that matching left free, over their finite sets
  void enumerate(std::size_t i) {
    if (full()) return;
    while (i < partial_.size() && partial_[i]) ++i;
    if (i == partial_.size()) {
      keep();
      return;
    }
    const ColourId set = i < t_.sets.size() ? t_.sets[i] : Colours::kDot;
    if (!colours_.at(set).size) return;  // not finite: unboundVariable says why
    for (const Value& v : colours_.values(set)) {
      partial_[i] = v;
      enumerate(i + 1);
      if (full()) break;
    }
    partial_[i].reset();
  }

  // the binding as it stands, when every rule allows it
  void keep() {
    Binding b;
    b.reserve(partial_.size());
    for (const auto& v : partial_) b.push_back(*v);
    if (found_.contains(b) || tried_.contains(b)) return;
    tried_.insert(b);
    auto arcs = occurrence(t_, colours_, b);
    if (!arcs) return;
    for (std::size_t a = 0; a < t_.arcs.size(); ++a) {
      const Multiset& m = (*arcs)[a];
      switch (t_.arcs[a].role) {
        case ArcRole::Take:
        case ArcRole::Test:
          // each arc against its own place's marking
          if (!containedIn(m, marking_(a))) return;
          break;
        case ArcRole::Inhibit:
          if (!m.empty() && containedIn(m, marking_(a))) return;
          break;
        case ArcRole::Put:
          if (room_ && !room_(a, multisetSize(m))) return;
          break;
      }
    }
    found_.emplace(std::move(b), std::move(*arcs));
  }

  const TransitionInscriptions& t_;
  const Colours& colours_;
  const ArcMarking& marking_;
  const ArcRoom& room_;
  std::size_t most_;
  std::vector<Pattern> patterns_;
  Partial partial_;
  std::map<Binding, std::vector<Multiset>> found_;  // the canonical order
  std::set<Binding> tried_;                         // met before and refused
};

}  // namespace

std::vector<BoundOccurrence> enabledBindings(const TransitionInscriptions& t, const Colours& colours,
                                             const ArcMarking& marking, const ArcRoom& room, std::size_t most) {
  return Search(t, colours, marking, room, most).run();
}

std::optional<std::vector<BoundOccurrence>> allBindings(const TransitionInscriptions& t, const Colours& colours,
                                                        std::size_t most, std::string& why) {
  // the product of the variables' sets, refused before it is enumerated when too large
  std::size_t count = 1;
  std::vector<std::vector<Value>> values;
  for (std::size_t i = 0; i < t.variables.size(); ++i) {
    const ColourId set = i < t.sets.size() ? t.sets[i] : Colours::kDot;
    const auto& size = colours.at(set).size;
    if (!size) {
      why = "variable '" + t.variables[i] + "' (" + colours.at(set).name + ") is not of a finite colour set";
      return std::nullopt;
    }
    const auto n = static_cast<std::size_t>(*size);
    if (n != 0 && count > most / n) {
      why = "its variables take more than " + std::to_string(most) + " bindings";
      return std::nullopt;
    }
    count *= n;
  }
  for (std::size_t i = 0; i < t.variables.size(); ++i) values.push_back(colours.values(t.sets[i]));
  std::vector<BoundOccurrence> out;
  if (count == 0) return out;
  // an odometer, the last variable fastest: the canonical order
  std::vector<std::size_t> at(values.size(), 0);
  while (true) {
    Binding b;
    b.reserve(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) b.push_back(values[i][at[i]]);
    if (auto arcs = occurrence(t, colours, b)) out.push_back({std::move(b), std::move(*arcs)});
    std::size_t i = values.size();
    while (i > 0) {
      --i;
      if (++at[i] < values[i].size()) break;
      at[i] = 0;
      if (i == 0) return out;
    }
    if (values.empty()) return out;
  }
}

std::string unboundVariable(const TransitionInscriptions& t, const Colours& colours) {
  std::vector<bool> matched(t.variables.size(), false);
  for (const Pattern& p : patterns(t, colours)) markVars(*p.expr, matched);
  for (std::size_t i = 0; i < t.variables.size(); ++i) {
    const ColourId set = i < t.sets.size() ? t.sets[i] : Colours::kDot;
    if (!matched[i] && !colours.at(set).size) {
      return "variable '" + t.variables[i] + "' (" + colours.at(set).name +
             ") is bound by no input arc and its colour set is not finite";
    }
  }
  // the free variables' combinations: each is tried whenever the transition is
  std::int64_t combinations = 1;
  std::string free;
  for (std::size_t i = 0; i < t.variables.size(); ++i) {
    if (matched[i]) continue;
    const auto size = *colours.at(i < t.sets.size() ? t.sets[i] : Colours::kDot).size;
    free += (free.empty() ? "'" : ", '") + t.variables[i] + "'";
    combinations = size != 0 && combinations > kMostValues / size ? kMostValues + 1 : combinations * size;
  }
  if (combinations > kMostValues) {
    return "variables " + free + " are bound by no input arc, and enumerating their values would try more than " +
           std::to_string(kMostValues) + " bindings each time: bind them on an input arc";
  }
  return {};
}

}  // namespace gdpn::net
