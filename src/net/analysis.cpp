#include "gdpn/net/analysis.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <memory>

#include "gdpn/net/invariants.h"

namespace gdpn::net {
namespace {

using StateId = std::uint32_t;
constexpr StateId kNone = 0xffffffffu;
/// ω in an unpacked marking.
constexpr std::int64_t kW = std::numeric_limits<std::int64_t>::max();
/// The most tokens a packed field holds.
constexpr std::uint32_t kMaxBits = 32;

/// Where each place slot's count lies in a packed marking: a bit field that never crosses a
/// 64-bit word. A field that may become ω keeps its all-ones code for it.
class Layout {
 public:
  struct Field {
    std::uint32_t word = 0;
    std::uint32_t shift = 0;
    std::uint64_t mask = 0;
    bool omega = false;
  };

  Layout(const std::vector<std::uint32_t>& bits, const std::vector<bool>& omega) : bits_(bits) {
    std::uint32_t used = 64;
    for (std::size_t k = 0; k < bits.size(); ++k) {
      if (used + bits[k] > 64) ++words_, used = 0;
      fields_.push_back({static_cast<std::uint32_t>(words_ - 1), used, (std::uint64_t{1} << bits[k]) - 1, omega[k]});
      used += bits[k];
    }
    words_ = std::max<std::size_t>(words_, 1);
  }
  std::size_t words() const { return words_; }
  std::size_t width() const { return fields_.size(); }
  std::uint32_t bits(std::size_t k) const { return bits_[k]; }
  const Field& field(std::size_t k) const { return fields_[k]; }
  std::uint64_t code(const std::uint64_t* m, std::size_t k) const {
    const Field& f = fields_[k];
    return (m[f.word] >> f.shift) & f.mask;
  }
  void setCode(std::uint64_t* m, std::size_t k, std::uint64_t c) const {
    const Field& f = fields_[k];
    m[f.word] = (m[f.word] & ~(f.mask << f.shift)) | (c << f.shift);
  }
  bool isOmega(std::size_t k, std::uint64_t c) const { return fields_[k].omega && c == fields_[k].mask; }
  /// The largest count the field holds.
  std::uint64_t maxCount(std::size_t k) const { return fields_[k].omega ? fields_[k].mask - 1 : fields_[k].mask; }
  std::int64_t value(const std::uint64_t* m, std::size_t k) const {
    const std::uint64_t c = code(m, k);
    return isOmega(k, c) ? kW : static_cast<std::int64_t>(c);
  }
  void unpack(const std::uint64_t* m, std::int64_t* out) const {
    for (std::size_t k = 0; k < fields_.size(); ++k) out[k] = value(m, k);
  }
  /// Packs `in`; false (and `bad` set) when a count does not fit its field.
  bool pack(const std::int64_t* in, std::uint64_t* out, std::size_t& bad) const {
    std::fill(out, out + words_, 0);
    for (std::size_t k = 0; k < fields_.size(); ++k) {
      std::uint64_t c = 0;
      if (in[k] == kW) {
        c = fields_[k].mask;
      } else if (static_cast<std::uint64_t>(in[k]) <= maxCount(k)) {
        c = static_cast<std::uint64_t>(in[k]);
      } else {
        bad = k;
        return false;
      }
      setCode(out, k, c);
    }
    return true;
  }

 private:
  std::vector<std::uint32_t> bits_;
  std::vector<Field> fields_;
  std::size_t words_ = 0;
};

/// Fixed-size chunks, so that growing never copies and never holds twice the memory.
template <typename T>
class Chunked {
 public:
  explicit Chunked(std::size_t stride = 1) : stride_(stride) {}
  T* at(std::size_t i) { return chunks_[i >> kShift].get() + (i & kMask) * stride_; }
  const T* at(std::size_t i) const { return chunks_[i >> kShift].get() + (i & kMask) * stride_; }
  T* append() {
    if ((size_ >> kShift) >= chunks_.size()) chunks_.push_back(std::make_unique<T[]>((kMask + 1) * stride_));
    return at(size_++);
  }
  void push(const T& x) { *append() = x; }
  T& operator[](std::size_t i) { return *at(i); }
  T& back() { return *at(size_ - 1); }
  bool empty() const { return size_ == 0; }
  /// Drops the elements from `n` on; the chunks stay for reuse.
  void shrink(std::size_t n) { size_ = std::min(size_, n); }
  std::size_t size() const { return size_; }
  std::size_t bytes() const { return chunks_.size() * (kMask + 1) * stride_ * sizeof(T); }
  void clear() {
    chunks_.clear();
    size_ = 0;
  }

 private:
  static constexpr std::size_t kShift = 16;
  static constexpr std::size_t kMask = (std::size_t{1} << kShift) - 1;
  std::size_t stride_;
  std::size_t size_ = 0;
  std::vector<std::unique_ptr<T[]>> chunks_;
};

/// The packed markings met so far and an open-addressing table over them. A table entry
/// holds the state's id and 32 bits of its hash, so most probes never touch the markings.
class Store {
 public:
  explicit Store(Layout layout) : layout_(std::move(layout)), arena_(layout_.words()) { table_.assign(1024, kEmpty); }

  const Layout& layout() const { return layout_; }
  std::size_t words() const { return layout_.words(); }
  std::size_t size() const { return arena_.size(); }
  const std::uint64_t* at(StateId s) const { return arena_.at(s); }
  std::size_t bytes() const { return arena_.bytes() + table_.size() * sizeof(std::uint64_t); }

  std::uint64_t hash(const std::uint64_t* m) const {
    std::uint64_t h = 0x243f6a8885a308d3ULL;
    for (std::size_t k = 0; k < words(); ++k) {
      h = (h ^ m[k]) * 0x9e3779b97f4a7c15ULL;
      h ^= h >> 31;
    }
    h *= 0xbf58476d1ce4e5b9ULL;
    return h ^ (h >> 29);
  }
  void prefetch(std::uint64_t h) const { __builtin_prefetch(&table_[h & (table_.size() - 1)]); }

  /// The id of `m`, or kNone.
  StateId find(const std::uint64_t* m, std::uint64_t h) const {
    const std::uint64_t tag = h >> 32;
    for (std::size_t i = h & (table_.size() - 1);; i = (i + 1) & (table_.size() - 1)) {
      const std::uint64_t e = table_[i];
      if (e == kEmpty) return kNone;
      const auto s = static_cast<StateId>(e);
      if ((e >> 32) == tag && std::memcmp(at(s), m, words() * sizeof(std::uint64_t)) == 0) return s;
    }
  }
  /// The id of `m`, adding it when new (`added` says which).
  StateId insert(const std::uint64_t* m, std::uint64_t h, bool& added) {
    if ((size() + 1) * 10 > table_.size() * 7) grow();
    const std::uint64_t tag = h >> 32;
    for (std::size_t i = h & (table_.size() - 1);; i = (i + 1) & (table_.size() - 1)) {
      const std::uint64_t e = table_[i];
      if (e == kEmpty) {
        const auto s = static_cast<StateId>(size());
        std::memcpy(arena_.append(), m, words() * sizeof(std::uint64_t));
        table_[i] = (tag << 32) | s;
        added = true;
        return s;
      }
      const auto s = static_cast<StateId>(e);
      if ((e >> 32) == tag && std::memcmp(at(s), m, words() * sizeof(std::uint64_t)) == 0) {
        added = false;
        return s;
      }
    }
  }
  /// Re-packs every marking into `layout` (wider fields), keeping the ids.
  void relayout(Layout layout) {
    Chunked<std::uint64_t> next(layout.words());
    std::vector<std::int64_t> m(layout_.width());
    for (std::size_t s = 0; s < size(); ++s) {
      layout_.unpack(at(static_cast<StateId>(s)), m.data());
      std::size_t bad = 0;
      layout.pack(m.data(), next.append(), bad);
    }
    layout_ = std::move(layout);
    arena_ = std::move(next);
    rehash(table_.size());
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  void grow() { rehash(table_.size() * 2); }
  void rehash(std::size_t capacity) {
    table_.assign(capacity, kEmpty);
    for (std::size_t s = 0; s < size(); ++s) {
      const std::uint64_t h = hash(at(static_cast<StateId>(s)));
      std::size_t i = h & (capacity - 1);
      while (table_[i] != kEmpty) i = (i + 1) & (capacity - 1);
      table_[i] = ((h >> 32) << 32) | s;
    }
  }
  Layout layout_;
  Chunked<std::uint64_t> arena_;
  std::vector<std::uint64_t> table_;
};

/// The search: a depth-first walk that finds strongly connected components as it goes
/// (Pearce's single-index variant of Tarjan's algorithm), so that no edge is stored.
class Search {
 public:
  Search(const Net& net, const ExploreOptions& options) : net_(net), options_(options) {}

  StateSpace run();

 private:
  enum class Expand : std::uint8_t { Ok, Widened, Overflow };

  /// Successors of `v` into succ_ (ids) and its enabled transitions into via_.
  Expand expand(StateId v);
  /// Fires `t` on the packed marking `m` into `out`; Overflow or Widened on a count that
  /// does not fit. False in `enabled` when `t` is not enabled.
  Expand fire(TransitionId t, const std::uint64_t* m, std::uint64_t* out, bool& enabled);
  bool widen(std::size_t k);
  /// Karp-Miller acceleration of `m` against the markings on the search path.
  void accelerate(std::vector<std::int64_t>& m) const;
  void noteNew(StateId s);
  void finishComponent(StateId v);
  void shortestPathToDeadlock(StateSpace& out);
  std::uint64_t bytes() const;
  bool enabledIn(TransitionId t, const std::uint64_t* m) const;

  /// A state on the search path. Its successors not yet visited when it was expanded lie
  /// in edges_ from the previous frame's `end` to its own.
  struct Frame {
    std::uint32_t v_root = 0;  ///< the state, and in the top bit: no edge reached below its index yet
    std::uint32_t end = 0;     ///< its pending successors end here in edges_
    StateId state() const { return v_root & 0x7fffffffu; }
    bool root() const { return (v_root >> 31) != 0; }
  };
  /// The edge from `f`'s state to a visited state whose rindex is `rw`.
  void settle(Frame& f, std::uint32_t rw) {
    std::uint32_t& rv = *rindex_.at(f.state());
    if (rw < rv) rv = rw, f.v_root &= 0x7fffffffu;
    if (rw > next_comp_) leaves_[f.state()] = true;  // w's component is finished: an edge leaves
  }

  const Net& net_;
  const ExploreOptions& options_;
  std::unique_ptr<Store> store_;
  std::vector<bool> accel_;   // per place slot: may be accelerated to ω
  bool cover_ = false;        // some place slot has no structural bound
  std::vector<std::int64_t> path_;  // unpacked markings on the search path (cover_ only)
  std::uint64_t edges_count_ = 0;
  ExploreStop stop_ = ExploreStop::Done;

  // per state
  Chunked<std::uint32_t> rindex_;
  std::vector<bool> leaves_;
  // the walk
  Chunked<Frame> frames_;
  Chunked<StateId> edges_;
  Chunked<StateId> stack_;
  std::uint32_t next_index_ = 1;
  std::uint32_t next_comp_ = 0xfffffffeu;
  // scratch
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint64_t> hashes_;
  std::vector<TransitionId> succ_t_;
  std::vector<std::int64_t> unpacked_;
  std::vector<bool> union_;
  // answers
  std::vector<std::int64_t> low_, high_;
  std::int64_t max_marking_ = 0;
  std::vector<bool> fired_;
  bool deadlock_ = false;
  bool live_ = true;
  std::uint32_t bottoms_ = 0;
  bool root_bottom_ = false;
  std::uint64_t peak_ = 0;
};

bool Search::enabledIn(TransitionId t, const std::uint64_t* m) const {
  const Layout& L = store_->layout();
  for (const Term& term : net_.termsOf(t)) {
    const std::int64_t v = L.value(m, term.place_slot);
    switch (term.kind) {
      case TermKind::Input:
      case TermKind::Test:
        if (v < term.weight) return false;
        break;
      case TermKind::Inhibitor:
        if (v >= term.weight) return false;
        break;
      case TermKind::Output: {
        const auto cap = net_.placeSlots()[term.place_slot].capacity;
        if (cap != kUnbounded && v != kW && v - term.take + term.weight > cap) return false;
        break;
      }
      case TermKind::Condition:
        break;  // sensor conditions are free to be either: explore as if true
    }
  }
  return true;
}

Search::Expand Search::fire(TransitionId t, const std::uint64_t* m, std::uint64_t* out, bool& enabled) {
  enabled = enabledIn(t, m);
  if (!enabled) return Expand::Ok;
  const Layout& L = store_->layout();
  std::memcpy(out, m, L.words() * sizeof(std::uint64_t));
  // inputs come before outputs among a transition's terms
  for (const Term& term : net_.termsOf(t)) {
    const std::size_t k = term.place_slot;
    const std::uint64_t c = L.code(out, k);
    if (L.isOmega(k, c)) continue;
    if (term.kind == TermKind::Input) L.setCode(out, k, c - static_cast<std::uint64_t>(term.weight));
    if (term.kind == TermKind::Output) {
      const std::uint64_t next = c + static_cast<std::uint64_t>(term.weight);
      if (next > L.maxCount(k)) return widen(k) ? Expand::Widened : Expand::Overflow;
      L.setCode(out, k, next);
    }
  }
  return Expand::Ok;
}

bool Search::widen(std::size_t k) {
  const Layout& L = store_->layout();
  if (L.bits(k) >= kMaxBits) return false;
  std::vector<std::uint32_t> bits(L.width());
  std::vector<bool> omega(L.width());
  for (std::size_t j = 0; j < L.width(); ++j) bits[j] = L.bits(j), omega[j] = L.field(j).omega;
  bits[k] = std::min(kMaxBits, bits[k] * 2);
  store_->relayout(Layout(bits, omega));
  return true;
}

void Search::accelerate(std::vector<std::int64_t>& m) const {
  const std::size_t width = m.size();
  for (std::size_t at = 0; at < path_.size(); at += width) {
    const std::int64_t* a = path_.data() + at;
    bool ge = true, gt = false;
    for (std::size_t k = 0; k < width && ge; ++k) {
      if (m[k] < a[k]) ge = false;
      if (m[k] > a[k]) {
        // only where the firing sequence surely repeats: no inhibitor or capacity reads it
        if (!accel_[k]) ge = false;
        gt = true;
      }
    }
    if (!ge || !gt) continue;
    for (std::size_t k = 0; k < width; ++k) {
      if (m[k] > a[k]) m[k] = kW;
    }
  }
}

Search::Expand Search::expand(StateId v) {
  const Layout& L = store_->layout();
  const std::size_t words = L.words();
  const std::size_t transitions = net_.transitions().size();
  keys_.resize(transitions * words);
  hashes_.clear();
  succ_t_.clear();
  const std::uint64_t* m = store_->at(v);
  for (TransitionId t = 0; t < transitions; ++t) {
    bool enabled = false;
    std::uint64_t* out = keys_.data() + succ_t_.size() * words;
    const Expand e = fire(t, m, out, enabled);
    if (e != Expand::Ok) return e;
    if (!enabled) continue;
    succ_t_.push_back(t);
    const std::uint64_t h = store_->hash(out);
    hashes_.push_back(h);
    store_->prefetch(h);
  }
  std::uint32_t& rv = *rindex_.at(v);
  bool root = true;
  for (std::size_t i = 0; i < succ_t_.size(); ++i) {
    std::uint64_t* key = keys_.data() + i * words;
    std::uint64_t h = hashes_[i];
    if (cover_ && store_->find(key, h) == kNone) {
      unpacked_.resize(L.width());
      L.unpack(key, unpacked_.data());
      accelerate(unpacked_);
      std::size_t bad = 0;
      L.pack(unpacked_.data(), key, bad);  // ω always fits
      h = store_->hash(key);
    }
    bool added = false;
    const StateId w = store_->insert(key, h, added);
    if (added) noteNew(w);
    fired_[succ_t_[i]] = true;
    // an edge to a state already visited is settled now; the others wait in edges_
    const std::uint32_t rw = *rindex_.at(w);
    if (rw == 0) {
      edges_.push(w);
      continue;
    }
    if (rw < rv) rv = rw, root = false;
    if (rw > next_comp_) leaves_[v] = true;  // w's component is finished: an edge leaves
  }
  edges_count_ += succ_t_.size();
  if (succ_t_.empty()) deadlock_ = true;
  frames_.push({v | (root ? 0x80000000u : 0u), static_cast<std::uint32_t>(edges_.size())});
  return Expand::Ok;
}

void Search::noteNew(StateId s) {
  const Layout& L = store_->layout();
  const std::uint64_t* m = store_->at(s);
  std::int64_t total = 0;
  for (std::size_t k = 0; k < L.width(); ++k) {
    const std::int64_t v = L.value(m, k);
    low_[k] = std::min(low_[k], v);
    high_[k] = std::max(high_[k], v);
    if (v != kW) total += v;
  }
  max_marking_ = std::max(max_marking_, total);
  *rindex_.append() = 0;
  leaves_.push_back(false);
}

void Search::finishComponent(StateId v) {
  // the component: v and the states above it on the stack
  std::size_t first = stack_.size();
  while (first > 0 && *rindex_.at(stack_[first - 1]) >= *rindex_.at(v)) --first;
  const std::size_t size = stack_.size();
  bool leaves = leaves_[v];
  for (std::size_t i = first; i < size; ++i) leaves = leaves || leaves_[stack_[i]];
  if (!leaves) {
    // a bottom component: every edge stays inside, so the transitions that fire inside it
    // are those enabled in its states
    ++bottoms_;
    if (live_) {
      union_.assign(net_.transitions().size(), false);
      auto mark = [&](StateId s) {
        for (TransitionId t = 0; t < union_.size(); ++t) {
          if (!union_[t] && enabledIn(t, store_->at(s))) union_[t] = true;
        }
      };
      mark(v);
      for (std::size_t i = first; i < size; ++i) mark(stack_[i]);
      live_ = std::all_of(union_.begin(), union_.end(), [](bool b) { return b; });
    }
  }
  root_bottom_ = !leaves;
  for (std::size_t i = first; i < size; ++i) *rindex_.at(stack_[i]) = next_comp_;
  *rindex_.at(v) = next_comp_;
  --next_comp_;
  stack_.shrink(first);
}

std::uint64_t Search::bytes() const {
  return store_->bytes() + rindex_.bytes() + leaves_.capacity() / 8 + frames_.bytes() + edges_.bytes() +
         stack_.bytes() + path_.capacity() * sizeof(std::int64_t);
}

void Search::shortestPathToDeadlock(StateSpace& out) {
  // breadth first over the known states; the first dead one met is "the first"
  const std::size_t n = store_->size();
  rindex_.clear();
  std::vector<StateId> parent(n, kNone);
  std::vector<TransitionId> via(n, 0);
  std::vector<StateId> queue{0};
  parent[0] = 0;
  const std::size_t words = store_->words();
  std::vector<std::uint64_t> next(words);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const StateId s = queue[head];
    bool any = false;
    for (TransitionId t = 0; t < net_.transitions().size(); ++t) {
      bool enabled = false;
      fire(t, store_->at(s), next.data(), enabled);
      if (!enabled) continue;
      any = true;
      if (cover_) {
        // the search stored the accelerated form
        std::vector<std::int64_t> m(store_->layout().width());
        store_->layout().unpack(next.data(), m.data());
        std::size_t bad = 0;
        if (store_->find(next.data(), store_->hash(next.data())) == kNone) {
          accelerate(m);
          store_->layout().pack(m.data(), next.data(), bad);
        }
      }
      const StateId w = store_->find(next.data(), store_->hash(next.data()));
      if (w == kNone || parent[w] != kNone) continue;
      parent[w] = s;
      via[w] = t;
      queue.push_back(w);
    }
    if (!any) {
      for (StateId x = s; x != 0; x = parent[x]) out.deadlock_path.push_back(via[x]);
      std::reverse(out.deadlock_path.begin(), out.deadlock_path.end());
      return;
    }
  }
}

StateSpace Search::run() {
  StateSpace out;
  const std::size_t width = net_.placeSlots().size();
  const std::size_t transitions = net_.transitions().size();

  // field sizes from the invariants' bounds; the others start small and widen when needed
  const Invariants inv = invariants(net_, {2'000});
  std::vector<std::uint32_t> bits(width);
  std::vector<bool> omega(width);
  accel_.assign(width, false);
  std::vector<std::int64_t> m0(width);
  for (std::size_t k = 0; k < width; ++k) {
    const PlaceSlot& ps = net_.placeSlots()[k];
    std::int64_t bound = inv.bound[k];
    if (ps.capacity != kUnbounded && (bound < 0 || ps.capacity < bound)) bound = ps.capacity;
    m0[k] = ps.initial;
    if (bound >= 0) {
      bits[k] = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::bit_width(static_cast<std::uint64_t>(bound))));
    } else {
      omega[k] = true;
      cover_ = true;
      accel_[k] = true;
      std::uint32_t b = 4;
      while (b < kMaxBits && static_cast<std::uint64_t>(ps.initial) + 1 >= (std::uint64_t{1} << b)) b *= 2;
      bits[k] = b;
    }
    if (bits[k] > kMaxBits || static_cast<std::uint64_t>(ps.initial) > (std::uint64_t{1} << kMaxBits) - 2) {
      out.complete = false;
      out.stop = ExploreStop::Overflow;
      out.decided = out.live = out.reversible = false;
      out.fired.assign(transitions, false);
      out.quasi_live = transitions == 0;
      return out;
    }
  }
  for (const Term& term : net_.terms()) {
    if (term.kind == TermKind::Inhibitor) accel_[term.place_slot] = false;
  }
  store_ = std::make_unique<Store>(Layout(bits, omega));
  std::vector<std::uint64_t> key(store_->words());
  std::size_t bad = 0;
  store_->layout().pack(m0.data(), key.data(), bad);
  low_.assign(width, kW);
  high_.assign(width, 0);
  fired_.assign(transitions, false);
  bool added = false;
  store_->insert(key.data(), store_->hash(key.data()), added);
  noteNew(0);

  auto visit = [&](StateId v) -> bool {
    *rindex_.at(v) = next_index_++;
    if (cover_) {
      path_.resize(path_.size() + width);
      store_->layout().unpack(store_->at(v), path_.data() + path_.size() - width);
    }
    for (;;) {
      const Expand e = expand(v);
      if (e == Expand::Ok) return true;
      if (e == Expand::Overflow) {
        stop_ = ExploreStop::Overflow;
        return false;
      }
      // a field grew: the markings were re-packed; compute the successors again
    }
  };

  std::uint64_t next_report = 1 << 12;
  bool running = visit(0);
  while (running && !frames_.empty()) {
    Frame& f = frames_.back();
    const std::uint32_t begin = frames_.size() > 1 ? frames_[frames_.size() - 2].end : 0;
    if (f.end > begin) {
      // the next pending successor, taken from the top
      const StateId w = edges_[--f.end];
      edges_.shrink(f.end);
      const std::uint32_t rw = *rindex_.at(w);
      if (rw != 0) {
        settle(f, rw);
        continue;
      }
      running = visit(w);
      if (store_->size() >= next_report) {
        next_report += 1 << 12;
        const std::uint64_t b = bytes();
        peak_ = std::max(peak_, b);
        if (options_.progress) options_.progress({store_->size(), edges_count_, b});
        if (options_.max_bytes != 0 && b > options_.max_bytes) stop_ = ExploreStop::MaxMemory, running = false;
      }
      // ids keep their top bit free (Frame::v_root)
      if (store_->size() > std::min<std::uint64_t>(options_.max_states, 0x7ffffff0u)) stop_ = ExploreStop::MaxStates, running = false;
      continue;
    }
    const StateId v = f.state();
    const bool root = f.root();
    frames_.shrink(frames_.size() - 1);
    if (cover_) path_.resize(path_.size() - width);
    if (root) {
      finishComponent(v);
    } else {
      stack_.push(v);
    }
    // the edge from the parent to v is settled now that v is done
    if (!frames_.empty()) settle(frames_.back(), *rindex_.at(v));
  }
  peak_ = std::max(peak_, bytes());

  out.stop = stop_;
  out.complete = stop_ == ExploreStop::Done;
  out.states = store_->size();
  out.edges = edges_count_;
  out.fired = fired_;
  out.quasi_live = std::all_of(fired_.begin(), fired_.end(), [](bool b) { return b; });
  const auto places = net_.places();
  out.place_bound.assign(places.size(), 0);
  for (PlaceId p = 0; p < places.size(); ++p) {
    bool constant = true;
    for (auto ps = places[p].slots_begin; ps < places[p].slots_end; ++ps) {
      if (high_[ps] == kW) {
        out.place_bound[p] = kOmega;
      } else if (out.place_bound[p] != kOmega) {
        out.place_bound[p] += high_[ps];
      }
      constant = constant && low_[ps] == high_[ps];
    }
    if (constant) out.constant_places.push_back(p);
    if (out.place_bound[p] == kOmega) {
      out.bounded = false;
      out.unbounded_places.push_back(p);
    } else {
      out.max_place = std::max(out.max_place, out.place_bound[p]);
    }
  }
  out.max_marking = max_marking_;
  out.one_safe = out.bounded && out.max_place <= 1;
  out.decided = out.complete && out.bounded;
  out.deadlock = deadlock_;
  if (out.decided) {
    out.live = live_;
    out.reversible = bottoms_ == 1 && root_bottom_;
  } else {
    out.live = out.reversible = false;
  }
  if (deadlock_ && out.complete) shortestPathToDeadlock(out);
  out.peak_bytes = peak_;
  return out;
}

}  // namespace

StateSpace explore(const Net& net, const ExploreOptions& options) { return Search(net, options).run(); }

const char* stopReason(ExploreStop stop) {
  switch (stop) {
    case ExploreStop::MaxStates:
      return "partial: --max-states reached";
    case ExploreStop::MaxMemory:
      return "partial: --max-memory reached";
    case ExploreStop::Overflow:
      return "partial: a place went past 2^32 - 2 tokens";
    case ExploreStop::Done:
      break;
  }
  return "complete";
}

}  // namespace gdpn::net
