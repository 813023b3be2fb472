// CTL on the fly: a formula's value at the initial marking worked out by searches that make
// only the markings they need (LazyGraph), each temporal subformula by a depth-first search
// that stops as soon as it is decided, its subformulas asked marking by marking as the search
// meets them; every value a search settles is kept (per subformula, per marking).

#include <algorithm>
#include <deque>
#include <memory>

#include "detail/lazy_graph.h"
#include "detail/query_graph.h"
#include "detail/stubborn.h"

namespace gdpn::net::detail {
namespace {

/// A CTL formula rewritten over the operators the searches work out: EF p = E[true U p], AF p =
/// A[true U p], AG p = not E[true U not p].
struct CtlNode {
  enum Kind : std::uint8_t { Atom, Not, And, Or, EX, AX, EU, AU, EG } kind = Atom;
  const Formula* atom = nullptr;        // Atom: a state formula; EU of true: the state formula sought
  std::vector<std::uint32_t> operands;  // EU, AU: what holds until, then what holds
};

class Local {
 public:
  Local(const Net& net, const ExploreOptions& limits) : net_(net), g_(net, limits), reduce_(limits.reduction) {}
  /// Counts the memory the searches keep per marking (a byte per node, four per temporal one).
  void account() { g_.alsoPerMarking(nodes_.size() * 5); }
  LazyGraph& graph() { return g_; }

  /// The node of `f` (CTL).
  std::uint32_t add(const Formula& f) {
    if (isStateFormula(f)) return push({CtlNode::Atom, &f, {}});
    switch (f.kind) {
      case FormulaKind::Not: return push({CtlNode::Not, nullptr, {add(f.operands[0])}});
      case FormulaKind::And:
      case FormulaKind::Or: {
        CtlNode n{f.kind == FormulaKind::And ? CtlNode::And : CtlNode::Or, nullptr, {}};
        // the state formulas first: they are cheap and may decide it
        for (int pass = 0; pass < 2; ++pass) {
          for (const Formula& o : f.operands) {
            if (isStateFormula(o) == (pass == 0)) n.operands.push_back(add(o));
          }
        }
        return push(std::move(n));
      }
      case FormulaKind::Exists:
      case FormulaKind::All: {
        const bool all = f.kind == FormulaKind::All;
        const Formula& path = f.operands[0];
        switch (path.kind) {
          case FormulaKind::Next: return push({all ? CtlNode::AX : CtlNode::EX, nullptr, {add(path.operands[0])}});
          case FormulaKind::Until:
            return push({all ? CtlNode::AU : CtlNode::EU, nullptr, {add(path.operands[0]), add(path.operands[1])}});
          case FormulaKind::Future: {
            // EF of a state formula: searched over stubborn sets
            const Formula* sought = !all && isStateFormula(path.operands[0]) ? &path.operands[0] : nullptr;
            return push({all ? CtlNode::AU : CtlNode::EU, sought, {truth(), add(path.operands[0])}});
          }
          case FormulaKind::Globally: {
            const std::uint32_t p = add(path.operands[0]);
            if (!all) return push({CtlNode::EG, nullptr, {p}});
            const std::uint32_t notp = push({CtlNode::Not, nullptr, {p}});
            // AG of a state formula: EF of its negation, searched over stubborn sets
            const Formula* sought = nullptr;
            if (isStateFormula(path.operands[0])) {
              Formula& n = owned_.emplace_back();
              n.kind = FormulaKind::Not;
              n.operands.push_back(path.operands[0]);
              sought = &n;
            }
            const std::uint32_t ef = push({CtlNode::EU, sought, {truth(), notp}});
            return push({CtlNode::Not, nullptr, {ef}});
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
          case FormulaKind::True: break;  // not CTL: never asked (isCtl)
        }
        return truth();
      }
      case FormulaKind::Bound:
      case FormulaKind::Compare:
      case FormulaKind::Deadlock:
      case FormulaKind::False:
      case FormulaKind::Fireable:
      case FormulaKind::Future:
      case FormulaKind::Globally:
      case FormulaKind::Next:
      case FormulaKind::True:
      case FormulaKind::Until: break;  // state formulas above; path operators only under a quantifier
    }
    return truth();
  }

  /// Whether node `n` holds in marking `s`; throws Stopped past a limit.
  bool holds(std::uint32_t n, StateId s) {
    std::uint8_t& known = memo(n, s);
    if (known != 0) return known == 1;
    const CtlNode& x = nodes_[n];
    bool v = false;
    switch (x.kind) {
      case CtlNode::Atom: {
        v = g_.check().holds(*x.atom, g_.store().load(s, m_));
        break;
      }
      case CtlNode::Not: v = !holds(x.operands[0], s); break;
      case CtlNode::And:
        v = std::all_of(x.operands.begin(), x.operands.end(), [&](std::uint32_t o) { return holds(o, s); });
        break;
      case CtlNode::Or:
        v = std::any_of(x.operands.begin(), x.operands.end(), [&](std::uint32_t o) { return holds(o, s); });
        break;
      case CtlNode::EX:
      case CtlNode::AX: {
        // paths end at a dead marking: EX fails there, AX holds
        const bool all = x.kind == CtlNode::AX;
        v = all;
        for (std::uint64_t e = g_.first(s); e < g_.end(s); ++e) {
          if (holds(x.operands[0], g_.succ(e)) != all) {
            v = !all;
            break;
          }
        }
        break;
      }
      case CtlNode::EU: v = search(n, s, CtlNode::EU); break;
      case CtlNode::AU: v = search(n, s, CtlNode::AU); break;
      case CtlNode::EG: v = search(n, s, CtlNode::EG); break;
    }
    memo(n, s) = v ? 1 : 2;  // the reference may have moved: the searches grow the tables
    return v;
  }

 private:
  std::uint32_t push(CtlNode n) {
    nodes_.push_back(std::move(n));
    memo_.emplace_back();
    stamp_.emplace_back();
    epoch_.push_back(0);
    return static_cast<std::uint32_t>(nodes_.size() - 1);
  }
  std::uint32_t truth() {
    static const Formula yes{};  // kind True
    return push({CtlNode::Atom, &yes, {}});
  }
  std::uint8_t& memo(std::uint32_t n, StateId s) {
    auto& m = memo_[n];
    if (m.size() <= s) m.resize(std::max<std::size_t>(g_.size(), s + 1), 0);
    return m[s];
  }
  std::uint32_t& stamp(std::uint32_t n, StateId s) {
    auto& m = stamp_[n];
    if (m.size() <= s) m.resize(std::max<std::size_t>(g_.size(), s + 1), 0);
    return m[s];
  }

  /// E[p U q], A[p U q] or EG p at `s0`, depth first from it: through markings where
  /// the search must go on (EU: p and not q; AU: p and not q; EG: p) until the answer shows
  /// (EU: a q marking; AU: a path that breaks it, by a marking where neither holds, a dead
  /// marking or a cycle; EG: a cycle or a dead marking). Every marking on the depth-first
  /// path then has the value shown; when the search ends without it, every marking it met has
  /// the other.
  bool search(std::uint32_t n, StateId s0, CtlNode::Kind kind) {
    // the value `shown` is EU: true, AU: false, EG: true
    const bool shown = kind != CtlNode::AU;
    const std::uint32_t p = nodes_[n].operands[0];
    const std::uint32_t q = kind == CtlNode::EG ? p : nodes_[n].operands[1];
    const std::uint32_t on = 2 * ++epoch_[n], done = on + 1;  // stamps: on the path, finished
    struct Frame {
      StateId s;
      std::uint64_t edge, end;  // into the graph's edges, or (reduced) into `succs`
    };
    std::vector<Frame> frames;
    // EF of a state formula: each marking's successors by the enabled members of a stubborn
    // set for it (those that keep every marking where it holds reachable), kept in `succs`
    const Formula* sought = kind == CtlNode::EU && reduce_ ? nodes_[n].atom : nullptr;
    if (sought && !stubborn_) stubborn_ = std::make_unique<Stubborn>(net_, g_.store().layout());
    std::vector<StateId> succs;
    std::vector<TransitionId> chosen;
    std::vector<StateId> met;
    // whether marking v shows the answer; where the search goes on through it, it is pushed
    auto meet = [&](StateId v) {
      const std::uint8_t known = memo(n, v);
      if (known != 0) return (known == 1) == shown;
      if (kind != CtlNode::EG && holds(q, v)) {
        memo(n, v) = 1;
        return shown;  // EU: reached; AU: this path is fine
      }
      if (!holds(p, v)) {
        memo(n, v) = 2;
        return kind == CtlNode::AU;  // AU: broken here; EU, EG: not through here
      }
      stamp(n, v) = on;
      met.push_back(v);
      if (sought) {
        stubborn_->select(*sought, g_.store().load(v, m_), g_.check(), chosen);
        const std::uint64_t from = succs.size();
        g_.fireOnly(v, chosen, succs);
        frames.push_back({v, from, succs.size()});
        return false;
      }
      const std::uint64_t first = g_.first(v);
      if (g_.degree(v) == 0 && kind != CtlNode::EU) {
        memo(n, v) = shown ? 1 : 2;  // AU: the path ends without q; EG: a maximal path of p
        met.pop_back();
        return true;
      }
      frames.push_back({v, first, g_.end(v)});
      return false;
    };
    bool found = meet(s0);
    while (!found && !frames.empty()) {
      Frame& f = frames.back();
      if (f.edge == f.end) {
        stamp(n, f.s) = done;
        frames.pop_back();
        continue;
      }
      const StateId w = sought ? succs[f.edge++] : g_.succ(f.edge++);
      const std::uint32_t st = stamp(n, w);
      if (st == on) {
        found = kind != CtlNode::EU;  // a cycle: AU broken, EG kept; EU: nothing new
      } else if (st != done) {
        found = meet(w);
      }
    }
    if (found) {
      for (const Frame& f : frames) memo(n, f.s) = shown ? 1 : 2;
      return shown;
    }
    for (StateId v : met) memo(n, v) = shown ? 2 : 1;
    return !shown;
  }

  const Net& net_;
  LazyGraph g_;
  bool reduce_;                        // EF of a state formula over stubborn sets
  std::unique_ptr<Stubborn> stubborn_;
  std::deque<Formula> owned_;          // the negations AG p searches for
  std::vector<CtlNode> nodes_;
  std::vector<std::vector<std::uint8_t>> memo_;   // per node, per marking: 0 unknown, 1 holds, 2 fails
  std::vector<std::vector<std::uint32_t>> stamp_;  // per node, per marking: its searches' marks
  std::vector<std::uint32_t> epoch_;               // per node: its searches so far
  std::vector<std::uint64_t> m_;
};

}  // namespace

QueryAnswer answerCtlLocally(const Net& net, const Formula& f, const ExploreOptions& limits) {
  QueryAnswer out;
  out.technique = "EXPLICIT CTL_LOCAL";
  Local local(net, limits);
  if (!local.graph().ok()) {
    out.stop = ExploreStop::Overflow;
    return out;
  }
  const std::uint32_t root = local.add(f);
  local.account();
  try {
    out.verdict = local.holds(root, 0) ? Verdict::True : Verdict::False;
  } catch (const Stopped&) {
    out.stop = local.graph().stop();
  }
  out.states = local.graph().size();
  return out;
}

}  // namespace gdpn::net::detail
