// LTL on the stored reachability graph: the formula's negation (for A) or the formula (for E)
// in negation normal form, a generalized Büchi automaton from it by the tableau of Gerth,
// Peled, Vardi and Wolper, and its product with the graph searched for a reachable cycle that
// meets every acceptance set (strongly connected components, Tarjan's algorithm without
// recursion). A dead marking repeats itself forever: its paths stutter there.

#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <utility>

#include "detail/lazy_graph.h"
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
      case FormulaKind::All:
      case FormulaKind::Bound:
      case FormulaKind::Compare:
      case FormulaKind::Deadlock:
      case FormulaKind::Exists:
      case FormulaKind::False:
      case FormulaKind::Fireable:
      case FormulaKind::True: return add({Node::False});  // atoms are above; a quantifier inside: not LTL, never asked
    }
    return add({Node::False});  // no value of the enum
  }

 private:
  // interns `n`, rewritten first by identities of LTL on infinite paths that keep the
  // automaton small: X moved outward (F X p = X F p, X p and X q = X (p and q)), F F p = F p,
  // G G p = G p, and G F p, F G p the same at every position (so X, F, G over them vanish)
  std::uint32_t add(Node n) {
    const auto is = [&](std::uint32_t x, Node::Kind k) { return nodes[x].kind == k; };
    const auto future = [&](std::uint32_t x) { return is(x, Node::Until) && is(nodes[x].a, Node::True); };
    const auto globally = [&](std::uint32_t x) { return is(x, Node::Release) && is(nodes[x].a, Node::False); };
    const auto recurrent = [&](std::uint32_t x) {
      return (globally(x) && future(nodes[x].b)) || (future(x) && globally(nodes[x].b));
    };
    switch (n.kind) {
      case Node::Next:
        if (recurrent(n.a) || is(n.a, Node::True) || is(n.a, Node::False)) return n.a;
        break;
      case Node::And:
      case Node::Or: {
        const Node::Kind unit = n.kind == Node::And ? Node::True : Node::False;
        if (n.a == n.b || is(n.b, unit)) return n.a;
        if (is(n.a, unit)) return n.b;
        if (is(n.a, Node::True) || is(n.a, Node::False)) return n.a;  // the other constant absorbs
        if (is(n.b, Node::True) || is(n.b, Node::False)) return n.b;
        if (is(n.a, Node::Next) && is(n.b, Node::Next)) {
          const Node x{n.kind, nodes[n.a].a, nodes[n.b].a};
          return add({Node::Next, add(x), 0});
        }
        break;
      }
      case Node::Until:
      case Node::Release: {
        if (is(n.b, Node::True) || is(n.b, Node::False)) return n.b;  // p U true, p R false, ...
        if (is(n.a, Node::Next) && is(n.b, Node::Next)) {
          const Node x{n.kind, nodes[n.a].a, nodes[n.b].a};
          return add({Node::Next, add(x), 0});
        }
        const bool f = n.kind == Node::Until && is(n.a, Node::True);
        const bool g = n.kind == Node::Release && is(n.a, Node::False);
        if (!f && !g) break;
        if (recurrent(n.b) || (f && future(n.b)) || (g && globally(n.b))) return n.b;
        if (is(n.b, Node::Next)) {
          const Node x{n.kind, n.a, nodes[n.b].a};
          return add({Node::Next, add(x), 0});
        }
        break;
      }
      case Node::Atom:
      case Node::False:
      case Node::NotAtom:
      case Node::True: break;
    }
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
Automaton merged(Automaton a);

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
  return merged(std::move(a));
}

/// `a` with states that read the same, accept the same and lead to the same states merged,
/// until none are left to merge.
Automaton merged(Automaton a) {
  while (true) {
    std::map<std::tuple<std::vector<std::uint32_t>, std::vector<std::uint32_t>, std::uint64_t, std::vector<std::uint32_t>>,
             std::uint32_t>
        classes;
    std::vector<std::uint32_t> to(a.states.size());
    for (std::uint32_t i = 0; i < a.states.size(); ++i) {
      auto& st = a.states[i];
      std::sort(st.next.begin(), st.next.end());
      st.next.erase(std::unique(st.next.begin(), st.next.end()), st.next.end());
      to[i] = classes.emplace(std::make_tuple(st.atoms, st.not_atoms, st.accepting, st.next), i).first->second;
    }
    if (classes.size() == a.states.size()) break;
    for (auto& st : a.states) {
      for (auto& n : st.next) n = to[n];
    }
    for (auto& i : a.initial) i = to[i];
    // renumbered: the representatives only
    std::vector<std::uint32_t> number(a.states.size(), 0xffffffffu);
    Automaton b;
    b.sets = a.sets;
    for (std::uint32_t i = 0; i < a.states.size(); ++i) {
      if (to[i] != i) continue;
      number[i] = static_cast<std::uint32_t>(b.states.size());
      b.states.push_back(std::move(a.states[i]));
    }
    for (auto& st : b.states) {
      for (auto& n : st.next) n = number[n];
    }
    for (std::uint32_t i : a.initial) b.initial.push_back(number[i]);
    std::sort(b.initial.begin(), b.initial.end());
    b.initial.erase(std::unique(b.initial.begin(), b.initial.end()), b.initial.end());
    a = std::move(b);
  }
  return a;
}

/// Product states' keys (marking id times automaton size plus automaton state) to their
/// depth-first numbers: open addressing, 12 bytes a slot, at most half full.
class KeyIndex {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  KeyIndex() { grow(1u << 12); }
  /// The number stored for `key`, or kNone.
  std::uint32_t find(std::uint64_t key) const {
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (values_[i] == kNone) return kNone;
      if (keys_[i] == key) return values_[i];
    }
  }
  /// Stores `value` for `key` (not stored yet).
  void insert(std::uint64_t key, std::uint32_t value) {
    if (2 * (size_ + 1) > keys_.size()) grow(keys_.size() * 2);
    place(key, value);
    ++size_;
  }
  std::uint64_t bytes() const { return keys_.size() * 12; }

 private:
  std::size_t slot(std::uint64_t key) const {
    key ^= key >> 31;
    key *= 0x9e3779b97f4a7c15ull;
    return (key >> 20) & mask_;
  }
  void place(std::uint64_t key, std::uint32_t value) {
    std::size_t i = slot(key);
    while (values_[i] != kNone) i = (i + 1) & mask_;
    keys_[i] = key;
    values_[i] = value;
  }
  void grow(std::size_t n) {
    std::vector<std::uint64_t> keys(n);
    std::vector<std::uint32_t> values(n, kNone);
    keys.swap(keys_);
    values.swap(values_);
    mask_ = n - 1;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (values[i] != kNone) place(keys[i], values[i]);
    }
  }
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> values_;
  std::size_t mask_ = 0, size_ = 0;
};

/// The product of the graph and the automaton, searched depth first for a reachable cycle
/// that meets every acceptance set, by Couvreur's algorithm (1999): components are merged as
/// back edges close them, so an accepting cycle is seen as soon as its last edge is, not when
/// its whole component is done. Then the lasso: the depth-first path to the component's root
/// and a cycle from the root through every acceptance set back to it.
template <class Graph>
class Product {
 public:
  /// Whether a lasso was found, none exists, or a limit stopped the search.
  enum class Search : std::uint8_t { Found, None, Stopped };
  static constexpr std::uint32_t kNone = KeyIndex::kNone;

  Product(Graph& g, const Automaton& a, const ExploreOptions& limits)
      : g_(g), a_(a), limits_(limits), q_(a.states.size()),
        all_(a.sets >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << a.sets) - 1) {}

  Search search(ExploreStop& stop) {
    for (std::uint32_t init : a_.initial) {
      if (!reads(0, init) || index_.find(keyOf(0, init)) != KeyIndex::kNone) continue;
      starts_.push_back(static_cast<std::uint32_t>(key_of_.size()));
      visit(keyOf(0, init));
      while (!frames_.empty()) {
        if (stop_ != ExploreStop::Done) {
          stop = stop_;
          return Search::Stopped;
        }
        Frame& f = frames_.back();
        const StateId s = markingOf(f.v);
        const std::uint64_t end = f.end;
        if (f.edge < end) {
          const auto& nexts = a_.states[stateOf(f.v)].next;
          if (f.next >= nexts.size()) {
            ++f.edge;
            f.next = 0;
            continue;
          }
          const std::uint32_t to = nexts[f.next++];
          const StateId w = target(s, f.edge);
          if (!reads(w, to)) continue;
          const std::uint64_t key = keyOf(w, to);
          const std::uint32_t at = index_.find(key);
          if (at == KeyIndex::kNone) {
            visit(key);  // the frame keeps its edge while the new state is searched: the lasso's prefix
            continue;
          }
          if (dead_[at]) continue;
          // a cycle: every component on the stack above the one holding `at` joins it
          std::uint64_t marks = 0;
          while (roots_.back().v > at) {
            marks |= roots_.back().marks;
            roots_.pop_back();
          }
          roots_.back().marks |= marks;
          if ((roots_.back().marks & all_) == all_) return Search::Found;
          continue;
        }
        const std::uint32_t v = f.v;
        frames_.pop_back();
        on_stack_[v] = false;
        if (roots_.back().v != v) continue;
        roots_.pop_back();  // v's component is done: no accepting cycle in it
        while (true) {
          const std::uint32_t x = live_.back();
          live_.pop_back();
          dead_[x] = true;
          if (x == v) break;
        }
      }
    }
    return Search::None;
  }

  /// After Found: a shortest firing sequence from the initial marking into the accepting
  /// component, then a cycle inside it through every acceptance set back to where it entered
  /// (empty where that is a dead marking repeating itself), and the marking the cycle starts
  /// from.
  void lasso(std::vector<TransitionId>& prefix, std::vector<TransitionId>& cycle, StateId& at) {
    const std::uint32_t root = roots_.back().v;
    auto inside = [&](std::uint32_t x) { return x >= root && !dead_[x]; };
    std::uint32_t entry = kNone;
    for (std::uint32_t v : starts_) {
      if (inside(v)) entry = v;
    }
    if (entry == kNone) entry = walk(starts_, [](std::uint32_t) { return true; }, inside, prefix);
    at = markingOf(entry);
    // greedily to the nearest state meeting a set not met yet, then home
    std::uint64_t need = all_ & ~a_.states[stateOf(entry)].accepting;
    std::uint32_t from = entry;
    while (need != 0) {
      from = walk({from}, inside, [&](std::uint32_t x) { return (a_.states[stateOf(x)].accepting & need) != 0; }, cycle);
      need &= ~a_.states[stateOf(from)].accepting;
    }
    walk({from}, inside, [&](std::uint32_t x) { return x == entry; }, cycle);
  }

 private:
  struct Frame {
    std::uint32_t v;       // the product state's depth-first number
    std::uint64_t edge;    // the graph edge tried now (a dead marking: its one stutter step)
    std::uint64_t end;     // one past its last (a marking expanded fully later keeps the list it had)
    std::uint32_t next;    // the automaton successor tried next for it
  };
  struct Root {
    std::uint32_t v;       // the depth-first number of a component's first state
    std::uint64_t marks;   // the acceptance sets its states meet
  };

  std::uint64_t keyOf(StateId s, std::uint32_t state) const { return std::uint64_t{s} * q_ + state; }
  StateId markingOf(std::uint32_t v) const { return static_cast<StateId>(key_of_[v] / q_); }
  std::uint32_t stateOf(std::uint32_t v) const { return static_cast<std::uint32_t>(key_of_[v] % q_); }
  // a dead marking has one step, to itself (s expanded)
  std::uint64_t endOf(StateId s) const { return g_.degree(s) == 0 ? g_.end(s) + 1 : g_.end(s); }
  StateId target(StateId s, std::uint64_t edge) const { return g_.degree(s) == 0 ? s : g_.succ(edge); }

  bool reads(StateId s, std::uint32_t state) const {
    const auto& st = a_.states[state];
    return std::all_of(st.atoms.begin(), st.atoms.end(), [&](std::uint32_t x) { return g_.atom(x, s); }) &&
           std::none_of(st.not_atoms.begin(), st.not_atoms.end(), [&](std::uint32_t x) { return g_.atom(x, s); });
  }

  void visit(std::uint64_t key) {
    const auto v = static_cast<std::uint32_t>(key_of_.size());
    if ((v & 0xfff) == 0) {
      const std::uint64_t bytes = g_.bytes() + index_.bytes() + key_of_.capacity() * 9 +
                                  (live_.capacity() + frames_.capacity() * 4) * 4;
      stop_ = v >= limits_.max_states ? ExploreStop::MaxStates : passedLimit(limits_, bytes);
    }
    index_.insert(key, v);
    key_of_.push_back(key);
    dead_.push_back(false);
    live_.push_back(v);
    on_stack_.push_back(true);
    roots_.push_back({v, a_.states[key % q_].accepting});
    const auto s = static_cast<StateId>(key / q_);
    std::uint64_t first = g_.first(s);
    if (g_.reduced(s) && closesCycle(s, stateOf(v), key)) {
      // the cycle proviso: an ample set that closes a cycle on the stack gives way to all
      // enabled transitions, so that no transition is put off for ever around a cycle
      g_.expandFully(s);
      first = g_.first(s);
    }
    frames_.push_back({v, first, endOf(s), 0});
  }

  /// Whether an edge of marking `s` (automaton state `q`, product key `key`) leads to a
  /// product state on the depth-first stack (or to itself).
  bool closesCycle(StateId s, std::uint32_t q, std::uint64_t key) const {
    for (std::uint64_t e = g_.first(s); e < g_.end(s); ++e) {
      const StateId w = g_.succ(e);
      for (std::uint32_t to : a_.states[q].next) {
        if (!reads(w, to)) continue;
        const std::uint64_t k = keyOf(w, to);
        if (k == key) return true;
        const std::uint32_t at = index_.find(k);
        if (at != KeyIndex::kNone && on_stack_[at]) return true;
      }
    }
    return false;
  }

  /// Breadth first from `sources` (at least one step) through states where `allowed` holds to
  /// the nearest one where `goal` holds; appends the transitions on the way and returns it.
  template <class Allowed, class Goal>
  std::uint32_t walk(const std::vector<std::uint32_t>& sources, Allowed allowed, Goal goal,
                     std::vector<TransitionId>& out) {
    std::vector<std::uint32_t> parent(key_of_.size(), kNone);
    std::vector<std::uint32_t> queue = sources;
    auto step = [&](std::uint32_t x, auto visit) {
      const StateId s = markingOf(x);
      for (std::uint64_t e = g_.first(s); e < endOf(s); ++e) {
        for (std::uint32_t to : a_.states[stateOf(x)].next) {
          const StateId w = target(s, e);
          if (!reads(w, to)) continue;
          const std::uint32_t y = index_.find(keyOf(w, to));
          if (y != KeyIndex::kNone && !visit(y, e)) return;
        }
      }
    };
    std::uint32_t reached = kNone;
    for (std::size_t i = 0; i < queue.size() && reached == kNone; ++i) {
      step(queue[i], [&](std::uint32_t y, std::uint64_t) {
        if (parent[y] != kNone || !allowed(y)) return true;
        parent[y] = queue[i];
        if (goal(y)) {
          reached = y;
          return false;
        }
        queue.push_back(y);
        return true;
      });
    }
    if (reached == kNone) return sources.front();  // cannot happen: the component is strongly connected
    // back from where it arrived, each step's transition found again among its parent's edges
    std::vector<TransitionId> way;
    for (std::uint32_t z = reached;;) {
      const std::uint32_t before = parent[z];
      step(before, [&](std::uint32_t y, std::uint64_t e) {
        if (y != z) return true;
        if (g_.degree(markingOf(before)) != 0) way.push_back(g_.via(e));
        return false;
      });
      z = before;
      if (std::find(sources.begin(), sources.end(), z) != sources.end()) break;
    }
    out.insert(out.end(), way.rbegin(), way.rend());
    return reached;
  }

  Graph& g_;
  const Automaton& a_;
  const ExploreOptions& limits_;
  const std::size_t q_;
  const std::uint64_t all_;
  ExploreStop stop_ = ExploreStop::Done;
  KeyIndex index_;
  std::vector<std::uint64_t> key_of_;  // by depth-first number
  std::vector<bool> dead_;             // its component is done
  std::vector<bool> on_stack_;         // on the depth-first stack
  std::vector<std::uint32_t> live_;    // states of components not done, in visiting order
  std::vector<Root> roots_;
  std::vector<Frame> frames_;
  std::vector<std::uint32_t> starts_;  // the initial product states
};


/// The whole graph seen as a Product searches it, the atoms worked out for every marking.
class WholeView {
 public:
  WholeView(const Net& net, const StateGraph& g, const std::vector<const Formula*>& atoms)
      : g_(g), atoms_(atoms.size()) {
    StateCheck check(net, g.store->layout());
    atom_.resize(g.size() * atoms_);
    std::vector<std::uint64_t> m;
    for (StateId s = 0; s < g.size(); ++s) {
      const std::uint64_t* x = g.store->load(s, m);
      for (std::size_t k = 0; k < atoms_; ++k) atom_[s * atoms_ + k] = check.holds(*atoms[k], x) ? 1 : 0;
    }
  }
  std::uint64_t first(StateId s) const { return g_.first[s]; }
  std::uint64_t end(StateId s) const { return g_.first[s + 1]; }
  std::uint32_t degree(StateId s) const { return static_cast<std::uint32_t>(g_.outDegree(s)); }
  StateId succ(std::uint64_t e) const { return g_.succ[e]; }
  TransitionId via(std::uint64_t e) const { return g_.via[e]; }
  bool atom(std::size_t k, StateId s) const { return atom_[s * atoms_ + k] != 0; }
  std::uint64_t bytes() const { return 0; }  // held before the product, not by it
  bool reduced(StateId) const { return false; }  // every edge is there
  void expandFully(StateId) {}

 private:
  const StateGraph& g_;
  std::size_t atoms_;
  std::vector<std::uint8_t> atom_;
};

/// Whether X stands anywhere in `f`.
bool hasNext(const Formula& f) {
  return f.kind == FormulaKind::Next ||
         std::any_of(f.operands.begin(), f.operands.end(), [](const Formula& o) { return hasNext(o); });
}

/// The automaton of an LTL formula (A or E over a path formula): of the path formula, negated
/// for A. Nullopt, with `out.unsupported` said, for a formula it cannot make.
std::optional<Automaton> automatonOf(const Formula& f, Nnf& nnf, QueryAnswer& out) {
  if ((f.kind != FormulaKind::All && f.kind != FormulaKind::Exists) || f.operands.size() != 1) {
    out.unsupported = "an LTL formula starts with A or E";
    return std::nullopt;
  }
  // A p holds when no path satisfies not p; E p when some path satisfies p
  const std::uint32_t root = nnf.of(f.operands[0], f.kind == FormulaKind::All);
  if (nnf.nodes.size() > 60) {
    out.unsupported = "LTL formulas of more than 60 subformulas are not answered yet";
    return std::nullopt;
  }
  Automaton a = tableau(nnf, root);
  if (a.sets > 64) {
    out.unsupported = "LTL formulas of more than 64 until operators are not answered yet";
    return std::nullopt;
  }
  return a;
}

/// Searches the product of `g` and `a` for `f` (A or E) and fills in `out`: the verdict and,
/// where a lasso shows it, the lasso.
template <class Graph>
void searchProduct(Graph& g, const Store& store, const Automaton& a, const Formula& f, const ExploreOptions& limits,
                   QueryAnswer& out) {
  const bool all = f.kind == FormulaKind::All;
  Product<Graph> product(g, a, limits);
  typename Product<Graph>::Search found = Product<Graph>::Search::Stopped;
  try {
    found = product.search(out.stop);
  } catch (const Stopped&) {
    return;  // the caller says why
  }
  if (found == Product<Graph>::Search::Stopped) return;
  out.verdict = (found == Product<Graph>::Search::Found) == all ? Verdict::False : Verdict::True;
  if (found == Product<Graph>::Search::Found) {
    // the path that shows it: for A, one that breaks the formula; for E, one that keeps it
    StateId at = 0;
    product.lasso(out.path, out.cycle, at);
    out.lasso = true;
    std::vector<std::uint64_t> m;
    out.marking.resize(store.layout().width());
    store.layout().unpack(store.load(at, m), out.marking.data());
    out.has_marking = true;
  }
}

}  // namespace

QueryAnswer answerLtl(const Net& net, const StateGraph& g, const Formula& f, const ExploreOptions& limits) {
  QueryAnswer out;
  out.states = g.size();
  Nnf nnf;
  const auto a = automatonOf(f, nnf, out);
  if (!a) return out;
  out.technique = "EXPLICIT LTL_TABLEAU";
  WholeView view(net, g, nnf.atoms);
  searchProduct(view, *g.store, *a, f, limits, out);
  return out;
}

QueryAnswer answerLtlOnTheFly(const Net& net, const Formula& f, const ExploreOptions& limits) {
  QueryAnswer out;
  Nnf nnf;
  const auto a = automatonOf(f, nnf, out);
  if (!a) return out;
  out.technique = "EXPLICIT LTL_TABLEAU ON_THE_FLY";
  LazyGraph g(net, limits, nnf.atoms);
  if (!g.ok()) {
    out.stop = ExploreStop::Overflow;
    return out;
  }
  // without next, the formula cannot tell stuttering apart: ample sets serve
  if (limits.reduction && !hasNext(f)) {
    g.reduceFor(net);
    out.technique += " STUBBORN_SETS";
  }
  searchProduct(g, g.store(), *a, f, limits, out);
  if (out.verdict == Verdict::Unknown && out.stop == ExploreStop::Done) out.stop = g.stop();
  out.states = g.size();
  return out;
}

}  // namespace gdpn::net::detail
