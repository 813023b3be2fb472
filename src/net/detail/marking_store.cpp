#include "marking_store.h"

#include "gdpn/net/invariants.h"
#include "gdpn/net/state_equation.h"

namespace gdpn::net::detail {

Store::Store(Layout layout, bool index, std::vector<Derived> derived)
    : layout_(std::move(layout)),
      key_bytes_(layout_.keyBytes()),
      index_bytes_(index ? sizeof(std::uint32_t) : 0),
      arena_(arenaShape(key_bytes_ + index_bytes_).first, arenaShape(key_bytes_ + index_bytes_).second) {
  for (const Derived& d : derived) {
    Rule r{d.slot, static_cast<std::uint32_t>(bit_terms_.size()), static_cast<std::uint32_t>(field_terms_.size()), d.constant,
           d.divisor};
    rules_.push_back(r);
    for (const auto& term : d.terms) {
      const std::uint32_t slot = term.first;
      const std::int64_t weight = term.second;  // named, not bound: a lambda below reads it
      const Layout::Field& f = layout_.field(slot);
      if (layout_.bits(slot) != 1 || f.omega) {
        field_terms_.push_back({slot, weight});
        continue;
      }
      // one-token fields of one weight in one word: one count of set bits
      auto same_word = [&](const BitTerm& b) { return b.word == f.word && b.weight == weight; };
      const auto at = std::find_if(bit_terms_.begin() + r.bits, bit_terms_.end(), same_word);
      if (at != bit_terms_.end()) {
        at->mask |= f.mask << f.shift;
      } else {
        bit_terms_.push_back({f.word, f.mask << f.shift, weight});
      }
    }
  }
  rules_.push_back({0, static_cast<std::uint32_t>(bit_terms_.size()), static_cast<std::uint32_t>(field_terms_.size()), 0, 1});
  low_mask_ = key_bytes_ >= 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (8 * key_bytes_)) - 1;
  rehash(1024);
}

void Store::load(StateId s, std::uint64_t* out) const {
  // word by word (little-endian: a key's bytes are its words' low bytes first), the last one
  // read where the one before ends; then the words that hold no kept field, zero
  const unsigned char* p = arena_.at(s);
  const std::size_t full = key_bytes_ / 8, rest = key_bytes_ % 8;
  std::size_t w = 0;
  for (; w < full; ++w) out[w] = word(p + 8 * w);
  if (rest != 0) out[w++] = key_bytes_ < 8 ? word(p) & low_mask_ : word(p + key_bytes_ - 8) >> (8 * (8 - rest));
  for (; w < words(); ++w) out[w] = 0;
  for (std::size_t r = 0; r + 1 < rules_.size(); ++r) {
    const Rule& rule = rules_[r];
    std::int64_t sum = 0;
    for (std::uint32_t i = rule.bits; i < rules_[r + 1].bits; ++i) {
      sum += bit_terms_[i].weight * std::popcount(out[bit_terms_[i].word] & bit_terms_[i].mask);
    }
    for (std::uint32_t i = rule.fields; i < rules_[r + 1].fields; ++i) {
      sum += field_terms_[i].weight * static_cast<std::int64_t>(layout_.code(out, field_terms_[i].slot));
    }
    layout_.setCode(out, rule.slot, static_cast<std::uint64_t>((rule.constant - sum) / rule.divisor));
  }
}

StateId Store::add(const std::uint64_t* m, std::uint64_t h, std::size_t i, bool& added) {
  if (growthWithin(1) != 0) {
    grow();
    return insert(m, h, added);
  }
  const auto s = static_cast<StateId>(size());
  unsigned char* slot = arena_.append();
  std::memcpy(slot, reinterpret_cast<const unsigned char*>(m), key_bytes_);
  std::memset(slot + key_bytes_, 0, index_bytes_);
  table_[i] = tagOf(h) | s;
  added = true;
  return s;
}

void Store::rehash(std::size_t capacity) {
  // the old table goes first (the markings give it again), so that the two never add up;
  // a table of many megabytes is probed at random: its allocator puts it on huge pages,
  // which spare a TLB miss per probe
  dropIndex();
  table_.assign(capacity, kEmpty);
  id_mask_ = static_cast<std::uint32_t>(capacity - 1);
  std::vector<std::uint64_t> m(words());
  for (std::size_t s = 0; s < size(); ++s) {
    // the hash reads the kept words alone: no slot needs working out
    std::memcpy(reinterpret_cast<unsigned char*>(m.data()), arena_.at(s), key_bytes_);
    const std::uint64_t h = hash(m.data());
    std::size_t i = h & (capacity - 1);
    while (table_[i] != kEmpty) i = (i + 1) & (capacity - 1);
    table_[i] = tagOf(h) | static_cast<std::uint32_t>(s);
  }
}

void Store::relayout(Layout layout) {
  const auto [stride, shift] = arenaShape(layout.keyBytes() + index_bytes_);
  Chunked<unsigned char> next(stride, shift);
  std::vector<std::int64_t> counts(layout_.width());
  std::vector<std::uint64_t> before(layout_.words()), after(layout.words());
  for (std::size_t s = 0; s < size(); ++s) {
    load(static_cast<StateId>(s), before.data());
    layout_.unpack(before.data(), counts.data());
    std::size_t bad = 0;
    layout.pack(counts.data(), after.data(), bad);
    unsigned char* slot = next.append();
    std::memcpy(slot, reinterpret_cast<const unsigned char*>(after.data()), layout.keyBytes());
    std::memcpy(slot + layout.keyBytes(), arena_.at(s) + key_bytes_, index_bytes_);
  }
  layout_ = std::move(layout);
  key_bytes_ = layout_.keyBytes();
  low_mask_ = key_bytes_ >= 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (8 * key_bytes_)) - 1;
  arena_ = std::move(next);
  rehash(table_.size());
}

void Firing::use(const Layout& layout) {
  words_ = layout.words();
  const std::size_t transitions = net_.transitions().size();
  spans_.assign(transitions + 1, Span{});
  needs_.clear();
  tests_.clear();
  adds_.clear();
  changes_.clear();
  deltas_.clear();
  std::vector<std::int64_t> delta(layout.width(), 0);
  std::vector<std::size_t> touched;
  auto here = [&] {
    return Span{static_cast<std::uint32_t>(needs_.size()), static_cast<std::uint32_t>(tests_.size()),
                static_cast<std::uint32_t>(adds_.size()), static_cast<std::uint32_t>(changes_.size()),
                static_cast<std::uint32_t>(deltas_.size())};
  };
  for (TransitionId t{0}; t < transitions; ++t) {
    spans_[t] = here();
    touched.clear();
    for (const Term& term : net_.termsOf(t)) {
      const std::size_t k = term.place_slot;
      const Layout::Field& f = layout.field(k);
      const auto weight = static_cast<std::uint64_t>(term.weight);
      Test x{f.word, f.shift, f.mask, 0, f.mask, false};
      switch (term.kind) {
        case TermKind::Input:
        case TermKind::Test:
          x.lo = weight;  // ω holds any number of tokens
          x.omega = f.omega;
          break;
        case TermKind::Inhibitor:
          // fewer than `weight`, and never ω
          x.hi = std::min(weight - 1, layout.maxCount(k));
          break;
        case TermKind::Output: {
          const auto cap = net_.placeSlots()[k].capacity;
          if (cap == kUnbounded) break;
          // at most the capacity once fired, unless ω
          const std::int64_t most = cap + term.take - term.weight;
          if (most < 0) {
            x.lo = 1, x.hi = 0;
          } else {
            x.hi = std::min<std::uint64_t>(static_cast<std::uint64_t>(most), f.mask);
          }
          x.omega = f.omega;
          break;
        }
        case TermKind::Condition:
          continue;  // sensor conditions are free to be either: explore as if true
      }
      if (x.lo == 1 && x.hi == 1 && x.mask == 1 && !x.omega) {
        // one token of a one-bit field: a bit that must be set
        if (needs_.size() > spans_[t].needs && needs_.back().word == f.word) {
          needs_.back().bits |= std::uint64_t{1} << f.shift;
        } else {
          needs_.push_back({f.word, std::uint64_t{1} << f.shift});
        }
      } else if (x.lo > 0 || x.hi < x.mask) {
        tests_.push_back(x);
      }
      if (term.kind != TermKind::Input && term.kind != TermKind::Output) continue;
      if (std::find(touched.begin(), touched.end(), k) == touched.end()) touched.push_back(k);
      delta[k] += term.kind == TermKind::Input ? -term.weight : term.weight;
    }
    for (const std::size_t k : touched) {
      const Layout::Field& f = layout.field(k);
      if (delta[k] != 0) {
        deltas_.push_back({f.word, f.shift, static_cast<std::uint32_t>(k), f.omega, f.mask, layout.maxCount(k), delta[k]});
      }
      if (delta[k] != 0 && !f.bounded) {
        changes_.push_back({f.word, f.shift, static_cast<std::uint32_t>(k), f.omega, f.mask, layout.maxCount(k), delta[k]});
      } else if (delta[k] != 0) {
        // two's complement in place: the count stays within its field, so nothing carries
        const std::uint64_t add = static_cast<std::uint64_t>(delta[k]) << f.shift;
        const auto at = std::find_if(adds_.begin() + spans_[t].adds, adds_.end(), [&](const Add& a) { return a.word == f.word; });
        if (at == adds_.end()) {
          adds_.push_back({f.word, add});
        } else {
          at->add += add;
        }
      }
      delta[k] = 0;
    }
  }
  spans_[transitions] = here();
}

Affected::Affected(const Net& net, std::size_t most) {
  if (most == 0) return;
  const std::size_t transitions = net.transitions().size();
  // per place slot: the transitions whose enabling reads its count
  std::vector<std::vector<TransitionId>> readers(net.placeSlots().size());
  for (TransitionId t{0}; t < transitions; ++t) {
    for (const Term& term : net.termsOf(t)) {
      const bool reads = term.kind == TermKind::Input || term.kind == TermKind::Test || term.kind == TermKind::Inhibitor ||
                         (term.kind == TermKind::Output && net.placeSlots()[term.place_slot].capacity != kUnbounded);
      auto& r = readers[term.place_slot];
      if (reads && (r.empty() || r.back() != t)) r.push_back(t);
    }
  }
  std::vector<std::int64_t> delta(net.placeSlots().size(), 0);
  std::vector<bool> in(transitions, false);
  begin_.assign(transitions + 1, 0);
  for (TransitionId t{0}; t < transitions; ++t) {
    begin_[t] = static_cast<std::uint32_t>(list_.size());
    for (const Term& term : net.termsOf(t)) {
      if (term.kind == TermKind::Input) delta[term.place_slot] -= term.weight;
      if (term.kind == TermKind::Output) delta[term.place_slot] += term.weight;
    }
    for (const Term& term : net.termsOf(t)) {
      const PlaceSlotId k = term.place_slot;
      if (delta[k] != 0) {
        for (const TransitionId u : readers[k]) {
          if (!in[u]) in[u] = true, list_.push_back(u);
        }
      }
    }
    for (const Term& term : net.termsOf(t)) delta[term.place_slot] = 0;
    for (auto i = begin_[t]; i < list_.size(); ++i) in[list_[i]] = false;
    if (list_.size() > most) {
      // firings that each touch many transitions (around shared places): not worth it
      std::vector<std::uint32_t>().swap(begin_);
      std::vector<TransitionId>().swap(list_);
      return;
    }
  }
  begin_[transitions] = static_cast<std::uint32_t>(list_.size());
}

std::size_t markEnabled(const Firing& firing, const Candidates& candidates, const std::uint64_t* m,
                        std::vector<bool>& seen, std::vector<TransitionId>& scratch) {
  std::size_t added = 0;
  candidates.find(m, firing, scratch);
  for (TransitionId t : scratch) {
    if (!seen[t] && firing.enabled(t, m)) seen[t] = true, ++added;
  }
  return added;
}

Candidates::Candidates(const Net& net, Way way) : net_(&net), way_(way) {
  const std::size_t places = net.placeSlots().size();
  // forward: the slots a transition takes from or tests; backward: those it puts into
  auto watches = [way](const Term& term) {
    return way == Way::Forward ? term.kind == TermKind::Input || term.kind == TermKind::Test : term.kind == TermKind::Output;
  };
  std::vector<std::uint32_t> takers(places, 0);
  for (const Term& term : net.terms()) {
    if (watches(term)) ++takers[term.place_slot];
  }
  std::vector<std::uint32_t> sentinel(net.transitions().size(), kNone);
  std::vector<std::uint32_t> count(places + 1, 0);
  for (TransitionId t{0}; t < net.transitions().size(); ++t) {
    for (const Term& term : net.termsOf(t)) {
      if (!watches(term)) continue;
      if (sentinel[t] == kNone || takers[term.place_slot] < takers[sentinel[t]]) sentinel[t] = term.place_slot;
    }
    if (sentinel[t] == kNone) {
      always_.push_back(t);
    } else {
      ++count[sentinel[t] + 1];
    }
  }
  for (std::size_t k = 0; k < places; ++k) count[k + 1] += count[k];
  begin_ = count;
  watchers_.resize(count[places]);
  for (TransitionId t{0}; t < net.transitions().size(); ++t) {
    if (sentinel[t] != kNone) watchers_[count[sentinel[t]]++].t = t;
  }
}

void Candidates::use(const Layout& layout) {
  field_at_.assign(layout.words() * 64, 0);
  watched_.assign(layout.words(), 0);
  masks_.resize(layout.width());
  for (std::size_t k = 0; k < layout.width(); ++k) {
    const auto& f = layout.field(k);
    masks_[k] = f.mask << f.shift;
    for (std::uint32_t b = 0; b < layout.bits(k); ++b) field_at_[f.word * 64 + f.shift + b] = static_cast<std::uint32_t>(k);
    if (begin_[k + 1] > begin_[k]) watched_[f.word] |= masks_[k];
  }
  // each watcher's filter (forward only): of the words holding one-bit fields it takes from
  // or tests (each then needs its bit set, ω aside) other than the slot it watches (whose
  // field is known not to be 0), the one with the most such fields
  // (what it costs grows with the terms, not with the words of a marking)
  if (way_ == Way::Backward) return;
  std::vector<std::pair<std::uint32_t, std::uint64_t>> bits;  // (word, a field's bit)
  for (std::size_t k = 0; k < layout.width(); ++k) {
    for (std::uint32_t i = begin_[k]; i < begin_[k + 1]; ++i) {
      Watcher& w = watchers_[i];
      bits.clear();
      for (const Term& term : net_->termsOf(w.t)) {
        const auto& f = layout.field(term.place_slot);
        const bool needed = term.kind == TermKind::Input || term.kind == TermKind::Test;
        if (needed && term.place_slot != k && f.mask == 1 && !f.omega) bits.emplace_back(f.word, std::uint64_t{1} << f.shift);
      }
      std::sort(bits.begin(), bits.end());
      w.word = 0;
      w.bits = 0;
      for (std::size_t a = 0, b = 0; a < bits.size(); a = b) {
        std::uint64_t word = 0;
        for (b = a; b < bits.size() && bits[b].first == bits[a].first; ++b) word |= bits[b].second;
        if (std::popcount(word) > std::popcount(w.bits)) w.word = bits[a].first, w.bits = word;
      }
    }
  }
}

void Candidates::findBackward(const std::uint64_t* m, std::vector<TransitionId>& out) const {
  out.assign(always_.begin(), always_.end());
  for (std::size_t w = 0; w < watched_.size(); ++w) {
    for (std::uint64_t x = m[w] & watched_[w]; x != 0;) {
      const std::uint32_t k = field_at_[w * 64 + static_cast<std::size_t>(std::countr_zero(x))];
      x &= ~masks_[k];
      for (std::uint32_t i = begin_[k]; i < begin_[k + 1]; ++i) out.push_back(watchers_[i].t);
    }
  }
}

void Candidates::find(const std::uint64_t* m, const Firing& firing, std::vector<TransitionId>& out) const {
  out.assign(always_.begin(), always_.end());
  for (std::size_t w = 0; w < watched_.size(); ++w) {
    std::uint64_t x = m[w] & watched_[w];
    while (x != 0) {
      const std::uint32_t k = field_at_[w * 64 + static_cast<std::size_t>(std::countr_zero(x))];
      x &= ~masks_[k];
      for (std::uint32_t i = begin_[k]; i < begin_[k + 1]; ++i) {
        const Watcher& c = watchers_[i];
        if ((m[c.word] & c.bits) == c.bits && firing.ready(c.t, m)) out.push_back(c.t);
      }
    }
  }
}


Plan plan(const Net& net, const ExploreOptions& options) {
  // field sizes from the invariants' bounds (under the search's limits); the others start
  // small and widen when needed
  const std::size_t width = net.placeSlots().size();
  InvariantOptions limits;
  limits.max_candidates = 2'000;
  limits.max_bytes = options.max_bytes;
  limits.deadline = options.deadline;
  const Invariants inv = options.invariants ? *options.invariants : invariants(net, limits);
  // where the invariants leave a slot without a bound (cut short, or none exists), the state
  // equation may still bound it
  std::vector<bool> open(width, false);
  bool any = false;
  for (std::size_t k = 0; k < width; ++k) {
    open[k] = inv.bound[k] < 0 && net.placeSlots()[k].capacity == kUnbounded;
    any = any || open[k];
  }
  std::vector<std::int64_t> lp(width, -1);
  if (any) lp = stateEquationBounds(net, open, limits);
  Plan p;
  p.bits.assign(width, 1);
  p.omega.assign(width, false);
  p.accel.assign(width, false);
  p.m0.assign(width, 0);
  for (std::size_t k = 0; k < width; ++k) {
    const PlaceSlot& ps = net.placeSlots()[k];
    std::int64_t bound = inv.bound[k];
    if (ps.capacity != kUnbounded && (bound < 0 || ps.capacity < bound)) bound = ps.capacity;
    if (lp[k] >= 0 && (bound < 0 || lp[k] < bound)) bound = lp[k];
    p.m0[k] = ps.initial;
    if (bound >= 0) {
      p.bits[k] = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::bit_width(static_cast<std::uint64_t>(bound))));
    } else {
      p.omega[k] = p.accel[k] = p.cover = true;
      std::uint32_t b = 4;
      while (b < kMaxBits && static_cast<std::uint64_t>(ps.initial) + 1 >= (std::uint64_t{1} << b)) b *= 2;
      p.bits[k] = b;
    }
    if (p.bits[k] > kMaxBits || static_cast<std::uint64_t>(ps.initial) > (std::uint64_t{1} << kMaxBits) - 2) {
      p.overflow = true;
    }
  }
  // only where the firing sequence surely repeats: no inhibitor reads the slot
  for (const Term& term : net.terms()) {
    if (term.kind == TermKind::Inhibitor) p.accel[term.place_slot] = false;
  }
  if (!p.cover && !p.overflow) p.derived = derivable(inv.p, p.bits, p.m0);
  return p;
}

Layout Plan::layout() const {
  if (derived.empty()) return Layout::omegaOrBounded(bits, omega);
  std::vector<bool> left_out(bits.size(), false);
  for (const Derived& d : derived) left_out[d.slot] = true;
  std::vector<std::uint32_t> order;
  for (std::size_t k = 0; k < bits.size(); ++k) {
    if (!left_out[k]) order.push_back(static_cast<std::uint32_t>(k));
  }
  const std::size_t kept = order.size();
  for (const Derived& d : derived) order.push_back(d.slot);
  std::vector<bool> bounded = omega;
  bounded.flip();
  return Layout(bits, omega, bounded, order, kept);
}

std::vector<Derived> derivable(const std::vector<Invariant>& p, const std::vector<std::uint32_t>& bits,
                               const std::vector<std::int64_t>& m0) {
  std::vector<std::size_t> order(p.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a].weights.size() < p[b].weights.size(); });
  // a slot in the support of an invariant chosen is never worked out by a later one: each
  // rule then reads only slots kept or worked out before it
  std::vector<bool> used(bits.size(), false);
  std::vector<Derived> out;
  for (const std::size_t i : order) {
    const auto& w = p[i].weights;
    std::size_t best = w.size();
    std::int64_t constant = 0;
    bool fits = true;
    for (std::size_t j = 0; j < w.size(); ++j) {
      const auto [slot, weight] = w[j];
      std::int64_t term = 0;
      fits = fits && !__builtin_mul_overflow(weight, m0[slot], &term) && !__builtin_add_overflow(constant, term, &constant);
      if (used[slot]) continue;
      if (best == w.size() || bits[slot] > bits[w[best].first] || (bits[slot] == bits[w[best].first] && weight < w[best].second)) {
        best = j;
      }
    }
    if (best == w.size() || !fits) continue;
    Derived d{w[best].first, constant, w[best].second, {}};
    for (std::size_t j = 0; j < w.size(); ++j) {
      if (j != best) d.terms.push_back(w[j]);
      used[w[j].first] = true;
    }
    out.push_back(std::move(d));
  }
  return out;
}

Observed::Observed(const Layout& layout)
    : low(layout.width(), kW), high(layout.width(), 0), any(layout.words(), 0), all(layout.words(), ~std::uint64_t{0}) {
  // a word whose fields all hold one token at most is noted as a whole: its bits OR-ed and
  // AND-ed over the markings give each field's highest and lowest count
  single.assign(layout.words(), true);
  for (std::size_t k = 0; k < layout.width(); ++k) {
    if (layout.bits(k) != 1 || layout.field(k).omega) single[layout.field(k).word] = false;
  }
  for (std::size_t k = 0; k < layout.width(); ++k) {
    if (!single[layout.field(k).word]) fields.push_back(static_cast<std::uint32_t>(k));
  }
}

std::int64_t Observed::note(const Layout& layout, const std::uint64_t* m) {
  std::int64_t total = 0;
  for (std::size_t w = 0; w < any.size(); ++w) {
    if (!single[w]) continue;
    any[w] |= m[w];
    all[w] &= m[w];
    total += std::popcount(m[w]);
  }
  for (const std::uint32_t k : fields) {
    const std::int64_t v = layout.value(m, k);
    low[k] = std::min(low[k], v);
    high[k] = std::max(high[k], v);
    if (v != kW) total += v;
  }
  max_marking = std::max(max_marking, total);
  return total;
}

void Observed::noteChange(const Layout& layout, const std::uint64_t* m, std::span<const Term> terms, std::int64_t total) {
  for (const Term& term : terms) {
    if (term.kind != TermKind::Input && term.kind != TermKind::Output) continue;
    const std::size_t k = term.place_slot;
    const auto& f = layout.field(k);
    if (single[f.word]) {
      const std::uint64_t bit = std::uint64_t{1} << f.shift;
      if ((m[f.word] & bit) != 0) {
        any[f.word] |= bit;
      } else {
        all[f.word] &= ~bit;
      }
      continue;
    }
    const std::int64_t v = layout.value(m, k);
    low[k] = std::min(low[k], v);
    high[k] = std::max(high[k], v);
  }
  max_marking = std::max(max_marking, total);
}

void Observed::settle(const Layout& layout) {
  for (std::size_t k = 0; k < layout.width(); ++k) {
    const auto& f = layout.field(k);
    if (!single[f.word]) continue;
    high[k] = static_cast<std::int64_t>((any[f.word] >> f.shift) & 1u);
    low[k] = static_cast<std::int64_t>((all[f.word] >> f.shift) & 1u);
  }
}

void Observed::relayout(const Layout& before, const Layout& after) {
  settle(before);
  Observed next(after);
  next.low = std::move(low);
  next.high = std::move(high);
  next.max_marking = max_marking;
  for (std::size_t k = 0; k < after.width(); ++k) {
    const auto& f = after.field(k);
    if (!next.single[f.word]) continue;
    if (next.high[k] > 0) next.any[f.word] |= std::uint64_t{1} << f.shift;
    if (next.low[k] == 0) next.all[f.word] &= ~(std::uint64_t{1} << f.shift);
  }
  *this = std::move(next);
}

void Observed::merge(const Observed& other) {
  for (std::size_t w = 0; w < any.size(); ++w) any[w] |= other.any[w], all[w] &= other.all[w];
  for (std::size_t k = 0; k < low.size(); ++k) {
    low[k] = std::min(low[k], other.low[k]);
    high[k] = std::max(high[k], other.high[k]);
  }
  max_marking = std::max(max_marking, other.max_marking);
}

void summarise(const Net& net, const Observed& seen, StateSpace& out) {
  out.quasi_live = std::all_of(out.fired.begin(), out.fired.end(), [](bool b) { return b; });
  const auto places = net.places();
  out.place_bound.assign(places.size(), 0);
  for (PlaceId p{0}; p < places.size(); ++p) {
    bool constant = true;
    for (auto ps = places[p].slots_begin; ps < places[p].slots_end; ++ps) {
      if (seen.high[ps] == kW) {
        out.place_bound[p] = kOmega;
      } else if (out.place_bound[p] != kOmega) {
        out.place_bound[p] += seen.high[ps];
      }
      constant = constant && seen.low[ps] == seen.high[ps];
    }
    if (constant) out.constant_places.push_back(p);
    if (out.place_bound[p] == kOmega) {
      out.bounded = false;
      out.unbounded_places.push_back(p);
    } else {
      out.max_place = std::max(out.max_place, out.place_bound[p]);
    }
  }
  out.max_marking = seen.max_marking;
  out.one_safe = out.bounded && out.max_place <= 1;
  out.decided = out.complete && out.bounded;
  if (!out.decided) out.live = out.reversible = false;
}

StateSpace overflowAnswer(const Net& net) {
  StateSpace out;
  out.complete = false;
  out.stop = ExploreStop::Overflow;
  out.decided = out.live = out.reversible = false;
  out.fired.assign(net.transitions().size(), false);
  out.quasi_live = net.transitions().empty();
  return out;
}

}  // namespace gdpn::net::detail
