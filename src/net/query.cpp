// Answers to queries: which technique each formula gets (a state formula at the initial
// marking; reachability, EF and AG, by a breadth-first search over packed markings that stops
// at the first marking deciding it; the rest on the stored graph), and the search itself.

#include "gdpn/net/query.h"

#include <algorithm>
#include <optional>

#include "detail/query_graph.h"
#include "detail/state_check.h"
#include "detail/stubborn.h"
#include "gdpn/net/state_equation.h"

namespace gdpn::net {
namespace {

using namespace detail;

std::vector<std::int64_t> unpacked(const Layout& layout, const std::uint64_t* m) {
  std::vector<std::int64_t> out(layout.width());
  layout.unpack(m, out.data());
  return out;
}

/// Breadth first from the initial marking to the first marking where `target` holds: its path
/// and the marking (shortest among the transitions searched: with stubborn sets, those of the
/// sets), or, when there is none, every marking of the (reduced) graph seen.
struct Reach {
  bool found = false;
  ExploreStop stop = ExploreStop::Done;
  std::vector<TransitionId> path;
  std::vector<std::int64_t> marking;
  std::uint64_t states = 0;
};

Reach reach(const Net& net, const Formula& target, const ExploreOptions& limits) {
  Reach out;
  ConcreteStates states(net, limits);
  if (!states.ok()) {
    out.stop = ExploreStop::Overflow;
    return out;
  }
  Store& store = states.store();
  std::optional<Stubborn> stubborn;
  if (limits.reduction) stubborn.emplace(net, store.layout());
  std::vector<TransitionId> chosen;
  std::vector<StateId> parent{0};
  std::vector<TransitionId> via{TransitionId{0}};  // one entry (a bare {0} would be the size)
  std::vector<std::uint64_t> marking, expanded;
  auto found = [&](StateId s) {
    if (!states.check().holds(target, store.load(s, marking))) return false;
    out.found = true;
    for (StateId x = s; x != 0; x = parent[x]) out.path.push_back(via[x]);
    std::reverse(out.path.begin(), out.path.end());
    out.marking = unpacked(store.layout(), marking.data());
    return true;
  };
  if (found(0)) {
    out.states = 1;
    return out;
  }
  for (StateId s = 0; s < store.size() && !out.found && out.stop == ExploreStop::Done; ++s) {
    if ((s & 0xfff) == 0) out.stop = passedLimit(limits, store.bytes() + parent.capacity() * 8);
    if (out.stop != ExploreStop::Done) break;
    auto each = [&](TransitionId t, StateId w, bool added) {
      if (!added) return true;
      parent.push_back(s);
      via.push_back(t);
      if (found(w)) return false;
      if (store.size() > std::min<std::uint64_t>(limits.max_states, 0xfffffff0u)) out.stop = ExploreStop::MaxStates;
      return out.stop == ExploreStop::Done;
    };
    bool fits = true;
    if (stubborn) {
      stubborn->select(target, store.load(s, expanded), states.check(), chosen);
      fits = states.fire(s, chosen, each);
    } else {
      fits = states.successors(s, each);
    }
    if (!fits) out.stop = ExploreStop::Overflow;
  }
  out.states = store.size();
  return out;
}

Formula negation(const Formula& f) {
  Formula n;
  n.kind = FormulaKind::Not;
  n.column = f.column;
  n.operands.push_back(f);
  return n;
}

}  // namespace

namespace {

/// The formula under its negations, and how many there are.
const Formula& unnegated(const Formula& f, bool& odd) {
  const Formula* x = &f;
  odd = false;
  while (x->kind == FormulaKind::Not) x = &x->operands[0], odd = !odd;
  return *x;
}

/// EF or AG of a formula without path operators: a search on the fly can answer it.
bool reachability(const Formula& f) {
  if ((f.kind != FormulaKind::Exists && f.kind != FormulaKind::All) || f.operands.empty()) return false;
  const Formula& path = f.operands[0];
  const FormulaKind want = f.kind == FormulaKind::Exists ? FormulaKind::Future : FormulaKind::Globally;
  return path.kind == want && isStateFormula(path.operands[0]);
}

QueryAnswer atInitialMarking(const Net& net, const Formula& f) {
  QueryAnswer a;
  std::vector<std::int64_t> m0;
  for (const PlaceSlot& ps : net.placeSlots()) m0.push_back(ps.initial);
  a.verdict = holdsIn(net, f, m0) ? Verdict::True : Verdict::False;
  a.states = 1;
  a.technique = "INITIAL_STATE";
  return a;
}

/// EF p or AG p by a breadth-first search that stops at the first marking deciding it.
QueryAnswer onTheFly(const Net& net, const Formula& f, const ExploreOptions& limits) {
  QueryAnswer a;
  const bool ef = f.kind == FormulaKind::Exists;
  const Formula& p = f.operands[0].operands[0];
  // EF p: a marking where p holds; AG p: none where it fails
  const Formula target = ef ? p : negation(p);
  if (limits.state_equation && stateEquationExcludes(net, target)) {
    // no solution of the state equation holds the target: no reachable marking does
    a.verdict = ef ? Verdict::False : Verdict::True;
    a.states = 0;
    a.technique = "STATE_EQUATION";
    return a;
  }
  const Reach r = reach(net, target, limits);
  a.states = r.states;
  a.technique = limits.reduction ? "EXPLICIT BREADTH_FIRST_SEARCH STUBBORN_SETS" : "EXPLICIT BREADTH_FIRST_SEARCH";
  if (r.found) {
    a.verdict = ef ? Verdict::True : Verdict::False;
    a.path = r.path;
    a.marking = r.marking;
    a.has_marking = true;
  } else if (r.stop == ExploreStop::Done) {
    a.verdict = ef ? Verdict::False : Verdict::True;
  } else {
    a.stop = r.stop;
  }
  return a;
}

}  // namespace

QueryAnswer answerQuery(const Net& net, const Formula& f, const ExploreOptions& limits) {
  return answerQueries(net, {f}, limits)[0];
}

std::vector<QueryAnswer> answerQueries(const Net& net, const std::vector<Formula>& formulas,
                                       const ExploreOptions& limits) {
  // the whole graph once where it pays: a formula needs it, or two need a search
  std::size_t searches = 0;
  bool whole = false;
  for (const Formula& f : formulas) {
    bool odd = false;
    const Formula& x = unnegated(f, odd);
    if (isStateFormula(x)) continue;
    ++searches;
    whole = whole || !reachability(x);
  }
  // with stubborn sets, a reachability search on the fly usually sees a small part of the
  // graph: the graph is stored only when a formula needs it
  std::optional<StateGraph> graph;
  if (whole || (searches >= 2 && !limits.reduction)) graph = buildGraph(net, limits);
  std::vector<QueryAnswer> out;
  for (const Formula& f : formulas) {
    bool odd = false;
    const Formula& x = unnegated(f, odd);
    QueryAnswer a;
    if (isStateFormula(x)) {
      a = atInitialMarking(net, x);
    } else if (graph && graph->stop == ExploreStop::Done) {
      a = answerOnGraph(net, *graph, x, limits);
    } else if (reachability(x)) {
      a = onTheFly(net, x, limits);
    } else {
      a.stop = graph->stop;  // a limit stopped the graph that this formula needs
      a.states = graph->size();
    }
    // a negation turns the answer over; the marking that shows it shows this one too
    if (odd && (a.verdict == Verdict::True || a.verdict == Verdict::False)) {
      a.verdict = a.verdict == Verdict::True ? Verdict::False : Verdict::True;
    }
    out.push_back(std::move(a));
  }
  return out;
}

bool holdsIn(const Net& net, const Formula& f, const std::vector<std::int64_t>& marking) {
  const std::vector<bool> no(marking.size(), false);
  const Layout layout(std::vector<std::uint32_t>(marking.size(), kMaxBits), no, no);
  std::vector<std::uint64_t> packed(layout.words());
  std::size_t bad = 0;
  if (!layout.pack(marking.data(), packed.data(), bad)) return false;
  StateCheck check(net, layout);
  return check.holds(f, packed.data());
}

}  // namespace gdpn::net
