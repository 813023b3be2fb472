// The bindings of a coloured transition, by a search planned once per transition: matched
// against the values its input places hold, fixed by the condition's equations, enumerated over
// what finite sets leave free, the condition's conjuncts checked as soon as their variables are
// bound, then each checked against every arc. Also every binding whatever the marking (for
// unfolding).

#include <algorithm>

#include "gdpn/net/inscription.h"

namespace gdpn::net {
// the plan's types: named, as BindingSearch::Plan holds them
namespace binding_plan {

// one term c'pattern of a normal or test input arc's sum: c a constant, the pattern a
// variable, a constant or a tuple (record) of them
struct Pattern {
  std::size_t arc = 0;
  std::int64_t times = 1;
  const Expr* expr = nullptr;
};

}  // namespace binding_plan

namespace {

using binding_plan::Pattern;

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

void varsOf(const Expr& e, std::vector<std::size_t>& out) {
  if (e.op == Expr::Op::Var && e.index >= 0) out.push_back(static_cast<std::size_t>(e.index));
  for (const Expr& a : e.args) varsOf(a, out);
}

// the conjuncts of condition `e`: it holds when each does
void conjuncts(const Expr& e, std::vector<const Expr*>& out) {
  if (e.op == Expr::Op::And) {
    conjuncts(e.args[0], out);
    conjuncts(e.args[1], out);
    return;
  }
  out.push_back(&e);
}

// the variables pattern `p` binds that `bound` does not hold yet, in the order a value holds
// them (a record's in its set's field order), marked bound
void newVars(const Expr& p, const Colours& colours, std::vector<bool>& bound, std::vector<std::size_t>& out) {
  if (p.op == Expr::Op::Var) {
    if (p.index < 0 || static_cast<std::size_t>(p.index) >= bound.size()) return;
    const auto k = static_cast<std::size_t>(p.index);
    if (!bound[k]) out.push_back(k);
    bound[k] = true;
  } else if (p.op == Expr::Op::Tuple) {
    for (const Expr& a : p.args) newVars(a, colours, bound, out);
  } else if (p.op == Expr::Op::Record && p.type < colours.sets().size()) {
    for (const std::string& f : colours.at(p.type).fields) {
      const auto it = std::find(p.fields.begin(), p.fields.end(), f);
      if (it != p.fields.end()) newVars(p.args[static_cast<std::size_t>(it - p.fields.begin())], colours, bound, out);
    }
  }
}

// matches `v` against pattern `p`, binding what is free (undone through `bound` by the caller);
// false when it does not match
bool unify(const Expr& p, const Value& v, const TransitionInscriptions& t, const Colours& colours, Binding& b,
           std::vector<char>& set, std::vector<std::size_t>& bound) {
  switch (p.op) {
    case Expr::Op::Const: return p.value == v;
    case Expr::Op::Var: {
      if (p.index < 0 || static_cast<std::size_t>(p.index) >= b.size()) return false;
      const auto k = static_cast<std::size_t>(p.index);
      if (set[k]) return b[k] == v;
      if (k >= t.sets.size() || !colours.contains(t.sets[k], v)) return false;
      b[k] = v;
      set[k] = 1;
      bound.push_back(k);
      return true;
    }
    case Expr::Op::Tuple:
      if (v.tag != Value::Tag::Tuple || v.items.size() != p.args.size()) return false;
      for (std::size_t k = 0; k < p.args.size(); ++k) {
        if (!unify(p.args[k], v.items[k], t, colours, b, set, bound)) return false;
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
        if (!unify(p.args[static_cast<std::size_t>(it - p.fields.begin())], v.items[k], t, colours, b, set, bound)) {
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

}  // namespace

namespace binding_plan {

// one step of a planned search
struct Step {
  enum class Kind : std::uint8_t {
    Match,      // each distinct value the arc's place holds (with `times` copies) against the pattern
    Check,      // the pattern, its variables bound, is held `times` times
    Fix,        // variable `var` is the value of `expr` (a conjunct var = expr of the condition)
    Guard,      // conjunct `expr` of the condition holds
    Enumerate,  // variable `var` over its finite set
  };
  Kind kind = Kind::Match;
  std::size_t arc = 0;         // Match, Check: the pattern's arc
  std::int64_t times = 1;      // Match, Check: the copies it needs
  const Expr* expr = nullptr;  // Match, Check: the pattern; Fix: the value; Guard: the conjunct
  std::size_t var = 0;         // Fix, Enumerate: the variable
  bool range = false;          // Enumerate: an integer range, counted from lo to hi
  std::int64_t lo = 0, hi = 0; // Enumerate a range: its ends
  std::vector<Value> values;   // Enumerate another set: its values
};

// a planned search: its steps in order
struct Steps {
  const TransitionInscriptions& t;
  const Colours& colours;
  std::vector<Step> steps;
  bool ordered = true;  // the depth-first search meets the bindings in the canonical order
  std::string refusal;  // why the variables cannot all be bound, or ""
  // per arc: a normal or test input arc whose whole inscription is one pattern (with its
  // multiplicity), so that matching it already found its multiset in its place
  std::vector<char> covered;
};

}  // namespace binding_plan

using binding_plan::Step;
using binding_plan::Steps;

struct BindingSearch::Plan : Steps {
  Plan(const TransitionInscriptions& ti, const Colours& c) : Steps{ti, c, {}, true, {}, {}} { build(); }

 private:
  ColourId setOf(std::size_t v) const { return v < t.sets.size() ? t.sets[v] : Colours::kDot; }

  void build() {
    const std::size_t n = t.variables.size();
    const std::vector<Pattern> pats = patterns(t, colours);
    covered.assign(t.arcs.size(), 0);
    for (std::size_t a = 0; a < t.arcs.size(); ++a) {
      const Expr& e = t.arcs[a].expr;
      const Expr& whole = e.op == Expr::Op::Times ? e.args[1] : e;
      const auto on = std::count_if(pats.begin(), pats.end(), [&](const Pattern& q) { return q.arc == a; });
      covered[a] = on == 1 && std::any_of(pats.begin(), pats.end(), [&](const Pattern& q) { return q.expr == &whole; });
    }
    std::vector<std::vector<std::size_t>> pattern_vars(pats.size());
    for (std::size_t k = 0; k < pats.size(); ++k) varsOf(*pats[k].expr, pattern_vars[k]);
    // the condition's conjuncts, and those of them that can fix a variable: var = e or e = var
    struct Conjunct {
      const Expr* expr;
      std::vector<std::size_t> vars;
      bool done = false;
    };
    struct Equation {
      std::size_t conjunct, var;
      const Expr* value;
    };
    std::vector<Conjunct> cs;
    std::vector<Equation> eqs;
    if (t.when) {
      std::vector<const Expr*> parts;
      conjuncts(*t.when, parts);
      for (const Expr* c : parts) {
        cs.push_back({c, {}, false});
        varsOf(*c, cs.back().vars);
        if (c->op != Expr::Op::Eq) continue;
        for (std::size_t side = 0; side < 2; ++side) {
          const Expr& x = c->args[side];
          const Expr& e = c->args[1 - side];
          if (x.op != Expr::Op::Var || x.index < 0 || static_cast<std::size_t>(x.index) >= n || e.multiset) continue;
          std::vector<std::size_t> uses;
          varsOf(e, uses);
          if (std::find(uses.begin(), uses.end(), static_cast<std::size_t>(x.index)) != uses.end()) continue;
          eqs.push_back({cs.size() - 1, static_cast<std::size_t>(x.index), &e});
        }
      }
    }
    std::vector<bool> bound(n, false), used(pats.size(), false);
    auto allBound = [&](const std::vector<std::size_t>& vars) {
      return std::all_of(vars.begin(), vars.end(), [&](std::size_t v) { return v < n && bound[v]; });
    };
    // the variables whose values the search branches over, in the order it binds them: the
    // bindings come in the canonical order when that order ascends and every fixed variable
    // depends on earlier ones alone
    std::size_t last = 0;
    bool any = false;
    auto branch = [&](std::size_t v) {
      if (any && v < last) ordered = false;
      last = std::max(last, v);
      any = true;
    };
    // what the variables bound so far allow: fixed variables, checked patterns and conjuncts
    auto settle = [&] {
      for (bool changed = true; changed;) {
        changed = false;
        for (const Equation& q : eqs) {
          if (bound[q.var] || cs[q.conjunct].done) continue;
          std::vector<std::size_t> uses;
          varsOf(*q.value, uses);
          if (!allBound(uses)) continue;
          for (const std::size_t u : uses) ordered = ordered && u < q.var;
          Step s;
          s.kind = Step::Kind::Fix;
          s.var = q.var;
          s.expr = q.value;
          steps.push_back(std::move(s));
          bound[q.var] = true;
          cs[q.conjunct].done = true;  // holds by construction
          changed = true;
        }
        for (std::size_t k = 0; k < pats.size(); ++k) {
          if (used[k] || !allBound(pattern_vars[k])) continue;
          used[k] = true;
          Step s;
          s.kind = Step::Kind::Check;
          s.arc = pats[k].arc;
          s.times = pats[k].times;
          s.expr = pats[k].expr;
          steps.push_back(std::move(s));
        }
        for (Conjunct& c : cs) {
          if (c.done || !allBound(c.vars)) continue;
          c.done = true;
          Step s;
          s.kind = Step::Kind::Guard;
          s.expr = c.expr;
          steps.push_back(std::move(s));
        }
      }
    };
    auto match = [&](std::size_t k) {
      used[k] = true;
      Step s;
      s.kind = Step::Kind::Match;
      s.arc = pats[k].arc;
      s.times = pats[k].times;
      s.expr = pats[k].expr;
      steps.push_back(std::move(s));
      std::vector<std::size_t> fresh;
      newVars(*pats[k].expr, colours, bound, fresh);
      for (const std::size_t v : fresh) branch(v);
    };
    std::int64_t combinations = 1;
    std::string free;
    auto enumerate = [&](std::size_t v) {
      const ColourSet& set = colours.at(setOf(v));
      Step s;
      s.kind = Step::Kind::Enumerate;
      s.var = v;
      if (set.kind == ColourKind::Integer && set.range) {
        s.range = true;
        s.lo = set.lo;
        s.hi = set.hi;
      } else {
        s.values = colours.values(setOf(v));
      }
      steps.push_back(std::move(s));
      bound[v] = true;
      branch(v);
      const std::int64_t size = *set.size;
      free += (free.empty() ? "'" : ", '") + t.variables[v] + "'";
      combinations = size != 0 && combinations > kMostValues / size ? kMostValues + 1 : combinations * size;
    };
    settle();
    // the least variable still free next: from a pattern that binds it, else over its set;
    // one that neither can bind waits for an equation, the other variables bound first
    while (true) {
      std::size_t v = 0;
      while (v < n && bound[v]) ++v;
      if (v == n) break;
      std::size_t k = 0;
      while (k < pats.size() &&
             (used[k] || std::find(pattern_vars[k].begin(), pattern_vars[k].end(), v) == pattern_vars[k].end())) {
        ++k;
      }
      if (k < pats.size()) {
        match(k);
      } else if (colours.at(setOf(v)).size) {
        enumerate(v);
      } else {
        // a pattern with a free variable, else a free variable of a finite set
        k = 0;
        while (k < pats.size() && (used[k] || allBound(pattern_vars[k]))) ++k;
        std::size_t u = v;
        while (u < n && (bound[u] || !colours.at(setOf(u)).size)) ++u;
        if (k < pats.size()) {
          match(k);
        } else if (u < n) {
          enumerate(u);
        } else {
          refusal = "variable '" + t.variables[v] + "' (" + colours.at(setOf(v)).name +
                    ") is bound by no input arc and its colour set is not finite";
          return;
        }
      }
      settle();
    }
    if (combinations > kMostValues) {
      refusal = "variables " + free + " are bound by no input arc, and enumerating their values would try more than " +
                std::to_string(kMostValues) + " bindings each time: bind them on an input arc";
    }
  }
};

namespace {

// one run of a plan against a marking
class Run {
 public:
  Run(const Steps& plan, const ArcMarking& marking, const ArcRoom& room, std::size_t most,
      const BindingFilter& accept)
      : p_(plan), t_(plan.t), colours_(plan.colours), marking_(marking), room_(room), accept_(accept), most_(most),
        b_(scratch_.b), set_(scratch_.set), undo_(scratch_.undo) {
    // the scratch of this thread's last search, its buffers reused (searches do not nest)
    b_.resize(t_.variables.size());
    set_.assign(t_.variables.size(), 0);
    undo_.clear();
  }

  std::vector<BoundOccurrence> go() {
    if (!p_.refusal.empty() || most_ == 0) return {};
    step(0);
    if (!p_.ordered) {
      std::sort(found_.begin(), found_.end(),
                [](const BoundOccurrence& x, const BoundOccurrence& y) { return x.binding < y.binding; });
      if (found_.size() > most_) found_.resize(most_);
    }
    return std::move(found_);
  }

 private:
  // an ordered search stops at the most-th binding; another must see them all
  bool full() const { return p_.ordered && found_.size() >= most_; }

  void step(std::size_t k) {
    if (k == p_.steps.size()) {
      keep();
      return;
    }
    const Step& s = p_.steps[k];
    switch (s.kind) {
      case Step::Kind::Match: {
        const Multiset& held = marking_(s.arc);
        for (const auto& [v, n] : held) {
          if (n < s.times) continue;  // this term alone needs times copies of its value
          // the variables it binds are undone on the way back up
          const std::size_t mark = undo_.size();
          if (unify(*s.expr, v, t_, colours_, b_, set_, undo_)) step(k + 1);
          for (std::size_t i = mark; i < undo_.size(); ++i) set_[undo_[i]] = 0;
          undo_.resize(mark);
          if (full()) return;
        }
        return;
      }
      case Step::Kind::Check: {
        const auto v = evaluate(*s.expr, b_, colours_);
        if (!v) return;
        const Multiset& held = marking_(s.arc);
        const auto it = held.find(*v);
        if (it != held.end() && it->second >= s.times) step(k + 1);
        return;
      }
      case Step::Kind::Fix: {
        auto v = evaluate(*s.expr, b_, colours_);
        if (!v || s.var >= t_.sets.size() || !colours_.contains(t_.sets[s.var], *v)) return;
        b_[s.var] = std::move(*v);
        set_[s.var] = 1;
        step(k + 1);
        set_[s.var] = 0;
        return;
      }
      case Step::Kind::Guard: {
        const auto c = evaluate(*s.expr, b_, colours_);
        if (c && c->tag == Value::Tag::Bool && c->i == 1) step(k + 1);
        return;
      }
      case Step::Kind::Enumerate:
        set_[s.var] = 1;
        if (s.range) {
          for (std::int64_t i = s.lo; i <= s.hi; ++i) {
            b_[s.var] = Value::integer(i);
            step(k + 1);
            if (full()) break;
          }
        } else {
          for (const Value& v : s.values) {
            b_[s.var] = v;
            step(k + 1);
            if (full()) break;
          }
        }
        set_[s.var] = 0;
        return;
    }
  }

  // the binding as it stands (the condition holds: its conjuncts were checked), when every arc
  // allows it
  void keep() {
    std::vector<Multiset> arcs(t_.arcs.size());
    for (std::size_t a = 0; a < t_.arcs.size(); ++a) {
      const ArcInscription& arc = t_.arcs[a];
      Multiset& m = arcs[a];
      if (!evaluateInto(arc.expr, b_, colours_, arc.set, m)) return;
      switch (arc.role) {
        case ArcRole::Take:
        case ArcRole::Test:
          // each arc against its own place's marking (a Match or Check step did for a covered one)
          if (!p_.covered[a] && !containedIn(m, marking_(a))) return;
          break;
        case ArcRole::Inhibit:
          if (!m.empty() && containedIn(m, marking_(a))) return;
          break;
        case ArcRole::Put:
          if (room_ && !room_(a, multisetSize(m))) return;
          break;
      }
    }
    BoundOccurrence o{b_, std::move(arcs)};
    if (accept_ && !accept_(o)) return;
    found_.push_back(std::move(o));
  }

  const Steps& p_;
  const TransitionInscriptions& t_;
  const Colours& colours_;
  const ArcMarking& marking_;
  const ArcRoom& room_;
  const BindingFilter& accept_;
  std::size_t most_;
  struct Scratch {
    Binding b;
    std::vector<char> set;
    std::vector<std::size_t> undo;
  };
  static thread_local Scratch scratch_;
  Binding& b_;                      // the values bound so far (others stale)
  std::vector<char>& set_;          // per variable: bound now
  std::vector<std::size_t>& undo_;  // what the matches on the way down bound
  std::vector<BoundOccurrence> found_;
};

thread_local Run::Scratch Run::scratch_;

}  // namespace

BindingSearch::BindingSearch(const TransitionInscriptions& t, const Colours& colours)
    : plan_(std::make_unique<Plan>(t, colours)) {}
BindingSearch::~BindingSearch() = default;
BindingSearch::BindingSearch(BindingSearch&&) noexcept = default;

std::vector<BoundOccurrence> BindingSearch::enabled(const ArcMarking& marking, const ArcRoom& room, std::size_t most,
                                                    const BindingFilter& accept) const {
  return Run(*plan_, marking, room, most, accept).go();
}

bool BindingSearch::ordered() const { return plan_->ordered; }

const std::string& BindingSearch::refusal() const { return plan_->refusal; }

std::vector<BoundOccurrence> enabledBindings(const TransitionInscriptions& t, const Colours& colours,
                                             const ArcMarking& marking, const ArcRoom& room, std::size_t most) {
  return BindingSearch(t, colours).enabled(marking, room, most);
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
  return BindingSearch(t, colours).refusal();
}

}  // namespace gdpn::net
