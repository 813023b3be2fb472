// Answers to queries: a state formula at the initial marking, and reachability (EF, AG) by a
// breadth-first search over packed markings that stops at the first marking deciding it.

#include "gdpn/net/query.h"

#include <algorithm>

#include "detail/marking_store.h"

namespace gdpn::net {
namespace {

using namespace detail;

/// Evaluates state formulas on packed markings.
class StateCheck {
 public:
  StateCheck(const Net& net, const Layout& layout) : layout_(layout), candidates_(net), firing_(net) {
    candidates_.use(layout_);
    firing_.use(layout_);
  }
  const Firing& firing() const { return firing_; }
  const Candidates& candidates() const { return candidates_; }

  bool holds(const Formula& f, const std::uint64_t* m) {
    switch (f.kind) {
      case FormulaKind::True: return true;
      case FormulaKind::False: return false;
      case FormulaKind::Deadlock: {
        candidates_.find(m, scratch_);
        return std::none_of(scratch_.begin(), scratch_.end(), [&](TransitionId t) { return firing_.enabled(t, m); });
      }
      case FormulaKind::Fireable:
        return std::any_of(f.transitions.begin(), f.transitions.end(),
                           [&](TransitionId t) { return firing_.enabled(t, m); });
      case FormulaKind::Compare: {
        const std::int64_t a = sum(f.left, m), b = sum(f.right, m);
        switch (f.compare) {
          case Comparison::Less: return a < b;
          case Comparison::LessEqual: return a <= b;
          case Comparison::Equal: return a == b;
          case Comparison::NotEqual: return a != b;
          case Comparison::GreaterEqual: return a >= b;
          case Comparison::Greater: return a > b;
        }
        return false;
      }
      case FormulaKind::Not: return !holds(f.operands[0], m);
      case FormulaKind::And:
        return std::all_of(f.operands.begin(), f.operands.end(), [&](const Formula& o) { return holds(o, m); });
      case FormulaKind::Or:
        return std::any_of(f.operands.begin(), f.operands.end(), [&](const Formula& o) { return holds(o, m); });
      default: return false;  // not a state formula: never asked
    }
  }

 private:
  std::int64_t sum(const TokenSum& s, const std::uint64_t* m) const {
    std::int64_t total = s.constant;
    for (PlaceSlotId k : s.slots) total += layout_.value(m, k);
    return total;
  }
  const Layout& layout_;
  Candidates candidates_;
  Firing firing_;
  std::vector<TransitionId> scratch_;
};

/// Field sizes for concrete markings: the bounds the invariants and the state equation give,
/// and 32 bits where there is none (a count past that stops the search).
Layout concreteLayout(const Plan& p) {
  std::vector<std::uint32_t> bits = p.bits;
  for (std::size_t k = 0; k < bits.size(); ++k) {
    if (p.omega[k]) bits[k] = kMaxBits;
  }
  return Layout(bits, std::vector<bool>(bits.size(), false));
}

std::vector<std::int64_t> unpacked(const Layout& layout, const std::uint64_t* m) {
  std::vector<std::int64_t> out(layout.width());
  layout.unpack(m, out.data());
  return out;
}

/// Breadth first from the initial marking to the first marking where `target` holds: its
/// shortest path and the marking, or, when there is none, every reachable marking seen.
struct Reach {
  bool found = false;
  ExploreStop stop = ExploreStop::Done;
  std::vector<TransitionId> path;
  std::vector<std::int64_t> marking;
  std::uint64_t states = 0;
};

Reach reach(const Net& net, const Formula& target, const ExploreOptions& limits) {
  Reach out;
  const Plan p = plan(net, limits);
  if (p.overflow) {
    out.stop = ExploreStop::Overflow;
    return out;
  }
  Store store(concreteLayout(p));
  const Layout& L = store.layout();
  StateCheck check(net, L);
  std::vector<std::uint64_t> key(L.words()), next(L.words());
  std::size_t bad = 0;
  L.pack(p.m0.data(), key.data(), bad);
  bool added = false;
  store.insert(key.data(), store.hash(key.data()), added);
  std::vector<StateId> parent{0};
  std::vector<TransitionId> via{0};
  auto finish = [&](StateId s) {
    out.found = true;
    for (StateId x = s; x != 0; x = parent[x]) out.path.push_back(via[x]);
    std::reverse(out.path.begin(), out.path.end());
    out.marking = unpacked(L, store.at(s));
    out.states = store.size();
  };
  if (check.holds(target, store.at(0))) {
    finish(0);
    return out;
  }
  std::vector<TransitionId> candidates;
  for (StateId s = 0; s < store.size(); ++s) {
    if ((s & 0xfff) == 0) {
      if (limits.max_bytes != 0 && store.bytes() + parent.capacity() * 8 > limits.max_bytes) out.stop = ExploreStop::MaxMemory;
      if (limits.deadline && std::chrono::steady_clock::now() >= *limits.deadline) out.stop = ExploreStop::TimeLimit;
      if (out.stop != ExploreStop::Done) break;
    }
    check.candidates().find(store.at(s), candidates);
    for (TransitionId t : candidates) {
      std::size_t field = 0;
      const Fired f = check.firing().fire(t, store.at(s), next.data(), field);
      if (f == Fired::NotEnabled) continue;
      if (f == Fired::TooBig) {
        out.stop = ExploreStop::Overflow;
        break;
      }
      const StateId w = store.insert(next.data(), store.hash(next.data()), added);
      if (!added) continue;
      parent.push_back(s);
      via.push_back(t);
      if (check.holds(target, store.at(w))) {
        finish(w);
        return out;
      }
      if (store.size() > std::min<std::uint64_t>(limits.max_states, 0xfffffff0u)) {
        out.stop = ExploreStop::MaxStates;
        break;
      }
    }
    if (out.stop != ExploreStop::Done) break;
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

QueryAnswer answerQuery(const Net& net, const Formula& f, const ExploreOptions& limits) {
  QueryAnswer a;
  if (isStateFormula(f)) {
    std::vector<std::int64_t> m0;
    for (const PlaceSlot& ps : net.placeSlots()) m0.push_back(ps.initial);
    a.verdict = holdsIn(net, f, m0) ? Verdict::True : Verdict::False;
    a.states = 1;
    a.technique = "INITIAL_STATE";
    return a;
  }
  if (f.kind == FormulaKind::Not) {
    // the answer to what is negated, turned over: its marking shows this answer too
    QueryAnswer inner = answerQuery(net, f.operands[0], limits);
    if (inner.verdict != Verdict::Unknown) inner.verdict = inner.verdict == Verdict::True ? Verdict::False : Verdict::True;
    return inner;
  }
  const bool quantified = (f.kind == FormulaKind::Exists || f.kind == FormulaKind::All) && f.operands.size() == 1;
  const Formula* path = quantified ? &f.operands[0] : nullptr;
  const bool ef = path && f.kind == FormulaKind::Exists && path->kind == FormulaKind::Future &&
                  isStateFormula(path->operands[0]);
  const bool ag = path && f.kind == FormulaKind::All && path->kind == FormulaKind::Globally &&
                  isStateFormula(path->operands[0]);
  if (!ef && !ag) {
    a.unsupported = "only reachability is answered so far: EF or AG of a formula without path operators, or its negation";
    return a;
  }
  // EF p: a marking where p holds; AG p: none where it fails
  const Reach r = reach(net, ef ? path->operands[0] : negation(path->operands[0]), limits);
  a.states = r.states;
  a.technique = "EXPLICIT BREADTH_FIRST_SEARCH";
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

bool holdsIn(const Net& net, const Formula& f, const std::vector<std::int64_t>& marking) {
  const Layout layout(std::vector<std::uint32_t>(marking.size(), kMaxBits), std::vector<bool>(marking.size(), false));
  std::vector<std::uint64_t> packed(layout.words());
  std::size_t bad = 0;
  if (!layout.pack(marking.data(), packed.data(), bad)) return false;
  StateCheck check(net, layout);
  return check.holds(f, packed.data());
}

}  // namespace gdpn::net
