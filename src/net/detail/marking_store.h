#pragma once
// Internal to the net module: packed markings and the store of markings shared by the
// sequential and the parallel state-space searches, and what both note about each marking.

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "gdpn/net/analysis.h"
#include "gdpn/net/net.h"

namespace gdpn::net::detail {

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

/// What firing a transition on a packed marking gave.
enum class Fired : std::uint8_t { Ok, NotEnabled, TooBig };

/// True when `t` is enabled in the packed marking `m` (sensor conditions count as true).
bool enabledIn(const Net& net, const Layout& layout, TransitionId t, const std::uint64_t* m);

/// Marks in `seen` the transitions enabled in `m`; returns how many were not marked before.
/// Over the states of a bottom component it gives the transitions that fire inside it.
std::size_t markEnabled(const Net& net, const Layout& layout, const std::uint64_t* m, std::vector<bool>& seen);

/// Fires `t` on `m` into `out`. TooBig (with the field in `field`) when a count does not fit.
Fired fireInto(const Net& net, const Layout& layout, TransitionId t, const std::uint64_t* m, std::uint64_t* out,
               std::size_t& field);

/// How a search packs markings: field sizes from the invariants' bounds and capacities.
struct Plan {
  std::vector<std::uint32_t> bits;   ///< per place slot
  std::vector<bool> omega;           ///< per place slot: no bound known, may become ω
  std::vector<bool> accel;           ///< per place slot: may be accelerated to ω
  std::vector<std::int64_t> m0;      ///< the initial marking
  bool cover = false;                ///< some place slot has no bound: watch for ω
  bool overflow = false;             ///< an initial count is beyond what a field holds
};
Plan plan(const Net& net, const ExploreOptions& options);

/// The lowest and highest count of each place slot, and the largest marking, over the
/// markings noted.
struct Observed {
  std::vector<std::int64_t> low, high;
  std::int64_t max_marking = 0;
  explicit Observed(std::size_t width) : low(width, kW), high(width, 0) {}
  void note(const Layout& layout, const std::uint64_t* m);
  void merge(const Observed& other);
};

/// Fills the answers read off the observations: place bounds, unbounded and constant places,
/// one-safeness, quasi-liveness; `out.complete`, `fired` and the counts must be set.
void summarise(const Net& net, const Observed& seen, StateSpace& out);

/// The answer for a net whose initial marking cannot be stored.
StateSpace overflowAnswer(const Net& net);

/// The parallel search (ExploreOptions::threads > 1, no place without a bound).
StateSpace exploreParallel(const Net& net, const ExploreOptions& options, const Plan& plan);

}  // namespace gdpn::net::detail
