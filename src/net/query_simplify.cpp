// Formulas made simpler before they are answered: what the state equation shows of every
// reachable marking, then constants folded and repeated operators merged.

#include <algorithm>

#include "detail/query_graph.h"
#include "detail/simplify.h"
#include "gdpn/net/state_equation.h"

namespace gdpn::net::detail {
namespace {

Formula constantFormula(bool v, std::size_t column) {
  Formula f;
  f.kind = v ? FormulaKind::True : FormulaKind::False;
  f.column = column;
  return f;
}

/// True or false when `f` is a constant; nullopt otherwise.
std::optional<bool> constantOf(const Formula& f) {
  if (f.kind == FormulaKind::True) return true;
  if (f.kind == FormulaKind::False) return false;
  return std::nullopt;
}

/// Q (quantifier) over a path operator `op` with `operands`.
/// Whether `f` is Q op (something).
bool isQuantified(const Formula& f, FormulaKind q, FormulaKind op) {
  return f.kind == q && !f.operands.empty() && f.operands[0].kind == op;
}

void sumsOf(const Formula& f, std::vector<const TokenSum*>& out) {
  if (f.kind == FormulaKind::Compare) out.push_back(&f.left), out.push_back(&f.right);
  for (const Formula& o : f.operands) sumsOf(o, out);
}

}  // namespace

std::int64_t Simplifier::most(const TokenSum& s) {
  if (s.slots.empty()) return s.constant;
  std::vector<PlaceSlotId> key = s.slots;
  std::sort(key.begin(), key.end());
  const auto at = most_.find(key);
  if (at == most_.end() || at->second < 0) return -1;
  return at->second + s.constant;
}

std::optional<bool> Simplifier::decide(const Formula& c) {
  // each side between its constant (no tokens) and its bound (-1: none known)
  const std::int64_t lo_a = c.left.constant, lo_b = c.right.constant;
  const std::int64_t hi_a = most(c.left), hi_b = most(c.right);
  const bool ha = hi_a >= 0 || c.left.slots.empty(), hb = hi_b >= 0 || c.right.slots.empty();
  // a <= b surely when a's most is at most b's least; never when a's least passes b's most
  auto atMost = [&](std::int64_t slack) -> std::optional<bool> {  // a + slack <= b
    if (ha && hi_a + slack <= lo_b) return true;
    if (hb && lo_a + slack > hi_b) return false;
    return std::nullopt;
  };
  auto atLeast = [&](std::int64_t slack) -> std::optional<bool> {  // a >= b + slack
    if (hb && lo_a >= hi_b + slack) return true;
    if (ha && hi_a < lo_b + slack) return false;
    return std::nullopt;
  };
  switch (c.compare) {
    case Comparison::Less: return atMost(1);
    case Comparison::LessEqual: return atMost(0);
    case Comparison::GreaterEqual: return atLeast(0);
    case Comparison::Greater: return atLeast(1);
    case Comparison::Equal:
    case Comparison::NotEqual: {
      std::optional<bool> eq;
      if ((hb && lo_a > hi_b) || (ha && hi_a < lo_b)) eq = false;
      if (ha && hb && lo_a == hi_a && lo_b == hi_b && lo_a == lo_b) eq = true;
      if (eq && c.compare == Comparison::NotEqual) eq = !*eq;
      return eq;
    }
  }
  return std::nullopt;
}

std::optional<bool> Simplifier::constant(const Formula& f) {
  if (late()) return std::nullopt;
  if (stateEquationExcludes(net_, f)) return false;
  Formula n;
  n.kind = FormulaKind::Not;
  n.operands.push_back(f);
  if (!late() && stateEquationExcludes(net_, n)) return true;
  return std::nullopt;
}

Formula Simplifier::simplified(const Formula& f, std::size_t& changed) {
  // the bounds of every sum in the formula first, in one go
  std::vector<const TokenSum*> sums;
  sumsOf(f, sums);
  std::vector<TokenSum> wanted;
  for (const TokenSum* s : sums) {
    if (s->slots.empty()) continue;
    std::vector<PlaceSlotId> key = s->slots;
    std::sort(key.begin(), key.end());
    if (most_.count(key) != 0) continue;
    most_[key] = -1;
    wanted.push_back({key, 0});
  }
  if (!wanted.empty() && !late()) {
    InvariantOptions limits;
    limits.deadline = deadline_;
    const auto bounds = stateEquationMaxima(net_, wanted, limits);
    for (std::size_t i = 0; i < wanted.size(); ++i) most_[wanted[i].slots] = bounds[i];
  }
  // bottom up; `top`: f is a state formula whose parent is not one (asked of the state
  // equation as a whole)
  auto walk = [&](auto& self, const Formula& x, bool top) -> Formula {
    const bool state = isStateFormula(x);
    Formula out = x;
    if (x.kind == FormulaKind::Compare) {
      if (const auto c = decide(x)) {
        ++changed;
        return constantFormula(*c, x.column);
      }
    }
    for (std::size_t i = 0; i < out.operands.size(); ++i) out.operands[i] = self(self, x.operands[i], state ? false : true);
    switch (out.kind) {
      case FormulaKind::Not: {
        if (const auto c = constantOf(out.operands[0])) return constantFormula(!*c, x.column);
        if (out.operands[0].kind == FormulaKind::Not) return std::move(out.operands[0].operands[0]);
        // through a CTL quantifier (paths being maximal): not AG p = EF not p, not EF p = AG not
        // p, not AF p = EG not p, not EG p = AF not p, not AX p = EX not p, not EX p = AX not p;
        // then simplified again (EF EF q = EF q)
        Formula& q = out.operands[0];
        if ((q.kind == FormulaKind::Exists || q.kind == FormulaKind::All) && isCtl(q) &&
            q.operands[0].kind != FormulaKind::Until) {
          Formula flipped = std::move(q);
          flipped.kind = flipped.kind == FormulaKind::Exists ? FormulaKind::All : FormulaKind::Exists;
          Formula& path = flipped.operands[0];
          if (path.kind == FormulaKind::Future) {
            path.kind = FormulaKind::Globally;
          } else if (path.kind == FormulaKind::Globally) {
            path.kind = FormulaKind::Future;
          }
          Formula inner;
          inner.kind = FormulaKind::Not;
          inner.column = path.operands[0].column;
          inner.operands.push_back(std::move(path.operands[0]));
          path.operands[0] = std::move(inner);
          return self(self, flipped, top);
        }
        break;
      }
      case FormulaKind::And:
      case FormulaKind::Or: {
        const bool absorbing = out.kind == FormulaKind::Or;  // true absorbs an or; false an and
        std::vector<Formula> kept;
        for (Formula& o : out.operands) {
          const auto c = constantOf(o);
          if (c && *c == absorbing) return constantFormula(absorbing, x.column);
          if (c) continue;  // neutral
          if (o.kind == out.kind) {
            for (Formula& p : o.operands) kept.push_back(std::move(p));
          } else {
            kept.push_back(std::move(o));
          }
        }
        if (kept.empty()) return constantFormula(!absorbing, x.column);
        if (kept.size() == 1) return std::move(kept[0]);
        out.operands = std::move(kept);
        break;
      }
      case FormulaKind::Exists:
      case FormulaKind::All: {
        const bool all = out.kind == FormulaKind::All;
        Formula& path = out.operands[0];
        // a path formula folded to a state formula (F c = c, [false U q] = q): that formula, on
        // every path the same
        const bool pathOperator = path.kind == FormulaKind::Next || path.kind == FormulaKind::Future ||
                                  path.kind == FormulaKind::Globally || path.kind == FormulaKind::Until;
        if (!pathOperator && isCtl(path)) return std::move(path);
        // EX false and AX true whatever the successors; not EX true (a dead marking has none)
        if (path.kind == FormulaKind::Next) {
          const auto c = constantOf(path.operands[0]);
          if (c && *c == all) return constantFormula(all, x.column);
        }
        // F F p = F p, G G p = G p under the same quantifier
        if ((path.kind == FormulaKind::Future || path.kind == FormulaKind::Globally) &&
            isQuantified(path.operands[0], out.kind, path.kind)) {
          return std::move(path.operands[0]);
        }
        break;
      }
      case FormulaKind::Future:
      case FormulaKind::Globally: {
        // on maximal paths F c = G c = c for a constant
        if (constantOf(out.operands[0])) return std::move(out.operands[0]);
        break;
      }
      case FormulaKind::Until: {
        // [p U true] = true, [p U false] = false, [false U q] = q, [true U q] = F q
        if (constantOf(out.operands[1])) return std::move(out.operands[1]);
        if (const auto c = constantOf(out.operands[0])) {
          if (!*c) return std::move(out.operands[1]);
          Formula future;
          future.kind = FormulaKind::Future;
          future.column = x.column;
          future.operands.push_back(std::move(out.operands[1]));
          return future;
        }
        break;
      }
      case FormulaKind::Bound:
      case FormulaKind::Compare:
      case FormulaKind::Deadlock:
      case FormulaKind::False:
      case FormulaKind::Fireable:
      case FormulaKind::Next:
      case FormulaKind::True: break;
    }
    // a whole state formula under a temporal operator: what the state equation says of it
    if (state && top && !constantOf(out) && out.kind != FormulaKind::Bound) {
      if (const auto c = constant(out)) {
        ++changed;
        return constantFormula(*c, x.column);
      }
    }
    return out;
  };
  return walk(walk, f, !isStateFormula(f));
}

}  // namespace gdpn::net::detail
