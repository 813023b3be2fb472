#include "gdpn/net/state_equation.h"

#include <glpk.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

namespace gdpn::net {
namespace {

/// GLPK writes nothing to the terminal while gdpn runs.
int silent(void*, const char*) { return 1; }

struct ProblemDeleter {
  void operator()(glp_prob* p) const { glp_delete_prob(p); }
};

using Lp = std::unique_ptr<glp_prob, ProblemDeleter>;

/// The state equation as a linear program: rows M(p) - M0(p) = C_p · x, with 0 <= M(p) <=
/// capacity; columns x >= 0. Its constraint matrix is `c`.
Lp stateEquation(const Net& net, const Incidence& c) {
  const std::size_t places = net.placeSlots().size();
  const std::size_t transitions = net.transitions().size();
  glp_term_hook(silent, nullptr);
  Lp lp(glp_create_prob());
  glp_add_rows(lp.get(), static_cast<int>(places));
  glp_add_cols(lp.get(), static_cast<int>(transitions));
  for (std::size_t k = 0; k < places; ++k) {
    const PlaceSlot& ps = net.placeSlots()[k];
    const auto m0 = static_cast<double>(ps.initial);
    if (ps.capacity == kUnbounded) {
      glp_set_row_bnds(lp.get(), static_cast<int>(k + 1), GLP_LO, -m0, 0.0);
    } else {
      glp_set_row_bnds(lp.get(), static_cast<int>(k + 1), GLP_DB, -m0, static_cast<double>(ps.capacity) - m0);
    }
  }
  for (std::size_t t = 0; t < transitions; ++t) glp_set_col_bnds(lp.get(), static_cast<int>(t + 1), GLP_LO, 0.0, 0.0);
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0.0};
  for (TransitionId t{0}; t < transitions; ++t) {
    for (const auto& [ps, v] : c.by_transition[t]) {
      ia.push_back(static_cast<int>(ps + 1));
      ja.push_back(static_cast<int>(t + 1));
      ar.push_back(static_cast<double>(v));
    }
  }
  glp_load_matrix(lp.get(), static_cast<int>(ar.size() - 1), ia.data(), ja.data(), ar.data());
  return lp;
}

}  // namespace

std::vector<std::int64_t> stateEquationBounds(const Net& net, const std::vector<bool>& wanted,
                                              const InvariantOptions& options) {
  const std::size_t places = net.placeSlots().size();
  std::vector<TokenSum> sums;
  std::vector<std::size_t> slot;  // per sum: the place slot it bounds
  for (std::size_t k = 0; k < places && k < wanted.size(); ++k) {
    if (!wanted[k]) continue;
    sums.push_back({{PlaceSlotId{static_cast<std::uint32_t>(k)}}, 0});
    slot.push_back(k);
  }
  const auto most = stateEquationMaxima(net, sums, options);
  std::vector<std::int64_t> out(places, -1);
  for (std::size_t i = 0; i < most.size(); ++i) out[slot[i]] = most[i];
  return out;
}

std::vector<std::int64_t> stateEquationMaxima(const Net& net, const std::vector<TokenSum>& sums,
                                              const InvariantOptions& options) {
  const std::size_t transitions = net.transitions().size();
  std::vector<std::int64_t> out(sums.size(), -1);
  auto initial = [&](const TokenSum& s) {
    std::int64_t total = s.constant;
    for (PlaceSlotId k : s.slots) total += net.placeSlots()[k].initial;
    return total;
  };
  if (sums.empty()) return out;
  if (transitions == 0) {
    // nothing fires: each slot keeps what it has
    for (std::size_t i = 0; i < sums.size(); ++i) out[i] = initial(sums[i]);
    return out;
  }
  const Incidence c = incidenceMatrix(net);
  const Lp lp = stateEquation(net, c);
  glp_set_obj_dir(lp.get(), GLP_MAX);
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  parm.presolve = GLP_OFF;  // keep the basis from one program to the next
  std::vector<double> objective(transitions, 0.0);
  for (std::size_t i = 0; i < sums.size(); ++i) {
    if (options.deadline && std::chrono::steady_clock::now() >= *options.deadline) break;
    // maximise the sum's C · x; the sum is then its initial value plus that
    std::fill(objective.begin(), objective.end(), 0.0);
    bool moves = false;
    for (PlaceSlotId k : sums[i].slots) {
      for (const auto& [t, v] : c.by_place[k]) objective[t] += static_cast<double>(v), moves = true;
    }
    for (std::size_t t = 0; t < transitions; ++t) glp_set_obj_coef(lp.get(), static_cast<int>(t + 1), objective[t]);
    const std::int64_t m0 = initial(sums[i]);
    if (!moves) {
      out[i] = m0;
      continue;
    }
    if (glp_simplex(lp.get(), &parm) != 0) {
      // a numerical difficulty: start again from the standard basis once
      glp_std_basis(lp.get());
      if (glp_simplex(lp.get(), &parm) != 0) continue;
    }
    if (glp_get_status(lp.get()) != GLP_OPT) continue;  // unbounded (or, with M0 >= 0 feasible, nothing else)
    const double best = static_cast<double>(m0) + glp_get_obj_val(lp.get());
    // the solver works to tolerances of about 1e-7 per row, scaled: an optimum it reports a
    // little below a whole number is taken as that number (a bound one too high is still a
    // bound; one too low would let the search's counts outgrow their fields)
    if (best < 9e18) out[i] = static_cast<std::int64_t>(std::floor(best + 1e-3 * std::max(1.0, std::abs(best) * 1e-6)));
  }
  return out;
}

}  // namespace gdpn::net

namespace gdpn::net {
namespace {

// a linear constraint on a marking: sum of coefficient * M(slot), at most (or at least) `bound`
struct Linear {
  std::vector<std::pair<PlaceSlotId, std::int64_t>> terms;
  std::int64_t bound = 0;
  bool at_least = false;
};
using Conjunct = std::vector<Linear>;
using Dnf = std::vector<Conjunct>;
constexpr std::size_t kMostDisjuncts = 256;

// every conjunct of `a` with every one of `b`; nullopt past kMostDisjuncts. One conjunct of
// `b` is appended where `a`'s lie: a chain of n conjuncts then costs n copies, not n^2
std::optional<Dnf> product(Dnf a, const Dnf& b) {
  if (a.size() * b.size() > kMostDisjuncts) return std::nullopt;
  if (b.size() == 1) {
    for (Conjunct& x : a) x.insert(x.end(), b[0].begin(), b[0].end());
    return a;
  }
  Dnf out;
  for (const Conjunct& x : a) {
    for (const Conjunct& y : b) {
      out.push_back(x);
      out.back().insert(out.back().end(), y.begin(), y.end());
    }
  }
  return out;
}

// the needs of `t` on the marking as constraints, each negated where `violated`
std::vector<Linear> needs(const Net& net, TransitionId t, bool violated) {
  std::vector<Linear> out;
  // at least `n` tokens on slot k (violated: at most n - 1), or at most `n` (violated: n + 1 or more)
  auto atLeast = [&](PlaceSlotId k, std::int64_t n) { out.push_back({{{k, 1}}, violated ? n - 1 : n, !violated}); };
  auto atMost = [&](PlaceSlotId k, std::int64_t n) { out.push_back({{{k, 1}}, violated ? n + 1 : n, violated}); };
  for (const Term& term : net.termsOf(t)) {
    const PlaceSlotId k = term.place_slot;
    switch (term.kind) {
      case TermKind::Input:
      case TermKind::Test: atLeast(k, term.weight); break;
      case TermKind::Inhibitor: atMost(k, std::int64_t{term.weight} - 1); break;
      case TermKind::Output:
        if (net.placeSlots()[k].capacity != kUnbounded) atMost(k, net.placeSlots()[k].capacity + term.take - term.weight);
        break;
      case TermKind::Condition: break;  // a sensor condition: free to hold
    }
  }
  return out;
}

// `f` (or its negation) in disjunctive normal form over linear constraints
std::optional<Dnf> dnf(const Net& net, const Formula& f, bool positive) {
  switch (f.kind) {
    case FormulaKind::True:
    case FormulaKind::False: return (f.kind == FormulaKind::True) == positive ? Dnf{Conjunct{}} : Dnf{};
    case FormulaKind::Not: return dnf(net, f.operands[0], !positive);
    case FormulaKind::And:
    case FormulaKind::Or: {
      if ((f.kind == FormulaKind::And) == positive) {
        Dnf out{Conjunct{}};
        for (const Formula& o : f.operands) {
          const auto d = dnf(net, o, positive);
          if (!d) return std::nullopt;
          auto p = product(std::move(out), *d);
          if (!p) return std::nullopt;
          out = std::move(*p);
        }
        return out;
      }
      Dnf out;
      for (const Formula& o : f.operands) {
        const auto d = dnf(net, o, positive);
        if (!d || out.size() + d->size() > kMostDisjuncts) return std::nullopt;
        out.insert(out.end(), d->begin(), d->end());
      }
      return out;
    }
    case FormulaKind::Compare: {
      // left - right compared with 0: sum of the slots against the constants' difference
      Linear x;
      for (PlaceSlotId k : f.left.slots) x.terms.emplace_back(k, 1);
      for (PlaceSlotId k : f.right.slots) x.terms.emplace_back(k, -1);
      const std::int64_t c = f.right.constant - f.left.constant;
      Comparison op = f.compare;
      if (!positive) {
        op = negated(op);
      }
      auto with = [&](std::int64_t bound, bool at_least) {
        Linear y = x;
        y.bound = bound;
        y.at_least = at_least;
        return y;
      };
      switch (op) {
        case Comparison::Less: return Dnf{{with(c - 1, false)}};
        case Comparison::LessEqual: return Dnf{{with(c, false)}};
        case Comparison::Equal: return Dnf{{with(c, false), with(c, true)}};
        case Comparison::NotEqual: return Dnf{{with(c - 1, false)}, {with(c + 1, true)}};
        case Comparison::GreaterEqual: return Dnf{{with(c, true)}};
        case Comparison::Greater: return Dnf{{with(c + 1, true)}};
      }
      return std::nullopt;
    }
    case FormulaKind::Fireable:
    case FormulaKind::Deadlock: {
      std::vector<TransitionId> ts = f.transitions;
      bool enabled = positive;  // fireable: one of them enabled; deadlock: none
      if (f.kind == FormulaKind::Deadlock) {
        ts.resize(net.transitions().size());
        for (TransitionId t{0}; t < ts.size(); ++t) ts[t] = t;
        enabled = !positive;
      }
      if (enabled) {
        // one of them enabled: all the needs of one
        Dnf out;
        for (TransitionId t : ts) {
          if (out.size() >= kMostDisjuncts) return std::nullopt;
          out.push_back(needs(net, t, false));
        }
        return out;
      }
      // each of them disabled: one need of each violated
      Dnf out{Conjunct{}};
      for (TransitionId t : ts) {
        Dnf some;
        for (const Linear& x : needs(net, t, true)) some.push_back({x});
        auto p = product(std::move(out), some);
        if (!p) return std::nullopt;
        out = std::move(*p);
      }
      return out;
    }
    case FormulaKind::All:
    case FormulaKind::Bound:
    case FormulaKind::Exists:
    case FormulaKind::Future:
    case FormulaKind::Globally:
    case FormulaKind::Next:
    case FormulaKind::Until: return std::nullopt;  // not a state formula
  }
  return std::nullopt;  // no value of the enum
}

}  // namespace

bool stateEquationExcludes(const Net& net, const Formula& f) {
  const auto disjuncts = dnf(net, f, true);
  if (!disjuncts) return false;
  if (disjuncts->empty()) return true;
  const Incidence c = incidenceMatrix(net);
  const Lp lp = stateEquation(net, c);
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  const int base = glp_get_num_rows(lp.get());
  for (const Conjunct& conjunct : *disjuncts) {
    // each constraint on M = M0 + C x as a row over x
    for (const Linear& x : conjunct) {
      std::vector<double> row(net.transitions().size() + 1, 0.0);
      double m0 = 0.0;
      for (const auto& [k, coef] : x.terms) {
        m0 += static_cast<double>(coef) * static_cast<double>(net.placeSlots()[k].initial);
        for (const auto& [t, v] : c.by_place[k]) row[t + 1] += static_cast<double>(coef * v);
      }
      std::vector<int> index{0};
      std::vector<double> value{0.0};
      for (std::size_t t = 1; t < row.size(); ++t) {
        if (row[t] != 0.0) index.push_back(static_cast<int>(t)), value.push_back(row[t]);
      }
      const int r = glp_add_rows(lp.get(), 1);
      glp_set_mat_row(lp.get(), r, static_cast<int>(index.size() - 1), index.data(), value.data());
      const double bound = static_cast<double>(x.bound) - m0;
      glp_set_row_bnds(lp.get(), r, x.at_least ? GLP_LO : GLP_UP, bound, bound);
    }
    const bool solved = glp_simplex(lp.get(), &parm) == 0;
    const bool infeasible = solved && glp_get_prim_stat(lp.get()) == GLP_NOFEAS;
    // back to the state equation alone for the next conjunct
    const int added = glp_get_num_rows(lp.get()) - base;
    if (added > 0) {
      std::vector<int> rows{0};
      for (int r = base + 1; r <= base + added; ++r) rows.push_back(r);
      glp_del_rows(lp.get(), added, rows.data());
    }
    glp_std_basis(lp.get());
    if (!infeasible) return false;  // this disjunct may hold somewhere
  }
  return true;
}

std::optional<bool> positiveSolution(const std::vector<std::vector<std::pair<std::uint32_t, std::int64_t>>>& rows,
                                     std::size_t columns, bool equality) {
  glp_term_hook(silent, nullptr);
  Lp lp(glp_create_prob());
  // one constraint per column, one variable per row
  if (columns > 0) glp_add_rows(lp.get(), static_cast<int>(columns));
  if (!rows.empty()) glp_add_cols(lp.get(), static_cast<int>(rows.size()));
  for (std::size_t c = 0; c < columns; ++c) {
    glp_set_row_bnds(lp.get(), static_cast<int>(c + 1), equality ? GLP_FX : GLP_UP, 0.0, 0.0);
  }
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0.0};
  for (std::size_t v = 0; v < rows.size(); ++v) {
    glp_set_col_bnds(lp.get(), static_cast<int>(v + 1), GLP_LO, 1.0, 0.0);
    for (const auto& [c, x] : rows[v]) {
      ia.push_back(static_cast<int>(c + 1));
      ja.push_back(static_cast<int>(v + 1));
      ar.push_back(static_cast<double>(x));
    }
  }
  if (rows.empty()) return true;
  glp_load_matrix(lp.get(), static_cast<int>(ar.size() - 1), ia.data(), ja.data(), ar.data());
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  parm.presolve = GLP_ON;  // feasibility only: no objective
  const int rc = glp_simplex(lp.get(), &parm);
  if (rc == GLP_ENOPFS) return false;  // presolve found no primal feasible solution
  if (rc != 0) return std::nullopt;
  const int status = glp_get_status(lp.get());
  if (status == GLP_OPT || status == GLP_FEAS) return true;
  if (status == GLP_NOFEAS) return false;
  return std::nullopt;
}

}  // namespace gdpn::net
