// The state space of a coloured net over markings with values (coloured_search.h).
//
// A marking is a sorted list of entries (slot, count): a slot is a count slot of the net (its
// place slot's index) or a (value slot, value) pair, numbered as the search first meets it.
// Stored, a marking is the varint bytes of its entries (slot as the difference from the one
// before, then count). A transition's enabled bindings depend only on what its input, test and
// inhibitor arcs' place slots hold: per transition, that part of a marking is the key of a
// cache of the bindings it enables, each an "instance" (the transition under one binding, as
// an unfolding would have made it) whose changes to the marking are a sorted list of entries.
// After the first few markings, most expansions are hash lookups and merges of sorted lists.

#include "gdpn/net/coloured_search.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

#include "detail/marking_store.h"
#include "gdpn/core/assert.h"
#include "gdpn/net/inscription.h"
#include "gdpn/net/invariants.h"

namespace gdpn::net {
namespace {
namespace native {

using detail::Chunked;
using StateId = std::uint32_t;
constexpr StateId kNoState = 0xffffffffu;
/// The most copies of one value (or tokens in a count slot) a marking may hold.
constexpr std::uint64_t kMostCount = 0xfffffffeu;
/// The most states a search stores (ids are 32-bit; one expansion adds a few more).
constexpr std::uint64_t kMostStates = 0x7ffffff0u;
/// The most bytes a stored marking may take (it lies in one chunk of the store): about half a
/// million distinct values held at once.
constexpr std::uint32_t kMostBytes = std::uint32_t{1} << 20;

struct Entry {
  std::uint32_t slot = 0;
  std::uint32_t count = 0;
};

struct Change {
  std::uint32_t slot = 0;
  std::int64_t delta = 0;
};

std::uint64_t mix(std::uint64_t h, std::uint64_t x) {
  h = (h ^ x) * 0x9e3779b97f4a7c15ULL;
  return h ^ (h >> 31);
}

std::uint64_t finish(std::uint64_t h) {
  h *= 0xbf58476d1ce4e5b9ULL;
  return h ^ (h >> 29);
}

void putVarint(std::vector<std::uint8_t>& out, std::uint32_t x) {
  while (x >= 0x80) {
    out.push_back(static_cast<std::uint8_t>(x | 0x80));
    x >>= 7;
  }
  out.push_back(static_cast<std::uint8_t>(x));
}

std::uint32_t getVarint(const std::uint8_t*& p) {
  std::uint32_t x = 0;
  for (unsigned shift = 0;; shift += 7) {
    const std::uint8_t b = *p++;
    x |= static_cast<std::uint32_t>(b & 0x7f) << shift;
    if ((b & 0x80) == 0) return x;
  }
}

/// One transition under one binding.
struct Instance {
  TransitionId t{0};
  std::uint32_t binding = 0;           // into Search::bindings_
  std::uint32_t changes_begin = 0;     // into Search::changes_, sorted by slot
  std::uint32_t changes_end = 0;
  std::uint32_t rooms_begin = 0;       // into Search::rooms_
  std::uint32_t rooms_end = 0;
  bool fired = false;
  bool too_big = false;  // it changes a count by more than kMostCount
};

/// A place slot with a capacity that an instance puts into: its tokens must be at most `most`
/// before the instance fires.
struct Room {
  PlaceSlotId ps{0};
  std::int64_t most = 0;
};

/// Per transition: what its enabling reads, and the cache of its enabled instances.
struct TransitionPlan {
  bool coloured = false;
  std::vector<PlaceSlotId> reads;  // input, test and inhibitor place slots, sorted, distinct
  std::uint32_t plain = 0;         // an uncoloured transition's one instance
  // the cache: per key (the read part of a marking), the instances it enables
  struct Cached {
    std::uint64_t hash = 0;
    std::uint32_t key_begin = 0, key_end = 0;    // into keys
    std::uint32_t list_begin = 0, list_end = 0;  // into lists
  };
  std::vector<Cached> table;  // open addressing; list_end == kNoState marks an empty cell
  std::size_t used = 0;
  std::vector<std::uint32_t> keys;
  std::vector<std::uint32_t> lists;
};

class Search {
 public:
  Search(const Net& net, const ExploreOptions& options) : net_(net), options_(options), c_(*net.colouring()) {}

  StateSpace run();

 private:
  // ---- slots and values
  std::uint32_t valueId(const Value& v) {
    const auto [it, added] = value_ids_.try_emplace(v, static_cast<std::uint32_t>(values_.size()));
    if (added) values_.push_back(v);
    return it->second;
  }
  std::uint32_t slotOf(PlaceSlotId ps, const Value& v) {
    const std::uint64_t key = (std::uint64_t{ps} << 32) | valueId(v);
    const auto [it, added] = slot_ids_.try_emplace(key, static_cast<std::uint32_t>(slot_ps_.size()));
    if (added) {
      slot_ps_.push_back(ps);
      slot_place_.push_back(net_.placeSlots()[ps].place);
      slot_value_.push_back(static_cast<std::uint32_t>(key));
    }
    return it->second;
  }
  bool isValueSlot(PlaceSlotId ps) const { return c_.slot_set[ps] >= 0; }

  // ---- markings
  /// A marking made ready to store: its bytes in succ_bytes_, its hash.
  struct Encoded {
    std::uint64_t hash = 0;
    std::uint32_t begin = 0, length = 0;
    std::uint32_t instance = 0;
  };
  /// Encodes `entries` into succ_bytes_.
  Encoded encode(const std::vector<Entry>& entries);
  /// Encodes `entries` changed by instance `in`; false when a count passes kMostCount.
  bool encodeFired(const std::vector<Entry>& entries, const Instance& in, Encoded& out);
  /// Room in the table for `more` states more.
  void reserve(std::size_t more);
  /// Stores the marking `e` as a new state, or finds it; the state and whether it is new.
  std::pair<StateId, bool> store(const Encoded& e);
  std::size_t cell(std::uint64_t hash) const { return static_cast<std::size_t>(hash >> 32) & (table_.size() - 1); }
  void decode(StateId s, std::vector<Entry>& out) const;
  /// Reads the entries of the current marking into the per-place-slot views.
  void view(const std::vector<Entry>& entries);
  void clearView();

  // ---- enabling
  void plan();
  /// The instances of `t` enabled in the viewed marking (by its read part; room not checked).
  void instancesOf(TransitionId t, std::vector<std::uint32_t>& out);
  void computeInstances(TransitionId t, std::vector<std::uint32_t>& out);
  std::uint32_t instance(TransitionId t, const Binding& b, const std::vector<Multiset>* arcs);
  bool countTermsHold(TransitionId t) const;
  bool hasRoom(const Instance& in) const {
    for (std::uint32_t i = in.rooms_begin; i < in.rooms_end; ++i) {
      if (total_[rooms_[i].ps] > rooms_[i].most) return false;
    }
    return true;
  }

  // ---- after the search
  void components(StateSpace& out);
  std::uint64_t bytes() const;

  const Net& net_;
  const ExploreOptions& options_;
  const Colouring& c_;

  std::map<Value, std::uint32_t> value_ids_;
  std::vector<Value> values_;
  std::unordered_map<std::uint64_t, std::uint32_t> slot_ids_;
  std::vector<PlaceSlotId> slot_ps_;          // per slot: its place slot
  std::vector<PlaceId> slot_place_;           // per slot: its place
  std::vector<std::uint32_t> slot_value_;     // per slot: its value (value slots)

  std::vector<TransitionPlan> plans_;
  std::vector<Instance> instances_;
  std::map<std::pair<TransitionId, Binding>, std::uint32_t> instance_ids_;
  std::vector<Binding> bindings_;
  std::vector<Change> changes_;
  std::vector<Room> rooms_;

  // the states: their bytes, and per state where they lie (offset << 24 | length); the table,
  // open addressing, each cell the upper half of a state's hash (its cell's index too) and the
  // state, kEmpty where none
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  Chunked<std::uint8_t, 20> bytes_;
  Chunked<std::uint64_t> where_;
  std::vector<std::uint64_t, core::LargeAllocator<std::uint64_t>> table_;
  std::size_t states_ = 0;
  // the successors of the state expanded, encoded
  std::vector<std::uint8_t> succ_bytes_;
  std::vector<Encoded> succ_;

  // the graph: per state where its edges begin; per edge its target and instance
  Chunked<std::uint64_t> edge_begin_;
  Chunked<StateId> edge_to_;
  // which transitions each edge is of, for the liveness pass: per state a bit per transition
  // where the net has at most 64, else per edge its instance
  bool masks_ = false;
  Chunked<std::uint64_t> enabled_mask_;
  Chunked<std::uint32_t> edge_instance_;
  Chunked<StateId> parent_;           // per state: the state it was first reached from
  Chunked<std::uint32_t> parent_via_;  // and by which instance

  // the viewed marking
  std::vector<std::int64_t> count_;            // per place slot: its count (count slots)
  std::vector<std::int64_t> total_;            // per place slot: its tokens
  std::vector<std::vector<Entry>> held_;       // per value slot: its entries
  std::vector<PlaceSlotId> touched_;
  std::vector<std::int64_t> place_tokens_;     // per place: its tokens
  std::vector<PlaceId> touched_places_;
  std::vector<std::uint32_t> key_;
};

void Search::plan() {
  const auto slots = net_.placeSlots().size();
  count_.assign(slots, 0);
  total_.assign(slots, 0);
  held_.resize(slots);
  place_tokens_.assign(net_.places().size(), 0);
  plans_.resize(net_.transitions().size());
  for (const TransitionId t : net_.transitionIds()) {
    TransitionPlan& p = plans_[t];
    p.coloured = c_.of(t) != nullptr;
    for (const Term& term : net_.termsOf(t)) {
      if (term.kind == TermKind::Input || term.kind == TermKind::Test || term.kind == TermKind::Inhibitor) {
        p.reads.push_back(term.place_slot);
      }
    }
    std::sort(p.reads.begin(), p.reads.end());
    p.reads.erase(std::unique(p.reads.begin(), p.reads.end()), p.reads.end());
    if (!p.coloured) p.plain = instance(t, {}, nullptr);
    p.table.assign(16, TransitionPlan::Cached{0, 0, 0, 0, kNoState});
  }
}

bool Search::countTermsHold(TransitionId t) const {
  const Transition& tr = net_.transitions()[t];
  for (std::uint32_t i = tr.terms_begin; i < tr.terms_end; ++i) {
    const Term& term = net_.terms()[i];
    if (isValueSlot(term.place_slot)) continue;  // the binding search's
    const std::int64_t n = count_[term.place_slot];
    switch (term.kind) {
      case TermKind::Input:
      case TermKind::Test:
        if (n < term.weight) return false;
        break;
      case TermKind::Inhibitor:
        if (n >= term.weight) return false;
        break;
      case TermKind::Output:
      case TermKind::Condition: break;  // room per instance; sensor conditions are free
    }
  }
  return true;
}

std::uint32_t Search::instance(TransitionId t, const Binding& b, const std::vector<Multiset>* arcs) {
  const auto [it, added] = instance_ids_.try_emplace({t, b}, static_cast<std::uint32_t>(instances_.size()));
  if (!added) return it->second;
  Instance in;
  in.t = t;
  in.binding = static_cast<std::uint32_t>(bindings_.size());
  bindings_.push_back(b);
  // the changes, and per place slot what the instance takes and puts
  std::map<std::uint32_t, std::int64_t> delta;
  std::map<PlaceSlotId, std::pair<std::int64_t, std::int64_t>> take_put;
  const Transition& tr = net_.transitions()[t];
  std::vector<bool> inscribed(tr.terms_end - tr.terms_begin, false);  // by term, from the transition's first
  if (arcs) {
    const auto k = static_cast<std::size_t>(c_.of_transition[t]);
    const auto& ti = c_.transitions[k];
    for (std::size_t a = 0; a < ti.arcs.size(); ++a) {
      const TermId term_id = c_.arc_terms[k][a];
      inscribed[term_id - tr.terms_begin] = true;
      const PlaceSlotId ps = net_.terms()[term_id].place_slot;
      const ArcRole role = ti.arcs[a].role;
      if (role != ArcRole::Take && role != ArcRole::Put) continue;
      for (const auto& [v, n] : (*arcs)[a]) {
        if (n == 0) continue;
        delta[slotOf(ps, v)] += role == ArcRole::Take ? -n : n;
        (role == ArcRole::Take ? take_put[ps].first : take_put[ps].second) += n;
      }
    }
  }
  for (std::uint32_t i = tr.terms_begin; i < tr.terms_end; ++i) {
    const Term& term = net_.terms()[i];
    if (inscribed[i - tr.terms_begin] || (term.kind != TermKind::Input && term.kind != TermKind::Output)) continue;
    delta[term.place_slot] += term.kind == TermKind::Input ? -term.weight : term.weight;
    (term.kind == TermKind::Input ? take_put[term.place_slot].first : take_put[term.place_slot].second) += term.weight;
  }
  in.changes_begin = static_cast<std::uint32_t>(changes_.size());
  for (const auto& [slot, d] : delta) {
    if (d != 0) changes_.push_back({slot, d});
    // no count may pass kMostCount: such an instance stops the search where it fires
    in.too_big = in.too_big || d > static_cast<std::int64_t>(kMostCount) || -d > static_cast<std::int64_t>(kMostCount);
  }
  in.changes_end = static_cast<std::uint32_t>(changes_.size());
  in.rooms_begin = static_cast<std::uint32_t>(rooms_.size());
  for (const auto& [ps, tp] : take_put) {
    const std::int64_t cap = net_.placeSlots()[ps].capacity;
    if (cap == kUnbounded || tp.second == 0) continue;
    std::int64_t most = 0;
    if (__builtin_add_overflow(cap, tp.first, &most)) most = kUnbounded;
    rooms_.push_back({ps, most - tp.second});
  }
  in.rooms_end = static_cast<std::uint32_t>(rooms_.size());
  instances_.push_back(in);
  return it->second;
}

void Search::computeInstances(TransitionId t, std::vector<std::uint32_t>& out) {
  if (!countTermsHold(t)) return;
  const auto k = static_cast<std::size_t>(c_.of_transition[t]);
  const auto& ti = c_.transitions[k];
  std::map<PlaceSlotId, Multiset> held;
  for (std::size_t a = 0; a < ti.arcs.size(); ++a) {
    const PlaceSlotId ps = net_.terms()[c_.arc_terms[k][a]].place_slot;
    if (held.count(ps)) continue;
    Multiset& m = held[ps];
    for (const Entry& e : held_[ps]) m.emplace(values_[slot_value_[e.slot]], e.count);
  }
  const auto marking = [&](std::size_t a) -> const Multiset& {
    return held.at(net_.terms()[c_.arc_terms[k][a]].place_slot);
  };
  for (const BoundOccurrence& o : enabledBindings(ti, c_.colours, marking)) out.push_back(instance(t, o.binding, &o.arcs));
}

void Search::instancesOf(TransitionId t, std::vector<std::uint32_t>& out) {
  TransitionPlan& p = plans_[t];
  if (!p.coloured) {
    if (countTermsHold(t)) out.push_back(p.plain);
    return;
  }
  // the key: per place slot read, its count, or its entries after their number
  key_.clear();
  std::uint64_t h = t;
  for (const PlaceSlotId ps : p.reads) {
    if (!isValueSlot(ps)) {
      key_.push_back(static_cast<std::uint32_t>(count_[ps]));
      continue;
    }
    key_.push_back(static_cast<std::uint32_t>(held_[ps].size()));
    for (const Entry& e : held_[ps]) {
      key_.push_back(e.slot);
      key_.push_back(e.count);
    }
  }
  for (const std::uint32_t x : key_) h = mix(h, x);
  h = finish(h);
  const std::size_t mask = p.table.size() - 1;
  std::size_t i = h & mask;
  const std::size_t n = key_.size();
  while (p.table[i].list_end != kNoState) {
    const auto& c = p.table[i];
    if (c.hash == h && c.key_end - c.key_begin == n &&
        std::equal(key_.begin(), key_.end(), p.keys.begin() + c.key_begin)) {
      out.insert(out.end(), p.lists.begin() + c.list_begin, p.lists.begin() + c.list_end);
      return;
    }
    i = (i + 1) & mask;
  }
  const std::size_t first = out.size();
  computeInstances(t, out);
  TransitionPlan::Cached c;
  c.hash = h;
  c.key_begin = static_cast<std::uint32_t>(p.keys.size());
  p.keys.insert(p.keys.end(), key_.begin(), key_.end());
  c.key_end = static_cast<std::uint32_t>(p.keys.size());
  c.list_begin = static_cast<std::uint32_t>(p.lists.size());
  p.lists.insert(p.lists.end(), out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
  c.list_end = static_cast<std::uint32_t>(p.lists.size());
  p.table[i] = c;
  if (++p.used * 2 > p.table.size()) {
    std::vector<TransitionPlan::Cached> old(p.table.size() * 2, TransitionPlan::Cached{0, 0, 0, 0, kNoState});
    old.swap(p.table);
    const std::size_t m = p.table.size() - 1;
    for (const auto& x : old) {
      if (x.list_end == kNoState) continue;
      std::size_t j = x.hash & m;
      while (p.table[j].list_end != kNoState) j = (j + 1) & m;
      p.table[j] = x;
    }
  }
}

void Search::view(const std::vector<Entry>& entries) {
  for (const Entry& e : entries) {
    const PlaceSlotId ps = slot_ps_[e.slot];
    if (total_[ps] == 0 && held_[ps].empty()) touched_.push_back(ps);
    total_[ps] += e.count;
    if (isValueSlot(ps)) held_[ps].push_back(e);
    else count_[ps] = e.count;
  }
}

void Search::clearView() {
  for (const PlaceSlotId ps : touched_) {
    total_[ps] = 0;
    count_[ps] = 0;
    held_[ps].clear();
  }
  touched_.clear();
}

Search::Encoded Search::encode(const std::vector<Entry>& entries) {
  Encoded e;
  e.begin = static_cast<std::uint32_t>(succ_bytes_.size());
  std::uint32_t last = 0;
  std::uint64_t h = 0x243f6a8885a308d3ULL;
  for (const Entry& x : entries) {
    putVarint(succ_bytes_, x.slot - last);
    putVarint(succ_bytes_, x.count);
    h = mix(h, (std::uint64_t{x.slot} << 32) | x.count);
    last = x.slot;
  }
  e.hash = finish(h);
  e.length = static_cast<std::uint32_t>(succ_bytes_.size() - e.begin);
  return e;
}

bool Search::encodeFired(const std::vector<Entry>& entries, const Instance& in, Encoded& e) {
  // the sorted entries and the sorted changes merged, written as they come
  if (in.too_big) return false;
  e.begin = static_cast<std::uint32_t>(succ_bytes_.size());
  succ_bytes_.resize(e.begin + 10 * (entries.size() + (in.changes_end - in.changes_begin)));
  std::uint8_t* out = succ_bytes_.data() + e.begin;
  std::uint32_t last = 0;
  std::uint64_t h = 0x243f6a8885a308d3ULL;
  auto put = [&](std::uint32_t x) {
    while (x >= 0x80) {
      *out++ = static_cast<std::uint8_t>(x | 0x80);
      x >>= 7;
    }
    *out++ = static_cast<std::uint8_t>(x);
  };
  auto emit = [&](std::uint32_t slot, std::uint32_t count) {
    put(slot - last);
    put(count);
    h = mix(h, (std::uint64_t{slot} << 32) | count);
    last = slot;
  };
  std::size_t i = 0;
  std::uint32_t k = in.changes_begin;
  const std::size_t n = entries.size();
  while (i < n || k < in.changes_end) {
    if (k == in.changes_end || (i < n && entries[i].slot < changes_[k].slot)) {
      emit(entries[i].slot, entries[i].count);
      ++i;
      continue;
    }
    const Change& c = changes_[k++];
    std::int64_t count = c.delta;
    if (i < n && entries[i].slot == c.slot) count += entries[i++].count;
    GDPN_ASSERT(count >= 0, "an enabled instance takes no more than a marking holds");
    if (static_cast<std::uint64_t>(count) > kMostCount) return false;
    if (count > 0) emit(c.slot, static_cast<std::uint32_t>(count));
  }
  e.hash = finish(h);
  e.length = static_cast<std::uint32_t>(out - (succ_bytes_.data() + e.begin));
  succ_bytes_.resize(e.begin + e.length);
  return true;
}

void Search::reserve(std::size_t more) {
  if ((states_ + more) * 2 <= table_.size()) return;
  std::size_t size = std::max<std::size_t>(1024, table_.size());
  while ((states_ + more) * 2 > size) size *= 2;
  std::vector<std::uint64_t, core::LargeAllocator<std::uint64_t>> bigger(size, kEmpty);
  const std::size_t mask = size - 1;
  for (const std::uint64_t x : table_) {
    if (x == kEmpty) continue;
    std::size_t j = static_cast<std::size_t>(x >> 32) & mask;
    while (bigger[j] != kEmpty) j = (j + 1) & mask;
    bigger[j] = x;
  }
  table_.swap(bigger);
}

std::pair<StateId, bool> Search::store(const Encoded& e) {
  const std::uint8_t* bytes = succ_bytes_.data() + e.begin;
  const std::uint64_t tag = e.hash & 0xffffffff00000000ULL;
  const std::size_t mask = table_.size() - 1;
  std::size_t j = cell(e.hash);
  for (; table_[j] != kEmpty; j = (j + 1) & mask) {
    if ((table_[j] & 0xffffffff00000000ULL) != tag) continue;
    const auto s = static_cast<StateId>(table_[j]);
    const std::uint64_t w = where_[s];
    if ((w & 0xffffff) == e.length && (e.length == 0 || std::memcmp(bytes_.at(w >> 24), bytes, e.length) == 0)) {
      return {s, false};
    }
  }
  const auto s = static_cast<StateId>(states_++);
  table_[j] = tag | s;
  // a state's bytes lie in one chunk
  const std::uint64_t at = e.length == 0 ? 0 : bytes_.appendRun(e.length, 0);
  if (e.length != 0) std::memcpy(bytes_.at(at), bytes, e.length);
  where_.push(at << 24 | e.length);
  return {s, true};
}

void Search::decode(StateId s, std::vector<Entry>& out) const {
  out.clear();
  const std::uint64_t w = where_[s];
  if ((w & 0xffffff) == 0) return;
  const std::uint8_t* p = bytes_.at(w >> 24);
  const std::uint8_t* end = p + (w & 0xffffff);
  std::uint32_t last = 0;
  while (p < end) {
    last += getVarint(p);
    out.push_back({last, getVarint(p)});
  }
}

std::uint64_t Search::bytes() const {
  std::uint64_t caches = 0;
  for (const TransitionPlan& p : plans_) {
    caches += p.table.capacity() * sizeof(TransitionPlan::Cached) + (p.keys.capacity() + p.lists.capacity()) * 4;
  }
  // the instances (a binding's values and its map entry about 96 bytes more) and the slots
  caches += instances_.capacity() * (sizeof(Instance) + 96) + changes_.capacity() * sizeof(Change) +
            slot_ps_.capacity() * 48;
  return caches + bytes_.bytes() + where_.bytes() + table_.capacity() * 8 + succ_bytes_.capacity() + edge_begin_.bytes() +
         edge_to_.bytes() + edge_instance_.bytes() + enabled_mask_.bytes() + parent_.bytes() + parent_via_.bytes();
}

StateSpace Search::run() {
  StateSpace out;
  // slots: the count slots first, by their place slot's index; then (value slot, value) pairs
  for (const PlaceSlotId ps : net_.placeSlotIds()) {
    slot_ps_.push_back(ps);
    slot_place_.push_back(net_.placeSlots()[ps].place);
    slot_value_.push_back(0);
  }
  plan();
  std::vector<Entry> entries;
  for (const PlaceSlotId ps : net_.placeSlotIds()) {
    if (isValueSlot(ps)) {
      for (const auto& [v, n] : c_.initial[ps]) {
        if (n > 0) entries.push_back({slotOf(ps, v), static_cast<std::uint32_t>(std::min<std::int64_t>(n, kMostCount))});
      }
    } else if (net_.placeSlots()[ps].initial > 0) {
      entries.push_back({static_cast<std::uint32_t>(ps),
                         static_cast<std::uint32_t>(std::min<std::int64_t>(net_.placeSlots()[ps].initial, kMostCount))});
    }
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.slot < b.slot; });
  succ_bytes_.clear();
  reserve(1);
  store(encode(entries));
  parent_.push(kNoState);
  parent_via_.push(0);

  const std::size_t transitions = net_.transitions().size();
  masks_ = transitions <= 64;
  std::vector<bool> fired(transitions, false);
  std::vector<bool> changed(net_.places().size(), false);
  out.place_bound.assign(net_.places().size(), 0);
  std::vector<std::uint32_t> enabled;
  StateId first_dead = kNoState;
  std::uint64_t edges = 0;
  std::size_t next_look = 4096;

  for (StateId v = 0; v < states_; ++v) {
    decode(v, entries);
    view(entries);
    // figures of the marking
    std::int64_t in_marking = 0;
    for (const Entry& e : entries) {
      const PlaceId p = slot_place_[e.slot];
      if (place_tokens_[p] == 0) touched_places_.push_back(p);
      place_tokens_[p] += e.count;
      in_marking += e.count;
      out.max_value_count = std::max<std::int64_t>(out.max_value_count, e.count);
    }
    for (const PlaceId p : touched_places_) {
      out.place_bound[p] = std::max(out.place_bound[p], place_tokens_[p]);
      place_tokens_[p] = 0;
    }
    touched_places_.clear();
    out.max_marking = std::max(out.max_marking, in_marking);

    enabled.clear();
    for (const TransitionId t : net_.transitionIds()) instancesOf(t, enabled);
    edge_begin_.push(edges);
    // the successors encoded and their cells fetched first, then looked up
    succ_bytes_.clear();
    succ_.clear();
    for (const std::uint32_t i : enabled) {
      const Instance& in = instances_[i];
      if (!hasRoom(in)) continue;
      Encoded e;
      if (!encodeFired(entries, in, e)) {
        out.stop = ExploreStop::Overflow;
        break;
      }
      if (e.length > kMostBytes) {
        out.stop = ExploreStop::Overflow;
        break;
      }
      e.instance = i;
      succ_.push_back(e);
    }
    reserve(succ_.size());
    for (const Encoded& e : succ_) __builtin_prefetch(&table_[cell(e.hash)]);
    std::uint64_t mask = 0;
    for (const Encoded& e : succ_) {
      Instance& in = instances_[e.instance];
      const auto [w, added] = store(e);
      if (added) {
        parent_.push(v);
        parent_via_.push(e.instance);
      }
      edge_to_.push(w);
      if (masks_) mask |= std::uint64_t{1} << in.t;
      else edge_instance_.push(e.instance);
      ++edges;
      fired[in.t] = true;
      if (!in.fired) {
        in.fired = true;
        for (std::uint32_t k = in.changes_begin; k < in.changes_end; ++k) {
          changed[slot_place_[changes_[k].slot]] = true;
        }
      }
    }
    if (masks_) enabled_mask_.push(mask);
    clearView();
    if (out.stop != ExploreStop::Done) break;
    if (edge_begin_[v] == edges) {
      ++out.dead_markings;
      if (first_dead == kNoState) first_dead = v;
    }
    if (states_ > std::min<std::uint64_t>(options_.max_states, kMostStates)) {
      out.stop = ExploreStop::MaxStates;
      break;
    }
    if (states_ >= next_look || v + 1 >= next_look) {
      next_look = std::max<std::size_t>(states_, v + 1) + 4096;
      const std::uint64_t held = bytes();
      out.peak_bytes = std::max(out.peak_bytes, held);
      if (options_.progress) options_.progress({states_, edges, held});
      if (options_.max_bytes != 0 && held > options_.max_bytes) {
        out.stop = ExploreStop::MaxMemory;
        break;
      }
      if (options_.deadline && std::chrono::steady_clock::now() > *options_.deadline) {
        out.stop = ExploreStop::TimeLimit;
        break;
      }
    }
  }
  out.peak_bytes = std::max(out.peak_bytes, bytes());
  out.complete = out.stop == ExploreStop::Done;
  out.states = states_;
  out.edges = edges;
  out.bindings = 0;
  for (const Instance& in : instances_) out.bindings += in.fired && c_.of(in.t) ? 1u : 0u;
  out.deadlock = first_dead != kNoState;
  if (out.deadlock) {
    for (StateId s = first_dead; parent_[s] != kNoState; s = parent_[s]) {
      const Instance& in = instances_[parent_via_[s]];
      out.deadlock_path.push_back(in.t);
      std::string text;
      if (const auto* ti = c_.of(in.t)) {
        const Binding& b = bindings_[in.binding];
        for (std::size_t k = 0; k < b.size() && k < ti->variables.size(); ++k) {
          text += (k ? ", " : "") + ti->variables[k] + "=" + c_.colours.text(ti->sets[k], b[k]);
        }
      }
      out.deadlock_bindings.push_back(std::move(text));
    }
    std::reverse(out.deadlock_path.begin(), out.deadlock_path.end());
    // the dead marking, per place slot
    std::vector<Entry> dead;
    decode(first_dead, dead);
    std::map<PlaceSlotId, Multiset> held;
    std::map<PlaceSlotId, std::int64_t> counted;
    for (const Entry& e : dead) {
      const PlaceSlotId ps = slot_ps_[e.slot];
      if (isValueSlot(ps)) held[ps].emplace(values_[slot_value_[e.slot]], e.count);
      else counted[ps] = e.count;
    }
    for (const PlaceSlotId ps : net_.placeSlotIds()) {
      if (held.count(ps)) {
        out.dead_marking.push_back(placeSlotName(net_, ps) + " = " +
                                   c_.colours.text(static_cast<ColourId>(c_.slot_set[ps]), held[ps]));
      } else if (counted.count(ps)) {
        out.dead_marking.push_back(placeSlotName(net_, ps) + " = " + std::to_string(counted[ps]));
      }
    }
    std::reverse(out.deadlock_bindings.begin(), out.deadlock_bindings.end());
  }
  for (const PlaceId p : net_.placeIds()) {
    out.max_place = std::max(out.max_place, out.place_bound[p]);
    if (!changed[p]) out.constant_places.push_back(p);
  }
  out.one_safe = out.max_place <= 1;
  out.fired = fired;
  out.quasi_live = std::all_of(fired.begin(), fired.end(), [](bool f) { return f; });
  out.decided = out.complete;
  if (out.decided) {
    components(out);
  } else {
    out.live = false;
    out.reversible = false;
  }
  return out;
}

void Search::components(StateSpace& out) {
  // Tarjan's algorithm without recursion over the kept graph, each state's low link kept as a
  // position on the stack (the stack is in the order states were met, so positions compare as
  // indexes do). A component that an edge leaves (to a component finished before) is not a
  // bottom one; the net is live when every bottom component holds an edge of every
  // transition, reversible when the only bottom component holds the initial marking. Per
  // state one word: 0 not met yet, its position + 1 while on the stack, then kDone.
  const std::size_t n = states_;
  edge_begin_.push(edge_to_.size());
  constexpr std::uint32_t kDone = 0xffffffffu;
  std::vector<std::uint32_t, core::LargeAllocator<std::uint32_t>> at(n, 0);
  std::vector<std::uint32_t> low;  // per position on the stack
  std::vector<bool> leaves;        // per position: an edge leaves for a finished component
  std::vector<StateId> stack;
  struct Frame {
    StateId v;
    std::uint64_t e;
  };
  std::vector<Frame> frames;
  std::uint32_t comps = 0, bottoms = 0;
  bool live = true, reversible = true;
  const std::size_t transitions = net_.transitions().size();
  std::vector<std::uint32_t> seen_in(transitions, kNoState);
  auto push = [&](StateId w) {
    const auto p = static_cast<std::uint32_t>(stack.size());
    at[w] = p + 1;
    stack.push_back(w);
    low.push_back(p);
    leaves.push_back(false);
    frames.push_back({w, edge_begin_[w]});
  };
  for (StateId root = 0; root < n; ++root) {
    if (at[root] != 0) continue;
    push(root);
    while (!frames.empty()) {
      Frame& f = frames.back();
      const std::uint32_t pv = at[f.v] - 1;
      if (f.e < edge_begin_[f.v + 1]) {
        const StateId w = edge_to_[f.e++];
        const std::uint32_t aw = at[w];
        if (aw == 0) {
          push(w);
        } else if (aw != kDone) {
          low[pv] = std::min(low[pv], aw - 1);
        } else {
          leaves[pv] = true;
        }
        continue;
      }
      frames.pop_back();
      if (!frames.empty()) {
        const std::uint32_t pu = at[frames.back().v] - 1;
        low[pu] = std::min(low[pu], low[pv]);
      }
      if (low[pv] != pv) continue;
      // the state roots a component: it and those above it on the stack; the edge that led to
      // it leaves its parent's
      if (!frames.empty()) leaves[at[frames.back().v] - 1] = true;
      const std::uint32_t id = comps++;
      bool bottom = true;
      for (std::size_t k = pv; k < stack.size(); ++k) bottom = bottom && !leaves[k];
      if (bottom) {
        ++bottoms;
        // every edge of a bottom component stays in it
        std::size_t covered = 0;
        std::uint64_t mask = 0;
        for (std::size_t k = pv; k < stack.size() && covered < transitions; ++k) {
          if (masks_) {
            mask |= enabled_mask_[stack[k]];
            covered = static_cast<std::size_t>(std::popcount(mask));
            continue;
          }
          for (std::uint64_t e = edge_begin_[stack[k]]; e < edge_begin_[stack[k] + 1]; ++e) {
            const TransitionId t = instances_[edge_instance_[e]].t;
            if (seen_in[t] != id) {
              seen_in[t] = id;
              ++covered;
            }
          }
        }
        if (covered != transitions) live = false;
        // the initial state is the first root's, at the stack's bottom
        if (!(pv == 0 && stack[0] == 0)) reversible = false;
      }
      for (std::size_t k = pv; k < stack.size(); ++k) at[stack[k]] = kDone;
      stack.resize(pv);
      low.resize(pv);
      leaves.resize(pv);
    }
  }
  out.live = live;
  out.reversible = reversible && bottoms == 1;
}

}  // namespace native
}  // namespace

std::string colouredRefusal(const Net& net) {
  const Colouring* c = net.colouring();
  if (!c) return "the net has no value tokens";
  for (const TransitionId t : net.transitionIds()) {
    const auto* ti = c->of(t);
    const Transition& tr = net.transitions()[t];
    std::vector<bool> inscribed(tr.terms_end - tr.terms_begin, false);  // by term, from the transition's first
    if (ti) {
      for (const TermId term : c->arc_terms[static_cast<std::size_t>(c->of_transition[t])]) {
        inscribed[term - tr.terms_begin] = true;
      }
    }
    for (std::uint32_t i = tr.terms_begin; i < tr.terms_end; ++i) {
      const Term& term = net.terms()[i];
      if (c->setOf(term.place_slot) && !inscribed[i - tr.terms_begin] && term.kind != TermKind::Condition) {
        return "transition '" + net.transitionName(t) + "' has an arc without inscription on value slot of place '" +
               net.placeName(net.placeSlots()[term.place_slot].place) + "'";
      }
    }
  }
  return {};
}

StateSpace exploreColoured(const Net& net, const ExploreOptions& options) {
  GDPN_ASSERT(colouredRefusal(net).empty(), "exploreColoured is given only nets it can search (colouredRefusal)");
  return native::Search(net, options).run();
}

}  // namespace gdpn::net
