#include "gdpn/net/kernel.h"

#include "gdpn/core/memory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include "gdpn/core/assert.h"
#include "gdpn/core/text.h"
#include "detail/sort_keys.h"

namespace gdpn::net {
namespace {

// Completions due within kNearSize steps wait in the near wheel, by end step modulo its size:
// its lists, reused every kNearSize steps, stay in the cache. Later ones wait in the far wheel
// (by end step modulo kFarSize; a full turn of it away, they stay there) until they are near.
constexpr std::size_t kNearSize = 256;   // power of two
constexpr std::size_t kFarSize = 4096;   // power of two
constexpr std::int64_t kMaxSteps = std::int64_t{1} << 60;

// Fetches the cache line at `p` into the core's second-level cache, not its first: a big net's
// firings fetch their lines a whole loop ahead, and a first-level cache (48 KiB, 12 ways) filled
// that early evicts lines before they are read where many of them fall into the same sets
// (evenly spaced tokens: in a ring of 10^6 with 100 tokens, about 8 against 4.7 us a step).
// GCC counts a prefetch as having no effect: a function or loop that only fetches ahead is
// found "const" and its calls dropped (the completion loop's fetch of each slot's first
// watcher was). The empty volatile asm that takes the address keeps them.
inline void fetchAhead(const void* p) {
  __builtin_prefetch(p, 0, 2);
  asm volatile("" : : "r"(p));
}

std::uint32_t indexOf(std::uint64_t key) { return static_cast<std::uint32_t>(key); }
std::uint64_t rankOf(std::uint64_t key) { return key >> 32; }

}  // namespace

Kernel::Kernel(std::shared_ptr<const Net> net, KernelSettings settings)
    : net_(std::move(net)), dt_(settings.dt), random_(settings.seed), random_ties_(settings.random_ties) {
  GDPN_ASSERT(net_ != nullptr, "kernel needs a net");
  GDPN_ASSERT(dt_ > 0.0, "dt must be positive");
  const Net& n = *net_;
  terms_ = n.terms().data();
  core::reserveLarge(firing_terms_, n.terms().size());
  for (const Term& term : n.terms()) firing_terms_.push_back({term.place_slot, term.weight});

  // place slots: markings, capacities, watcher ranges and node FIFOs
  const auto slots = n.placeSlots();
  // a big net's state is read at random: huge pages spare a TLB miss per line
  core::reserveLarge(slots_, slots.size() + 1);
  slots_.resize(slots.size() + 1);
  const auto initial_nodes = n.initialNodes();
  for (std::size_t ps = 0; ps < slots.size(); ++ps) {
    auto& st = slots_[ps];
    st.m = slots[ps].initial;
    st.r = 0;
    st.capacity = slots[ps].capacity;
    st.watch_begin = static_cast<std::uint32_t>(watch_.size());
    const auto watchers = n.watchers(static_cast<PlaceSlotId>(ps));
    st.watch_count = static_cast<std::uint32_t>(watchers.size());
    for (std::size_t k = 0; k < watchers.size(); ++k) {
      const Term& term = terms_[watchers[k]];
      const Watch watch{term.transition, term.weight, term.take, term.kind, 1};
      if (k == 0) st.first = watch;
      else watch_.push_back(watch);
    }
    slots_[ps + 1].watch_begin = static_cast<std::uint32_t>(watch_.size());
    st.fifo = -1;
    st.scripts = slots[ps].scripts;
    st.slot = slots[ps].slot;
    if (slots[ps].kind != SlotKind::Node) continue;
    st.fifo = static_cast<std::int32_t>(fifos_.size());
    auto& fifo = fifos_.emplace_back();
    for (auto i = slots[ps].nodes_begin; i < slots[ps].nodes_end; ++i) {
      const auto name = initial_nodes[i];
      fifo.push_back(settings.node_refs.empty() ? NodeRef{name} : settings.node_refs[name]);
    }
  }

  // value slots and the terms of coloured transitions
  colouring_ = n.colouring();
  if (colouring_) {
    values_ = colouring_->initial;
    values_.resize(slots.size());
    term_arc_.assign(n.terms().size(), -1);
    for (const auto& terms : colouring_->arc_terms) {
      for (std::size_t k = 0; k < terms.size(); ++k) term_arc_[terms[k]] = static_cast<std::int32_t>(k);
    }
    auto searches = std::make_shared<std::vector<BindingSearch>>();
    searches->reserve(colouring_->transitions.size());
    for (const auto& ti : colouring_->transitions) searches->emplace_back(ti, colouring_->colours);
    searches_ = std::move(searches);
  }

  // transitions: packed firing data, and the count of terms that do not hold
  const auto transitions = n.transitions();
  const std::size_t count = transitions.size();
  GDPN_ASSERT(count < kOccurrenceBit, "too many transitions");
  core::reserveLarge(tr_, count);
  tr_.resize(count);
  big_ = (count + slots_.size()) * 64 + n.terms().size() * sizeof(Term) >= (std::size_t{4} << 20);
  warm_occurrences_ = core::secondLevelCacheBytes() / (4 * 4 * 64);
  for (TransitionId t{0}; t < count; ++t) {
    const auto& spec = transitions[t];
    auto& st = tr_[t];
    st.terms_begin = spec.terms_begin;
    st.inputs_end = spec.inputs_end;
    st.conditions_end = spec.conditions_end;
    st.terms_end = spec.terms_end;
    // ranks beyond 2^23 - 1 (more distinct priorities than that) share the lowest rank
    st.rank = std::min<std::uint32_t>(spec.priority_rank, (1u << 23) - 1) & 0x7fffffu;
    st.multi = spec.servers != 1 ? 1 : 0;
    if (spec.servers != 1) {
      if (servers_of_.empty()) servers_of_.assign(count, -1);
      servers_of_[t] = static_cast<std::int32_t>(servers_.size());
      servers_.push_back({spec.servers, 0, kNoOccurrence, kNoOccurrence});
    }
    st.scripts = spec.scripts;
    if ((spec.scripts & kInFire) && start_seq_.empty()) start_seq_.assign(count, 0);
    st.held = -1;
    if (spec.node_slot_mask != 0) {
      st.held = static_cast<std::int32_t>(held_.size());
      held_.emplace_back();
    }
    st.unsat = 0;
    const std::int64_t fixed = spec.duration.law == Duration::Law::Immediate ? 0
                               : spec.duration.fixed()                       ? durationSteps(spec.duration.a)
                                                                             : -1;
    st.fixed_steps = fixed <= std::numeric_limits<std::int32_t>::max() ? static_cast<std::int32_t>(fixed) : -1;
    immediates_ = immediates_ || fixed == 0;
    st.probability = spec.probability;
    st.enabled_step = 0;
    st.start_step = -1;
    st.end_step = -1;
  }
  for (PlaceSlotId ps{0}; ps < slots.size(); ++ps) {
    auto init = [&](Watch& watch) {
      if (!holds(slots_[ps], watch.kind, watch.weight, watch.take)) {
        watch.holds = 0;
        ++tr_[watch.transition].unsat;
      }
    };
    if (slots_[ps].watch_count > 0) init(slots_[ps].first);
    for (auto w = slots_[ps].watch_begin; w < slots_[ps + 1].watch_begin; ++w) init(watch_[w]);
  }
  // conditions do not hold until the sensor layer says they do
  for (TermId id{0}; id < n.terms().size(); ++id) {
    if (terms_[id].kind != TermKind::Condition) continue;
    if (cond_.empty()) cond_.assign(n.terms().size(), 0);
    ++tr_[terms_[id].transition].unsat;
  }
  // transitions that a guard, a predicate or a draw can hold back keep what their last
  // attempt to start found (the others' readiness is their terms')
  for (TransitionId t{0}; t < count; ++t) {
    bool predicates = false;
    for (auto i = tr_[t].terms_begin; i < tr_[t].conditions_end; ++i) predicates = predicates || terms_[i].predicate;
    const bool bound = colouring_ && colouring_->of(t);
    if (!(tr_[t].scripts & kGuard) && !predicates && !(tr_[t].probability < 1.0) && !bound) continue;
    if (verdict_.empty()) verdict_.assign(count, kFree);
    verdict_[t] = static_cast<std::uint8_t>(Readiness::Untried);
  }
  fluidInit();
  for (TransitionId t{0}; t < count; ++t) {
    if (tr_[t].unsat == 0) markEnabled(t);
  }
  wheel_.resize(kNearSize);
  far_.resize(kFarSize);
  near_end_ = static_cast<std::int64_t>(kNearSize) - 1;
}

void Kernel::addObserver(NetObserver* observer) { observers_.push_back(observer); }

void Kernel::removeObserver(NetObserver* observer) { std::erase(observers_, observer); }

std::int64_t Kernel::durationSteps(double seconds) const { return net::durationSteps(seconds, dt_); }

std::int64_t durationSteps(double seconds, double dt) {
  const double x = seconds / dt;
  if (!(x < static_cast<double>(kMaxSteps))) return kMaxSteps;
  // a duration within a billionth of a whole number of steps counts as that number
  const auto n = static_cast<std::int64_t>(std::ceil(x - 1e-9 * std::max(1.0, x)));
  return std::max<std::int64_t>(1, n);
}

std::int64_t Kernel::placeTokens(PlaceId p) const {
  const auto& place = net_->places()[p];
  std::int64_t total = 0;
  for (auto ps = place.slots_begin; ps < place.slots_end; ++ps) total += slots_[ps].m;
  return total;
}

std::vector<NodeRef> Kernel::nodes(PlaceSlotId ps) const {
  if (slots_[ps].fifo < 0) return {};
  const auto& fifo = fifos_[static_cast<std::size_t>(slots_[ps].fifo)];
  return {fifo.begin(), fifo.end()};
}

bool Kernel::holds(const SlotState& st, TermKind kind, std::int64_t weight, std::int64_t take) {
  switch (kind) {
    case TermKind::Input:
    case TermKind::Test: return st.m >= weight;
    case TermKind::Inhibitor: return st.m < weight;
    case TermKind::Output: return st.capacity == kUnbounded || st.capacity - (st.m - take) - st.r >= weight;
    case TermKind::Condition: return false;  // never watched: set through setCondition()
  }
  return false;
}

void Kernel::examine(const SlotState& st, Watch& watch) {
  const bool ok = holds(st, watch.kind, watch.weight, watch.take);
  if (ok == static_cast<bool>(watch.holds)) return;
  watch.holds = ok;
  const TransitionId t = watch.transition;
  if (ok) {
    if (--tr_[t].unsat == 0) markEnabled(t);
  } else if (tr_[t].unsat++ == 0) {
    --enabled_count_;
  }
}

void Kernel::update(PlaceSlotId ps) {
  SlotState& st = slots_[ps];
  if (st.watch_count == 0) return;
  examine(st, st.first);
  // the further watchers' count from this line (the next slot's watch_begin is another line)
  const auto end = st.watch_begin + st.watch_count - 1;
  for (auto w = st.watch_begin; w < end; ++w) examine(st, watch_[w]);
}

// For big nets: the loop over completions knows the transitions ahead of it, so it fetches
// what a firing reads in stages, each from what the stage before brought into the cache: 24
// items ahead the transition's state line, 16 ahead its terms, eight ahead the place slots
// they name. (The transitions watching those slots first were fetched as the start reserved
// them; fetching them again here, two items ahead, made a step of the ring of 10^6 slower:
// 4.95 to 5.0 against 4.66 to 4.88 us.) Only where more occurrences run than the
// second-level cache keeps the lines of (warm_occurrences_): where fewer run, what a
// completion reads was read as it started and is still there, and the stages' loads only
// cost time (a ring of 10^6 with 100 tokens, AMD EPYC: 4.23 against 3.88 us a step).
template <class Get>
void Kernel::prefetchAhead(std::size_t i, std::size_t n, Get get) const {
  constexpr std::size_t kState = 24, kTerms = 16, kSlots = 8;
  if (i + kState < n) fetchAhead(&tr_[get(i + kState)]);
  if (i + kTerms < n) prefetchTerms(get(i + kTerms));
  if (i + kSlots < n) prefetchSlots(get(i + kSlots));
}

// (prefetchTerms and prefetchSlots are inlined: a call each cost 3 % of a big net's
// instructions a step; fetchAhead() keeps them from being dropped once inlined)
inline __attribute__((always_inline)) void Kernel::prefetchTerms(TransitionId t) const {
  const TransitionState& tr = tr_[t];
  if (tr.terms_end == tr.terms_begin) return;
  // their first and last line (they may straddle lines)
  fetchAhead(&firing_terms_[tr.terms_begin]);
  fetchAhead(&firing_terms_[tr.terms_end - 1]);
}

inline __attribute__((always_inline)) void Kernel::prefetchSlots(TransitionId t) const {
  const TransitionState& tr = tr_[t];
  for (auto k = tr.terms_begin; k < tr.terms_end; ++k) fetchAhead(&slots_[firing_terms_[k].place_slot]);
}

void Kernel::markEnabled(TransitionId t) {
  // its terms are read when it starts, in this firing phase or the next: fetched now, while
  // its state line is in the cache
  if (big_) {
    prefetchTerms(t);
    // and a drawn duration's law, read as it starts (the net's transition: a line elsewhere)
    if (tr_[t].fixed_steps < 0) fetchAhead(&net_->transitions()[t].duration);
  }
  ++enabled_count_;
  tr_[t].enabled_step = settled_ && !in_firing_ ? step_ + 1 : step_;
  // a new enabling: what an earlier attempt found of its guard or draw no longer says anything
  if (!verdict_.empty() && verdict_[t] != kFree) verdict_[t] = static_cast<std::uint8_t>(Readiness::Untried);
  const std::uint64_t key = (std::uint64_t{tr_[t].rank} << 32) | t;
  (in_firing_ ? late_ : fresh_).push_back(key);
}

std::int64_t Kernel::drawSteps(TransitionId t) {
  if (tr_[t].fixed_steps >= 0) return tr_[t].fixed_steps;
  const DurationLaw& d = net_->transitions()[t].duration;
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
    case Duration::Law::Immediate: return 0;
  }
  return durationSteps(seconds);
}

bool Kernel::selectTokens(TransitionId t) {
  const TransitionState& tr = tr_[t];
  bool any = false;
  for (auto i = tr.terms_begin; i < tr.conditions_end; ++i) any = any || terms_[i].predicate;
  chosen_.clear();
  if (!any) return true;
  if (hooks_->halted()) return false;
  // per node input or test term, the first eligible tokens in FIFO order not already picked
  chosen_.resize(tr.conditions_end - tr.terms_begin);
  for (auto i = tr.terms_begin; i < tr.conditions_end; ++i) {
    const Term& term = terms_[i];
    const SlotState& st = slots_[term.place_slot];
    if (term.kind == TermKind::Inhibitor || st.fifo < 0) continue;
    const auto& fifo = fifos_[static_cast<std::size_t>(st.fifo)];
    auto& picked = chosen_[i - tr.terms_begin];
    for (std::size_t k = 0; k < fifo.size() && static_cast<std::int64_t>(picked.size()) < term.weight; ++k) {
      bool taken = false;
      for (auto j = tr.terms_begin; j < i && !taken; ++j) {
        if (terms_[j].place_slot != term.place_slot) continue;
        const auto& other = chosen_[j - tr.terms_begin];
        taken = std::find(other.begin(), other.end(), k) != other.end();
      }
      if (taken) continue;
      if (term.predicate && !hooks_->eligible(TermId{i}, fifo[k])) {
        if (hooks_->halted()) return false;
        continue;
      }
      picked.push_back(k);
    }
    if (static_cast<std::int64_t>(picked.size()) < term.weight) {
      chosen_.clear();
      return false;
    }
  }
  return true;
}

std::vector<BoundOccurrence> Kernel::bindings(TransitionId t, std::size_t most) const {
  const TransitionInscriptions* ti = colouring_ ? colouring_->of(t) : nullptr;
  if (!ti) return {};
  const auto c = static_cast<std::size_t>(colouring_->of_transition[t]);
  const auto& terms = colouring_->arc_terms[c];
  const auto marking = [&](std::size_t arc) -> const Multiset& { return values_[terms_[terms[arc]].place_slot]; };
  // room on an output's place slot: what this occurrence takes from it first frees room
  const TransitionState& tr = tr_[t];
  bool bounded = false;
  for (const auto term : terms) bounded = bounded || (terms_[term].kind == TermKind::Output && slots_[terms_[term].place_slot].capacity != kUnbounded);
  const auto room = [&](const BoundOccurrence& o) {
    for (std::size_t k = 0; k < terms.size(); ++k) {
      const Term& term = terms_[terms[k]];
      const SlotState& st = slots_[term.place_slot];
      if (term.kind != TermKind::Output || st.capacity == kUnbounded) continue;
      std::int64_t take = 0, put = 0;
      for (auto i = tr.terms_begin; i < tr.inputs_end; ++i) {
        if (terms_[i].place_slot == term.place_slot) take += term_arc_[i] >= 0 ? boundCount(i, o) : terms_[i].weight;
      }
      for (auto i = tr.conditions_end; i < tr.terms_end; ++i) {
        if (terms_[i].place_slot == term.place_slot) put += term_arc_[i] >= 0 ? boundCount(i, o) : terms_[i].weight;
      }
      if (st.capacity - (st.m - take) - st.r < put) return false;
    }
    return true;
  };
  // the search stops at the most-th in the canonical order
  return (*searches_)[c].enabled(marking, {}, most, bounded ? BindingFilter(room) : BindingFilter());
}

bool Kernel::selectBinding(TransitionId t) {
  // in declaration order, the first binding (the search stops there); with random ties, one
  // drawn from all
  auto found = bindings(t, random_ties_ ? SIZE_MAX : 1);
  if (found.empty()) return false;
  const std::size_t pick = random_ties_ && found.size() > 1 ? static_cast<std::size_t>(random_.below(found.size())) : 0;
  bound_next_ = std::move(found[pick]);
  return true;
}

bool Kernel::onlyUnbound() const {
  // the coloured transitions alone can be held so; count those that are
  if (enabled_count_ > colouring_->transition_ids.size() || verdict_.empty()) return false;
  std::size_t unbound = 0;
  for (const TransitionId t : colouring_->transition_ids) {
    if (tr_[t].unsat == 0 && verdict_[t] == static_cast<std::uint8_t>(Readiness::NoBinding)) ++unbound;
  }
  return unbound == enabled_count_;
}

const Multiset& Kernel::values(PlaceSlotId ps) const {
  static const Multiset kNone;
  return values_.empty() ? kNone : values_[ps];
}

const BoundOccurrence* Kernel::binding(TransitionId t) const {
  if (bound_.empty() || !colouring_ || !colouring_->of(t) || colouring_->of(t)->variables.empty()) return nullptr;
  Entry e = t;
  if (tr_[t].multi) {
    const Occurrence* o = currentOccurrence(t);
    if (!o) return nullptr;
    e = kOccurrenceBit | static_cast<Entry>(o - occ_.data());
  }
  const auto it = bound_.find(e);
  return it == bound_.end() ? nullptr : &it->second;
}

std::span<const std::pair<SlotId, NodeRef>> Kernel::held(TransitionId t) const {
  if (tr_[t].multi) {
    const Occurrence* o = currentOccurrence(t);
    return o ? std::span<const std::pair<SlotId, NodeRef>>(o->held) : std::span<const std::pair<SlotId, NodeRef>>();
  }
  if (tr_[t].held < 0) return {};
  return held_[static_cast<std::size_t>(tr_[t].held)];
}

const Kernel::Occurrence* Kernel::currentOccurrence(TransitionId t) const {
  if ((current_ & kOccurrenceBit) && current_ != kNoEntry && occ_[current_ & ~kOccurrenceBit].t == t) {
    return &occ_[current_ & ~kOccurrenceBit];
  }
  const auto oldest = servers_[static_cast<std::size_t>(servers_of_[t])].oldest;
  return oldest == kNoOccurrence ? nullptr : &occ_[oldest];
}

std::size_t Kernel::occurrences(TransitionId t) const {
  if (tr_[t].multi) return servers_[static_cast<std::size_t>(servers_of_[t])].busy;
  return occurring(t) ? 1 : 0;
}

std::int64_t Kernel::startStep(TransitionId t) const {
  const Occurrence* o = tr_[t].multi ? currentOccurrence(t) : nullptr;
  return (o ? o->start_step : tr_[t].start_step) + idle_;
}

std::int64_t Kernel::endStep(TransitionId t) const {
  const Occurrence* o = tr_[t].multi ? currentOccurrence(t) : nullptr;
  const std::int64_t end = o ? o->end_step : tr_[t].end_step;
  return end < 0 ? -1 : end + idle_;
}

std::string Kernel::setMarking(PlaceSlotId ps, std::int64_t count) {
  SlotState& st = slots_[ps];
  if (st.fifo >= 0) return "a node slot's tokens are nodes, not a count";
  if (!values_.empty() && colouring_->setOf(ps)) return "a value slot's tokens are values, not a count";
  if (count < 0) return "a marking cannot be negative";
  if (st.capacity != kUnbounded && count + st.r > st.capacity) {
    return "no room: capacity " + std::to_string(st.capacity) + ", reserved " + std::to_string(st.r);
  }
  const std::int64_t delta = count - st.m;
  if (delta == 0) return {};
  st.m = count;
  for (auto* o : observers_) {
    if (delta > 0) o->onDeposit(ps, delta, {}, steps());
    else o->onRemove(ps, -delta, {}, steps());
  }
  update(ps);
  return {};
}

std::string Kernel::setCapacity(PlaceSlotId ps, std::int64_t capacity) {
  SlotState& st = slots_[ps];
  if (capacity == st.capacity) return {};
  // outputs into a slot declared unbounded are not watched (they always hold): such a slot
  // keeps no capacity
  if (net_->placeSlots()[ps].capacity == kUnbounded) return "it has no capacity in the model (give it one to change it)";
  if (capacity != kUnbounded) {
    if (capacity < 0) return "a capacity cannot be negative";
    if (st.m + st.r > capacity) {
      return "it holds " + std::to_string(st.m) + " and has " + std::to_string(st.r) + " promised: more than " +
             std::to_string(capacity);
    }
  }
  st.capacity = capacity;
  update(ps);
  return {};
}

void Kernel::setCondition(TermId term, bool holds) {
  if (term >= cond_.size() || static_cast<bool>(cond_[term]) == holds) return;
  cond_[term] = holds;
  const TransitionId t = terms_[term].transition;
  if (holds) {
    if (--tr_[t].unsat == 0) markEnabled(t);
  } else if (tr_[t].unsat++ == 0) {
    --enabled_count_;
  }
}

std::string Kernel::addNode(PlaceSlotId ps, NodeRef ref) {
  SlotState& st = slots_[ps];
  if (st.fifo < 0) return "a control slot holds counts, not nodes";
  if (st.capacity != kUnbounded && st.m + st.r + 1 > st.capacity) {
    return "no room: capacity " + std::to_string(st.capacity) + ", reserved " + std::to_string(st.r);
  }
  fifos_[static_cast<std::size_t>(st.fifo)].push_back(ref);
  ++st.m;
  const NodeRef one[1] = {ref};
  for (auto* o : observers_) o->onDeposit(ps, 1, one, steps());
  update(ps);
  return {};
}

std::size_t Kernel::dropNodes(const std::function<bool(NodeRef)>& gone) {
  std::size_t dropped = 0;
  for (PlaceSlotId ps{0}; ps + 1 < slots_.size(); ++ps) {
    SlotState& st = slots_[ps];
    if (st.fifo < 0) continue;
    auto& fifo = fifos_[static_cast<std::size_t>(st.fifo)];
    moved_.clear();
    for (auto it = fifo.begin(); it != fifo.end();) {
      if (gone(*it)) {
        moved_.push_back(*it);
        it = fifo.erase(it);
      } else {
        ++it;
      }
    }
    if (moved_.empty()) continue;
    st.m -= static_cast<std::int64_t>(moved_.size());
    dropped += moved_.size();
    for (auto* o : observers_) o->onRemove(ps, static_cast<std::int64_t>(moved_.size()), moved_, steps());
    update(ps);
  }
  auto drop = [&](std::vector<std::pair<SlotId, NodeRef>>& held) {
    const auto before = held.size();
    held.erase(std::remove_if(held.begin(), held.end(), [&](const auto& h) { return gone(h.second); }), held.end());
    dropped += before - held.size();
  };
  for (auto& held : held_) drop(held);
  for (auto& o : occ_) drop(o.held);
  return dropped;
}

Kernel::Entry Kernel::startOccurrence(TransitionId t, std::int64_t end) {
  TransitionState& tr = tr_[t];
  Servers& sv = servers_[static_cast<std::size_t>(servers_of_[t])];
  // the virtual term of the occurrence counts only once every server is busy
  if (++sv.busy == sv.limit) {
    ++tr.unsat;
    --enabled_count_;
  }
  std::uint32_t o = 0;
  if (occ_free_.empty()) {
    o = static_cast<std::uint32_t>(occ_.size());
    GDPN_ASSERT(o < kOccurrenceBit, "too many occurrences at once");
    occ_.emplace_back();
  } else {
    o = occ_free_.back();
    occ_free_.pop_back();
  }
  Occurrence& occ = occ_[o];
  occ.t = t;
  occ.prev = sv.newest;
  occ.next = kNoOccurrence;
  occ.start_step = step_;
  occ.end_step = end;
  occ.start_idle = idle_;
  occ.seq = 0;
  occ.held.clear();
  (sv.newest == kNoOccurrence ? sv.oldest : occ_[sv.newest].next) = o;
  sv.newest = o;
  tr.end_step = occ_[sv.oldest].end_step;
  return kOccurrenceBit | o;
}

void Kernel::endOccurrence(Entry e) {
  // out of its transition's list, and free to reuse at once (no wheel or in_fire entry names it)
  const std::uint32_t o = e & ~kOccurrenceBit;
  Occurrence& occ = occ_[o];
  const TransitionId t = occ.t;
  TransitionState& tr = tr_[t];
  Servers& sv = servers_[static_cast<std::size_t>(servers_of_[t])];
  (occ.prev == kNoOccurrence ? sv.oldest : occ_[occ.prev].next) = occ.next;
  (occ.next == kNoOccurrence ? sv.newest : occ_[occ.next].prev) = occ.prev;
  occ.end_step = -1;
  occ.held.clear();
  occ_free_.push_back(o);
  tr.end_step = sv.oldest == kNoOccurrence ? -1 : occ_[sv.oldest].end_step;
  if (sv.busy-- == sv.limit && --tr.unsat == 0) markEnabled(t);
}

inline __attribute__((always_inline)) void Kernel::begin(TransitionId t) {
  if (tr_[t].multi) beginAs<true>(t);
  else beginAs<false>(t);
}

// begin() for a transition with servers or without: one text, compiled for each, so that a
// single server's start pays nothing for servers
template <bool kServers>
void Kernel::beginAs(TransitionId t) {
  TransitionState& tr = tr_[t];
  ++occurring_count_;
  ++start_count_;
  tr.start_step = step_;
  if (!start_idle_.empty()) start_idle_[t] = idle_;
  const std::int64_t lasts = tr.fixed_steps >= 0 ? tr.fixed_steps : drawSteps(t);
  const std::int64_t end = step_ + lasts;
  Entry entry = t;
  if constexpr (kServers) {
    entry = startOccurrence(t, end);
  } else {
    // the occurrence is a virtual unsatisfied term: t cannot start again until it completes
    ++tr.unsat;
    --enabled_count_;
    tr.end_step = end;
  }
  // an immediate occurrence completes below, in this phase: no wheel, no in_fire
  if (lasts > 0) {
    if (end <= near_end_) [[likely]] wheel_[static_cast<std::size_t>(end) & (kNearSize - 1)].push_back(entry);
    else waitFar(entry, end);
  }
  if ((tr.scripts & kInFire) && lasts > 0) {
    if constexpr (kServers) occ_[entry & ~kOccurrenceBit].seq = start_count_;
    else start_seq_[t] = start_count_;
    in_fire_.push_back(entry);
  }
  for (auto* o : observers_) o->onStart(t, steps());
  const BoundOccurrence* bound = nullptr;
  if (colouring_ && colouring_->of(t)) {
    auto& b = bound_[entry] = std::move(bound_next_);
    bound = &b;
    if (!b.binding.empty()) {
      for (auto* o : observers_) o->onBinding(t, b.binding, steps());
    }
  }

  // take the inputs (node tokens move into the transition, FIFO), then reserve the outputs;
  // scripts run only once the start is complete, so that what they do to the net (delete a
  // node, add or remove tokens) meets a consistent kernel and cannot undo a take half-way
  std::vector<RemoveCall> calls;
  for (auto i = tr.terms_begin; i < tr.inputs_end; ++i) {
    const FiringTerm& term = firing_terms_[i];
    const PlaceSlotId ps = term.place_slot;
    SlotState& st = slots_[ps];
    if (bound && term_arc_[i] >= 0) [[unlikely]] {
      // values: the binding says which and how many
      const Multiset& taken = bound->arcs[static_cast<std::size_t>(term_arc_[i])];
      const std::int64_t count = multisetSize(taken);
      st.m -= count;
      Multiset& here = values_[ps];
      for (const auto& [v, k] : taken) {
        auto it = here.find(v);
        if ((it->second -= k) == 0) here.erase(it);
      }
      moved_.clear();
      for (auto* o : observers_) {
        o->onRemove(ps, count, moved_, steps());
        o->onValues(ps, taken, false, steps());
      }
      if ((st.scripts & kOnRemove) && hooks_) calls.push_back({ps, count, false, 0});
      update(ps);
      continue;
    }
    st.m -= term.weight;
    moved_.clear();
    if (st.fifo >= 0) {
      auto& fifo = fifos_[static_cast<std::size_t>(st.fifo)];
      auto& held = heldOf<kServers>(entry);
      const SlotId slot = st.slot;
      if (!chosen_.empty()) {
        // the tokens the predicates picked, in FIFO order
        const auto& picked = chosen_[i - tr.terms_begin];
        for (auto k : picked) moved_.push_back(fifo[k]);
        for (auto k = picked.rbegin(); k != picked.rend(); ++k) fifo.erase(fifo.begin() + static_cast<std::ptrdiff_t>(*k));
      } else {
        for (std::int64_t k = 0; k < term.weight; ++k) {
          moved_.push_back(fifo.front());
          fifo.pop_front();
        }
      }
      for (NodeRef node : moved_) held.emplace_back(slot, node);
    }
    for (auto* o : observers_) o->onRemove(ps, term.weight, moved_, steps());
    if ((st.scripts & kOnRemove) && hooks_) {
      if (moved_.empty()) calls.push_back({ps, term.weight, false, 0});
      for (NodeRef node : moved_) calls.push_back({ps, 1, true, node});
    }
    update(ps);
  }
  for (auto i = tr.conditions_end; i < tr.terms_end; ++i) {
    const FiringTerm& term = firing_terms_[i];
    SlotState& st = slots_[term.place_slot];
    st.r += bound && term_arc_[i] >= 0 ? boundCount(i, *bound) : term.weight;
    if (st.capacity != kUnbounded) update(term.place_slot);
    // the completion deposits here and looks at the slot's first watcher: fetched now, while
    // the slot's line is in the cache
    if (big_ && st.watch_count > 0) fetchAhead(&tr_[st.first.transition]);
  }
  if (fluid_) [[unlikely]] fluidBegin(t);
  chosen_.clear();

  // on_remove per token taken, in the order taken, then pre_fire (self: this occurrence)
  if (!calls.empty() || ((tr.scripts & kPreFire) && hooks_)) {
    const Entry outer = std::exchange(current_, entry);
    for (const RemoveCall& call : calls) {
      for (std::int64_t k = 0; k < call.count && !hooks_->halted(); ++k) {
        hooks_->onRemove(call.ps, call.node ? &call.token : nullptr);
      }
    }
    if ((tr.scripts & kPreFire) && hooks_ && !hooks_->halted()) hooks_->preFire(t);
    current_ = outer;
  }
  if (lasts == 0) {
    immediate_fired_ = true;
    finish(entry);
  }
}

inline __attribute__((always_inline)) void Kernel::finish(Entry e) {
  if (e & kOccurrenceBit) finishAs<true>(e);
  else finishAs<false>(e);
}

template <bool kServers>
void Kernel::finishAs(Entry e) {
  const TransitionId t = kServers ? occ_[e & ~kOccurrenceBit].t : TransitionId{e};
  TransitionState& tr = tr_[t];
  if (!observers_.empty()) {
    // the step onStart saw: the start plus the idle steps before it
    const std::int64_t started =
        kServers ? occ_[e & ~kOccurrenceBit].start_step + occ_[e & ~kOccurrenceBit].start_idle
                 : tr.start_step + (start_idle_.empty() ? 0 : start_idle_[t]);
    for (auto* o : observers_) o->onComplete(t, steps(), started);
  }
  // scripts (post_fire, on_deposit) see this occurrence as self's
  if ((tr.scripts & kPostFire) && hooks_ && !hooks_->halted()) {
    const Entry outer = std::exchange(current_, e);
    hooks_->postFire(t);
    current_ = outer;
  }
  // the occurrence's binding: kept until its deposits (and their scripts) are done
  const bool coloured = !bound_.empty() && colouring_->of(t);
  const auto bound_at = coloured ? bound_.find(e) : bound_.end();
  for (auto i = tr.conditions_end; i < tr.terms_end; ++i) {
    const FiringTerm& term = firing_terms_[i];
    const PlaceSlotId ps = term.place_slot;
    SlotState& st = slots_[ps];
    if (coloured && term_arc_[i] >= 0) [[unlikely]] {
      Multiset& put = bound_at->second.arcs[static_cast<std::size_t>(term_arc_[i])];
      const std::int64_t count = multisetSize(put);
      st.r -= count;
      st.m += count;
      Multiset& here = values_[ps];
      if (observers_.empty()) {
        // nobody reads what was put: its values move into the place, node and all
        while (!put.empty()) {
          auto moved = here.insert(put.extract(put.begin()));
          if (!moved.inserted) moved.position->second += moved.node.mapped();
        }
      } else {
        for (const auto& [v, k] : put) here[v] += k;
      }
      moved_.clear();
      for (auto* o : observers_) {
        o->onDeposit(ps, count, moved_, steps());
        o->onValues(ps, put, true, steps());
      }
      update(ps);
      if ((st.scripts & kOnDeposit) && hooks_) {
        const Entry outer = std::exchange(current_, e);
        deposited(ps, st, count);
        current_ = outer;
      }
      continue;
    }
    st.r -= term.weight;
    moved_.clear();
    if (st.fifo < 0) st.m += term.weight;
    if (st.fifo >= 0) {
      // node tokens leave in the order they were taken, per slot
      auto& fifo = fifos_[static_cast<std::size_t>(st.fifo)];
      auto& held = heldOf<kServers>(e);
      const SlotId slot = st.slot;
      for (auto it = held.begin(); it != held.end() && static_cast<std::int64_t>(moved_.size()) < term.weight;) {
        if (it->first == slot) {
          moved_.push_back(it->second);
          fifo.push_back(it->second);
          it = held.erase(it);
        } else {
          ++it;
        }
      }
      // as many as it still holds: a deleted node is gone from the transition too
      st.m += static_cast<std::int64_t>(moved_.size());
    }
    const std::int64_t count = st.fifo >= 0 ? static_cast<std::int64_t>(moved_.size()) : term.weight;
    for (auto* o : observers_) o->onDeposit(ps, count, moved_, steps());
    update(ps);
    if ((st.scripts & kOnDeposit) && hooks_) {
      const Entry outer = std::exchange(current_, e);
      deposited(ps, st, count);
      current_ = outer;
    }
  }
  if (coloured) bound_.erase(bound_at);
  if (fluid_) [[unlikely]] fluidFinish(t);
  --occurring_count_;
  if constexpr (kServers) {
    endOccurrence(e);
  } else {
    tr.end_step = -1;
    if (--tr.unsat == 0) markEnabled(t);
  }
}

void Kernel::deposited(PlaceSlotId ps, const SlotState& st, std::int64_t count) {
  if (st.fifo < 0) {
    for (std::int64_t k = 0; k < count && !hooks_->halted(); ++k) hooks_->onDeposit(ps, nullptr);
    return;
  }
  // moved_ is reused by nested events: copy the tokens first
  const std::vector<NodeRef> tokens = moved_;
  for (std::size_t k = 0; k < tokens.size() && !hooks_->halted(); ++k) hooks_->onDeposit(ps, &tokens[k]);
}

void Kernel::waitFar(Entry e, std::int64_t end) {
  far_[static_cast<std::size_t>(end) & (kFarSize - 1)].push_back(e);
  ++far_count_;
}

std::size_t Kernel::takeEnding(std::vector<Entry>& from, std::int64_t end, std::vector<Entry>& to) const {
  std::size_t kept = 0;
  for (const Entry e : from) {
    if (endOf(e) == end) to.push_back(e);
    else from[kept++] = e;
  }
  const std::size_t taken = from.size() - kept;
  from.resize(kept);
  return taken;
}

void Kernel::completeOccurrences() {
  // the far wheel's occurrences that are now near move, in start order, to the near wheel's
  // list for their end step: it holds nothing yet (what starts from now on with that end
  // started later, and follows them)
  // (an empty far wheel is not walked)
  const std::int64_t near_end = step_ + static_cast<std::int64_t>(kNearSize) - 1;
  while (near_end_ < near_end && far_count_ != 0) {
    ++near_end_;
    auto& far = far_[static_cast<std::size_t>(near_end_) & (kFarSize - 1)];
    far_count_ -= takeEnding(far, near_end_, wheel_[static_cast<std::size_t>(near_end_) & (kNearSize - 1)]);
  }
  near_end_ = near_end;
  // the occurrences due now, in start order
  due_.clear();
  takeEnding(wheel_[static_cast<std::size_t>(step_) & (kNearSize - 1)], step_, due_);
  if (in_fire_.empty()) {
    const std::size_t n = due_.size();
    const bool ahead = big_ && occurring_count_ > warm_occurrences_;
    for (std::size_t i = 0; i < n; ++i) {
      if (ahead) prefetchAhead(i, n, [this](std::size_t k) { return transitionOf(due_[k]); });
      finish(due_[i]);
    }
    return;
  }
  // with in_fire scripts: every occurrence that has one, and every one due, in the order they
  // started; each runs in_fire, then completes if its time has come
  in_fire_next_.clear();
  std::size_t i = 0, j = 0;
  while (i < due_.size() || j < in_fire_.size()) {
    Entry e = 0;
    if (j >= in_fire_.size() || (i < due_.size() && seqOf(due_[i]) < seqOf(in_fire_[j]))) {
      e = due_[i++];
    } else {
      e = in_fire_[j++];
      if (i < due_.size() && due_[i] == e) ++i;
    }
    const TransitionId t = transitionOf(e);
    const TransitionState& tr = tr_[t];
    if ((tr.scripts & kInFire) && hooks_ && !hooks_->halted()) {
      const Entry outer = std::exchange(current_, e);
      hooks_->inFire(t);
      current_ = outer;
    }
    if (endOf(e) == step_) {
      finish(e);
    } else if (tr.scripts & kInFire) {
      in_fire_next_.push_back(e);
    }
  }
  in_fire_.swap(in_fire_next_);
}

void Kernel::start() { fireEnabled(); }

void Kernel::step() {
  beginStep();
  advanceFluid();
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
  immediate_fired_ = false;  // (a user's fire() of an immediate transition is not a round of this phase)

  // merge the three into one ordered list of candidates: (rank, step enabled, index)
  candidates_.clear();
  std::size_t ic = 0, il = 0, ifr = 0;
  const std::int64_t late_step = step_ - 1;
  auto before = [](std::uint64_t k1, std::int64_t s1, std::uint64_t k2, std::int64_t s2) {
    return candidateBefore({k1, s1}, {k2, s2});
  };
  while (true) {
    Carry best{};
    int from = -1;
    if (ic < carry_.size()) best = carry_[ic], from = 0;
    if (il < late_now_.size() && (from < 0 || before(late_now_[il], late_step, best.key, best.step)))
      best = {late_now_[il], late_step}, from = 1;
    if (ifr < fresh_.size() && (from < 0 || before(fresh_[ifr], step_, best.key, best.step)))
      best = {fresh_[ifr], step_}, from = 2;
    if (from < 0) break;
    (from == 0 ? ic : from == 1 ? il : ifr)++;
    candidates_.push_back(best);
  }

  if (random_ties_) shuffleTies(candidates_);
  const bool rounds = immediates_ ? startCandidates<true>() : startCandidates<false>();
  immediate_fired_ = false;
  fresh_.clear();
  late_now_.clear();
  // the next phase merges the carried candidates as a sorted sequence
  if (random_ties_ || rounds) std::sort(carry_next_.begin(), carry_next_.end(), candidateBefore);
  carry_.swap(carry_next_);
  in_firing_ = false;
  settled_ = true;
  // the flows as the phase left the marking: dead() asks whether anything still moves
  if (fluid_) fluidRates();
}

inline bool Kernel::tryStart(TransitionId t, bool again) {
  const TransitionState& tr = tr_[t];
  // what holds it back is kept for readiness() (verdict_), where the kernel decides anyway
  if ((tr.scripts & kGuard) && hooks_) {
    if (hooks_->halted()) return heldBy(t, Readiness::Halted);
    if (!hooks_->guard(t)) return heldBy(t, hooks_->halted() ? Readiness::Halted : Readiness::Guard);
  }
  if (tr.held >= 0 && hooks_ && !selectTokens(t)) return heldBy(t, hooks_->halted() ? Readiness::Halted : Readiness::Predicate);
  if (colouring_ && colouring_->of(t) && !selectBinding(t)) return heldBy(t, Readiness::NoBinding);
  const double p = tr.probability;
  if (p < 1.0) {
    // one draw per transition and phase, however often immediates re-enable it; a further
    // server's start in the same turn (`again`) draws anew
    if (drawn_.empty()) drawn_.assign(tr_.size(), -1);
    const bool drew = drawn_[t] == step_ && !again;
    drawn_[t] = step_;
    if (drew || !(random_.uniform01() < p)) return heldBy(t, Readiness::Probability);
  }
  if (!verdict_.empty() && verdict_[t] != kFree) verdict_[t] = static_cast<std::uint8_t>(Readiness::Able);
  begin(t);
  return true;
}

template <bool kRounds>
bool Kernel::startCandidates() {
  // the candidates in order, and what immediate occurrences enabled since the phase began
  // (extra_, a heap: the next to take in front), merged as they are taken
  const std::size_t n = candidates_.size();
  std::size_t pos = 0;
  extra_.clear();
  std::int64_t rounds = 0;
  // their terms were fetched as they were enabled: the slots they name, a window ahead of the
  // loop at a time, so that the misses overlap
  constexpr std::size_t kWindow = 128;
  auto slotsAhead = [&](std::size_t from, std::size_t to) {
    for (std::size_t j = from; j < std::min(n, to); ++j) prefetchSlots(TransitionId{indexOf(candidates_[j].key)});
  };
  if (big_) slotsAhead(0, kWindow);
  const std::int64_t most_rounds = kImmediateRounds + 4 * static_cast<std::int64_t>(tr_.size());
  ++phase_;
  Carry last{~std::uint64_t{0}, -1};
  TransitionId resume{kNoEntry};  // an immediate transition with servers whose turn goes on
  while (pos < n || (kRounds && !extra_.empty())) {
    const bool extra = kRounds && !extra_.empty() && (pos >= n || extraBefore(extra_.front().c, candidates_[pos]));
    Carry c{};
    if (extra) {
      c = extra_.front().c;
      std::pop_heap(extra_.begin(), extra_.end(), [this](const Extra& x, const Extra& y) { return extraAfter(x, y); });
      extra_.pop_back();
    } else {
      if (big_ && pos % (kWindow / 2) == 0 && pos > 0) slotsAhead(pos + kWindow / 2, pos + kWindow);
      c = candidates_[pos++];
    }
    const TransitionId t{indexOf(c.key)};
    TransitionState& tr = tr_[t];
    // stale entries: disabled since, or re-enabled later (a newer entry exists); the same
    // entry twice (enabled, disabled and enabled again in one phase) comes twice in a row,
    // or, with random ties, was stamped when taken
    bool again = sameEntry(c, last);
    last = c;
    if (random_ties_ && !again) {
      if (taken_phase_.empty()) taken_phase_.assign(tr_.size(), 0), taken_step_.assign(tr_.size(), -1);
      again = taken_phase_[t] == phase_ && taken_step_[t] == c.step;
      taken_phase_[t] = phase_;
      taken_step_[t] = c.step;
    }
    const bool resumed = kRounds && std::exchange(resume, TransitionId{kNoEntry}) == t;
    if (tr.unsat != 0 || tr.enabled_step != c.step || (again && !resumed)) continue;
    // condition 5, predicates and probability: one that does not start waits, still enabled
    if (!tryStart(t, resumed)) {
      carry_next_.push_back(c);
      continue;
    }
    // a transition with servers starts again while it stays enabled and a server is free
    for (std::uint32_t k = 1; tr.multi && tr.unsat == 0 && !immediate_fired_; ++k) {
      if (k == kStartsPerTurn || !tryStart(t, true)) {
        carry_next_.push_back(c);
        break;
      }
    }
    if (!kRounds || !immediate_fired_) continue;
    // an immediate occurrence completed: what it enabled may go before the rest, and the
    // immediate transition itself stays a candidate while it is enabled (servers left)
    immediate_fired_ = false;
    if (++rounds > most_rounds) {
      // a cycle of immediate transitions: what is left waits for the next step
      if (valid(c)) carry_next_.push_back(c);
      break;
    }
    if (tr.multi && valid(c)) resume = t;
    addExtras(c);
    last = {~std::uint64_t{0}, -1};
  }
  // what the rounds left (they ran out) stays enabled: carried to the next phase
  for (; pos < n; ++pos) {
    if (valid(candidates_[pos])) carry_next_.push_back(candidates_[pos]);
  }
  for (const Extra& x : extra_) {
    if (valid(x.c)) carry_next_.push_back(x.c);
  }
  extra_.clear();
  return rounds > 0;
}

void Kernel::addExtras(const Carry& fired) {
  // only entries still valid (enabled, at the step they name), each once: a cycle of
  // immediates re-enabling a transition must not pile up its entries
  next_.clear();
  if (valid(fired)) next_.push_back(fired);
  for (const std::uint64_t key : late_) {
    if (valid({key, step_})) next_.push_back({key, step_});
  }
  late_.clear();
  std::sort(next_.begin(), next_.end(), candidateBefore);
  if (random_ties_) {
    shuffleTies(next_);
    if (valid(fired)) taken_phase_[indexOf(fired.key)] = 0;  // it is to be taken again
  } else {
    next_.erase(std::unique(next_.begin(), next_.end(),
                            sameEntry),
                next_.end());
  }
  // into the heap of extras, each numbered in the order it came (with random ties, after
  // those already waiting in its group)
  for (const Carry& c : next_) {
    extra_.push_back({c, extra_count_++});
    std::push_heap(extra_.begin(), extra_.end(), [this](const Extra& x, const Extra& y) { return extraAfter(x, y); });
  }
}

void Kernel::shuffleTies(std::vector<Carry>& candidates) {
  // an entry listed twice (enabled, disabled and enabled again) is kept once
  candidates.erase(std::unique(candidates.begin(), candidates.end(),
                               sameEntry),
                   candidates.end());
  // each run of equal priority and time enabled in an order drawn from the generator
  // (Fisher-Yates, the last position first): one draw per candidate beyond the first of a run
  const std::size_t n = candidates.size();
  for (std::size_t begin = 0, end = 0; begin < n; begin = end) {
    end = begin + 1;
    while (end < n && rankOf(candidates[end].key) == rankOf(candidates[begin].key) &&
           candidates[end].step == candidates[begin].step) {
      ++end;
    }
    for (std::size_t i = end - 1; i > begin; --i) {
      const auto j = begin + static_cast<std::size_t>(random_.below(i - begin + 1));
      std::swap(candidates[i], candidates[j]);
    }
  }
}

std::string Kernel::fire(TransitionId t) { return fireIn(t, nullptr); }

std::string Kernel::fire(TransitionId t, const Binding& b) {
  const auto* ti = colouring_ ? colouring_->of(t) : nullptr;
  if (ti == nullptr || ti->variables.empty()) return "'" + net_->transitionName(t) + "' has no variables to bind";
  if (b.size() != ti->variables.size()) {
    return "a binding of '" + net_->transitionName(t) + "' gives " + std::to_string(ti->variables.size()) +
           " values, got " + std::to_string(b.size());
  }
  return fireIn(t, &b);
}

std::string Kernel::fireIn(TransitionId t, const Binding* chosen) {
  const Net& net = *net_;
  const std::string name = "'" + net.transitionName(t) + "'";
  TransitionState& tr = tr_[t];
  if (fluid_ && fluid_->continuous(t)) {
    return name + " is continuous: it flows while its arcs allow it, and is never fired";
  }
  if (occurring(t) && !tr.multi) return name + " is occurring";
  if (tr.multi && servers(t) != 0 && occurrences(t) == servers(t)) {
    return name + " is occurring on all its " + std::to_string(servers(t)) + " servers";
  }
  if (tr.unsat != 0) {
    // name the first term that does not hold
    for (std::uint32_t i = tr.terms_begin; i < tr.terms_end; ++i) {
      const Term& term = terms_[i];
      const SlotState& st = slots_[term.place_slot];
      if (term.kind == TermKind::Condition ? condition(TermId{i}) : holds(st, term.kind, term.weight, term.take)) continue;
      return name + " is not enabled: " + termText(i);
    }
    return name + " is not enabled";
  }
  // what holds it back is kept for readiness(), as in a firing phase
  if (hooks_ && hooks_->halted()) {
    heldBy(t, Readiness::Halted);
    return name + " cannot start: the model's scripts have stopped";
  }
  if ((tr.scripts & kGuard) && hooks_ && !hooks_->guard(t)) {
    heldBy(t, hooks_->halted() ? Readiness::Halted : Readiness::Guard);
    return name + "'s guard is false";
  }
  if (tr.held >= 0 && hooks_ && !selectTokens(t)) {
    heldBy(t, hooks_->halted() ? Readiness::Halted : Readiness::Predicate);
    return "no node token satisfies the predicates of " + name;
  }
  if (chosen != nullptr) {
    // the user's binding, when it is one of those enabled now
    auto found = bindings(t);
    const auto it = std::find_if(found.begin(), found.end(), [&](const BoundOccurrence& o) { return o.binding == *chosen; });
    if (it == found.end()) {
      const auto* ti = colouring_->of(t);
      std::string text;
      for (std::size_t i = 0; i < chosen->size(); ++i) {
        const auto set = i < ti->sets.size() ? ti->sets[i] : Colours::kDot;
        text += (i == 0 ? "" : ", ") + ti->variables[i] + " = " + colouring_->colours.text(set, (*chosen)[i]);
      }
      return "binding (" + text + ") of " + name + " is not enabled (" +
             (found.empty() ? std::string("none is now") : std::to_string(found.size()) + " enabled now") + ")";
    }
    bound_next_ = std::move(*it);
  } else if (colouring_ && colouring_->of(t) && !selectBinding(t)) {
    heldBy(t, Readiness::NoBinding);
    return "no binding of " + name + "'s variables is enabled";
  }
  if (!verdict_.empty() && verdict_[t] != kFree) verdict_[t] = static_cast<std::uint8_t>(Readiness::Able);
  // what the start enables waits for the next firing phase, as if enabled in this one
  const bool was = std::exchange(in_firing_, true);
  begin(t);
  in_firing_ = was;
  return {};
}

std::string Kernel::termText(std::uint32_t i) const {
  const Net& net = *net_;
  const Term& term = terms_[i];
  if (fluid_ && fluid_->of_term[i] >= 0) [[unlikely]] {
    const FluidTerm& ft = fluid_->terms[static_cast<std::size_t>(fluid_->of_term[i])];
    const FluidPlace& fp = fluid_->places[ft.place];
    const std::string unit = fp.unit.empty() ? "" : " " + fp.unit;
    const std::string place = "'" + net.placeName(fp.place) + "'";
    const std::string has = core::formatDouble(fluid_run_->x[ft.place]) + unit, w = core::formatDouble(ft.weight) + unit;
    switch (ft.test) {
      case LevelTest::AtLeast: return place + " holds " + has + " of the " + w + " it needs";
      case LevelTest::Below: return place + " holds " + has + ", its inhibitor arc allows less than " + w;
      case LevelTest::Room: return place + " has no room for " + w + " more (it holds " + has + ")";
    }
  }
  const SlotState& st = slots_[term.place_slot];
  const auto& ps = net.placeSlots()[term.place_slot];
  const std::string place = "'" + net.placeName(ps.place) + "' " + slotName(ps.slot);
  const std::string has = std::to_string(st.m), w = std::to_string(term.weight);
  switch (term.kind) {
    case TermKind::Input:
    case TermKind::Test: return place + " holds " + has + " of the " + w + " it needs";
    case TermKind::Inhibitor: return place + " holds " + has + ", its inhibitor arc allows fewer than " + w;
    case TermKind::Output: return place + " has no room for " + w + " more";
    case TermKind::Condition: return "the condition on " + place + " does not hold";
  }
  return place;
}

bool heldBack(Readiness r) {
  switch (r) {
    case Readiness::Able:
    case Readiness::Untried:
    case Readiness::Occurring:
    case Readiness::Tokens:
    case Readiness::Room: return false;
    case Readiness::Condition:
    case Readiness::Guard:
    case Readiness::Predicate:
    case Readiness::NoBinding:
    case Readiness::Probability:
    case Readiness::Halted: return true;
  }
  return false;
}

const char* readinessName(Readiness r) {
  switch (r) {
    case Readiness::Able: return "able";
    case Readiness::Untried: return "untried";
    case Readiness::Occurring: return "occurring";
    case Readiness::Tokens: return "tokens";
    case Readiness::Room: return "room";
    case Readiness::Condition: return "condition";
    case Readiness::Guard: return "guard";
    case Readiness::Predicate: return "predicate";
    case Readiness::NoBinding: return "binding";
    case Readiness::Probability: return "probability";
    case Readiness::Halted: return "halted";
  }
  return "?";
}

Readiness Kernel::readiness(TransitionId t) const {
  const TransitionState& tr = tr_[t];
  // its terms hold: what the last attempt found (Able for one only its terms can hold back)
  if (tr.unsat == 0) return verdict_.empty() || verdict_[t] == kFree ? Readiness::Able : static_cast<Readiness>(verdict_[t]);
  // no free server: the occurrence's virtual term
  if (!tr.multi && tr.end_step >= 0) return Readiness::Occurring;
  if (tr.multi) {
    const Servers& sv = servers_[static_cast<std::size_t>(servers_of_[t])];
    if (sv.limit != 0 && sv.busy == sv.limit) return Readiness::Occurring;
  }
  // a marking or a capacity before a condition: a condition holds it back only where the
  // marking suffices
  for (std::uint32_t i = tr.terms_begin; i < tr.terms_end; ++i) {
    const Term& term = terms_[i];
    if (fluid_ && fluid_->of_term[i] >= 0) [[unlikely]] {
      // a term on a continuous place: its amount, as a marking's
      const auto k = static_cast<std::uint32_t>(fluid_->of_term[i]);
      if (fluidTermHolds(k)) continue;
      return fluid_->terms[k].test == LevelTest::Room ? Readiness::Room : Readiness::Tokens;
    }
    if (term.kind == TermKind::Condition || holds(slots_[term.place_slot], term.kind, term.weight, term.take)) continue;
    return term.kind == TermKind::Output ? Readiness::Room : Readiness::Tokens;
  }
  // a continuous transition whose terms hold flows (its one never-holding term aside)
  if (fluid_ && fluid_->continuous(t) && tr.unsat == 1) return Readiness::Able;
  return Readiness::Condition;
}

std::string Kernel::readinessText(TransitionId t) const {
  const Net& net = *net_;
  const TransitionState& tr = tr_[t];
  // the first term of the kind readiness() found that does not hold
  auto firstFailing = [&](bool conditions) -> std::string {
    for (std::uint32_t i = tr.terms_begin; i < tr.terms_end; ++i) {
      const Term& term = terms_[i];
      if (fluid_ && fluid_->of_term[i] >= 0) [[unlikely]] {
        // a term on a continuous place: an amount's, as a marking's
        if (conditions || fluidTermHolds(static_cast<std::uint32_t>(fluid_->of_term[i]))) continue;
        return termText(i);
      }
      const bool is_condition = term.kind == TermKind::Condition;
      if (is_condition != conditions) continue;
      if (is_condition ? condition(TermId{i}) : holds(slots_[term.place_slot], term.kind, term.weight, term.take)) continue;
      if (!is_condition) return termText(i);
      const auto& ps = net.placeSlots()[term.place_slot];
      return "condition of arc '" + net.placeName(ps.place) + "' -> '" + net.transitionName(t) + "' false";
    }
    return {};
  };
  switch (readiness(t)) {
    case Readiness::Able: return "able to start";
    case Readiness::Untried: return "its arcs allow it; no firing phase has tried its guard, predicates, bindings or draw yet";
    case Readiness::Occurring:
      return tr.multi ? "occurring on all its " + std::to_string(servers(t)) + " servers" : std::string("occurring");
    case Readiness::Tokens:
    case Readiness::Room: return firstFailing(false);
    case Readiness::Condition: return firstFailing(true);
    case Readiness::Guard: return "guard false";
    case Readiness::Predicate: return "no node token satisfies its predicates";
    case Readiness::NoBinding: return "no binding of its variables is enabled by the values its places hold";
    case Readiness::Probability: {
      char p[32];
      std::snprintf(p, sizeof p, "%g", tr.probability);
      return std::string("lost its probability draw (p = ") + p + ")";
    }
    case Readiness::Halted: return "the model's scripts have stopped";
  }
  return {};
}

std::size_t Kernel::memoryBytes() const {
  std::size_t bytes = tr_.capacity() * sizeof(TransitionState) + slots_.capacity() * sizeof(SlotState) +
                      firing_terms_.capacity() * sizeof(FiringTerm) +
                      watch_.capacity() * sizeof(Watch) +
                      (fresh_.capacity() + late_.capacity() + late_now_.capacity() + scratch_.capacity()) *
                          sizeof(std::uint64_t) +
                      (carry_.capacity() + carry_next_.capacity() + candidates_.capacity()) * sizeof(Carry) +
                      wheel_.capacity() * sizeof(std::vector<TransitionId>) + due_.capacity() * sizeof(TransitionId);
  for (const auto& w : wheel_) bytes += w.capacity() * sizeof(TransitionId);
  bytes += far_.capacity() * sizeof(std::vector<TransitionId>);
  for (const auto& w : far_) bytes += w.capacity() * sizeof(TransitionId);
  for (const auto& f : fifos_) bytes += sizeof(f) + f.size() * sizeof(NodeRef);
  for (const auto& h : held_) bytes += sizeof(h) + h.capacity() * sizeof(h[0]);
  for (const auto& o : occ_) bytes += sizeof(o) + o.held.capacity() * sizeof(o.held[0]);
  bytes += occ_free_.capacity() * sizeof(std::uint32_t) + servers_of_.capacity() * sizeof(std::int32_t);
  bytes += servers_.capacity() * sizeof(Servers) + start_idle_.capacity() * sizeof(std::int64_t);
  bytes += start_seq_.capacity() * sizeof(std::uint64_t) + verdict_.capacity();
  return bytes;
}

}  // namespace gdpn::net
