#pragma once
// Internal to the net module: packed markings and the store of markings shared by the
// sequential and the parallel state-space searches, and what both note about each marking.

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <cstdlib>
#include <memory>
#include <span>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include "gdpn/core/memory.h"
#include "gdpn/net/analysis.h"
#include "gdpn/net/invariants.h"
#include "gdpn/net/net.h"

namespace gdpn::net::detail {

using StateId = std::uint32_t;
constexpr StateId kNone = 0xffffffffu;
/// ω in an unpacked marking.
constexpr std::int64_t kW = std::numeric_limits<std::int64_t>::max();
/// The most tokens a packed field holds.
constexpr std::uint32_t kMaxBits = 32;

/// A place slot whose count the others give: a P-invariant y has y·m = y·m0 in every
/// reachable marking, so m(slot) = (constant - sum of y_q·m(q) over its other slots) / divisor.
struct Derived {
  std::uint32_t slot = 0;     ///< the place slot left out of stored markings
  std::int64_t constant = 0;  ///< y·m0
  std::int64_t divisor = 1;   ///< y at the slot
  std::vector<std::pair<std::uint32_t, std::int64_t>> terms;  ///< the invariant's other slots: (slot, y_q)
};

/// Where each place slot's count lies in a packed marking: a bit field that never crosses a
/// 64-bit word. A field that may become ω keeps its all-ones code for it. The fields kept
/// when a marking is stored come first; those of slots the others give (Derived) begin on a
/// word of their own after them, so that a stored marking is a prefix of a packed one.
class Layout {
 public:
  struct Field {
    std::uint32_t word = 0;
    std::uint32_t shift = 0;
    std::uint64_t mask = 0;
    bool omega = false;
    /// The place slot has a bound the field holds (from the invariants, the state equation or
    /// its capacity): no marking a search meets outgrows it.
    bool bounded = false;
  };

  /// Fields of `bits` bits, in place slot order; those `omega` names may become ω, those
  /// `bounded` names hold a bound (a field may be neither: a search of concrete markings
  /// stops where its count does not fit).
  Layout(const std::vector<std::uint32_t>& bits, const std::vector<bool>& omega, const std::vector<bool>& bounded)
      : Layout(bits, omega, bounded, slotOrder(bits.size()), bits.size()) {}
  /// The same with the fields laid out in `order` (place slots), the first `kept` of them
  /// those a stored marking keeps.
  Layout(const std::vector<std::uint32_t>& bits, const std::vector<bool>& omega, const std::vector<bool>& bounded,
         const std::vector<std::uint32_t>& order, std::size_t kept)
      : bits_(bits), fields_(bits.size()) {
    std::uint32_t used = 64;
    for (std::size_t i = 0; i <= order.size(); ++i) {
      if (i == kept) {
        // the stored prefix ends here: the bytes up to the last kept field's end
        key_bytes_ = std::max<std::size_t>(1, words_ == 0 ? 0 : (words_ - 1) * 8 + (used + 7) / 8);
        key_words_ = words_;
        used = 64;  // the fields worked out begin a word of their own
      }
      if (i == order.size()) break;
      const std::size_t k = order[i];
      if (used + bits[k] > 64) ++words_, used = 0;
      fields_[k] = {static_cast<std::uint32_t>(words_ - 1), used, (std::uint64_t{1} << bits[k]) - 1, omega[k],
                    bounded[k] && !omega[k]};
      used += bits[k];
    }
    words_ = std::max<std::size_t>(words_, 1);
    key_words_ = std::max<std::size_t>(key_words_, 1);
    // per word: its fields, and whether all hold one token at most and never ω (tokens())
    ones_.assign(words_, 1);
    word_begin_.assign(words_ + 1, 0);
    for (const Field& f : fields_) ++word_begin_[f.word + 1];
    for (std::size_t w = 0; w < words_; ++w) word_begin_[w + 1] += word_begin_[w];
    word_fields_.resize(fields_.size());
    std::vector<std::uint32_t> at(word_begin_.begin(), word_begin_.end() - 1);
    for (std::size_t k = 0; k < fields_.size(); ++k) {
      word_fields_[at[fields_[k].word]++] = static_cast<std::uint32_t>(k);
      if (bits[k] != 1 || fields_[k].omega) ones_[fields_[k].word] = 0;
    }
  }
  std::size_t words() const { return words_; }
  /// The words that hold the fields a stored marking keeps (all of them where none is left out).
  std::size_t keyWords() const { return key_words_; }
  /// The bytes of those words up to the end of the last kept field: what a marking is stored as.
  std::size_t keyBytes() const { return key_bytes_; }
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
  /// The tokens of the packed marking `m`, ω not counted: a word of one-token fields by
  /// counting its set bits.
  std::int64_t tokens(const std::uint64_t* m) const {
    std::int64_t n = 0;
    for (std::size_t w = 0; w < words_; ++w) {
      if (ones_[w] != 0) {
        n += std::popcount(m[w]);
        continue;
      }
      for (std::uint32_t i = word_begin_[w]; i < word_begin_[w + 1]; ++i) {
        const std::int64_t v = value(m, word_fields_[i]);
        if (v != kW) n += v;
      }
    }
    return n;
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

  /// The layout of a search where a place slot without a bound may become ω: the fields
  /// `omega` does not name are bounded.
  static Layout omegaOrBounded(const std::vector<std::uint32_t>& bits, const std::vector<bool>& omega) {
    std::vector<bool> bounded = omega;
    bounded.flip();
    return Layout(bits, omega, bounded);
  }

 private:
  static std::vector<std::uint32_t> slotOrder(std::size_t n) {
    std::vector<std::uint32_t> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = static_cast<std::uint32_t>(k);
    return order;
  }
  std::vector<std::uint32_t> bits_;
  std::vector<Field> fields_;
  std::size_t words_ = 0;
  std::size_t key_words_ = 0;
  std::size_t key_bytes_ = 0;
  std::vector<std::uint8_t> ones_;           // per word: only one-token fields, none ω
  std::vector<std::uint32_t> word_begin_;    // per word: its fields in word_fields_ from here
  std::vector<std::uint32_t> word_fields_;   // the fields, word by word
};

/// Fixed-size chunks of 2^Shift elements, so that growing never copies and never holds twice
/// the memory. Chunks of 2 MiB or more lie on huge pages where the system offers them (what is
/// read at random, a state's marking or its index, then costs no TLB miss); smaller ones do
/// too once 2 MiB of them are held, a huge page's worth carved from one block (a walk of
/// millions of states would otherwise take its memory a small page fault at a time, 12 us
/// each on a virtual machine here).
template <typename T, std::size_t Shift = 16>
class Chunked {
 public:
  explicit Chunked(std::size_t stride = 1) : stride_(stride) {}
  /// Chunks of 2^`shift` elements instead of 2^Shift (chunkElements() is then not theirs).
  Chunked(std::size_t stride, std::size_t shift) : stride_(stride), shift_(shift), mask_((std::size_t{1} << shift) - 1) {}
  T* at(std::size_t i) { return chunks_[i >> shift_].get() + (i & mask_) * stride_; }
  const T* at(std::size_t i) const { return chunks_[i >> shift_].get() + (i & mask_) * stride_; }
  T* append() {
    if ((size_ >> shift_) >= chunks_.size()) grow();
    return at(size_++);
  }
  void push(const T& x) { *append() = x; }
  /// Appends `n` elements (1 to a chunk's worth) that lie one after another in memory, moving
  /// on to a new chunk where the current one has too little room (the rest of it set to
  /// `pad`); the index of the first.
  std::size_t appendRun(std::size_t n, const T& pad) {
    if ((size_ & mask_) + n > mask_ + 1) {
      std::fill(at(size_), at(size_ | mask_) + stride_, pad);
      size_ = (size_ | mask_) + 1;
    }
    while (((size_ + n - 1) >> shift_) >= chunks_.size()) grow();
    const std::size_t first = size_;
    size_ += n;
    return first;
  }
  /// The elements one chunk holds (of the default size, 2^Shift).
  static constexpr std::size_t chunkElements() { return kMask + 1; }
  /// The elements in use of chunk `c` (of size() / chunkElements(), rounded up): the first,
  /// and how many.
  std::pair<const T*, std::size_t> chunk(std::size_t c) const {
    return {chunks_[c].get(), std::min(size_ - (c << shift_), mask_ + 1) * stride_};
  }
  T& operator[](std::size_t i) { return *at(i); }
  const T& operator[](std::size_t i) const { return *at(i); }
  T& back() { return *at(size_ - 1); }
  bool empty() const { return size_ == 0; }
  /// Drops the elements from `n` on; the chunks stay for reuse.
  void shrink(std::size_t n) { size_ = std::min(size_, n); }
  std::size_t size() const { return size_; }
  /// Memory held, bytes: a chunk of 2 MiB or more only as far as it is used (its pages are
  /// touched, and so taken from the system, only then); smaller chunks every block taken for
  /// them, used or not (a block of 2 MiB on a huge page is taken whole at its first touch).
  std::size_t bytes() const { return chunkBytes() >= kHuge ? size_ * stride_ * sizeof(T) : held_; }
  void clear() {
    chunks_.clear();
    size_ = 0;
    held_ = 0;
  }

 private:
  static_assert(std::is_trivially_destructible_v<T>);
  static constexpr std::size_t kShift = Shift;
  static constexpr std::size_t kMask = (std::size_t{1} << kShift) - 1;
  static constexpr std::size_t kHuge = core::kHugePageBytes;
  /// Frees a block; the chunks carved from a block after its first own nothing.
  struct Free {
    bool owns = true;
    void operator()(T* p) const {
      if (owns) std::free(p);
    }
  };
  std::size_t chunkBytes() const { return (mask_ + 1) * stride_ * sizeof(T); }
  /// Room for one more chunk at least: a chunk of its own while chunks are large or few, else
  /// a huge page's worth of them.
  void grow() {
    const std::size_t bytes = chunkBytes();
    const std::size_t per_block = kHuge / bytes;
    const bool carve = bytes < kHuge && chunks_.size() >= per_block;
    const std::size_t n = carve ? per_block : 1;
    const std::size_t block = carve ? kHuge : bytes;
    // room in the list first, so that a block is never left without its owner (doubling, as
    // push_back would: an arena of 10^4 chunks grows it as often)
    if (chunks_.capacity() < chunks_.size() + n) chunks_.reserve(std::max(chunks_.size() + n, 2 * chunks_.capacity()));
    T* p = static_cast<T*>(core::allocateLarge(block));
    std::uninitialized_default_construct_n(p, n * (mask_ + 1) * stride_);
    for (std::size_t i = 0; i < n; ++i) chunks_.emplace_back(p + i * (mask_ + 1) * stride_, Free{i == 0});
    held_ += block;
  }
  std::size_t stride_;
  std::size_t shift_ = kShift, mask_ = kMask;
  std::size_t size_ = 0;
  std::size_t held_ = 0;  // bytes of the blocks taken
  std::vector<std::unique_ptr<T[], Free>> chunks_;
};

/// A hash of the `n` words at `m`.
inline std::uint64_t hashWords(const std::uint64_t* m, std::size_t n) {
  std::uint64_t h = 0x243f6a8885a308d3ULL;
  for (std::size_t k = 0; k < n; ++k) {
    h = (h ^ m[k]) * 0x9e3779b97f4a7c15ULL;
    h ^= h >> 31;
  }
  h *= 0xbf58476d1ce4e5b9ULL;
  return h ^ (h >> 29);
}

/// The markings met so far and an open-addressing table over them. A marking is stored as
/// the bytes of its kept fields (Layout::keyBytes(), the slots the invariants give left out
/// and worked out again as it is read); a table entry is 32 bits: the state's id in the low
/// bits, as many as the table's size needs, and the hash's top bits above, so that most
/// probes never touch the markings.
class Store {
 public:
  /// The bytes a state takes in the arena (`bytes`, eight at least, so that a word is read
  /// from any state without passing its chunk; past 64 rounded up to a multiple of 64) and
  /// log2 of the states a chunk holds: each chunk an odd number of 2 MiB pages, never rounded
  /// up to the next (as many as the bytes a state over its largest power-of-two factor, from
  /// 63 for small markings to n for markings of n times 64 bytes).
  static std::pair<std::size_t, std::size_t> arenaShape(std::size_t bytes) {
    bytes = std::max<std::size_t>(bytes, 8);
    if (bytes > 64) bytes = (bytes + 63) / 64 * 64;
    return {bytes, 21 - std::min<std::size_t>(21, static_cast<std::size_t>(std::countr_zero(bytes)))};
  }
  /// With `index`, each state has 32 bits beside its marking (zero when stored): what a
  /// search keeps per state, read in the same cache line as the marking. `derived`: the
  /// slots `layout` leaves out of what is stored, in the order they are worked out.
  explicit Store(Layout layout, bool index = false, std::vector<Derived> derived = {});

  const Layout& layout() const { return layout_; }
  /// The words of a packed marking, the slots left out included.
  std::size_t words() const { return layout_.words(); }
  /// Bytes a stored state takes: its marking's kept part, and its index where kept (padded
  /// for wide markings: arenaShape()).
  std::size_t stateBytes() const { return arenaShape(key_bytes_ + index_bytes_).first; }
  std::size_t size() const { return arena_.size(); }
  /// Writes state `s`'s packed marking into `out` (words() words), the slots left out
  /// worked out from the others.
  void load(StateId s, std::uint64_t* out) const;
  /// The same into `buffer` (resized); its data.
  const std::uint64_t* load(StateId s, std::vector<std::uint64_t>& buffer) const {
    buffer.resize(words());
    load(s, buffer.data());
    return buffer.data();
  }
  /// The 32 bits kept beside state `s` (Store made with `index`).
  std::uint32_t index(StateId s) const {
    std::uint32_t v = 0;
    std::memcpy(&v, arena_.at(s) + key_bytes_, sizeof v);
    return v;
  }
  void setIndex(StateId s, std::uint32_t v) { std::memcpy(arena_.at(s) + key_bytes_, &v, sizeof v); }
  std::size_t bytes() const { return arena_.bytes() + tableBytes(); }
  /// What the table alone holds (dropIndex() frees it).
  std::size_t tableBytes() const { return table_.size() * sizeof(std::uint32_t); }
  /// Bytes the table grows by while `n` more markings are added (0 if it does not grow).
  std::size_t growthWithin(std::size_t n) const {
    if (table_.empty()) return 0;  // dropped: nothing more is added
    std::size_t capacity = table_.size();
    while ((size() + n) * 10 > capacity * 7) capacity *= 2;
    return (capacity - table_.size()) * sizeof(std::uint32_t);
  }
  /// Bytes the table grows by as the `n` markings `key(j)`, of hashes `hash(j)`, are
  /// inserted: near a growth point only those not stored yet count (a lookup each, there
  /// alone).
  template <class Key, class Hash>
  std::size_t growthInserting(std::size_t n, Key key, Hash hash) const {
    if (growthWithin(n) == 0) return 0;
    std::size_t fresh = 0;
    for (std::size_t j = 0; j < n; ++j) {
      if (find(key(j), hash(j)) == kNone) ++fresh;
    }
    return growthWithin(fresh);
  }

  /// The hash of a packed marking: of the words that hold its kept fields.
  std::uint64_t hash(const std::uint64_t* m) const { return hashWords(m, layout_.keyWords()); }
  void prefetch(std::uint64_t h) const { __builtin_prefetch(&table_[h & (table_.size() - 1)]); }
  /// The first state whose hash tag matches `h` (likely the marking itself), or kNone; its
  /// marking is fetched into the cache, so that a find or insert that follows waits less.
  StateId peek(std::uint64_t h) const {
    const std::uint32_t tag = tagOf(h);
    for (std::size_t i = h & (table_.size() - 1);; i = (i + 1) & (table_.size() - 1)) {
      const std::uint32_t e = table_[i];
      if (e == kEmpty) return kNone;
      if ((e & ~id_mask_) == tag) {
        __builtin_prefetch(arena_.at(e & id_mask_));
        return e & id_mask_;
      }
    }
  }

  /// The id of the packed marking `m`, or kNone.
  StateId find(const std::uint64_t* m, std::uint64_t h) const {
    const std::uint32_t tag = tagOf(h);
    for (std::size_t i = h & (table_.size() - 1);; i = (i + 1) & (table_.size() - 1)) {
      const std::uint32_t e = table_[i];
      if (e == kEmpty) return kNone;
      if ((e & ~id_mask_) == tag && same(e & id_mask_, m)) return e & id_mask_;
    }
  }
  /// The same, where peek(h) gave `peeked` (a stored state, or kNone): when that is `m`'s
  /// state, the table is not probed again.
  StateId find(const std::uint64_t* m, std::uint64_t h, StateId peeked) const {
    return isState(peeked, m) ? peeked : find(m, h);
  }
  /// The id of `m`, adding it when new (`added` says which). The table grows only as a new
  /// marking is added (growthWithin() counts those alone).
  StateId insert(const std::uint64_t* m, std::uint64_t h, bool& added) {
    // inlined where the search looks up each successor: most are stored already, and a new
    // one is added out of line
    const std::uint32_t tag = tagOf(h);
    const std::uint32_t* table = table_.data();
    const std::size_t mask = table_.size() - 1;
    for (std::size_t i = h & mask;; i = (i + 1) & mask) {
      const std::uint32_t e = table[i];
      if (e == kEmpty) return add(m, h, i, added);
      if ((e & ~id_mask_) == tag && same(e & id_mask_, m)) {
        added = false;
        return e & id_mask_;
      }
    }
  }
  /// The same, where peek(h) gave `peeked` (a stored state, or kNone): when that is `m`'s
  /// state, the table is not probed again.
  StateId insert(const std::uint64_t* m, std::uint64_t h, StateId peeked, bool& added) {
    if (isState(peeked, m)) {
      added = false;
      return peeked;
    }
    return insert(m, h, added);
  }
  /// Frees the table: the markings stay readable by id (load(), index()), but none can be
  /// looked up or added any more.
  void dropIndex() { decltype(table_)().swap(table_); }
  /// Re-packs every marking into `layout` (wider fields), keeping the ids. A store that
  /// leaves no slot out only.
  void relayout(Layout layout);

 private:
  static constexpr std::uint32_t kEmpty = 0xffffffffu;
  /// The hash's top bits that a table entry keeps above the id.
  std::uint32_t tagOf(std::uint64_t h) const { return static_cast<std::uint32_t>((h >> 32) & ~std::uint64_t{id_mask_}); }
  /// Adds `m` (hash `h`) at table slot `i`, the first empty one of its probe, or, where the
  /// table is due to grow, into the grown table.
  StateId add(const std::uint64_t* m, std::uint64_t h, std::size_t i, bool& added);
  /// Whether `s` (a stored state, or kNone) is the marking `m`.
  bool isState(StateId s, const std::uint64_t* m) const { return s != kNone && same(s, m); }
  /// The eight bytes at `p`, as a word (a state's bytes lie at any address).
  static std::uint64_t word(const unsigned char* p) {
    std::uint64_t x = 0;
    std::memcpy(&x, p, sizeof x);
    return x;
  }
  /// Word by word, not through a call to memcmp: the last word read where the one before it
  /// ends (overlapping), a key of under eight bytes under a mask. (A marking of one word has
  /// a key of eight bytes at most: GCC, inlining this where one is passed, cannot see that the
  /// longer reads are never made.)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
  bool same(StateId s, const std::uint64_t* m) const {
    const unsigned char* a = arena_.at(s);
    const auto* b = reinterpret_cast<const unsigned char*>(m);
    if (key_bytes_ <= 8) return ((word(a) ^ word(b)) & low_mask_) == 0;
    std::size_t i = 0;
    for (; i + 8 <= key_bytes_; i += 8) {
      if (word(a + i) != word(b + i)) return false;
    }
    return i == key_bytes_ || word(a + key_bytes_ - 8) == word(b + key_bytes_ - 8);
  }
#pragma GCC diagnostic pop
  void grow() { rehash(table_.size() * 2); }
  void rehash(std::size_t capacity);
  Layout layout_;
  std::size_t key_bytes_ = 0;    // Layout::keyBytes()
  std::uint64_t low_mask_ = 0;   // the bits of a key's first word where it has under eight bytes
  std::size_t index_bytes_ = 0;  // 4 with an index, else 0
  std::uint32_t id_mask_ = 0;    // the bits of a table entry that hold the id
  Chunked<unsigned char> arena_;
  std::vector<std::uint32_t, core::LargeAllocator<std::uint32_t>> table_;
  // the slots left out, worked out in turn as a marking is read: a sum of weighted counts of
  // set bits over one-token fields by word, and of weighted counts of the other fields
  struct Rule {
    std::uint32_t slot = 0;
    std::uint32_t bits = 0, fields = 0;  // where its terms begin in bit_terms_ and field_terms_
    std::int64_t constant = 0, divisor = 1;
  };
  struct BitTerm {
    std::uint32_t word = 0;
    std::uint64_t mask = 0;
    std::int64_t weight = 0;
  };
  struct FieldTerm {
    std::uint32_t slot = 0;
    std::int64_t weight = 0;
  };
  std::vector<Rule> rules_;  // then one past the last, where the terms end
  std::vector<BitTerm> bit_terms_;
  std::vector<FieldTerm> field_terms_;
};

class Firing;

/// The transitions that may be enabled in a packed marking, found from its marked place
/// slots rather than by trying every transition: each transition is watched through one
/// place slot it takes from or tests (the one the fewest transitions take from: a local
/// state rather than a shared resource) and can be enabled only while that slot holds tokens;
/// a transition that takes from and tests nothing is always a candidate.
class Candidates {
 public:
  /// Which way the candidates fire: forward, each transition watched through a place slot it
  /// takes from or tests; backward (the transitions that may have led to a marking), through
  /// a place slot it puts tokens into (the one the fewest transitions put into).
  enum class Way : std::uint8_t { Forward, Backward };
  explicit Candidates(const Net& net, Way way = Way::Forward);
  /// Reads where the fields lie; call again after the layout changes.
  void use(const Layout& layout);
  /// The candidates in `m`, in an order fixed by `m` (the order every search fires them in),
  /// into `out`: the watchers of its marked slots that `firing` finds ready.
  void find(const std::uint64_t* m, const Firing& firing, std::vector<TransitionId>& out) const;
  /// Backward: the transitions whose firing may have given `m` (the watchers of its marked
  /// slots), into `out`.
  void findBackward(const std::uint64_t* m, std::vector<TransitionId>& out) const;

 private:
  // a watcher, and bits of one word of the marking that must be set for it to be enabled
  // (those of one-bit fields it takes from or tests; none where it has no such field): a
  // filter that spares most watchers not enabled the look at their arcs
  struct Watcher {
    TransitionId t{0};
    std::uint32_t word = 0;
    std::uint64_t bits = 0;
  };
  const Net* net_;
  Way way_;
  std::vector<std::uint32_t> begin_;    // per place slot: its watchers in watchers_ from here
  std::vector<Watcher> watchers_;
  std::vector<TransitionId> always_;
  std::vector<std::uint32_t> field_at_;  // per bit of a packed marking: the field it lies in
  std::vector<std::uint64_t> watched_;   // per word: the bits of fields some transition watches
  std::vector<std::uint64_t> masks_;     // per field: its bits in place in its word
};

/// What firing a transition on a packed marking gave.
enum class Fired : std::uint8_t { Ok, NotEnabled, TooBig };

/// Each transition's arcs compiled for one layout: the bit-field tests its enabling makes
/// and the changes its firing makes, read from flat arrays rather than through the net.
/// A bounded field holds a count within its place slot's bound in every marking a search
/// meets, so a firing changes such fields by one addition per word: no count borrows from or
/// carries into its neighbour. The others are changed one by one and checked.
class Firing {
 public:
  explicit Firing(const Net& net) : net_(net) {}
  /// Compiles the arcs for `layout`; call again after the layout changes.
  void use(const Layout& layout);
  /// True when the one-bit fields `t` takes one token from or tests hold it in `m`: the
  /// quick part of enabled().
  bool ready(TransitionId t, const std::uint64_t* m) const {
    for (std::uint32_t i = spans_[t].needs; i < spans_[t + 1].needs; ++i) {
      if ((m[needs_[i].word] & needs_[i].bits) != needs_[i].bits) return false;
    }
    return true;
  }
  /// True when `t` is enabled in the packed marking `m` (sensor conditions count as true).
  bool enabled(TransitionId t, const std::uint64_t* m) const { return ready(t, m) && passes(t, m); }
  /// The rest of enabled(): the counts `t` tests lie within their ranges.
  bool passes(TransitionId t, const std::uint64_t* m) const {
    for (std::uint32_t i = spans_[t].tests; i < spans_[t + 1].tests; ++i) {
      const Test& x = tests_[i];
      const std::uint64_t c = (m[x.word] >> x.shift) & x.mask;
      if ((c < x.lo || c > x.hi) && !(x.omega && c == x.mask)) return false;
    }
    return true;
  }
  /// Fires `t` on `m` into `out`. TooBig (with the field in `field`) when a count does not fit.
  Fired fire(TransitionId t, const std::uint64_t* m, std::uint64_t* out, std::size_t& field) const {
    if (!ready(t, m)) return Fired::NotEnabled;
    return fireReady(t, m, out, field);
  }
  /// The same for a transition ready() in `m` (Candidates::find gives only such).
  Fired fireReady(TransitionId t, const std::uint64_t* m, std::uint64_t* out, std::size_t& field) const {
    if (!passes(t, m)) return Fired::NotEnabled;
    return fireEnabled(t, m, out, field);
  }
  /// The marking that firing `t` turned into `m`, into `out`: each count `t` changes less what
  /// it added; false where one leaves its field (no marking gives `m` by `t`). Whether `t` is
  /// enabled in `out` is not asked. Markings without ω only.
  bool unfire(TransitionId t, const std::uint64_t* m, std::uint64_t* out) const {
    copy(m, out);
    for (std::uint32_t i = spans_[t].deltas; i < spans_[t + 1].deltas; ++i) {
      const Change& x = deltas_[i];
      const auto before = static_cast<std::int64_t>((out[x.word] >> x.shift) & x.mask) - x.delta;
      if (before < 0 || static_cast<std::uint64_t>(before) > x.max) return false;
      out[x.word] = (out[x.word] & ~(x.mask << x.shift)) | (static_cast<std::uint64_t>(before) << x.shift);
    }
    return true;
  }
  /// Copies the packed marking `m` to `out`: markings of up to four words word by word, not
  /// through a call to memcpy.
  void copy(const std::uint64_t* m, std::uint64_t* out) const {
    switch (words_) {
      case 4: out[3] = m[3]; [[fallthrough]];
      case 3: out[2] = m[2]; [[fallthrough]];
      case 2: out[1] = m[1]; [[fallthrough]];
      case 1: out[0] = m[0]; break;
      default: std::memcpy(out, m, words_ * sizeof(std::uint64_t));
    }
  }
  /// As fire(), for a transition enabled() in `m`.
  Fired fireEnabled(TransitionId t, const std::uint64_t* m, std::uint64_t* out, std::size_t& field) const {
    copy(m, out);
    const Span& r = spans_[t];
    const Span& end = spans_[t + 1];
    for (std::uint32_t i = r.adds; i < end.adds; ++i) out[adds_[i].word] += adds_[i].add;
    for (std::uint32_t i = r.changes; i < end.changes; ++i) {
      const Change& x = changes_[i];
      const std::uint64_t c = (out[x.word] >> x.shift) & x.mask;
      if (x.omega && c == x.mask) continue;  // ω stays ω
      const std::uint64_t next = c + static_cast<std::uint64_t>(x.delta);
      if (next > x.max) {
        field = x.field;
        return Fired::TooBig;
      }
      out[x.word] = (out[x.word] & ~(x.mask << x.shift)) | (next << x.shift);
    }
    return Fired::Ok;
  }

 private:
  // one-token inputs and tests of one-bit fields: these bits of the word must be set
  struct Need {
    std::uint32_t word = 0;
    std::uint64_t bits = 0;
  };
  // enabled only if lo <= code <= hi, or the code is ω where `omega` says ω passes
  struct Test {
    std::uint32_t word = 0, shift = 0;
    std::uint64_t mask = 0, lo = 0, hi = 0;
    bool omega = false;
  };
  // the bounded fields of a word change by `add` (their deltas in place, modulo 2^64)
  struct Add {
    std::uint32_t word = 0;
    std::uint64_t add = 0;
  };
  // another field changes by delta (what the outputs add less what the inputs take), up to
  // `max`; ω, where `omega` allows it, stays ω
  struct Change {
    std::uint32_t word = 0, shift = 0, field = 0;
    bool omega = false;
    std::uint64_t mask = 0, max = 0;
    std::int64_t delta = 0;
  };
  // where a transition's entries begin in each array; they end where the next one's begin
  struct Span {
    std::uint32_t needs = 0, tests = 0, adds = 0, changes = 0, deltas = 0;
  };
  const Net& net_;
  std::size_t words_ = 0;
  std::vector<Span> spans_;  // per transition, then one past the last
  std::vector<Need> needs_;
  std::vector<Test> tests_;
  std::vector<Add> adds_;
  std::vector<Change> changes_;
  std::vector<Change> deltas_;  // every field a transition changes, bounded or not (unfire())
};

/// For each transition, the transitions whose enabling its firing may change: those with an
/// arc (input, test, inhibitor, or output to a slot with a capacity) on a place slot whose
/// count it changes. A state's enabled transitions are then its parent's with these tested
/// again, not all of them.
class Affected {
 public:
  /// Builds the lists unless they would hold more than `most` entries in all (then none is
  /// kept, and nothing is built where `most` is 0).
  Affected(const Net& net, std::size_t most);
  /// The lists were built.
  bool built() const { return !begin_.empty(); }
  /// The transitions firing `t` may enable or disable.
  std::span<const TransitionId> of(TransitionId t) const {
    return {list_.data() + begin_[t], list_.data() + begin_[t + 1]};
  }

 private:
  std::vector<std::uint32_t> begin_;  // per transition, then one past the last
  std::vector<TransitionId> list_;
};

/// Marks in `seen` the transitions enabled in `m`; returns how many were not marked before.
/// Over the states of a bottom component it gives the transitions that fire inside it.
/// `scratch` holds the candidates.
std::size_t markEnabled(const Firing& firing, const Candidates& candidates, const std::uint64_t* m,
                        std::vector<bool>& seen, std::vector<TransitionId>& scratch);

/// Whether every one of `transitions` transitions is enabled in one of the `n` markings
/// `marking(i)` gives (those of a bottom component, in which each enabled one fires): looks
/// at them in turn until all are seen, so a live net's component costs a few of its states.
/// `seen` and `scratch` are scratch space.
template <typename Marking>
bool enablesAll(const Firing& firing, const Candidates& candidates, std::size_t transitions, std::size_t n,
                Marking&& marking, std::vector<bool>& seen, std::vector<TransitionId>& scratch) {
  seen.assign(transitions, false);
  std::size_t fire = 0;
  for (std::size_t i = 0; i < n && fire < transitions; ++i) fire += markEnabled(firing, candidates, marking(i), seen, scratch);
  return fire == transitions;
}

/// How a search packs markings: field sizes from the invariants' bounds and capacities.
struct Plan {
  std::vector<std::uint32_t> bits;   ///< per place slot
  std::vector<bool> omega;           ///< per place slot: no bound known, may become ω
  std::vector<bool> accel;           ///< per place slot: may be accelerated to ω
  std::vector<std::int64_t> m0;      ///< the initial marking
  bool cover = false;                ///< some place slot has no bound: watch for ω
  bool overflow = false;             ///< an initial count is beyond what a field holds
  /// Where no slot may become ω: the slots the P-invariants give from the others, left out of
  /// stored markings, in the order they are worked out.
  std::vector<Derived> derived;
  /// The layout of the search's markings: the kept fields first, then those of `derived`.
  Layout layout() const;
};
Plan plan(const Net& net, const ExploreOptions& options);

/// The slots of `net` that the P-invariants `p` give from the others, each from one
/// invariant whose other slots are kept or given before it, for the initial marking `m0`:
/// invariants of small support first (each slot worked out costs a look at its support), of
/// each the widest field (`bits`) not in the support of one chosen before.
std::vector<Derived> derivable(const std::vector<Invariant>& p, const std::vector<std::uint32_t>& bits,
                               const std::vector<std::int64_t>& m0);

/// The lowest and highest count of each place slot, and the largest marking, over the
/// markings noted (in `layout`, which must not change between them).
struct Observed {
  std::vector<std::int64_t> low, high;  ///< per place slot, once settled
  std::int64_t max_marking = 0;
  std::vector<std::uint64_t> any, all;  ///< per word of one-token fields: OR and AND of the markings
  std::vector<bool> single;             ///< per word: all its fields hold one token at most
  std::vector<std::uint32_t> fields;    ///< the fields noted one by one (the others' words whole)
  explicit Observed(const Layout& layout);
  /// Notes every slot of `m`; returns its tokens (ω not counted).
  std::int64_t note(const Layout& layout, const std::uint64_t* m);
  /// Notes the slots `terms` touch in `m`, whose tokens are `total` (the others were noted in
  /// the marking it was reached from).
  void noteChange(const Layout& layout, const std::uint64_t* m, std::span<const Term> terms, std::int64_t total);
  void merge(const Observed& other);
  /// Fills `low` and `high` for the fields noted by word; call once all are noted.
  void settle(const Layout& layout);
  /// Goes on in `after` from what was noted in `before` (the markings were re-packed).
  void relayout(const Layout& before, const Layout& after);
};

/// Fills the answers read off the observations: place bounds, unbounded and constant places,
/// one-safeness, quasi-liveness; `out.complete`, `fired` and the counts must be set.
void summarise(const Net& net, const Observed& seen, StateSpace& out);

/// The answer for a net whose initial marking cannot be stored.
StateSpace overflowAnswer(const Net& net);

/// The most transitions a net may have for the parallel search (one state's successors lie
/// in one chunk of its arrays); a net with more is searched by one thread.
constexpr std::size_t kParallelTransitions = (std::size_t{1} << 20) - 2;
/// The parallel search (ExploreOptions::threads > 1, no place without a bound).
StateSpace exploreParallel(const Net& net, const ExploreOptions& options, const Plan& plan);

}  // namespace gdpn::net::detail
