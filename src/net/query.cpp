// Answers to queries: which technique each formula gets (a state formula at the initial
// marking; reachability, EF and AG, by a breadth-first search over packed markings that stops
// at the first marking deciding it; the rest on the stored graph), and the search itself.

#include "gdpn/net/query.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <queue>
#include <sstream>

#include "detail/query_graph.h"
#include "detail/simplify.h"
#include "gdpn/net/invariants.h"
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

/// How far marking `m` is from one where `f` holds (`positive`; else from one where it fails):
/// the tokens missing or too many in its comparisons, the arcs' tokens missing for
/// fireable; 0 exactly where it holds (fails). The guided search's measure.
std::int64_t distance(const Net& net, StateCheck& check, const Layout& layout, const Formula& f, bool positive,
                      const std::uint64_t* m) {
  constexpr std::int64_t kFar = std::int64_t{1} << 40;
  switch (f.kind) {
    case FormulaKind::True: return positive ? 0 : kFar;
    case FormulaKind::False: return positive ? kFar : 0;
    case FormulaKind::Compare: {
      const std::int64_t x = check.sum(f.left, m), y = check.sum(f.right, m);
      switch (positive ? f.compare : negated(f.compare)) {
        case Comparison::Less: return std::max<std::int64_t>(0, x - y + 1);
        case Comparison::LessEqual: return std::max<std::int64_t>(0, x - y);
        case Comparison::Equal: return x > y ? x - y : y - x;
        case Comparison::NotEqual: return x == y ? 1 : 0;
        case Comparison::GreaterEqual: return std::max<std::int64_t>(0, y - x);
        case Comparison::Greater: return std::max<std::int64_t>(0, y - x + 1);
      }
      return 0;
    }
    case FormulaKind::Fireable: {
      if (!positive) {
        // each of them enabled must come to be disabled
        return static_cast<std::int64_t>(std::count_if(f.transitions.begin(), f.transitions.end(),
                                                       [&](TransitionId t) { return check.firing().enabled(t, m); }));
      }
      std::int64_t best = kFar;
      for (TransitionId t : f.transitions) {
        std::int64_t missing = 0;
        for (const Term& term : net.termsOf(t)) {
          const std::int64_t v = layout.value(m, term.place_slot);
          switch (term.kind) {
            case TermKind::Input:
            case TermKind::Test: missing += std::max<std::int64_t>(0, term.weight - v); break;
            case TermKind::Inhibitor: missing += std::max<std::int64_t>(0, v - term.weight + 1); break;
            case TermKind::Output:
            case TermKind::Condition: break;
          }
        }
        best = std::min(best, missing);
      }
      return best;
    }
    case FormulaKind::Not: return distance(net, check, layout, f.operands[0], !positive, m);
    case FormulaKind::And:
    case FormulaKind::Or: {
      // a conjunction (a negated disjunction) needs each part; a disjunction one of them
      const bool each = (f.kind == FormulaKind::And) == positive;
      std::int64_t d = each ? 0 : kFar;
      for (const Formula& o : f.operands) {
        const std::int64_t x = distance(net, check, layout, o, positive, m);
        d = each ? std::min(kFar, d + x) : std::min(d, x);
      }
      return d;
    }
    case FormulaKind::Deadlock: {
      if (!positive) return check.holds(f, m) ? 1 : 0;
      // each enabled transition must come to be disabled
      std::vector<TransitionId> candidates;
      check.candidates().find(m, check.firing(), candidates);
      return static_cast<std::int64_t>(
          std::count_if(candidates.begin(), candidates.end(), [&](TransitionId t) { return check.firing().enabled(t, m); }));
    }
    case FormulaKind::All:
    case FormulaKind::Bound:
    case FormulaKind::Exists:
    case FormulaKind::Future:
    case FormulaKind::Globally:
    case FormulaKind::Next:
    case FormulaKind::Until: return check.holds(f, m) == positive ? 0 : 1;
  }
  return 0;  // no value of the enum
}

/// How a reachability search takes its markings: breadth first (shortest paths), or the
/// nearest to the target first by distance() (a guided search, for targets deep down).
enum class Order : std::uint8_t { BreadthFirst, Guided };

Reach reach(const Net& net, const Formula& target, const ExploreOptions& limits, Order order = Order::BreadthFirst) {
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
  // guided: markings by distance, the nearest first, in two queues taken in turns: of equal
  // distance the one met first (widening at each distance: Dekker's bounds), and the one
  // furthest from the initial marking (down one promising path: Philosophers' 25 eating,
  // 2.1 M markings the first way); each marking is expanded once
  using Entry = std::pair<std::int64_t, std::int64_t>;  // distance, then id, or -(depth, id)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> wide, deep;
  std::vector<bool> taken;          // by id: expanded already
  std::vector<std::uint32_t> depth{0};  // by id: firings from the initial marking
  auto found = [&](StateId s) {
    const std::uint64_t* m = store.load(s, marking);
    if (!states.check().holds(target, m)) {
      if (order == Order::Guided) {
        const std::int64_t d = std::max<std::int64_t>(1, distance(net, states.check(), store.layout(), target, true, m));
        wide.push({d, static_cast<std::int64_t>(s)});
        deep.push({d, -static_cast<std::int64_t>((std::uint64_t{depth[s]} << 32) | s)});
      }
      return false;
    }
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
  StateId next = 0;  // breadth first: the states in the order met
  for (std::uint64_t round = 0; !out.found && out.stop == ExploreStop::Done; ++round) {
    StateId s = next;
    if (order == Order::Guided) {
      // the next marking not yet taken, from one queue and then the other
      auto& first = (round & 1) != 0 ? deep : wide;
      auto& second = (round & 1) != 0 ? wide : deep;
      const auto next_of = [&](auto& q) -> std::optional<StateId> {
        while (!q.empty()) {
          const auto id = static_cast<StateId>((q.top().second < 0 ? -q.top().second : q.top().second) & 0xffffffff);
          q.pop();
          if (id >= taken.size() || !taken[id]) return id;
        }
        return std::nullopt;
      };
      auto picked = next_of(first);
      if (!picked) picked = next_of(second);
      if (!picked) break;
      s = *picked;
      if (s >= taken.size()) taken.resize(std::max<std::size_t>(s + 1, taken.size() * 2), false);
      taken[s] = true;
    } else if (next++ >= store.size()) {
      break;
    }
    if ((round & 0xfff) == 0) {
      out.stop = passedLimit(limits, store.bytes() + parent.capacity() * 8 +
                                         (wide.size() + deep.size()) * sizeof(Entry) + taken.capacity() / 8 +
                                         depth.capacity() * 4);
    }
    if (out.stop != ExploreStop::Done) break;
    auto each = [&](TransitionId t, StateId w, bool added) {
      if (!added) return true;
      parent.push_back(s);
      via.push_back(t);
      if (order == Order::Guided) depth.push_back(depth[s] + 1);
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

/// EF p or AG p: refuted by the state equation where it can be, else by a search that stops
/// at the first marking deciding it (breadth first, or guided by the distance to it).
QueryAnswer reachabilityAnswer(const Net& net, const Formula& f, const ExploreOptions& limits, Order order) {
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
  const Reach r = reach(net, target, limits, order);
  a.states = r.states;
  a.technique = order == Order::Guided ? "EXPLICIT BEST_FIRST_SEARCH" : "EXPLICIT BREADTH_FIRST_SEARCH";
  if (limits.reduction) a.technique += " STUBBORN_SETS";
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

/// bound(s) without the whole graph: the state equation's bound on the sum, where a search
/// guided towards it reaches a marking that holds it (then no marking holds more).
QueryAnswer boundAnswer(const Net& net, const Formula& f, const ExploreOptions& limits) {
  QueryAnswer a;
  InvariantOptions lp;
  lp.deadline = limits.deadline;
  const std::int64_t most = stateEquationMaxima(net, {f.left}, lp)[0];
  if (most < 0) {
    a.stop = limits.deadline && std::chrono::steady_clock::now() >= *limits.deadline ? ExploreStop::TimeLimit
                                                                                     : ExploreStop::Done;
    a.unsupported = a.stop == ExploreStop::Done ? "the state equation does not bound it" : "";
    return a;
  }
  Formula target;
  target.kind = FormulaKind::Compare;
  target.compare = Comparison::GreaterEqual;
  target.left = f.left;
  target.right.constant = most;
  const Reach r = reach(net, target, limits, Order::Guided);
  a.states = r.states;
  if (!r.found) {
    // none reached: the bound lies lower (a search of the whole graph finds it), or a limit
    a.stop = r.stop;
    if (r.stop == ExploreStop::Done) a.unsupported = "the state equation's bound " + std::to_string(most) + " is not reached";
    return a;
  }
  a.verdict = Verdict::Value;
  a.value = most;
  a.path = r.path;
  a.marking = r.marking;
  a.has_marking = true;
  a.technique = r.path.empty() ? "STATE_EQUATION INITIAL_STATE" : "STATE_EQUATION EXPLICIT BEST_FIRST_SEARCH";
  return a;
}

/// True when no path quantifier stands in `f`.
bool quantifierFree(const Formula& f) {
  return f.kind != FormulaKind::Exists && f.kind != FormulaKind::All &&
         std::all_of(f.operands.begin(), f.operands.end(), [](const Formula& o) { return quantifierFree(o); });
}

/// Decided: true, false or a number.
bool decided(const QueryAnswer& a) { return a.verdict != Verdict::Unknown; }

/// The limits of one formula's try on the fly: `states` markings at most and, under a
/// deadline, a `share` of the time left.
ExploreOptions tryLimits(const ExploreOptions& limits, std::uint64_t states, double share) {
  ExploreOptions l = limits;
  l.max_states = std::min(limits.max_states, states);
  if (limits.deadline) {
    const auto now = std::chrono::steady_clock::now();
    const auto left = *limits.deadline > now ? *limits.deadline - now : std::chrono::steady_clock::duration{0};
    l.deadline = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(left * share);
  }
  return l;
}

QueryAnswer withoutGraph(const Net& net, const Formula& x, const ExploreOptions& limits);

/// `p and q ...` (`p or q ...`), each part answered on its own by the means that suits it
/// (EF of a state formula by a reachability search, ...), under a share of the limits: false
/// (true) at the first part that is, true (false) when every part is; without a witness.
QueryAnswer booleanAnswer(const Net& net, const Formula& x, const ExploreOptions& limits) {
  const bool conjunction = x.kind == FormulaKind::And;
  QueryAnswer out;
  std::vector<std::string> techniques;
  // the state formulas first: they cost one marking
  std::vector<const Formula*> parts;
  for (int pass = 0; pass < 2; ++pass) {
    for (const Formula& o : x.operands) {
      if (isStateFormula(o) == (pass == 0)) parts.push_back(&o);
    }
  }
  bool open = false;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    bool odd = false;
    const Formula& part = unnegated(*parts[k], odd);
    const QueryAnswer a = isStateFormula(part)
                              ? atInitialMarking(net, part)
                              : withoutGraph(net, part, tryLimits(limits, limits.max_states,
                                                                  1.0 / static_cast<double>(parts.size() - k)));
    out.states = std::max(out.states, a.states);  // the most markings one part explored
    if (!decided(a)) {
      open = true;
      if (out.stop == ExploreStop::Done) out.stop = a.stop;
      if (out.unsupported.empty()) out.unsupported = a.unsupported;
      continue;
    }
    // each word once (EXPLICIT, STUBBORN_SETS, ... shared by the parts' techniques)
    std::istringstream words(a.technique);
    for (std::string w; words >> w;) {
      if (std::find(techniques.begin(), techniques.end(), w) == techniques.end()) techniques.push_back(w);
    }
    if (((a.verdict == Verdict::True) != odd) != conjunction) {
      // this part decides it
      out.verdict = conjunction ? Verdict::False : Verdict::True;
      out.stop = ExploreStop::Done;
      out.unsupported.clear();
      out.technique = a.technique;
      return out;
    }
  }
  if (open) return out;
  out.verdict = conjunction ? Verdict::True : Verdict::False;
  for (const std::string& t : techniques) out.technique += (out.technique.empty() ? "" : " ") + t;
  return out;
}

/// The formula `x` (no negation on top) answered without the whole graph: reachability by a
/// search on the fly (breadth first, then guided), a bound by the state equation and a guided
/// search, other CTL formulas by local searches, LTL by the product made on the fly.
QueryAnswer withoutGraph(const Net& net, const Formula& x, const ExploreOptions& limits) {
  if (x.kind == FormulaKind::Bound) return boundAnswer(net, x, limits);
  if (x.kind == FormulaKind::And || x.kind == FormulaKind::Or) return booleanAnswer(net, x, limits);
  if (reachability(x)) {
    // breadth first for a while (shortest paths where the target is near), then guided
    ExploreOptions first = limits;
    first.max_states = std::min<std::uint64_t>(limits.max_states, 1u << 16);
    QueryAnswer a = reachabilityAnswer(net, x, first, Order::BreadthFirst);
    if (decided(a) || a.stop != ExploreStop::MaxStates || limits.max_states <= first.max_states) return a;
    return reachabilityAnswer(net, x, limits, Order::Guided);
  }
  if (isCtl(x)) {
    QueryAnswer a = answerCtlLocally(net, x, limits);
    if (lassoShows(x, a.verdict)) takeLasso(a, answerLtlOnTheFly(net, x, limits));
    return a;
  }
  return answerLtlOnTheFly(net, x, limits);
}

}  // namespace

QueryAnswer answerQuery(const Net& net, const Formula& f, const ExploreOptions& limits) {
  return answerQueries(net, {f}, limits)[0];
}

std::vector<QueryAnswer> answerQueries(const Net& net, const std::vector<Formula>& formulas,
                                       const ExploreOptions& limits) {
  // the invariants once for every search (they size the markings)
  ExploreOptions base = limits;
  std::optional<Invariants> inv;
  if (base.invariants == nullptr) {
    InvariantOptions io;
    io.max_candidates = 2'000;
    io.max_bytes = limits.max_bytes;
    io.deadline = limits.deadline;
    inv = invariants(net, io);
    base.invariants = &*inv;
  }
  std::vector<QueryAnswer> out(formulas.size());
  std::vector<std::size_t> open;  // formulas not answered yet
  std::vector<bool> odd(formulas.size(), false);
  std::vector<Formula> simple(formulas.size());
  std::vector<const Formula*> bare(formulas.size());
  std::vector<std::size_t> changed(formulas.size(), 0);  // subformulas the simplification replaced
  // with reductions, each formula simplified first, under a quarter of the time
  std::optional<Simplifier> simplifier;
  if (limits.reduction) simplifier.emplace(net, tryLimits(base, base.max_states, 0.25).deadline);
  for (std::size_t i = 0; i < formulas.size(); ++i) {
    bool o = false;
    bare[i] = &unnegated(formulas[i], o);
    odd[i] = o;
    // (EF p and AG p ask the state equation themselves, and say so)
    if (simplifier && bare[i]->kind != FormulaKind::Bound && !reachability(*bare[i])) {
      simple[i] = simplifier->simplified(*bare[i], changed[i]);
      bare[i] = &unnegated(simple[i], o);
      odd[i] = odd[i] != o;
    }
    if (isStateFormula(*bare[i])) {
      out[i] = atInitialMarking(net, *bare[i]);
    } else {
      open.push_back(i);
    }
  }
  // 1. with stubborn sets, each formula on the fly under a share of the limits: most are
  // decided long before the whole graph is made. Without them (--no-reduction), the graph
  // first, as before.
  bool whole_hopeless = false;  // a try ran out of memory or time: the whole graph will too
  auto tryEach = [&](std::uint64_t states, bool last) {
    std::vector<std::size_t> still;
    for (std::size_t k = 0; k < open.size(); ++k) {
      const std::size_t i = open[k];
      const double share = last ? 1.0 / static_cast<double>(open.size() - k) : 0.5 / static_cast<double>(open.size() - k);
      QueryAnswer a = withoutGraph(net, *bare[i], tryLimits(base, states, share));
      if (!decided(a)) {
        whole_hopeless = whole_hopeless || a.stop == ExploreStop::MaxMemory || a.stop == ExploreStop::TimeLimit;
        still.push_back(i);
        if (!last && a.unsupported.empty()) continue;  // the next pass says why
      }
      out[i] = std::move(a);
    }
    open = std::move(still);
  };
  if (limits.reduction) tryEach(1u << 20, false);
  // 2. the whole graph once for those left, every answer read from it
  if (!open.empty() && !whole_hopeless) {
    const StateGraph graph = buildGraph(net, base);
    std::vector<std::size_t> still;
    for (std::size_t i : open) {
      if (graph.stop == ExploreStop::Done) {
        out[i] = answerOnGraph(net, graph, *bare[i], base);
      } else {
        still.push_back(i);
      }
    }
    whole_hopeless = graph.stop != ExploreStop::Done;
    open = std::move(still);
  }
  // 3. on the fly again with what is left of the limits, shared out
  // (a formula that ends before its share leaves the rest to those after it; those cut short
  // by their share get what is left over, again, while a second or more remains)
  for (int round = 0; round < 4 && !open.empty(); ++round) {
    if (round > 0) {
      const bool cut =
          std::any_of(open.begin(), open.end(), [&](std::size_t i) { return out[i].stop == ExploreStop::TimeLimit; });
      const bool time = limits.deadline && *limits.deadline - std::chrono::steady_clock::now() > std::chrono::seconds(1);
      if (!cut || !time) break;
    }
    tryEach(limits.max_states, true);
  }
  for (std::size_t i = 0; i < formulas.size(); ++i) {
    // a negation turns the answer over; the marking that shows it shows this one too
    QueryAnswer& a = out[i];
    if (changed[i] != 0 && decided(a)) a.technique = "QUERY_SIMPLIFICATION STATE_EQUATION " + a.technique;
    if (odd[i] && (a.verdict == Verdict::True || a.verdict == Verdict::False)) {
      a.verdict = a.verdict == Verdict::True ? Verdict::False : Verdict::True;
    }
    // a lasso shows the formula as simplified, and so the one asked where that is a path
    // formula over state formulas (the two agree on every path through reachable markings);
    // where the one asked nests quantifiers, a path shows nothing of it
    bool o = false;
    const Formula& asked = unnegated(formulas[i], o);
    if (a.lasso && !(asked.operands.size() == 1 && quantifierFree(asked.operands[0]))) {
      a.lasso = a.has_marking = false;
      a.path.clear();
      a.cycle.clear();
      a.marking.clear();
    }
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
