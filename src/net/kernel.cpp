#include "gdpn/net/kernel.h"

#include <algorithm>
#include <cmath>

#include "gdpn/core/assert.h"
#include "net/detail/sort_keys.h"

namespace gdpn::net {
namespace {

constexpr std::size_t kWheelSize = 4096;  // power of two
constexpr std::int64_t kMaxSteps = std::int64_t{1} << 60;

std::uint32_t indexOf(std::uint64_t key) { return static_cast<std::uint32_t>(key); }
std::uint64_t rankOf(std::uint64_t key) { return key >> 32; }

}  // namespace

Kernel::Kernel(std::shared_ptr<const Net> net, KernelSettings settings)
    : net_(std::move(net)), dt_(settings.dt), random_(settings.seed) {
  GDPN_ASSERT(net_ != nullptr, "kernel needs a net");
  GDPN_ASSERT(dt_ > 0.0, "dt must be positive");
  const Net& n = *net_;
  terms_ = n.terms().data();

  // place slots: markings, capacities and node FIFOs
  const auto slots = n.placeSlots();
  m_.resize(slots.size());
  r_.assign(slots.size(), 0);
  cap_.resize(slots.size());
  fifo_of_.assign(slots.size(), -1);
  const auto initial_nodes = n.initialNodes();
  for (std::size_t ps = 0; ps < slots.size(); ++ps) {
    m_[ps] = slots[ps].initial;
    cap_[ps] = slots[ps].capacity;
    if (slots[ps].kind != SlotKind::Node) continue;
    fifo_of_[ps] = static_cast<std::int32_t>(fifos_.size());
    auto& fifo = fifos_.emplace_back();
    for (auto i = slots[ps].nodes_begin; i < slots[ps].nodes_end; ++i) fifo.push_back(initial_nodes[i]);
  }

  // transitions: packed firing data, and the count of terms that do not hold
  const auto transitions = n.transitions();
  const std::size_t count = transitions.size();
  hot_.resize(count);
  unsat_.assign(count, 0);
  enabled_step_.assign(count, 0);
  considered_.assign(count, -1);
  start_step_.assign(count, -1);
  end_step_.assign(count, -1);
  for (TransitionId t = 0; t < count; ++t) {
    const auto& tr = transitions[t];
    auto& h = hot_[t];
    h.terms_begin = tr.terms_begin;
    h.inputs_end = tr.inputs_end;
    h.conditions_end = tr.conditions_end;
    h.terms_end = tr.terms_end;
    h.rank = tr.priority_rank;
    h.held = -1;
    if (tr.node_slot_mask != 0) {
      h.held = static_cast<std::int32_t>(held_.size());
      held_.emplace_back();
    }
    h.fixed_steps = tr.duration.fixed() ? durationSteps(tr.duration.a) : -1;
    h.probability = tr.probability;
  }
  holds_.assign(n.terms().size(), 1);
  for (PlaceSlotId ps = 0; ps < slots.size(); ++ps) {
    for (TermId id : n.watchers(ps)) {
      if (!holds(terms_[id])) {
        holds_[id] = 0;
        ++unsat_[terms_[id].transition];
      }
    }
  }
  for (TransitionId t = 0; t < count; ++t) {
    if (unsat_[t] == 0) markEnabled(t);
  }
  wheel_.resize(kWheelSize);
}

void Kernel::addObserver(NetObserver* observer) { observers_.push_back(observer); }

std::int64_t Kernel::durationSteps(double seconds) const {
  const double x = seconds / dt_;
  if (!(x < static_cast<double>(kMaxSteps))) return kMaxSteps;
  // a duration within a billionth of a whole number of steps counts as that number
  const auto n = static_cast<std::int64_t>(std::ceil(x - 1e-9 * std::max(1.0, x)));
  return std::max<std::int64_t>(1, n);
}

std::int64_t Kernel::placeTokens(PlaceId p) const {
  const auto& place = net_->places()[p];
  std::int64_t total = 0;
  for (auto ps = place.slots_begin; ps < place.slots_end; ++ps) total += m_[ps];
  return total;
}

std::vector<NodeRef> Kernel::nodes(PlaceSlotId ps) const {
  if (fifo_of_[ps] < 0) return {};
  const auto& fifo = fifos_[static_cast<std::size_t>(fifo_of_[ps])];
  return {fifo.begin(), fifo.end()};
}

bool Kernel::holds(const Term& term) const {
  const std::int64_t m = m_[term.place_slot];
  switch (term.kind) {
    case TermKind::Input:
    case TermKind::Test: return m >= term.weight;
    case TermKind::Inhibitor: return m < term.weight;
    case TermKind::Output: {
      const std::int64_t cap = cap_[term.place_slot];
      return cap == kUnbounded || cap - (m - term.take) - r_[term.place_slot] >= term.weight;
    }
  }
  return false;
}

void Kernel::update(PlaceSlotId ps) {
  for (TermId id : net_->watchers(ps)) {
    const Term& term = terms_[id];
    const bool ok = holds(term);
    if (ok == static_cast<bool>(holds_[id])) continue;
    holds_[id] = ok;
    const TransitionId t = term.transition;
    if (ok) {
      if (--unsat_[t] == 0) markEnabled(t);
    } else if (unsat_[t]++ == 0) {
      --enabled_count_;
    }
  }
}

void Kernel::markEnabled(TransitionId t) {
  ++enabled_count_;
  enabled_step_[t] = step_;
  const std::uint64_t key = (std::uint64_t{hot_[t].rank} << 32) | t;
  (in_firing_ ? late_ : fresh_).push_back(key);
}

std::int64_t Kernel::drawSteps(TransitionId t) {
  if (hot_[t].fixed_steps >= 0) return hot_[t].fixed_steps;
  const Duration& d = net_->transitions()[t].duration;
  double seconds = 0.0;
  switch (d.law) {
    case Duration::Law::Fixed: seconds = d.a; break;
    case Duration::Law::Uniform: seconds = random_.uniform(d.a, d.b); break;
    case Duration::Law::Normal: {
      // truncated at 0: redraw negatives (the mean is not negative, so this ends quickly)
      int tries = 0;
      do {
        seconds = random_.normal(d.a, d.b);
      } while (seconds < 0.0 && ++tries < 1000);
      seconds = std::max(0.0, seconds);
      break;
    }
    case Duration::Law::Exponential: seconds = random_.exponential(d.a); break;
  }
  return durationSteps(seconds);
}

void Kernel::begin(TransitionId t) {
  const Hot& h = hot_[t];
  // the occurrence is a virtual unsatisfied term: t cannot start again until it completes
  ++unsat_[t];
  --enabled_count_;
  ++occurring_count_;
  start_step_[t] = step_;
  const std::int64_t end = step_ + drawSteps(t);
  end_step_[t] = end;
  wheel_[static_cast<std::size_t>(end) & (kWheelSize - 1)].push_back(t);
  for (auto* o : observers_) o->onStart(t, step_);

  // take the inputs (node tokens move into the transition, FIFO), then reserve the outputs
  for (auto i = h.terms_begin; i < h.inputs_end; ++i) {
    const Term& term = terms_[i];
    const PlaceSlotId ps = term.place_slot;
    m_[ps] -= term.weight;
    if (h.held >= 0 && fifo_of_[ps] >= 0) {
      auto& fifo = fifos_[static_cast<std::size_t>(fifo_of_[ps])];
      auto& held = held_[static_cast<std::size_t>(h.held)];
      std::vector<NodeRef> moved;
      for (std::int64_t k = 0; k < term.weight; ++k) {
        moved.push_back(fifo.front());
        held.emplace_back(net_->placeSlots()[ps].slot, fifo.front());
        fifo.pop_front();
      }
      for (auto* o : observers_) o->onRemove(ps, term.weight, moved, step_);
    } else {
      for (auto* o : observers_) o->onRemove(ps, term.weight, {}, step_);
    }
    update(ps);
  }
  for (auto i = h.conditions_end; i < h.terms_end; ++i) {
    const Term& term = terms_[i];
    r_[term.place_slot] += term.weight;
    if (cap_[term.place_slot] != kUnbounded) update(term.place_slot);
  }
}

void Kernel::finish(TransitionId t) {
  const Hot& h = hot_[t];
  for (auto* o : observers_) o->onComplete(t, step_);
  for (auto i = h.conditions_end; i < h.terms_end; ++i) {
    const Term& term = terms_[i];
    const PlaceSlotId ps = term.place_slot;
    r_[ps] -= term.weight;
    m_[ps] += term.weight;
    if (h.held >= 0 && fifo_of_[ps] >= 0) {
      // node tokens leave in the order they were taken, per slot
      auto& fifo = fifos_[static_cast<std::size_t>(fifo_of_[ps])];
      auto& held = held_[static_cast<std::size_t>(h.held)];
      const SlotId slot = net_->placeSlots()[ps].slot;
      std::vector<NodeRef> moved;
      for (auto it = held.begin(); it != held.end() && static_cast<std::int64_t>(moved.size()) < term.weight;) {
        if (it->first == slot) {
          moved.push_back(it->second);
          fifo.push_back(it->second);
          it = held.erase(it);
        } else {
          ++it;
        }
      }
      for (auto* o : observers_) o->onDeposit(ps, term.weight, moved, step_);
    } else {
      for (auto* o : observers_) o->onDeposit(ps, term.weight, {}, step_);
    }
    update(ps);
  }
  end_step_[t] = -1;
  --occurring_count_;
  if (--unsat_[t] == 0) markEnabled(t);
}

void Kernel::completeOccurrences() {
  auto& slot = wheel_[static_cast<std::size_t>(step_) & (kWheelSize - 1)];
  if (slot.empty()) return;
  due_.swap(slot);
  slot.clear();
  // entries are in start order; ones due later (a full turn of the wheel away) stay
  for (TransitionId t : due_) {
    if (end_step_[t] == step_) {
      finish(t);
    } else {
      slot.push_back(t);
    }
  }
  due_.clear();
}

void Kernel::start() { fireEnabled(); }

void Kernel::step() {
  beginStep();
  completeOccurrences();
  fireEnabled();
}

void Kernel::fireEnabled() {
  // three sorted sequences of candidates: carried over (enabled in earlier steps),
  // late (enabled during the previous firing phase) and fresh (enabled in this step)
  late_now_.swap(late_);
  late_.clear();
  detail::sortKeys(late_now_, scratch_);
  detail::sortKeys(fresh_, scratch_);
  in_firing_ = true;
  carry_next_.clear();

  std::size_t ic = 0, il = 0, ifr = 0;
  const std::int64_t late_step = step_ - 1;
  while (true) {
    // pick the smallest (rank, step enabled, index) among the three heads
    std::uint64_t key = 0;
    std::int64_t when = 0;
    int from = -1;
    auto consider = [&](std::uint64_t k, std::int64_t s, int which) {
      if (from < 0 || rankOf(k) < rankOf(key) || (rankOf(k) == rankOf(key) && (s < when || (s == when && k < key)))) {
        key = k;
        when = s;
        from = which;
      }
    };
    if (ic < carry_.size()) consider(carry_[ic].key, carry_[ic].step, 0);
    if (il < late_now_.size()) consider(late_now_[il], late_step, 1);
    if (ifr < fresh_.size()) consider(fresh_[ifr], step_, 2);
    if (from < 0) break;
    if (from == 0) ++ic;
    else if (from == 1) ++il;
    else ++ifr;

    const TransitionId t = indexOf(key);
    // stale entries: disabled since, re-enabled later (a newer entry exists), or seen already
    if (unsat_[t] != 0 || enabled_step_[t] != when || considered_[t] == step_) continue;
    considered_[t] = step_;
    const double p = hot_[t].probability;
    if (p < 1.0 && !(random_.uniform01() < p)) {
      carry_next_.push_back({key, when});
      continue;
    }
    begin(t);
  }
  fresh_.clear();
  late_now_.clear();
  carry_.swap(carry_next_);
  in_firing_ = false;
}

std::size_t Kernel::memoryBytes() const {
  std::size_t bytes = hot_.capacity() * sizeof(Hot) +
                      (m_.capacity() + r_.capacity() + cap_.capacity()) * sizeof(std::int64_t) +
                      fifo_of_.capacity() * sizeof(std::int32_t) + holds_.capacity() +
                      unsat_.capacity() * sizeof(std::uint32_t) +
                      (enabled_step_.capacity() + considered_.capacity() + start_step_.capacity() +
                       end_step_.capacity()) * sizeof(std::int64_t) +
                      (fresh_.capacity() + late_.capacity() + late_now_.capacity() + scratch_.capacity()) *
                          sizeof(std::uint64_t) +
                      (carry_.capacity() + carry_next_.capacity()) * sizeof(Carry) +
                      wheel_.capacity() * sizeof(std::vector<TransitionId>);
  for (const auto& w : wheel_) bytes += w.capacity() * sizeof(TransitionId);
  for (const auto& f : fifos_) bytes += sizeof(f) + f.size() * sizeof(NodeRef);
  return bytes;
}

}  // namespace gdpn::net
