#include "gdpn/net/analysis.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <thread>
#include <unordered_map>
#include <utility>

#include "gdpn/net/invariants.h"
#include "detail/marking_store.h"

namespace gdpn::net {
namespace {

using namespace detail;

/// Two searches of a net with place slots that no invariant, capacity or the state equation
/// bounds, one thread each: the coverability search, and one of the reachable markings that
/// never accelerates. Where the net is bounded, they walk the same states in the same order
/// (no marking on a path lies below a later one) and the plain one, spared the comparisons
/// with the path, ends first; where it is not, the plain one never ends: it gives up once it
/// holds four times the states of the other, or when the other ends.
struct Race {
  std::atomic<bool> over{false};              ///< one search is done: the other stops
  std::atomic<std::uint64_t> cover_states{0};  ///< the coverability search's states, as last noted
};

/// The search: a depth-first walk that finds strongly connected components as it goes
/// (Pearce's single-index variant of Tarjan's algorithm), so that no edge is stored.
class Search {
 public:
  /// A search of `net` laid out by `plan`; in a race, `accelerate` says which of the two.
  Search(const Net& net, const ExploreOptions& options, const Plan& plan, Race* race = nullptr, bool accelerate = true)
      : net_(net),
        options_(options),
        plan_(plan),
        race_(race),
        accelerate_(accelerate),
        candidates_(net),
        firing_(net),
        affected_(net, net.transitions().size() <= kEnabledSetTransitions ? kMostAffected * net.transitions().size() : 0),
        enabled_sets_(affected_.built()) {}

  StateSpace run();

 private:
  enum class Expand : std::uint8_t { Ok, Widened, Overflow, Full };

  /// The successors of a state: their transitions, packed markings and hashes.
  struct Successors {
    std::vector<TransitionId> t;
    std::vector<std::uint64_t> keys;
    std::vector<std::uint64_t> hashes;
    std::vector<StateId> peeked;  ///< per successor: Store::peek (empty: not peeked yet)
    /// A bit per transition: enabled in the state (where the net has at most
    /// kEnabledSetTransitions; the successors then come in the transitions' order).
    std::vector<std::uint64_t> enabled;
    std::int64_t total = 0;  ///< the tokens of the state whose successors they are
    StateId state = kNone;   ///< whose (kNone: none made ahead)
    std::size_t index = 0;   ///< made ahead: of the successor `index` of the state expanded before
  };
  /// Expands `v`: its successors looked up or added, the edges to states visited settled and
  /// the others pending in edges_, its frame pushed.
  Expand expand(StateId v);
  /// Makes the successors of the packed marking `m` into `out`, their table slots on their way
  /// into the cache.
  Expand successors(const std::uint64_t* m, Successors& out);
  /// The same for successor `i` of `parent`: its enabled transitions are the parent's with
  /// those the firing may change tested again.
  Expand successorsAfter(const Successors& parent, std::size_t i, Successors& out);
  /// Fires the transitions enabled in `m` (out.enabled) into `out`.
  Expand fireEnabled(const std::uint64_t* m, Successors& out);
  /// Empties `out` for a state's successors, with room for `n` of them; each is made at
  /// next(out), then kept. Expand::Full where that room would take the search past
  /// --max-memory (a net of 10^5 parts has markings of tens of KiB and as many successors).
  Expand reset(Successors& out, std::size_t n);
  std::uint64_t* next(Successors& out) const { return out.keys.data() + out.t.size() * store_->layout().words(); }
  /// Keeps the marking made at `key` (next(out)) as the successor by `t`: hashed, its table
  /// slot fetched.
  void keep(Successors& out, TransitionId t, const std::uint64_t* key) const {
    const std::uint64_t h = store_->hash(key);
    out.t.push_back(t);
    out.hashes.push_back(h);
    store_->prefetch(h);
  }
  /// Nets with more transitions, or whose firings each may change the enabling of more than
  /// kMostAffected transitions on average (a thousand transitions around shared places), find
  /// a state's candidates from its marked slots alone.
  static constexpr std::size_t kEnabledSetTransitions = 4096, kMostAffected = 64;
  /// The most bytes of successors' markings for which the next state's successors are made
  /// ahead (the size of the cache close to one core).
  static constexpr std::size_t kAheadBytes = std::size_t{1} << 20;
  /// Fires `t` on the packed marking `m` into `out`; Overflow or Widened on a count that
  /// does not fit. False in `enabled` when `t` is not enabled.
  Expand fire(TransitionId t, const std::uint64_t* m, std::uint64_t* out, bool& enabled) {
    std::size_t field = 0;
    return expandOf(firing_.fire(t, m, out, field), field, enabled);
  }
  /// The same for a candidate (ready in `m`).
  Expand fireCandidate(TransitionId t, const std::uint64_t* m, std::uint64_t* out, bool& enabled) {
    std::size_t field = 0;
    return expandOf(firing_.fireReady(t, m, out, field), field, enabled);
  }
  /// What a firing that gave `f` means for the search: TooBig widens `field` (Widened, or
  /// Overflow where it cannot); `enabled` says whether the transition was.
  Expand expandOf(Fired f, std::size_t field, bool& enabled) {
    enabled = f != Fired::NotEnabled;
    if (f != Fired::TooBig) return Expand::Ok;
    return widen(field) ? Expand::Widened : Expand::Overflow;
  }
  bool widen(std::size_t k);
  /// Karp-Miller acceleration of the packed marking `key` against the markings on the
  /// search path: true when some count became ω (`key` is then changed).
  bool accelerate(std::uint64_t* key);
  /// A hash of the packed counts of the slots that are never accelerated.
  std::uint64_t boundedHash(const std::uint64_t* m) const;
  /// Over the slots that may be accelerated: how many are ω, and the sum of the others'
  /// counts. Compared in that order it grows strictly with the counts: a marking below `m`
  /// on those slots (ω above any count) has a smaller one.
  /// `sketch`: 16 fields of 4 bits, slot i of accel_slots_ in field i % 16, each the most
  /// of min(count, 7) over its slots (ω: 7); below `m`, every field is at most m's.
  struct Weight {
    std::uint64_t omegas = 0, counts = 0;
    std::uint64_t sketch = 0;
    /// Whether a marking of weight `*this` may be below one of weight `w` (and not equal).
    bool mayBeBelow(const Weight& w) const {
      constexpr std::uint64_t kHigh = 0x8888888888888888ULL;
      if (std::pair(omegas, counts) >= std::pair(w.omegas, w.counts)) return false;
      // each field of w, its high bit set, less this one's: the high bit stays where w's is
      // no less (no borrow crosses: fields hold 0 to 7)
      return (((w.sketch | kHigh) - sketch) & kHigh) == kHigh;
    }
  };
  /// `values` gets the counts of those slots (kW for ω), in accel_slots_' order.
  Weight acceleratedWeight(const std::uint64_t* m, std::int64_t* values) const;
  /// The weight of those counts, given in accel_slots_' order.
  Weight weightOf(const std::int64_t* values) const;
  /// Puts the packed marking `m` on top of the search path, or takes the top one off.
  void pushPath(const std::uint64_t* m);
  void popPath();
  /// The bits of each word that hold slots never accelerated, for the current layout; and
  /// the path's hashes again after the layout changed.
  void boundedParts();
  /// Notes the new state of packed marking `m`, reached by `t` from a marking of `from`
  /// tokens (kUnknownTotal: the initial state); `accelerated`: `m` is not the firing's but
  /// got ω.
  void noteNew(const std::uint64_t* m, std::int64_t from, TransitionId t, bool accelerated);
  void finishComponent(StateId v);
  /// A shortest firing sequence to a dead state: breadth first over the states stored,
  /// ending at the first dead one it generates.
  void shortestPathToDeadlock(StateSpace& out);
  /// The path to the first dead state the search met, from the search path it had then:
  /// each step the transition to the furthest state of that path one firing reaches.
  // the transitions that lead along `path`, a search path of states (skipping ahead where a
  // later state of it is a successor); empty when it cannot be followed
  std::vector<TransitionId> firingsAlong(const std::vector<StateId>& path);
  std::uint64_t bytes() const;

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
    if (rw < rindex(f.state())) setRindex(f.state(), rw), f.v_root &= 0x7fffffffu;
    if (rw > next_comp_) leaves_[f.state()] = true;  // w's component is finished: an edge leaves
  }

  const Net& net_;
  const ExploreOptions& options_;
  const Plan& plan_;
  Race* race_ = nullptr;
  bool accelerate_ = true;  // false: the plain search of a race
  bool widens_ = false;     // some field may outgrow its bits (no bound known): no look-ahead
  std::unique_ptr<Store> store_;
  Candidates candidates_;
  Firing firing_;
  Affected affected_;
  bool enabled_sets_ = false;  // affected_ was built: a state's enabled set from its parent's
  std::vector<bool> accel_;   // per place slot: may be accelerated to ω
  std::vector<std::size_t> accel_slots_;  // those place slots
  bool cover_ = false;        // some place slot has no structural bound
  std::vector<std::uint64_t> path_;  // packed markings on the search path (cover_ only)
  std::vector<std::uint64_t> path_hash_;  // per position on the path: boundedHash
  struct OnPath {
    Weight weight;           // acceleratedWeight
    std::uint32_t position;  // on the path
  };
  std::vector<std::uint64_t> bounded_mask_;  // per word: the bits of slots never accelerated
  // boundedHash: the markings on the path with it, bottom first (scanned in a row)
  std::unordered_map<std::uint64_t, std::vector<OnPath>> on_path_;
  std::uint64_t edges_count_ = 0;
  ExploreStop stop_ = ExploreStop::Done;

  // per state
  // a state's index (Pearce's rindex) lies beside its marking in the store: read once per edge
  std::uint32_t rindex(StateId s) const { return store_->index(s); }
  void setRindex(StateId s, std::uint32_t v) { store_->setIndex(s, v); }
  static constexpr std::int64_t kUnknownTotal = -1;
  std::vector<std::int64_t> token_delta_;  // per transition: tokens it adds minus tokens it takes
  std::vector<bool> leaves_;
  std::vector<std::uint64_t> visited_;  // a bit per state: visited
  bool visited(StateId s) const { return (s >> 6) < visited_.size() && ((visited_[s >> 6] >> (s & 63)) & 1) != 0; }
  // the walk
  Chunked<Frame> frames_;
  Chunked<StateId> edges_;
  Chunked<StateId> stack_;
  std::uint32_t next_index_ = 1;
  std::uint32_t next_comp_ = 0xfffffffeu;
  // scratch
  // the successors of the state expanded, and those of the state the walk visits next, made
  // while the first wait on the memory
  Successors now_, ahead_;
  std::vector<TransitionId> candidates_now_;
  std::vector<std::uint64_t> loaded_;  // a stored marking, read back
  std::vector<std::int64_t> unpacked_;
  std::vector<bool> union_;
  // answers
  std::unique_ptr<Observed> seen_;
  std::vector<bool> fired_;
  bool deadlock_ = false;
  std::vector<std::vector<StateId>> dead_paths_;  // the search paths to the first kDeadPaths dead states
  std::uint64_t dead_count_ = 0;
  std::vector<StateId> dead_states_;  // every dead state (for a shortest path only)
  bool live_ = true;
  std::uint32_t bottoms_ = 0;
  bool root_bottom_ = false;
  std::uint64_t peak_ = 0;
};

bool Search::widen(std::size_t k) {
  const Layout& L = store_->layout();
  if (L.bits(k) >= kMaxBits) return false;
  std::vector<std::uint32_t> bits(L.width());
  std::vector<bool> omega(L.width());
  for (std::size_t j = 0; j < L.width(); ++j) bits[j] = L.bits(j), omega[j] = L.field(j).omega;
  // four times the bits, for every field that may become ω and is no wider: a count that
  // outgrows its field tends to go on growing, the others like it too, and each widening
  // re-packs every marking stored
  const std::uint32_t from = bits[k];
  for (std::size_t j = 0; j < L.width(); ++j) {
    if (j == k || (omega[j] && bits[j] <= from)) bits[j] = std::min(kMaxBits, bits[j] * 4);
  }
  const Layout before = L;
  store_->relayout(Layout::omegaOrBounded(bits, omega));
  seen_->relayout(before, store_->layout());
  candidates_.use(store_->layout());
  firing_.use(store_->layout());
  if (cover_) {
    // the path's markings in the new layout, and their hashes
    const Layout& after = store_->layout();
    std::vector<std::uint64_t> path(path_hash_.size() * after.words());
    std::vector<std::int64_t> m(after.width());
    for (std::size_t i = 0; i < path_hash_.size(); ++i) {
      before.unpack(path_.data() + i * before.words(), m.data());
      std::size_t bad = 0;
      after.pack(m.data(), path.data() + i * after.words(), bad);
    }
    path_ = std::move(path);
    boundedParts();
  }
  return true;
}

void Search::boundedParts() {
  const Layout& L = store_->layout();
  bounded_mask_.assign(L.words(), 0);
  for (std::size_t k = 0; k < L.width(); ++k) {
    if (!accel_[k]) bounded_mask_[L.field(k).word] |= L.field(k).mask << L.field(k).shift;
  }
  on_path_.clear();
  const std::vector<std::uint64_t> path = std::move(path_);
  const std::size_t n = path_hash_.size();
  path_.clear();
  path_hash_.clear();
  for (std::size_t i = 0; i < n; ++i) pushPath(path.data() + i * L.words());
}

Search::Weight Search::acceleratedWeight(const std::uint64_t* m, std::int64_t* values) const {
  const Layout& L = store_->layout();
  for (std::size_t i = 0; i < accel_slots_.size(); ++i) values[i] = L.value(m, accel_slots_[i]);
  return weightOf(values);
}

Search::Weight Search::weightOf(const std::int64_t* values) const {
  Weight w;
  for (std::size_t i = 0; i < accel_slots_.size(); ++i) {
    const std::int64_t v = values[i];
    if (v == kW) {
      ++w.omegas;
    } else {
      w.counts += static_cast<std::uint64_t>(v);  // below 2^32 each: no overflow
    }
    const unsigned shift = 4 * static_cast<unsigned>(i % 16);
    const std::uint64_t c = v == kW ? 7 : static_cast<std::uint64_t>(std::min<std::int64_t>(v, 7));
    if (c > ((w.sketch >> shift) & 7)) w.sketch = (w.sketch & ~(std::uint64_t{15} << shift)) | (c << shift);
  }
  return w;
}

void Search::pushPath(const std::uint64_t* m) {
  const std::size_t words = store_->words();
  path_.insert(path_.end(), m, m + words);
  const std::uint64_t h = boundedHash(m);
  unpacked_.resize(accel_slots_.size());
  on_path_[h].push_back({acceleratedWeight(m, unpacked_.data()), static_cast<std::uint32_t>(path_hash_.size())});
  path_hash_.push_back(h);
}

void Search::popPath() {
  path_.resize(path_.size() - store_->words());
  const auto bucket = on_path_.find(path_hash_.back());
  bucket->second.pop_back();
  if (bucket->second.empty()) on_path_.erase(bucket);
  path_hash_.pop_back();
}

std::uint64_t Search::boundedHash(const std::uint64_t* m) const {
  std::uint64_t h = 0x243f6a8885a308d3ULL;
  for (std::size_t w = 0; w < bounded_mask_.size(); ++w) {
    h = (h ^ (m[w] & bounded_mask_[w])) * 0x9e3779b97f4a7c15ULL;
    h ^= h >> 29;
  }
  return h;
}

bool Search::accelerate(std::uint64_t* key) {
  // a marking on the path can be below the key only where it agrees with it on every slot
  // that is never accelerated: only those with the same such part are compared, on the
  // slots that may be accelerated, and only where their weight (acceleratedWeight) allows it
  const auto bucket = on_path_.find(boundedHash(key));
  if (bucket == on_path_.end()) return false;
  const Layout& L = store_->layout();
  const std::size_t words = L.words();
  // the key's counts on those slots; a marking of less weight that is nowhere above them is
  // below the key (and not equal to it). Each one below makes ω where the key is greater, and
  // the markings after it (bottom first) are compared with the key so accelerated
  std::vector<std::int64_t>& m = unpacked_;
  m.resize(accel_slots_.size());
  Weight weight = acceleratedWeight(key, m.data());
  bool changed = false;
  for (const OnPath& below : bucket->second) {
    if (!below.weight.mayBeBelow(weight)) continue;
    const std::uint64_t* a = path_.data() + static_cast<std::size_t>(below.position) * words;
    bool ge = true;
    for (std::size_t i = 0; i < accel_slots_.size() && ge; ++i) ge = m[i] >= L.value(a, accel_slots_[i]);
    for (std::size_t w = 0; w < words && ge; ++w) ge = ((a[w] ^ key[w]) & bounded_mask_[w]) == 0;
    if (!ge) continue;
    for (std::size_t i = 0; i < accel_slots_.size(); ++i) {
      if (m[i] > L.value(a, accel_slots_[i])) m[i] = kW, changed = true;
    }
    weight = weightOf(m.data());
  }
  if (!changed) return false;
  std::vector<std::int64_t> all(L.width());
  L.unpack(key, all.data());
  for (std::size_t i = 0; i < accel_slots_.size(); ++i) all[accel_slots_[i]] = m[i];
  std::size_t bad = 0;
  L.pack(all.data(), key, bad);  // ω always fits
  return true;
}

Search::Expand Search::successors(const std::uint64_t* m, Successors& out) {
  out.total = store_->layout().tokens(m);
  candidates_.find(m, firing_, candidates_now_);
  if (enabled_sets_) {
    out.enabled.assign((net_.transitions().size() + 63) / 64, 0);
    for (TransitionId t : candidates_now_) {
      if (firing_.passes(t, m)) out.enabled[t >> 6] |= std::uint64_t{1} << (t & 63);
    }
    return fireEnabled(m, out);
  }
  if (const Expand e = reset(out, candidates_now_.size()); e != Expand::Ok) return e;
  for (TransitionId t : candidates_now_) {
    bool enabled = false;
    const Expand e = fireCandidate(t, m, next(out), enabled);
    if (e != Expand::Ok) return e;
    if (enabled) keep(out, t, next(out));
  }
  return Expand::Ok;
}

Search::Expand Search::reset(Successors& out, std::size_t n) {
  const std::size_t words = n * store_->layout().words();
  if (words > out.keys.capacity()) {
    // a quarter more, so that a few more successors later do not move it again; the old
    // room let go first (what it holds is made anew), so that it is never held twice
    const std::size_t room = words + words / 4;
    if (options_.max_bytes != 0 && bytes() + (room - out.keys.capacity()) * sizeof(std::uint64_t) > options_.max_bytes) {
      return Expand::Full;
    }
    std::vector<std::uint64_t>().swap(out.keys);
    out.keys.reserve(room);
  }
  if (words > out.keys.size()) out.keys.resize(words);
  out.hashes.clear();
  out.t.clear();
  out.peeked.clear();
  return Expand::Ok;
}

Search::Expand Search::successorsAfter(const Successors& parent, std::size_t i, Successors& out) {
  const std::uint64_t* m = parent.keys.data() + i * store_->layout().words();
  if (!enabled_sets_) return successors(m, out);
  out.total = parent.total + token_delta_[parent.t[i]];
  out.enabled = parent.enabled;
  for (const TransitionId u : affected_.of(parent.t[i])) {
    const std::uint64_t bit = std::uint64_t{1} << (u & 63);
    out.enabled[u >> 6] = firing_.enabled(u, m) ? out.enabled[u >> 6] | bit : out.enabled[u >> 6] & ~bit;
  }
  return fireEnabled(m, out);
}

Search::Expand Search::fireEnabled(const std::uint64_t* m, Successors& out) {
  std::size_t count = 0;
  for (const std::uint64_t x : out.enabled) count += static_cast<std::size_t>(std::popcount(x));
  if (const Expand e = reset(out, count); e != Expand::Ok) return e;
  const std::size_t words = store_->layout().words();
  std::uint64_t* key = out.keys.data();
  const std::uint64_t* bits = out.enabled.data();
  for (std::size_t w = 0, n = out.enabled.size(); w < n; ++w) {
    for (std::uint64_t x = bits[w]; x != 0; x &= x - 1) {
      const auto t = static_cast<TransitionId>(w * 64 + static_cast<std::size_t>(std::countr_zero(x)));
      std::size_t field = 0;
      bool enabled = false;
      const Expand e = expandOf(firing_.fireEnabled(t, m, key, field), field, enabled);
      if (e != Expand::Ok) return e;
      keep(out, t, key);
      key += words;
    }
  }
  return Expand::Ok;
}

Search::Expand Search::expand(StateId v) {
  const std::size_t words = store_->layout().words();
  if (ahead_.state == v) {
    std::swap(now_, ahead_);
  } else if (const Expand e = successors(store_->load(v, loaded_), now_); e != Expand::Ok) {
    return e;
  }
  ahead_.state = kNone;
  const std::vector<TransitionId>& via = now_.t;
  // the markings the successors likely are (and their index beside them) fetched into the
  // cache while the others are looked up (made ahead, they were fetched already)
  auto peek = [&](Successors& x) {
    x.peeked.resize(x.t.size());
    for (std::size_t i = 0; i < x.t.size(); ++i) x.peeked[i] = store_->peek(x.hashes[i]);
  };
  if (now_.peeked.size() != via.size()) peek(now_);
  // the walk goes on with the last successor not visited (it is pushed last): found so, its
  // successors are made now and their slots fetched while this state's lookups wait on the
  // memory, and their markings once these are done. A state found by its hash's tag alone
  // may be another: then nothing comes of it. Not where a field may widen (the markings are
  // laid out anew) or accelerate, nor where the successors outgrow the cache close to the
  // core (they would not stay there), nor where making them would pass --max-memory
  ahead_.index = via.size();
  const bool small = via.size() * words * sizeof(std::uint64_t) <= kAheadBytes;
  for (std::size_t i = via.size(); i-- > 0 && !widens_ && small;) {
    if (now_.peeked[i] == kNone || !visited(now_.peeked[i])) {
      ahead_.index = i;
      break;
    }
  }
  if (ahead_.index < via.size() && successorsAfter(now_, ahead_.index, ahead_) != Expand::Ok) ahead_.index = via.size();
  // markings and a table that would grow past --max-memory stop the search before they grow
  // (the markings counted as if every successor were new, and where that passes the limit,
  // only those not stored yet)
  if (options_.max_bytes != 0) {
    auto key = [&](std::size_t i) { return now_.keys.data() + i * words; };
    auto hash = [&](std::size_t i) { return now_.hashes[i]; };
    const std::size_t table = store_->growthInserting(via.size(), key, hash);
    const std::size_t marking = store_->stateBytes();
    const std::uint64_t held = bytes() + table;
    std::size_t fresh = via.size();
    if (held + fresh * marking > options_.max_bytes) {
      fresh = 0;
      for (std::size_t i = 0; i < via.size(); ++i) fresh += store_->find(key(i), hash(i)) == kNone ? 1u : 0u;
    }
    if (held + fresh * marking > options_.max_bytes) return Expand::Full;
  }
  std::uint32_t rv = rindex(v);
  bool root = true;
  for (std::size_t i = 0; i < via.size(); ++i) {
    std::uint64_t* key = now_.keys.data() + i * words;
    std::uint64_t h = now_.hashes[i];
    const bool accelerated = cover_ && store_->find(key, h) == kNone && accelerate(key);
    if (accelerated) h = store_->hash(key);
    bool added = false;
    const StateId w = store_->insert(key, h, now_.peeked[i], added);
    if (added) noteNew(key, now_.total, via[i], accelerated);
    if (i == ahead_.index) ahead_.state = w;
    fired_[via[i]] = true;
    // an edge to a state already visited is settled now; the others wait in edges_
    const std::uint32_t rw = rindex(w);
    if (rw == 0) {
      edges_.push(w);
      continue;
    }
    if (rw < rv) rv = rw, root = false;
    if (rw > next_comp_) leaves_[v] = true;  // w's component is finished: an edge leaves
  }
  if (ahead_.state != kNone) peek(ahead_);
  setRindex(v, rv);
  edges_count_ += via.size();
  if (via.empty() && options_.shortest_path) dead_states_.push_back(v);
  if (via.empty()) {
    // the first few dead states: the search path to each (the frames' states, then v)
    deadlock_ = true;
    ++dead_count_;
    if (dead_paths_.size() < kDeadPaths) {
      auto& path = dead_paths_.emplace_back();
      for (std::size_t i = 0; i < frames_.size(); ++i) path.push_back(frames_[i].state());
      path.push_back(v);
    }
  }
  frames_.push({v | (root ? 0x80000000u : 0u), static_cast<std::uint32_t>(edges_.size())});
  return Expand::Ok;
}

void Search::noteNew(const std::uint64_t* m, std::int64_t from, TransitionId t, bool accelerated) {
  // a successor's tokens are its parent's and what the transition changes, and only the
  // slots it touches need noting; where acceleration, ω on a slot it touches or a large count
  // stands in the way, every slot (the tokens counted leave out ω)
  const Layout& L = store_->layout();
  auto touchesOmega = [&] {
    for (const Term& term : net_.termsOf(t)) {
      if ((term.kind == TermKind::Input || term.kind == TermKind::Output) && L.value(m, term.place_slot) == kW) return true;
    }
    return false;
  };
  if (from != kUnknownTotal && !accelerated && !(cover_ && touchesOmega())) {
    seen_->noteChange(L, m, net_.termsOf(t), from + token_delta_[t]);
  } else {
    seen_->note(L, m);
  }
  leaves_.push_back(false);
}

void Search::finishComponent(StateId v) {
  // the component: v and the states above it on the stack (all of them where v is the
  // search's first state: its index is the lowest; nothing reads their indexes after it)
  const bool last = frames_.empty();
  std::size_t first = last ? 0 : stack_.size();
  while (first > 0 && rindex(stack_[first - 1]) >= rindex(v)) --first;
  const std::size_t size = stack_.size();
  // a component of every state has no edge that leaves it
  const bool every = size - first + 1 == store_->size();
  bool leaves = leaves_[v];
  for (std::size_t i = first; i < size && !every; ++i) leaves = leaves || leaves_[stack_[i]];
  if (!leaves) {
    // a bottom component: every edge stays inside, so the transitions that fire inside it
    // are those enabled in its states
    ++bottoms_;
    if (live_ && every) {
      // the transitions fired inside are all those fired
      live_ = std::all_of(fired_.begin(), fired_.end(), [](bool f) { return f; });
    } else if (live_) {
      auto marking = [&](std::size_t i) { return store_->load(i == 0 ? v : stack_[first + i - 1], loaded_); };
      live_ = enablesAll(firing_, candidates_, net_.transitions().size(), size - first + 1, marking, union_, candidates_now_);
    }
  }
  root_bottom_ = !leaves;
  for (std::size_t i = first; i < size && !last; ++i) setRindex(stack_[i], next_comp_);
  setRindex(v, next_comp_);
  --next_comp_;
  stack_.shrink(first);
}

std::uint64_t Search::bytes() const {
  return store_->bytes() + leaves_.capacity() / 8 + visited_.capacity() * sizeof(std::uint64_t) + frames_.bytes() +
         edges_.bytes() + stack_.bytes() + path_.capacity() * sizeof(std::uint64_t) +
         (now_.keys.capacity() + ahead_.keys.capacity()) * sizeof(std::uint64_t);
}

std::vector<TransitionId> Search::firingsAlong(const std::vector<StateId>& path) {
  std::vector<TransitionId> out;
  if (path.size() < 2) return out;
  std::unordered_map<StateId, std::size_t> position;
  for (std::size_t i = 0; i < path.size(); ++i) position.emplace(path[i], i);
  const Layout& L = store_->layout();
  std::vector<std::uint64_t> next(store_->words()), here, there;
  // in a coverability graph a stored successor may be the accelerated form: ω where the
  // firing gave a number
  auto covers = [&](StateId s, const std::uint64_t* m) {
    const std::uint64_t* stored = store_->load(s, there);
    for (std::size_t k = 0; k < L.width(); ++k) {
      const std::int64_t v = L.value(stored, k);
      if (v != kW && v != L.value(m, k)) return false;
    }
    return true;
  };
  for (std::size_t i = 0; i + 1 < path.size();) {
    std::size_t best = i;
    TransitionId via{0};
    const std::uint64_t* m = store_->load(path[i], here);
    candidates_.find(m, firing_, candidates_now_);
    for (TransitionId t : candidates_now_) {
      bool enabled = false;
      if (fire(t, m, next.data(), enabled) != Expand::Ok || !enabled) continue;
      const StateId w = store_->find(next.data(), store_->hash(next.data()));
      std::size_t j = i;
      if (w != kNone) {
        const auto at = position.find(w);
        if (at != position.end()) j = at->second;
      } else if (cover_ && covers(path[i + 1], next.data())) {
        j = i + 1;
      }
      if (j > best) best = j, via = t;
    }
    if (best == i) return {};  // cannot happen: the next state on the path is a successor
    out.push_back(via);
    i = best;
  }
  return out;
}

void Search::shortestPathToDeadlock(StateSpace& out) {
  // breadth first over the known states, ending at the first dead state it meets (the search
  // noted which ones are dead)
  const std::size_t n = store_->size();
  std::vector<bool> dead(n, false);
  for (StateId s : dead_states_) dead[s] = true;
  std::vector<StateId> parent(n, kNone);
  std::vector<TransitionId> via(n);
  std::vector<StateId> queue{0};
  parent[0] = 0;
  const std::size_t words = store_->words();
  std::vector<std::uint64_t> next(words);
  auto pathTo = [&](StateId x) {
    for (; x != 0; x = parent[x]) out.deadlock_path.push_back(via[x]);
    std::reverse(out.deadlock_path.begin(), out.deadlock_path.end());
  };
  if (dead[0]) return;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const StateId s = queue[head];
    const std::uint64_t* m = store_->load(s, loaded_);
    candidates_.find(m, firing_, candidates_now_);
    for (TransitionId t : candidates_now_) {
      bool enabled = false;
      fire(t, m, next.data(), enabled);
      if (!enabled) continue;
      // the search stored the accelerated form (against the path it had then: gone now)
      if (cover_ && store_->find(next.data(), store_->hash(next.data())) == kNone) accelerate(next.data());
      const StateId w = store_->find(next.data(), store_->hash(next.data()));
      if (w == kNone || parent[w] != kNone) continue;
      parent[w] = s;
      via[w] = t;
      if (dead[w]) return pathTo(w);
      queue.push_back(w);
    }
  }
}

StateSpace Search::run() {
  StateSpace out;
  const std::size_t transitions = net_.transitions().size();

  const Plan& p = plan_;
  cover_ = p.cover && accelerate_;
  widens_ = p.cover;
  token_delta_.assign(transitions, 0);
  for (TransitionId t{0}; t < transitions; ++t) {
    for (const Term& term : net_.termsOf(t)) {
      if (term.kind == TermKind::Input) token_delta_[t] -= term.weight;
      if (term.kind == TermKind::Output) token_delta_[t] += term.weight;
    }
  }
  accel_ = p.accel;
  for (std::size_t k = 0; k < accel_.size(); ++k) {
    if (accel_[k]) accel_slots_.push_back(k);
  }
  store_ = std::make_unique<Store>(p.layout(), true, p.derived);
  candidates_.use(store_->layout());
  firing_.use(store_->layout());
  if (cover_) boundedParts();
  std::vector<std::uint64_t> key(store_->words());
  std::size_t bad = 0;
  store_->layout().pack(p.m0.data(), key.data(), bad);
  seen_ = std::make_unique<Observed>(store_->layout());
  fired_.assign(transitions, false);
  bool added = false;
  store_->insert(key.data(), store_->hash(key.data()), added);
  noteNew(key.data(), kUnknownTotal, TransitionId{0}, false);

  auto visit = [&](StateId v) -> bool {
    setRindex(v, next_index_++);
    if ((v >> 6) >= visited_.size()) visited_.resize(std::max<std::size_t>(1024, visited_.size() * 2), 0);
    visited_[v >> 6] |= std::uint64_t{1} << (v & 63);
    if (cover_) pushPath(store_->load(v, loaded_));
    for (;;) {
      const Expand e = expand(v);
      if (e == Expand::Ok) return true;
      if (e == Expand::Overflow || e == Expand::Full) {
        stop_ = e == Expand::Full ? ExploreStop::MaxMemory : ExploreStop::Overflow;
        return false;
      }
      // a field grew: the markings were re-packed; compute the successors again
    }
  };

  std::uint64_t next_report = 1 << 12, pops = 0;
  // the limits of memory and time: looked at every 4,096 new states, and every 4,096 states
  // done, for the walk back holds more as it goes (the stack of states whose component is
  // not finished) while it finds no new state
  auto withinLimits = [&](std::uint64_t b) {
    if (options_.max_bytes != 0 && b > options_.max_bytes) stop_ = ExploreStop::MaxMemory;
    if (options_.deadline && std::chrono::steady_clock::now() >= *options_.deadline) stop_ = ExploreStop::TimeLimit;
    return stop_ == ExploreStop::Done;
  };
  bool running = visit(0);
  while (running && !frames_.empty()) {
    Frame& f = frames_.back();
    const std::uint32_t begin = frames_.size() > 1 ? frames_[frames_.size() - 2].end : 0;
    if (f.end > begin) {
      // the next pending successor, taken from the top
      const StateId w = edges_[--f.end];
      edges_.shrink(f.end);
      // unvisited when f's state was expanded and visited since: below it in the search, so
      // the edge tells nothing the path down to it did not (its index reached f's state
      // through that path, and a component finished on the way made an edge leave f's own);
      // a bit per state says so without reading the store
      if (visited(w)) continue;
      running = visit(w);
      if (store_->size() >= next_report) {
        next_report += 1 << 12;
        const std::uint64_t b = bytes();
        peak_ = std::max(peak_, b);
        if (options_.progress) options_.progress({store_->size(), edges_count_, b});
        if (race_ != nullptr) {
          // the other search is done, or this plain one has outgrown it: the net is unbounded
          if (cover_) race_->cover_states.store(store_->size(), std::memory_order_relaxed);
          const bool outgrown = !cover_ && store_->size() > 4 * race_->cover_states.load(std::memory_order_relaxed) + (1 << 16);
          if (race_->over.load(std::memory_order_relaxed) || outgrown) stop_ = ExploreStop::MaxStates, running = false;
        }
        running = withinLimits(b) && running;
      }
      // ids keep their top bit free (Frame::v_root)
      if (store_->size() > std::min<std::uint64_t>(options_.max_states, 0x7ffffff0u)) stop_ = ExploreStop::MaxStates, running = false;
      continue;
    }
    const StateId v = f.state();
    const bool root = f.root();
    frames_.shrink(frames_.size() - 1);
    if (cover_) popPath();
    if (root) {
      finishComponent(v);
    } else {
      stack_.push(v);
    }
    if ((++pops & 0xfff) == 0) {
      const std::uint64_t b = bytes();
      peak_ = std::max(peak_, b);
      running = withinLimits(b);
    }
    // the edge from the parent to v is settled now that v is done
    if (!frames_.empty()) settle(frames_.back(), rindex(v));
  }
  peak_ = std::max(peak_, bytes());

  out.stop = stop_;
  out.complete = stop_ == ExploreStop::Done;
  out.states = store_->size();
  out.edges = edges_count_;
  out.fired = fired_;
  seen_->settle(store_->layout());
  summarise(net_, *seen_, out);
  out.deadlock = deadlock_;
  if (out.decided) {
    out.live = live_;
    out.reversible = bottoms_ == 1 && root_bottom_;
  }
  out.dead_markings = dead_count_;
  if (deadlock_ && options_.shortest_path && out.complete) {
    shortestPathToDeadlock(out);
  } else if (deadlock_) {
    out.deadlock_path = firingsAlong(dead_paths_[0]);
  }
  for (std::size_t i = 1; i < dead_paths_.size(); ++i) out.more_dead_paths.push_back(firingsAlong(dead_paths_[i]));
  out.peak_bytes = peak_;
  return out;
}

}  // namespace

namespace {

/// The coverability search and the plain one side by side (Race): the first to end gives the
/// answer, the other stops.
StateSpace race(const Net& net, const ExploreOptions& options, const Plan& p) {
  Race r;
  // a guard on memory is shared: half each
  ExploreOptions each = options;
  each.max_bytes = options.max_bytes / 2;
  ExploreOptions quiet = each;
  quiet.progress = nullptr;
  Search cover(net, each, p, &r, true);
  Search plain(net, quiet, p, &r, false);
  // memory that the limit did not foresee ends a search as the limit would (the plain one
  // here; the other's goes to the caller once this thread is joined)
  StateSpace found;
  found.complete = false;
  std::thread other([&] {
    try {
      found = plain.run();
    } catch (const std::bad_alloc&) {
      found.stop = ExploreStop::MaxMemory;
    }
    if (found.complete) r.over = true;
  });
  std::optional<StateSpace> out;
  try {
    out = cover.run();
  } catch (...) {
    r.over = true;
    other.join();
    throw;
  }
  r.over = true;
  other.join();
  return !out->complete && found.complete ? found : *out;
}

}  // namespace

StateSpace explore(const Net& net, const ExploreOptions& options) {
  const Plan p = plan(net, options);
  if (p.overflow) return overflowAnswer(net);
  // what reading the net and planning freed goes back to the system: it would otherwise stay
  // beside what the search holds (a contest net of 10^3 places leaves some 15 MB)
  core::returnFreedMemory();
  if (options.threads > 1 && net.transitions().size() <= kParallelTransitions) {
    if (!p.cover) return exploreParallel(net, options, p);
    // a limit on memory asked for holds for one search: no race
    if (options.max_bytes == 0 || options.max_bytes_guard) return race(net, options, p);
  }
  return Search(net, options, p).run();
}

const char* stopReason(ExploreStop stop) {
  switch (stop) {
    case ExploreStop::MaxStates:
      return "partial: --max-states reached";
    case ExploreStop::MaxMemory:
      return "partial: --max-memory reached";
    case ExploreStop::Overflow:
      return "partial: a place went past 2^32 - 2 tokens";
    case ExploreStop::TimeLimit:
      return "partial: --time-limit reached";
    case ExploreStop::Candidates:
      return "partial: too many candidates";
    case ExploreStop::Done:
      break;
  }
  return "complete";
}

}  // namespace gdpn::net
