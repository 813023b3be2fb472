// CTL on the explicit reachability graph: the markings breadth first with their edges both
// ways, then each subformula's set of markings bottom up, the temporal operators by fixed
// points (backward from what holds for the least ones, counting successors for the others).

#include "detail/query_graph.h"

#include <algorithm>
#include <limits>

#include "detail/state_check.h"

namespace gdpn::net::detail {
namespace {

bool pathOperator(FormulaKind k) {
  return k == FormulaKind::Next || k == FormulaKind::Future || k == FormulaKind::Globally || k == FormulaKind::Until;
}

}  // namespace

StateGraph buildGraph(const Net& net, const ExploreOptions& limits) {
  StateGraph g;
  ConcreteStates states(net, limits);
  if (!states.ok()) {
    g.stop = ExploreStop::Overflow;
    return g;
  }
  const Store& store = states.store();
  for (StateId s = 0; s < store.size() && g.stop == ExploreStop::Done; ++s) {
    if ((s & 0xfff) == 0) {
      g.stop = passedLimit(limits, store.bytes() + g.succ.capacity() * 8 + g.first.capacity() * 8);
    }
    g.first.push_back(g.succ.size());
    const bool fits = states.successors(s, [&](TransitionId t, StateId w, bool) {
      g.succ.push_back(w);
      g.via.push_back(t);
      if (store.size() > std::min<std::uint64_t>(limits.max_states, 0xfffffff0u)) g.stop = ExploreStop::MaxStates;
      return true;
    });
    if (!fits) g.stop = ExploreStop::Overflow;
  }
  g.first.push_back(g.succ.size());
  g.store = states.releaseStore();
  if (g.stop != ExploreStop::Done) return g;
  // the edges backwards
  const std::size_t n = g.size();
  g.pfirst.assign(n + 1, 0);
  for (StateId w : g.succ) ++g.pfirst[w + 1];
  for (std::size_t s = 0; s < n; ++s) g.pfirst[s + 1] += g.pfirst[s];
  g.pred.resize(g.succ.size());
  std::vector<std::uint64_t> at(g.pfirst.begin(), g.pfirst.end() - 1);
  for (StateId s = 0; s < n; ++s) {
    for (auto e = g.first[s]; e < g.first[s + 1]; ++e) g.pred[at[g.succ[e]]++] = s;
  }
  return g;
}

namespace {

// per marking: 1 where the formula holds (bytes, not bits: read and written at random)
using Set = std::vector<std::uint8_t>;

void flip(Set& x) {
  for (auto& b : x) b = !b;
}

class Checker {
 public:
  Checker(const Net& net, const StateGraph& g) : g_(g), check_(net, g.store->layout()) {}

  Set eval(const Formula& f) {
    const std::size_t n = g_.size();
    switch (f.kind) {
      case FormulaKind::Not: {
        Set x = eval(f.operands[0]);
        flip(x);
        return x;
      }
      case FormulaKind::And:
      case FormulaKind::Or: {
        Set x = eval(f.operands[0]);
        for (std::size_t i = 1; i < f.operands.size(); ++i) {
          const Set y = eval(f.operands[i]);
          for (std::size_t s = 0; s < n; ++s) x[s] = f.kind == FormulaKind::And ? x[s] && y[s] : x[s] || y[s];
        }
        return x;
      }
      case FormulaKind::Exists:
      case FormulaKind::All: return temporal(f.kind == FormulaKind::All, f.operands[0]);
      case FormulaKind::Bound:
      case FormulaKind::Compare:
      case FormulaKind::Deadlock:
      case FormulaKind::False:
      case FormulaKind::Fireable:
      case FormulaKind::Future:
      case FormulaKind::Globally:
      case FormulaKind::Next:
      case FormulaKind::True:
      case FormulaKind::Until: {
        Set x(n);
        std::vector<std::uint64_t> m;
        for (StateId s = 0; s < n; ++s) x[s] = check_.holds(f, g_.store->load(s, m));
        return x;
      }
    }
    return Set(n, 0);  // no value of the enum
  }

 private:
  Set temporal(bool all, const Formula& path) {
    const std::size_t n = g_.size();
    switch (path.kind) {
      case FormulaKind::Next: {
        const Set p = eval(path.operands[0]);
        Set x(n);
        for (StateId s = 0; s < n; ++s) {
          bool any = false, every = true;
          for (auto e = g_.first[s]; e < g_.first[s + 1]; ++e) any = any || p[g_.succ[e]], every = every && p[g_.succ[e]];
          x[s] = all ? every : any;
        }
        return x;
      }
      case FormulaKind::Future: {
        Set p = eval(path.operands[0]);
        if (!all) return until(Set(n, 1), std::move(p), false);  // EF p = E[true U p]
        flip(p);
        Set x = existsGlobally(std::move(p));  // AF p = not EG not p
        flip(x);
        return x;
      }
      case FormulaKind::Globally: {
        Set p = eval(path.operands[0]);
        if (!all) return existsGlobally(std::move(p));
        flip(p);
        Set x = until(Set(n, 1), std::move(p), false);  // AG p = not EF not p
        flip(x);
        return x;
      }
      case FormulaKind::Until: {
        Set p = eval(path.operands[0]), q = eval(path.operands[1]);
        return until(p, std::move(q), all);
      }
      case FormulaKind::All:
      case FormulaKind::And:
      case FormulaKind::Bound:
      case FormulaKind::Compare:
      case FormulaKind::Deadlock:
      case FormulaKind::Exists:
      case FormulaKind::False:
      case FormulaKind::Fireable:
      case FormulaKind::Not:
      case FormulaKind::Or:
      case FormulaKind::True: return Set(n, 0);  // not CTL: never asked (isCtl)
    }
    return Set(n, 0);  // no value of the enum
  }
  // E[p U q] (all: A[p U q]): q, then backwards through p, a p marking joining once one of
  // its edges (all: every one) leads into the set; a least fixed point
  Set until(const Set& p, Set q, bool all) {
    const std::size_t n = g_.size();
    std::vector<std::uint32_t> need(n, 1);  // edges still to lead into the set
    std::vector<StateId> todo;
    for (StateId s = 0; s < n; ++s) {
      if (all) need[s] = static_cast<std::uint32_t>(g_.outDegree(s));
      if (q[s]) todo.push_back(s);
    }
    while (!todo.empty()) {
      const StateId x = todo.back();
      todo.pop_back();
      for (auto e = g_.pfirst[x]; e < g_.pfirst[x + 1]; ++e) {
        const StateId r = g_.pred[e];
        if (!q[r] && p[r] && --need[r] == 0) q[r] = 1, todo.push_back(r);
      }
    }
    return q;
  }
  // EG p on maximal paths: the p markings, less those whose every edge leaves them (a dead
  // marking where p holds keeps it)
  Set existsGlobally(Set p) {
    const std::size_t n = g_.size();
    std::vector<std::uint32_t> inside(n, 0);  // edges into the set
    std::vector<StateId> todo;
    for (StateId s = 0; s < n; ++s) {
      if (!p[s]) continue;
      for (auto e = g_.first[s]; e < g_.first[s + 1]; ++e) inside[s] += p[g_.succ[e]] ? 1u : 0u;
      if (inside[s] == 0 && g_.outDegree(s) > 0) todo.push_back(s);
    }
    for (StateId s : todo) p[s] = 0;
    while (!todo.empty()) {
      const StateId x = todo.back();
      todo.pop_back();
      for (auto e = g_.pfirst[x]; e < g_.pfirst[x + 1]; ++e) {
        const StateId r = g_.pred[e];
        if (p[r] && --inside[r] == 0) p[r] = 0, todo.push_back(r);
      }
    }
    return p;
  }

  const StateGraph& g_;
  StateCheck check_;
};

}  // namespace

bool isCtl(const Formula& f) {
  if (f.kind == FormulaKind::All || f.kind == FormulaKind::Exists) {
    const Formula& path = f.operands[0];
    if (!pathOperator(path.kind)) return false;
    for (const Formula& o : path.operands) {
      if (!isCtl(o)) return false;
    }
    return true;
  }
  if (pathOperator(f.kind)) return false;
  for (const Formula& o : f.operands) {
    if (!isCtl(o)) return false;
  }
  return true;
}

namespace {

/// A shortest path over the graph's edges from the initial marking to the first marking in
/// `target` (breadth first); false when none is reachable.
bool shortestPath(const StateGraph& g, const Set& target, QueryAnswer& a) {
  std::vector<StateId> parent(g.size(), kNone);
  std::vector<std::uint64_t> edge(g.size(), 0);
  std::vector<StateId> queue{0};
  parent[0] = 0;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const StateId s = queue[head];
    if (target[s]) {
      for (StateId x = s; x != 0; x = parent[x]) a.path.push_back(g.via[edge[x]]);
      std::reverse(a.path.begin(), a.path.end());
      a.marking.resize(g.store->layout().width());
      std::vector<std::uint64_t> m;
      g.store->layout().unpack(g.store->load(s, m), a.marking.data());
      a.has_marking = true;
      return true;
    }
    for (auto e = g.first[s]; e < g.first[s + 1]; ++e) {
      const StateId w = g.succ[e];
      if (parent[w] != kNone) continue;
      parent[w] = s;
      edge[w] = e;
      queue.push_back(w);
    }
  }
  return false;
}

}  // namespace

QueryAnswer answerOnGraph(const Net& net, const StateGraph& g, const Formula& f, const ExploreOptions& limits) {
  QueryAnswer a;
  a.states = g.size();
  Checker checker(net, g);
  if (f.kind == FormulaKind::Bound) {
    // the most tokens, and a shortest way to a marking that holds them
    StateCheck check(net, g.store->layout());
    std::vector<std::int64_t> sums(g.size());
    std::vector<std::uint64_t> m;
    for (StateId s = 0; s < g.size(); ++s) sums[s] = check.sum(f.left, g.store->load(s, m));
    const std::int64_t most = *std::max_element(sums.begin(), sums.end());
    Set at(g.size());
    for (StateId s = 0; s < g.size(); ++s) at[s] = sums[s] == most;
    shortestPath(g, at, a);
    a.verdict = Verdict::Value;
    a.value = most;
    a.technique = "EXPLICIT";
    return a;
  }
  const Formula* path = (f.kind == FormulaKind::Exists || f.kind == FormulaKind::All) ? &f.operands[0] : nullptr;
  const bool ef = path && f.kind == FormulaKind::Exists && path->kind == FormulaKind::Future &&
                  isStateFormula(path->operands[0]);
  const bool ag = path && f.kind == FormulaKind::All && path->kind == FormulaKind::Globally &&
                  isStateFormula(path->operands[0]);
  if (ef || ag) {
    // EF p: a marking where p holds; AG p: none where it fails
    Set target = checker.eval(path->operands[0]);
    if (ag) flip(target);
    const bool found = shortestPath(g, target, a);
    a.verdict = found == ef ? Verdict::True : Verdict::False;
    a.technique = "EXPLICIT";
    return a;
  }
  if (!isCtl(f)) return answerLtl(net, g, f, limits);
  a.verdict = checker.eval(f)[0] ? Verdict::True : Verdict::False;
  a.technique = "EXPLICIT CTL_FIXED_POINTS";
  if (lassoShows(f, a.verdict)) takeLasso(a, answerLtl(net, g, f, limits));
  return a;
}

bool lassoShows(const Formula& f, Verdict v) {
  if ((f.kind != FormulaKind::Exists && f.kind != FormulaKind::All) || f.operands.empty()) return false;
  const Formula& path = f.operands[0];
  const bool single = pathOperator(path.kind) && path.kind != FormulaKind::Next && isStateFormula(path.operands[0]) &&
                      isStateFormula(path.operands.back());
  return single && (v == Verdict::True) == (f.kind == FormulaKind::Exists);
}

void takeLasso(QueryAnswer& a, QueryAnswer shown) {
  if (shown.verdict != a.verdict || !shown.lasso) return;
  a.path = std::move(shown.path);
  a.cycle = std::move(shown.cycle);
  a.marking = std::move(shown.marking);
  a.has_marking = a.lasso = true;
}

}  // namespace gdpn::net::detail
