// Stubborn sets for the queries' reachability searches: an up-set of the target formula,
// closed under "may disable or be disabled by" for enabled members and "can make its
// scapegoat need hold" for disabled ones.

#include "stubborn.h"

#include <algorithm>
#include <limits>

namespace gdpn::net::detail {

Stubborn::Rows Stubborn::rows(std::size_t slots, std::vector<std::vector<TransitionId>>& lists) {
  Rows r;
  r.begin.reserve(slots + 1);
  r.begin.push_back(0);
  for (auto& l : lists) {
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
    r.items.insert(r.items.end(), l.begin(), l.end());
    r.begin.push_back(static_cast<std::uint32_t>(r.items.size()));
  }
  return r;
}

Stubborn::Stubborn(const Net& net, const Layout& layout) : layout_(layout), stamp_(net.transitions().size(), 0) {
  constexpr std::int64_t kAny = std::numeric_limits<std::int64_t>::max();
  const std::size_t slots = net.placeSlots().size();
  std::vector<std::vector<TransitionId>> raise(slots), lower(slots), floors(slots), ceilings(slots);
  for (TransitionId t{0}; t < net.transitions().size(); ++t) {
    need_begin_.push_back(static_cast<std::uint32_t>(needs_.size()));
    change_begin_.push_back(static_cast<std::uint32_t>(changes_.size()));
    std::vector<std::pair<std::uint32_t, std::int64_t>> delta;
    for (const Term& term : net.termsOf(t)) {
      const std::uint32_t k = term.place_slot;
      switch (term.kind) {
        case TermKind::Input:
        case TermKind::Test: needs_.push_back({k, term.weight, kAny}); break;
        case TermKind::Inhibitor: needs_.push_back({k, 0, std::int64_t{term.weight} - 1}); break;
        case TermKind::Output: {
          const auto cap = net.placeSlots()[k].capacity;
          if (cap != kUnbounded) needs_.push_back({k, 0, cap + term.take - term.weight});
          break;
        }
        case TermKind::Condition: break;  // sensor conditions count as true in the analysis
      }
      if (term.kind != TermKind::Input && term.kind != TermKind::Output) continue;
      const std::int64_t d = term.kind == TermKind::Input ? -term.weight : term.weight;
      auto at = std::find_if(delta.begin(), delta.end(), [&](const auto& x) { return x.first == k; });
      if (at == delta.end()) {
        delta.emplace_back(k, d);
      } else {
        at->second += d;
      }
    }
    for (const auto& [k, d] : delta) {
      if (d == 0) continue;
      changes_.emplace_back(k, d);
      (d > 0 ? raise : lower)[k].push_back(t);
    }
    for (auto i = need_begin_.back(); i < needs_.size(); ++i) {
      if (needs_[i].lo > 0) floors[needs_[i].slot].push_back(t);
      if (needs_[i].hi != kAny) ceilings[needs_[i].slot].push_back(t);
    }
  }
  need_begin_.push_back(static_cast<std::uint32_t>(needs_.size()));
  change_begin_.push_back(static_cast<std::uint32_t>(changes_.size()));
  raisers_ = rows(slots, raise);
  lowerers_ = rows(slots, lower);
  floors_ = rows(slots, floors);
  ceilings_ = rows(slots, ceilings);
}

bool Stubborn::holds(const Need& n, const std::uint64_t* m) const {
  const std::int64_t c = layout_.value(m, n.slot);
  return c >= n.lo && c <= n.hi;
}

bool Stubborn::enabled(TransitionId t, const std::uint64_t* m) const {
  for (auto i = need_begin_[t]; i < need_begin_[t + 1]; ++i) {
    if (!holds(needs_[i], m)) return false;
  }
  return true;
}

std::span<const TransitionId> Stubborn::fixers(const Need& n, const std::uint64_t* m) const {
  return layout_.value(m, n.slot) < n.lo ? raisers_.of(n.slot) : lowerers_.of(n.slot);
}

void Stubborn::add(TransitionId t) {
  if (stamp_[t] == epoch_) return;
  stamp_[t] = epoch_;
  work_.push_back(t);
}

void Stubborn::addScapegoat(TransitionId t, const std::uint64_t* m) {
  const Need* best = nullptr;
  for (auto i = need_begin_[t]; i < need_begin_[t + 1]; ++i) {
    if (!holds(needs_[i], m) && (!best || fixers(needs_[i], m).size() < fixers(*best, m).size())) best = &needs_[i];
  }
  if (best) add(fixers(*best, m));
}

void Stubborn::addDisablers(TransitionId t) {
  for (auto i = need_begin_[t]; i < need_begin_[t + 1]; ++i) {
    if (needs_[i].lo > 0) add(lowerers_.of(needs_[i].slot));
    if (needs_[i].hi != std::numeric_limits<std::int64_t>::max()) add(raisers_.of(needs_[i].slot));
  }
}

void Stubborn::addMovers(const TokenSum& left, const TokenSum& right, bool raise) {
  for (PlaceSlotId k : left.slots) add(raise ? raisers_.of(k) : lowerers_.of(k));
  for (PlaceSlotId k : right.slots) add(raise ? lowerers_.of(k) : raisers_.of(k));
}

void Stubborn::addUpSet(const Formula& f, bool positive, const std::uint64_t* m, StateCheck& check) {
  switch (f.kind) {
    case FormulaKind::True:
    case FormulaKind::False: return;  // fails for ever: nothing helps
    case FormulaKind::Not: addUpSet(f.operands[0], !positive, m, check); return;
    case FormulaKind::And:
    case FormulaKind::Or:
      if ((f.kind == FormulaKind::And) == positive) {
        // every operand must come to hold (for `not or`: to fail): one that does not yet must change
        for (const Formula& o : f.operands) {
          if (check.holds(o, m) != positive) {
            addUpSet(o, positive, m, check);
            return;
          }
        }
      } else {
        for (const Formula& o : f.operands) addUpSet(o, positive, m, check);  // any of them may come to
      }
      return;
    case FormulaKind::Compare: {
      const std::int64_t d = check.sum(f.left, m) - check.sum(f.right, m);
      Comparison c = f.compare;
      if (!positive) {
        c = negated(c);
      }
      const bool raise = c == Comparison::Greater || c == Comparison::GreaterEqual || (c == Comparison::Equal && d < 0);
      const bool lower = c == Comparison::Less || c == Comparison::LessEqual || (c == Comparison::Equal && d > 0);
      if (raise || c == Comparison::NotEqual) addMovers(f.left, f.right, true);
      if (lower || c == Comparison::NotEqual) addMovers(f.left, f.right, false);
      return;
    }
    case FormulaKind::Fireable:
      if (positive) {
        for (TransitionId t : f.transitions) addScapegoat(t, m);  // each is disabled: any may come to be enabled
      } else {
        for (TransitionId t : f.transitions) {
          if (check.firing().enabled(t, m)) {
            addDisablers(t);  // it must come to be disabled
            return;
          }
        }
      }
      return;
    case FormulaKind::Deadlock:
      if (positive) {
        // some transition is enabled: it must come to be disabled
        std::vector<TransitionId> candidates;
        check.candidates().find(m, check.firing(), candidates);
        for (TransitionId t : candidates) {
          if (check.firing().enabled(t, m)) {
            addDisablers(t);
            return;
          }
        }
      }
      return;  // `not deadlock` fails: the marking is dead, nothing fires
    case FormulaKind::All:
    case FormulaKind::Bound:
    case FormulaKind::Exists:
    case FormulaKind::Future:
    case FormulaKind::Globally:
    case FormulaKind::Next:
    case FormulaKind::Until: return;  // not a state formula: never asked
  }
}

void Stubborn::select(const Formula& target, const std::uint64_t* m, StateCheck& check, std::vector<TransitionId>& out) {
  start();
  addUpSet(target, true, m, check);
  close(m, out);
}

bool Stubborn::selectFrom(TransitionId seed, const std::uint64_t* m, const std::vector<bool>& visible,
                          std::vector<TransitionId>& out) {
  start();
  add(seed);
  close(m, out);
  return std::none_of(out.begin(), out.end(), [&](TransitionId t) { return visible[t]; });
}

std::vector<bool> Stubborn::visibleTo(const std::vector<const Formula*>& atoms) const {
  // the place slots the atoms read: a sum's, and what a transition's enabling depends on
  std::vector<bool> read(raisers_.begin.size() - 1, false), visible(need_begin_.size() - 1, false);
  auto each = [&](auto& self, const Formula& f) -> bool {  // false: every slot counts (deadlock)
    switch (f.kind) {
      case FormulaKind::Compare:
        for (PlaceSlotId k : f.left.slots) read[k] = true;
        for (PlaceSlotId k : f.right.slots) read[k] = true;
        return true;
      case FormulaKind::Fireable:
        for (TransitionId t : f.transitions) {
          for (auto i = need_begin_[t]; i < need_begin_[t + 1]; ++i) read[needs_[i].slot] = true;
        }
        return true;
      case FormulaKind::Not:
      case FormulaKind::And:
      case FormulaKind::Or:
        return std::all_of(f.operands.begin(), f.operands.end(), [&](const Formula& o) { return self(self, o); });
      case FormulaKind::True:
      case FormulaKind::False: return true;
      case FormulaKind::Deadlock:
      case FormulaKind::All:
      case FormulaKind::Bound:
      case FormulaKind::Exists:
      case FormulaKind::Future:
      case FormulaKind::Globally:
      case FormulaKind::Next:
      case FormulaKind::Until: return false;
    }
    return false;  // no value of the enum
  };
  bool bounded = true;
  for (const Formula* f : atoms) bounded = each(each, *f) && bounded;
  if (!bounded) read.assign(read.size(), true);
  for (TransitionId t{0}; t < visible.size(); ++t) {
    for (auto j = change_begin_[t]; j < change_begin_[t + 1]; ++j) visible[t] = visible[t] || read[changes_[j].first];
  }
  return visible;
}

void Stubborn::start() {
  if (++epoch_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0);
    epoch_ = 1;
  }
  work_.clear();
}

void Stubborn::close(const std::uint64_t* m, std::vector<TransitionId>& out) {
  out.clear();
  for (std::size_t i = 0; i < work_.size(); ++i) {
    const TransitionId t = work_[i];
    if (!enabled(t, m)) {
      addScapegoat(t, m);
      continue;
    }
    out.push_back(t);
    addDisablers(t);
    // what it takes from, it may disable; where it adds, it may fill past a ceiling
    for (auto j = change_begin_[t]; j < change_begin_[t + 1]; ++j) {
      const auto [k, d] = changes_[j];
      add(d < 0 ? floors_.of(k) : ceilings_.of(k));
    }
  }
  std::sort(out.begin(), out.end());
}

}  // namespace gdpn::net::detail
