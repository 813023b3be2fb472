// LTL on the stored reachability graph: the formula's negation (for A) or the formula (for E)
// in negation normal form, a generalized Büchi automaton from it by the tableau of Gerth,
// Peled, Vardi and Wolper, and its product with the graph searched for a reachable cycle that
// meets every acceptance set (strongly connected components, Tarjan's algorithm without
// recursion). A dead marking repeats itself forever: its paths stutter there.

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

#include "detail/query_graph.h"
#include "detail/state_check.h"

namespace gdpn::net::detail {
namespace {

// a node of the formula in negation normal form, interned: equal formulas, equal indices
struct Node {
  enum Kind : std::uint8_t { True, False, Atom, NotAtom, And, Or, Next, Until, Release } kind;
  std::uint32_t a = 0, b = 0;  // operands (Atom, NotAtom: the atom's index)
  auto operator<=>(const Node&) const = default;
};

class Nnf {
 public:
  std::vector<Node> nodes;
  std::vector<const Formula*> atoms;  // the state formulas standing as atoms

  std::uint32_t of(const Formula& f, bool negated) {
    if (isStateFormula(f)) {
      const std::uint32_t atom = atomOf(f);
      return add({negated ? Node::NotAtom : Node::Atom, atom, 0});
    }
    switch (f.kind) {
      case FormulaKind::Not: return of(f.operands[0], !negated);
      case FormulaKind::And:
      case FormulaKind::Or: {
        const bool conj = (f.kind == FormulaKind::And) != negated;
        std::uint32_t x = of(f.operands[0], negated);
        for (std::size_t i = 1; i < f.operands.size(); ++i) x = add({conj ? Node::And : Node::Or, x, of(f.operands[i], negated)});
        return x;
      }
      case FormulaKind::Next: return add({Node::Next, of(f.operands[0], negated), 0});  // stuttering: X is self-dual
      case FormulaKind::Future: {
        const std::uint32_t p = of(f.operands[0], negated);
        // F p = true U p; not F p = false R not p
        return negated ? add({Node::Release, add({Node::False}), p}) : add({Node::Until, add({Node::True}), p});
      }
      case FormulaKind::Globally: {
        const std::uint32_t p = of(f.operands[0], negated);
        return negated ? add({Node::Until, add({Node::True}), p}) : add({Node::Release, add({Node::False}), p});
      }
      case FormulaKind::Until: {
        const std::uint32_t p = of(f.operands[0], negated), q = of(f.operands[1], negated);
        return add({negated ? Node::Release : Node::Until, p, q});  // not (p U q) = not p R not q
      }
      default: return add({Node::False});  // a quantifier inside: not LTL, never asked
    }
  }

 private:
  std::uint32_t add(Node n) {
    const auto [at, added] = index_.emplace(n, static_cast<std::uint32_t>(nodes.size()));
    if (added) nodes.push_back(n);
    return at->second;
  }
  std::uint32_t atomOf(const Formula& f) {
    atoms.push_back(&f);
    return static_cast<std::uint32_t>(atoms.size() - 1);
  }
  std::map<Node, std::uint32_t> index_;
};

/// A generalized Büchi automaton: each state requires some atoms to hold and others not to
/// hold in the marking it reads; acceptance sets by state.
struct Automaton {
  struct State {
    std::vector<std::uint32_t> atoms, not_atoms;  // must hold, must not hold
    std::vector<std::uint32_t> next;              // successors
    std::uint64_t accepting = 0;                  // bit i: in acceptance set i
  };
  std::vector<State> states;
  std::vector<std::uint32_t> initial;
  std::size_t sets = 0;
};

/// The tableau (Gerth, Peled, Vardi, Wolper 1995): nodes of (old, next) formula sets.
Automaton tableau(const Nnf& nnf, std::uint32_t root) {
  struct Tab {
    std::set<std::uint32_t> incoming;  // kInit for the initial
    std::vector<std::uint32_t> fresh;
    std::set<std::uint32_t> old, next;
  };
  constexpr std::uint32_t kInit = 0xffffffffu;
  std::vector<Tab> done;
  std::vector<Tab> todo{{{kInit}, {root}, {}, {}}};
  while (!todo.empty()) {
    Tab t = std::move(todo.back());
    todo.pop_back();
    if (t.fresh.empty()) {
      auto same = std::find_if(done.begin(), done.end(), [&](const Tab& d) { return d.old == t.old && d.next == t.next; });
      if (same != done.end()) {
        same->incoming.insert(t.incoming.begin(), t.incoming.end());
        continue;
      }
      done.push_back(t);
      todo.push_back({{static_cast<std::uint32_t>(done.size() - 1)}, {t.next.begin(), t.next.end()}, {}, {}});
      continue;
    }
    const std::uint32_t f = t.fresh.back();
    t.fresh.pop_back();
    if (t.old.contains(f)) {
      todo.push_back(std::move(t));
      continue;
    }
    const Node& n = nnf.nodes[f];
    switch (n.kind) {
      case Node::False: break;  // contradiction: dropped
      case Node::True: todo.push_back(std::move(t)); break;
      case Node::Atom:
      case Node::NotAtom: {
        const Node opposite{n.kind == Node::Atom ? Node::NotAtom : Node::Atom, n.a, 0};
        const bool clash = std::any_of(t.old.begin(), t.old.end(), [&](std::uint32_t o) { return nnf.nodes[o] == opposite; });
        if (clash) break;
        t.old.insert(f);
        todo.push_back(std::move(t));
        break;
      }
      case Node::And:
        t.old.insert(f);
        t.fresh.push_back(n.a);
        t.fresh.push_back(n.b);
        todo.push_back(std::move(t));
        break;
      case Node::Next:
        t.old.insert(f);
        t.next.insert(n.a);
        todo.push_back(std::move(t));
        break;
      case Node::Or:
      case Node::Until:
      case Node::Release: {
        // Or: a, or b. Until a U b: b, or a and X (a U b). Release a R b: a and b, or b and X (a R b)
        Tab left = t, right = std::move(t);
        left.old.insert(f);
        right.old.insert(f);
        if (n.kind == Node::Or) {
          left.fresh.push_back(n.a);
          right.fresh.push_back(n.b);
        } else if (n.kind == Node::Until) {
          left.fresh.push_back(n.b);
          right.fresh.push_back(n.a);
          right.next.insert(f);
        } else {
          left.fresh.push_back(n.a);
          left.fresh.push_back(n.b);
          right.fresh.push_back(n.b);
          right.next.insert(f);
        }
        todo.push_back(std::move(left));
        todo.push_back(std::move(right));
        break;
      }
    }
  }
  Automaton a;
  std::vector<std::uint32_t> untils;
  for (std::uint32_t i = 0; i < nnf.nodes.size(); ++i) {
    if (nnf.nodes[i].kind == Node::Until) untils.push_back(i);
  }
  a.sets = untils.size();
  a.states.resize(done.size());
  for (std::uint32_t i = 0; i < done.size(); ++i) {
    auto& s = a.states[i];
    for (std::uint32_t o : done[i].old) {
      if (nnf.nodes[o].kind == Node::Atom) s.atoms.push_back(nnf.nodes[o].a);
      if (nnf.nodes[o].kind == Node::NotAtom) s.not_atoms.push_back(nnf.nodes[o].a);
    }
    // the k-th until is met where it is not promised, or its right side holds
    for (std::size_t k = 0; k < untils.size(); ++k) {
      if (!done[i].old.contains(untils[k]) || done[i].old.contains(nnf.nodes[untils[k]].b)) s.accepting |= std::uint64_t{1} << k;
    }
    for (std::uint32_t from : done[i].incoming) {
      if (from == kInit) {
        a.initial.push_back(i);
      } else {
        a.states[from].next.push_back(i);
      }
    }
  }
  return a;
}

/// Whether some path of the product of `g` and `a` from the initial marking meets every
/// acceptance set infinitely often: Found, or None, or the limit that stopped the search.
enum class Search : std::uint8_t { Found, None, Stopped };
Search nonEmpty(const StateGraph& g, const Automaton& a, const std::vector<std::vector<std::uint8_t>>& atom,
                const ExploreOptions& limits, ExploreStop& stop) {
  const std::size_t q = a.states.size();
  auto reads = [&](StateId s, std::uint32_t state) {
    const auto& st = a.states[state];
    for (std::uint32_t x : st.atoms) {
      if (!atom[x][s]) return false;
    }
    for (std::uint32_t x : st.not_atoms) {
      if (atom[x][s]) return false;
    }
    return true;
  };
  const std::uint64_t all = a.sets >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << a.sets) - 1;
  // product states by (marking, automaton state); Tarjan's algorithm on explicit frames
  std::unordered_map<std::uint64_t, std::uint32_t> index;  // product key -> its DFS index
  std::vector<std::uint32_t> low;
  std::vector<std::uint64_t> key_of;
  std::vector<bool> on_stack;
  std::vector<std::uint32_t> stack;
  struct Frame {
    std::uint32_t v;
    std::uint64_t edge;   // next graph edge (or the stutter loop: first == last)
    std::uint32_t next;   // next automaton successor for that edge
  };
  std::vector<Frame> frames;
  auto keyOf = [&](StateId s, std::uint32_t state) { return std::uint64_t{s} * q + state; };
  auto visit = [&](std::uint64_t key) {
    const auto v = static_cast<std::uint32_t>(low.size());
    if ((v & 0xfff) == 0) {
      // about 80 bytes per product state: the map's entry, the index, the stacks
      stop = v > limits.max_states ? ExploreStop::MaxStates : passedLimit(limits, std::uint64_t{v} * 80);
    }
    index.emplace(key, v);
    low.push_back(v);
    key_of.push_back(key);
    on_stack.push_back(true);
    stack.push_back(v);
    frames.push_back({v, g.first[key / q], 0});
  };
  for (std::uint32_t init : a.initial) {
    if (!reads(0, init) || index.contains(keyOf(0, init))) continue;
    visit(keyOf(0, init));
    while (!frames.empty()) {
      if (stop != ExploreStop::Done) return Search::Stopped;
      Frame& f = frames.back();
      const auto s = static_cast<StateId>(key_of[f.v] / q);
      const auto state = static_cast<std::uint32_t>(key_of[f.v] % q);
      const bool dead = g.outDegree(s) == 0;
      const std::uint64_t end = dead ? g.first[s] + 1 : g.first[s + 1];  // a dead marking loops
      if (f.edge < end) {
        const StateId w = dead ? s : g.succ[f.edge];
        const auto& nexts = a.states[state].next;
        if (f.next >= nexts.size()) {
          ++f.edge;
          f.next = 0;
          continue;
        }
        const std::uint32_t to = nexts[f.next++];
        if (!reads(w, to)) continue;
        const std::uint64_t key = keyOf(w, to);
        const auto at = index.find(key);
        if (at == index.end()) {
          visit(key);
        } else if (on_stack[at->second]) {
          low[f.v] = std::min(low[f.v], at->second);
        }
        continue;
      }
      const std::uint32_t v = f.v;
      frames.pop_back();
      if (!frames.empty()) low[frames.back().v] = std::min(low[frames.back().v], low[v]);
      if (low[v] != v) continue;
      // a component: v and what lies above it on the stack
      std::uint64_t met = 0;
      std::size_t size = 0;
      for (std::size_t i = stack.size(); i-- > 0;) {
        met |= a.states[key_of[stack[i]] % q].accepting;
        ++size;
        if (stack[i] == v) break;
      }
      bool cycle = size > 1;
      if (!cycle) {
        // one product state: a cycle only through an edge to itself
        const auto s1 = static_cast<StateId>(key_of[v] / q);
        const auto st1 = static_cast<std::uint32_t>(key_of[v] % q);
        const auto& nexts = a.states[st1].next;
        const bool loops = std::find(nexts.begin(), nexts.end(), st1) != nexts.end();
        bool self = g.outDegree(s1) == 0;
        for (auto e = g.first[s1]; e < g.first[s1 + 1] && !self; ++e) self = g.succ[e] == s1;
        cycle = loops && self;
      }
      if (cycle && (met & all) == all) return Search::Found;
      while (true) {
        const std::uint32_t x = stack.back();
        stack.pop_back();
        on_stack[x] = false;
        if (x == v) break;
      }
    }
  }
  return Search::None;
}

}  // namespace

QueryAnswer answerLtl(const Net& net, const StateGraph& g, const Formula& f, const ExploreOptions& limits) {
  QueryAnswer out;
  out.states = g.size();
  if ((f.kind != FormulaKind::All && f.kind != FormulaKind::Exists) || f.operands.size() != 1) {
    out.unsupported = "an LTL formula starts with A or E";
    return out;
  }
  // A p holds when no path satisfies not p; E p when some path satisfies p
  const bool all = f.kind == FormulaKind::All;
  Nnf nnf;
  const std::uint32_t root = nnf.of(f.operands[0], all);
  if (nnf.nodes.size() > 60) {
    out.unsupported = "LTL formulas of more than 60 subformulas are not answered yet";
    return out;
  }
  const Automaton a = tableau(nnf, root);
  if (a.sets > 64) {
    out.unsupported = "LTL formulas of more than 64 until operators are not answered yet";
    return out;
  }
  StateCheck check(net, g.store->layout());
  std::vector<std::vector<std::uint8_t>> atom(nnf.atoms.size(), std::vector<std::uint8_t>(g.size()));
  for (std::size_t k = 0; k < nnf.atoms.size(); ++k) {
    for (StateId s = 0; s < g.size(); ++s) atom[k][s] = check.holds(*nnf.atoms[k], g.store->at(s));
  }
  out.technique = "EXPLICIT LTL_TABLEAU";
  const Search found = nonEmpty(g, a, atom, limits, out.stop);
  if (found == Search::Stopped) return out;
  out.verdict = (found == Search::Found) == all ? Verdict::False : Verdict::True;
  return out;
}

}  // namespace gdpn::net::detail
