// The parallel state-space search. Each thread owns the markings whose hash falls to it
// (a store of its own), expands them, and sends each successor to its owner's inbox; the
// search ends when no marking is in flight. The graph is written as it is found: each state
// expanded reserves a run of slots for its successors (in the order their transitions are
// found) and each slot gets its successor's id from the successor's owner once stored. Then
// liveness and reversibility are decided over those arrays: a dead state decides both; a way
// back to the start from every state decides both (found by the threads together); a
// transition never enabled past a state that cannot get back decides liveness; otherwise one
// thread finds the strongly connected components. A dead state gets a shortest path to it.
// The answers are the same as the sequential search's.
//
// A thread expands its states in batches: it makes every successor of a batch first, then
// looks them up in its table with the slots and the markings of the lookups ahead fetched
// into the cache, so that many misses are in flight rather than one state's worth.

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <exception>
#include <mutex>
#include <new>
#include <optional>
#include <thread>
#include <utility>

#include "detail/marking_store.h"

namespace gdpn::net::detail {
namespace {

/// Successor slots in one chunk of the graph arrays: a state's run of them (its own id and
/// its successors') never crosses a chunk.
using Succ = Chunked<std::uint32_t, 20>;
/// Fills the end of a chunk of successor slots that the next run did not fit in.
constexpr std::uint32_t kPad = 0xffffffffu;
/// Set in a run's first slot, which holds the state's own global id (ids keep their top bit
/// free): its successors' ids follow, up to the next slot with this bit (another run or kPad)
/// or the end of the chunk's slots in use.
constexpr std::uint32_t kHead = 0x80000000u;

/// Whether bit `g` of the bit set `bits` is set.
bool isSet(const std::vector<std::uint64_t>& bits, std::uint32_t g) { return ((bits[g >> 6] >> (g & 63)) & 1) != 0; }
/// Sets bit `g` of `bits`.
void set(std::vector<std::uint64_t>& bits, std::uint32_t g) { bits[g >> 6] |= std::uint64_t{1} << (g & 63); }
/// Whether bit `g` of `bits` is set, while other threads may set bits (claim()).
bool isSetShared(std::vector<std::uint64_t>& bits, std::uint32_t g) {
  return ((std::atomic_ref<std::uint64_t>(bits[g >> 6]).load(std::memory_order_relaxed) >> (g & 63)) & 1) != 0;
}
/// Sets bit `g` of `bits`, which other threads may set too: whether this call set it.
bool claim(std::vector<std::uint64_t>& bits, std::uint32_t g) {
  const std::uint64_t bit = std::uint64_t{1} << (g & 63);
  std::atomic_ref<std::uint64_t> word(bits[g >> 6]);
  return (word.load(std::memory_order_relaxed) & bit) == 0 && (word.fetch_or(bit, std::memory_order_relaxed) & bit) == 0;
}

struct Shard {
  std::unique_ptr<Store> store;
  std::mutex inbox_mutex;
  // records of a packed marking to store and the address of the slot its id goes to
  std::vector<std::uint64_t> inbox;
  std::vector<StateId> work;         // stored, not yet expanded
  std::unique_ptr<Observed> seen;
  std::vector<bool> fired;
  std::atomic<std::uint64_t> edges{0};
  std::atomic<std::uint64_t> bytes{0};  // what the store holds, as its thread last saw
  // what its thread's successors take on their way to be stored (made, sent, received),
  // as it last saw, and what its inbox holds (set under inbox_mutex): a net of 10^5 parts
  // has markings of tens of KiB and as many successors
  std::atomic<std::uint64_t> buffers{0}, inbox_bytes{0};
  // the words its inbox holds now (set under inbox_mutex): past kInboxBytes the others make
  // no more successors until it has taken them
  std::atomic<std::uint64_t> inbox_words{0};
  std::uint64_t dead = 0;               // states expanded without a successor
  std::uint64_t fresh = 0;              // states stored, not yet in Parallel::states_
  // the graph: each state expanded has a run in succ, in the order they were expanded: its
  // own global id with kHead set, then its successors' (global ids); a chunk's room too
  // small for the next run is filled with kPad. Local state i's run starts at first[i], found
  // after the search and only where a state's run is read by its id (findRunStarts())
  Chunked<std::uint64_t, 18> first;
  Succ succ;
  // edges into each block of kInBlock states (local ids), counted as they are stored, for
  // the edges reversed (the start's own record counted too)
  std::vector<std::uint32_t> into_blocks;
};

/// What a thread's inbox holds at most before the others wait for it to take it, bytes (the
/// markings in flight stay bounded where a thread runs late: the others would otherwise
/// pile up what they make for it).
constexpr std::uint64_t kInboxBytes = std::uint64_t{1} << 20;
/// Bytes of a state's successors (made, sent and stored) past which a thread looks at the
/// limit on memory before it makes them (below, it looks after each round of batches).
constexpr std::uint64_t kManySuccessorBytes = std::uint64_t{64} << 10;
/// The most sweeps over all of the graph's runs on the way back to the start: past them,
/// reversing the edges (a few passes over them) costs less.
constexpr unsigned kWholeSweeps = 32;
/// States (local ids) in one block of the edges reversed: a byte names one in its block.
constexpr unsigned kInBlockBits = 8;

class Parallel {
 public:
  Parallel(const Net& net, const ExploreOptions& options, const Plan& plan)
      : net_(net),
        options_(options),
        layout_(plan.layout()),
        candidates_(net),
        back_(net, Candidates::Way::Backward),
        firing_(net),
        threads_(options.threads),
        shard_bits_(static_cast<unsigned>(std::bit_width(options.threads - 1))),
        shards_(options.threads) {
    candidates_.use(layout_);
    back_.use(layout_);
    firing_.use(layout_);
    for (auto& s : shards_) {
      s.store = std::make_unique<Store>(layout_, false, plan.derived);
      s.seen = std::make_unique<Observed>(layout_);
      s.fired.assign(net.transitions().size(), false);
    }
    std::vector<std::uint64_t> key(layout_.words());
    std::size_t bad = 0;
    layout_.pack(plan.m0.data(), key.data(), bad);
    const std::uint64_t h = shards_[0].store->hash(key.data());
    start_ = owner(h);
    shards_[start_].inbox = key;
    shards_[start_].inbox.push_back(reinterpret_cast<std::uintptr_t>(&root_slot_));
    pending_ = 1 + static_cast<std::int64_t>(options.threads);
  }

  StateSpace run() {
    StateSpace out;
    std::vector<std::thread> pool;
    // memory the limit did not foresee (none given) stops the search as the limit would
    for (unsigned s = 0; s < threads_; ++s) {
      pool.emplace_back([this, s] {
        try {
          explore(s);
        } catch (const std::bad_alloc&) {
          halt(ExploreStop::MaxMemory);
        }
      });
    }
    for (auto& t : pool) t.join();
    out.fired.assign(net_.transitions().size(), false);
    Observed seen(layout_);
    std::uint64_t largest = 0;
    for (auto& s : shards_) {
      out.states += s.store->size();
      out.edges += s.edges.load();
      out.dead_markings += s.dead;
      for (std::size_t t = 0; t < s.fired.size(); ++t) out.fired[t] = out.fired[t] || s.fired[t];
      seen.merge(*s.seen);
      largest = std::max<std::uint64_t>(largest, s.store->size());
    }
    // ids keep their top bit free, as the sequential search's: the components count indexes
    // up from 1 and finished components down from 2^32 - 2
    const std::uint64_t ids = largest << shard_bits_;
    if (stop_ == ExploreStop::Done && ids >= 0x7ffffff0u) stop_ = ExploreStop::MaxStates;
    out.stop = stop_;
    out.complete = stop_ == ExploreStop::Done;
    // a partial search gives no path: its arrays may have slots no owner filled yet
    out.deadlock = out.dead_markings > 0;
    peak_ = std::max(peak_, bytes());
    if (out.complete) components(out, ids);
    dropTables();
    seen.settle(layout_);
    summarise(net_, seen, out);
    out.peak_bytes = std::max(peak_, bytes());
    return out;
  }

 private:
  unsigned owner(std::uint64_t h) const { return static_cast<unsigned>(((h >> 32) * threads_) >> 32); }
  /// A state's id in the graph: its id in its shard's store, then the shard in the low bits.
  std::uint32_t global(unsigned shard, StateId local) const { return (local << shard_bits_) | shard; }
  const Shard& shardOf(std::uint32_t g) const { return shards_[g & ((1u << shard_bits_) - 1)]; }
  StateId localOf(std::uint32_t g) const { return g >> shard_bits_; }

  /// Memory held, as each thread last reported it (safe to call while they run).
  std::uint64_t bytes() const {
    std::uint64_t b = 0;
    for (const auto& s : shards_) {
      b += s.bytes.load(std::memory_order_relaxed) + s.buffers.load(std::memory_order_relaxed) +
           s.inbox_bytes.load(std::memory_order_relaxed);
    }
    return b;
  }
  static void account(Shard& s) {
    s.bytes.store(s.store->bytes() + s.work.capacity() * sizeof(StateId) + s.first.bytes() +
                      s.succ.bytes(),
                  std::memory_order_relaxed);
  }

  /// Stores `key` in shard `me` (its own thread): its global id. A new marking becomes work.
  /// `peeked`: what Store::peek(h) gave, or kNone.
  std::uint32_t store(unsigned me, const std::uint64_t* key, std::uint64_t h, StateId peeked) {
    Shard& s = shards_[me];
    bool added = false;
    const StateId id = s.store->insert(key, h, peeked, added);
    if (added && (id & ((1u << kInBlockBits) - 1)) == 0) s.into_blocks.push_back(0);
    ++s.into_blocks[id >> kInBlockBits];
    if (added) {
      s.seen->note(layout_, key);
      s.work.push_back(id);
      ++s.fresh;
    }
    return global(me, id);
  }

  /// Runs `look(j, peeked)` for the `n` lookups j in a row, lookup j of hash `hash(j)` in the
  /// table of `store(j)`: the table slot of one further ahead and the marking of one nearer
  /// ahead on their way into the cache. `peeked` is what Store::peek gave for lookup j (kNone
  /// for the first few, which come too soon to be peeked).
  template <class StoreOf, class Hash, class Look>
  static void lookUpInRow(std::size_t n, StoreOf store, Hash hash, Look look) {
    constexpr std::size_t kSlotAhead = 16, kMarkingAhead = 8;
    std::array<StateId, kMarkingAhead> peeked;  // lookup j's at j % kMarkingAhead
    peeked.fill(kNone);
    for (std::size_t j = 0; j < std::min(n, kSlotAhead); ++j) store(j).prefetch(hash(j));
    for (std::size_t j = 0; j < n; ++j) {
      if (j + kSlotAhead < n) store(j + kSlotAhead).prefetch(hash(j + kSlotAhead));
      const StateId mine = peeked[j % kMarkingAhead];
      if (j + kMarkingAhead < n) peeked[j % kMarkingAhead] = store(j + kMarkingAhead).peek(hash(j + kMarkingAhead));
      look(j, mine);
    }
  }
  /// Stores the `n` markings `key(j)`, of hashes `hash(j)`, in shard `me` (its own thread),
  /// each id into `*slot(j)`, looked up in a row.
  template <class Key, class Hash, class Slot>
  void storeAll(unsigned me, std::size_t n, Key key, Hash hash, Slot slot) {
    const Store& mine = *shards_[me].store;
    lookUpInRow(
        n, [&](std::size_t) -> const Store& { return mine; }, hash,
        [&](std::size_t j, StateId peeked) { *slot(j) = store(me, key(j), hash(j), peeked); });
  }

  void explore(unsigned me) {
    // pending_ counts the markings in flight between threads (added by the sender before
    // they reach an inbox, taken off by the receiver after storing them) and the threads at
    // work (a thread that takes markings from its inbox counts itself before it takes them
    // off; one that runs out of work flushes its outboxes before it takes itself off). One
    // counter, read at once: all is done when it is zero.
    Shard& s = shards_[me];
    const std::size_t words = layout_.words();
    const std::size_t record = words + 1;
    // states a batch takes, and successors past which it takes no more
    constexpr std::size_t kBatchStates = 64, kBatchSuccessors = 512;
    std::vector<std::vector<std::uint64_t>> outbox(threads_);
    std::vector<std::uint64_t> batch, keys, hashes, in_hashes;
    std::vector<std::uint32_t> own;  // the successors this thread owns, by index
    std::vector<std::uint32_t*> slots;
    std::vector<TransitionId> candidates;
    std::vector<std::uint64_t> expanded;  // the marking of the state expanded
    // the successors' markings on their way, for the limit on memory
    auto buffered = [&] {
      std::size_t words_held = batch.capacity() + keys.capacity();
      for (const auto& box : outbox) words_held += box.capacity();
      s.buffers.store(words_held * sizeof(std::uint64_t), std::memory_order_relaxed);
    };
    auto flush = [&](unsigned to) {
      if (outbox[to].empty()) return;
      pending_.fetch_add(static_cast<std::int64_t>(outbox[to].size() / record));
      std::lock_guard lock(shards_[to].inbox_mutex);
      auto& in = shards_[to].inbox;
      in.insert(in.end(), outbox[to].begin(), outbox[to].end());
      shards_[to].inbox_bytes.store(in.capacity() * sizeof(std::uint64_t), std::memory_order_relaxed);
      shards_[to].inbox_words.store(in.size(), std::memory_order_relaxed);
      outbox[to].clear();
    };
    bool active = true;
    std::uint64_t next_report = 1 << 12;
    while (!stop_flag_.load(std::memory_order_relaxed)) {
      batch.clear();
      {
        std::lock_guard lock(s.inbox_mutex);
        batch.swap(s.inbox);
        s.inbox_bytes.store(s.inbox.capacity() * sizeof(std::uint64_t), std::memory_order_relaxed);
        s.inbox_words.store(0, std::memory_order_relaxed);
      }
      buffered();
      if (!batch.empty()) {
        if (!active) pending_.fetch_add(1), active = true;
        // looked up as the thread's own successors are
        const std::size_t n = batch.size() / record;
        in_hashes.resize(n);
        for (std::size_t i = 0; i < n; ++i) in_hashes[i] = s.store->hash(&batch[i * record]);
        auto key = [&](std::size_t i) { return &batch[i * record]; };
        auto hash = [&](std::size_t i) { return in_hashes[i]; };
        const auto promised = room(me, n, key, hash);
        if (!promised) break;
        storeAll(me, n, key, hash, [&](std::size_t i) {
          return reinterpret_cast<std::uint32_t*>(static_cast<std::uintptr_t>(batch[i * record + words]));
        });
        settle(me, *promised);
        pending_.fetch_sub(static_cast<std::int64_t>(batch.size() / record));
      }
      if (batch.empty() && !s.work.empty() && backedUp(me)) std::this_thread::yield();
      for (int n = 0; n < 16 && !s.work.empty() && !backedUp(me) && !stop_flag_.load(std::memory_order_relaxed); ++n) {
        // what this batch's many successors take, promised (as a table's growth is) until
        // they are made and sent, so that two threads do not both take the last room
        struct Promise {
          std::atomic<std::uint64_t>& to;
          std::uint64_t bytes = 0;
          ~Promise() { to.fetch_sub(bytes); }
        } ahead_promised{promised_};
        // the successors of a batch of states, each given the slot its id goes to
        std::size_t made = 0;
        for (std::size_t b = 0; b < kBatchStates && made < kBatchSuccessors && !s.work.empty(); ++b) {
          const StateId v = s.work.back();
          s.work.pop_back();
          const std::uint64_t* m = s.store->load(v, expanded);
          candidates_.find(m, firing_, candidates);
          // room for its successors, and for their copies on the way to their owners (their
          // stores look before they grow), that would pass the limit stops the search first:
          // looked at where the room grows, or where they are many (a state of a net of 10^5
          // parts has as many successors of tens of KiB; the others are looked at each round)
          const std::size_t need = (made + candidates.size()) * words;
          const std::size_t grown =
              need <= keys.size() ? keys.size() : std::max(need, std::min(2 * keys.size(), need + (std::size_t{1} << 20)));
          const std::size_t more = grown > keys.capacity() ? grown - keys.capacity() : 0;
          const std::size_t ahead = more + candidates.size() * record;
          if (options_.max_bytes != 0 && (more != 0 || ahead * sizeof(std::uint64_t) >= kManySuccessorBytes)) {
            const std::uint64_t want = ahead * sizeof(std::uint64_t);
            if (bytes() + promised_.fetch_add(want) + want > options_.max_bytes) {
              promised_.fetch_sub(want);
              halt(ExploreStop::MaxMemory);
              break;
            }
            ahead_promised.bytes += want;
          }
          if (more != 0 || grown > keys.size()) {
            // (nothing made yet in this batch: not held twice while it moves)
            if (made == 0 && more != 0) std::vector<std::uint64_t>().swap(keys);
            keys.resize(grown);
            buffered();
          }
          const std::size_t begin = made;
          bool overflow = false;
          for (TransitionId t : candidates) {
            std::size_t field = 0;
            const Fired f = firing_.fireReady(t, m, keys.data() + made * words, field);  // find() gives ready ones
            if (f == Fired::NotEnabled) continue;
            if (f == Fired::TooBig) {
              halt(ExploreStop::Overflow);
              overflow = true;
              break;
            }
            s.fired[t] = true;
            ++made;
          }
          const std::size_t count = made - begin;
          const std::size_t run = s.succ.appendRun(count + 1, kPad);
          s.succ.at(run)[0] = global(me, v) | kHead;
          if (count == 0 && !overflow) ++s.dead;
          if (slots.size() < made) slots.resize(2 * made), hashes.resize(2 * made);
          for (std::size_t i = begin; i < made; ++i) {
            slots[i] = s.succ.at(run + 1 + (i - begin));
            hashes[i] = s.store->hash(keys.data() + i * words);
          }
        }
        s.edges.fetch_add(made, std::memory_order_relaxed);
        // the others' successors to their owners, this thread's looked up
        own.clear();
        for (std::size_t i = 0; i < made; ++i) {
          const unsigned to = owner(hashes[i]);
          if (to == me) {
            own.push_back(static_cast<std::uint32_t>(i));
            continue;
          }
          const std::uint64_t* key = keys.data() + i * words;
          auto& box = outbox[to];
          const std::size_t at = box.size();
          box.resize(at + record);
          firing_.copy(key, box.data() + at);  // a few words: no call to memmove
          box[at + words] = reinterpret_cast<std::uintptr_t>(slots[i]);
          if (box.size() >= 1024 * record || box.size() * sizeof(std::uint64_t) >= kInboxBytes / 4) flush(to);
        }
        // made and sent, they count where they are now: the promise is given back
        buffered();
        promised_.fetch_sub(std::exchange(ahead_promised.bytes, 0));
        auto key = [&](std::size_t j) { return keys.data() + own[j] * words; };
        auto hash = [&](std::size_t j) { return hashes[own[j]]; };
        const auto promised = room(me, own.size(), key, hash);
        if (!promised) break;
        storeAll(me, own.size(), key, hash, [&](std::size_t j) { return slots[own[j]]; });
        settle(me, *promised);
      }
      account(s);
      // the states stored since the last time, added to the count all threads share once per
      // round (not once per state: the threads would take its cache line from each other)
      states_.fetch_add(s.fresh, std::memory_order_relaxed);
      s.fresh = 0;
      // limits and progress, looked at by the first thread: memory and time after each of its
      // rounds (once every state is stored, the graph still grows as the rest are expanded),
      // progress every 4,096 states
      const std::uint64_t states = states_.load(std::memory_order_relaxed);
      if (states > options_.max_states) halt(ExploreStop::MaxStates);
      if (me == 0) {
        const std::uint64_t b = bytes();
        peak_ = std::max(peak_, b);
        if (options_.progress && states >= next_report) {
          next_report = states + (1 << 12);
          std::uint64_t edges = 0;
          for (const auto& x : shards_) edges += x.edges.load(std::memory_order_relaxed);
          options_.progress({states, edges, b});
        }
        if (options_.max_bytes != 0 && b > options_.max_bytes) halt(ExploreStop::MaxMemory);
        if (options_.deadline && std::chrono::steady_clock::now() >= *options_.deadline) halt(ExploreStop::TimeLimit);
      }
      if (s.work.empty() && batch.empty()) {
        for (unsigned to = 0; to < threads_; ++to) flush(to);
        if (active) pending_.fetch_sub(1), active = false;
        if (pending_.load() == 0) break;
        std::this_thread::yield();
      }
    }
  }

  /// Whether another thread's inbox holds more than kInboxBytes: thread `me` then makes no
  /// successors until it is taken.
  bool backedUp(unsigned me) const {
    for (unsigned to = 0; to < threads_; ++to) {
      if (to != me && shards_[to].inbox_words.load(std::memory_order_relaxed) * sizeof(std::uint64_t) > kInboxBytes) return true;
    }
    return false;
  }

  /// Room under ExploreOptions::max_bytes for shard `me`'s table to grow as the `n`
  /// markings `key(j)` (of hashes `hash(j)`) are stored, and for the markings themselves
  /// (as if all were new): the bytes promised (0 where none are), to be given back with
  /// settle() once stored; none (and the search stops) where they would pass the limit, so
  /// that no table grows past it. Promises of the other threads count until they report what
  /// they stored (the shards fill evenly, so their tables grow at nearly the same moment).
  /// The markings are promised only where they are many (kManySuccessorBytes: markings of
  /// tens of KiB fill the limit between two growths of a table); fewer are only counted.
  template <class Key, class Hash>
  std::optional<std::uint64_t> room(unsigned me, std::size_t n, Key key, Hash hash) {
    if (options_.max_bytes == 0) return 0;
    Shard& s = shards_[me];
    const std::uint64_t growth = s.store->growthInserting(n, key, hash);
    const std::uint64_t markings = n * s.store->stateBytes();
    const std::uint64_t want = growth + (markings >= kManySuccessorBytes ? markings : 0);
    const std::uint64_t counted = want + (markings >= kManySuccessorBytes ? 0 : markings);
    if (want == 0) {
      if (bytes() + promised_.load() + counted <= options_.max_bytes) return 0;
      halt(ExploreStop::MaxMemory);
      return std::nullopt;
    }
    account(s);
    const std::uint64_t promised = promised_.fetch_add(want) + want;
    if (bytes() + promised + (counted - want) <= options_.max_bytes) return want;
    promised_.fetch_sub(want);
    halt(ExploreStop::MaxMemory);
    return std::nullopt;
  }
  /// Gives back what room() promised, now that shard `me` reports what it stored.
  void settle(unsigned me, std::uint64_t promised) {
    if (promised == 0) return;
    account(shards_[me]);
    promised_.fetch_sub(promised);
  }

  void halt(ExploreStop why) {
    std::lock_guard lock(halt_mutex_);
    if (stop_ == ExploreStop::Done) stop_ = why;
    stop_flag_ = true;
  }

  /// A state's run: its global id and its successors', [begin, end).
  struct Run {
    std::uint32_t v;
    const std::uint32_t* begin;
    const std::uint32_t* end;
  };
  /// The run whose first slot is data[i], in a chunk of `size` slots in use.
  static Run runIn(const std::uint32_t* data, std::size_t i, std::size_t size) {
    std::size_t j = i + 1;
    while (j < size && (data[j] & kHead) == 0) ++j;
    return {data[i] & ~kHead, data + i + 1, data + j};
  }
  /// The run that starts at slot `at` of shard `s`.
  static Run runAt(const Shard& s, std::size_t at) {
    const std::size_t c = at / Succ::chunkElements();
    const auto [data, size] = s.succ.chunk(c);
    return runIn(data, at - c * Succ::chunkElements(), size);
  }
  /// State g's run (Shard::first found).
  Run runOf(std::uint32_t g) const {
    const Shard& s = shardOf(g);
    return runAt(s, s.first[localOf(g)]);
  }
  /// State g's packed marking, read into `buffer`.
  const std::uint64_t* marking(std::uint32_t g, std::vector<std::uint64_t>& buffer) const {
    return shardOf(g).store->load(localOf(g), buffer);
  }

  /// Frees the tables: what follows reads the markings by id and the graph, never looks a
  /// marking up (the tables are a third of what the shards hold).
  void dropTables() {
    for (auto& s : shards_) s.store->dropIndex(), account(s);
  }

  /// Liveness and reversibility, and a shortest path to a dead state when there is one.
  /// Where a state is dead, the net is neither live (unless it has no transition) nor
  /// reversible (unless the dead state is the only one); where every state leads back to the
  /// start, it is reversible, and live when quasi-live; otherwise it is not reversible, and
  /// not live where missesATransition() says so; failing that, the strongly connected
  /// components over the arrays decide (Pearce's variant of Tarjan's algorithm, as in the
  /// sequential search).
  void components(StateSpace& out, std::uint64_t ids) {
    const std::size_t transitions = net_.transitions().size();
    const std::uint32_t s0 = global(start_, 0);
    if (out.deadlock) {
      dropTables();
      findRunStarts();
      out.live = transitions == 0;
      out.reversible = out.states == 1;
      pathToDeadlock(out, ids, s0);
      return;
    }
    // the common case first: the initial state reached from every state, one component
    std::vector<std::uint64_t> reach;
    const std::uint64_t reaching = reachingStart(ids, s0, out.states, reach);
    if (reaching == out.states) {
      out.reversible = true;
      out.live = std::all_of(out.fired.begin(), out.fired.end(), [](bool f) { return f; });
      return;
    }
    out.reversible = false;
    findRunStarts();
    if (missesATransition(ids, reach)) {
      out.live = false;
      return;
    }
    std::vector<std::uint32_t> rindex;  // read at random: on huge pages
    core::reserveLarge(rindex, ids);
    rindex.assign(ids, 0);
    std::vector<bool> leaves(ids, false);
    std::vector<std::uint32_t> stack;
    struct Frame {
      std::uint32_t v;
      const std::uint32_t* pos;
      const std::uint32_t* end;
      bool root;
    };
    std::vector<Frame> frames;
    std::uint32_t index = 1, comp = 0xfffffffeu, bottoms = 0;
    bool live = true, root_bottom = false;
    std::vector<bool> fires(transitions);
    std::vector<TransitionId> candidates;
    std::vector<std::uint64_t> loaded;  // a state's marking, read back
    auto visit = [&](std::uint32_t v) {
      rindex[v] = index++;
      const Run r = runOf(v);
      frames.push_back({v, r.begin, r.end, true});
    };
    visit(s0);
    while (!frames.empty()) {
      Frame& f = frames.back();
      if (f.pos != f.end) {
        const std::uint32_t w = *f.pos;
        if (rindex[w] == 0) {
          visit(w);
          continue;
        }
        if (rindex[w] < rindex[f.v]) rindex[f.v] = rindex[w], f.root = false;
        if (rindex[w] > comp) leaves[f.v] = true;
        ++f.pos;
        continue;
      }
      const std::uint32_t v = f.v;
      const bool root = f.root;
      frames.pop_back();
      if (root) {
        std::size_t first = stack.size();
        while (first > 0 && rindex[stack[first - 1]] >= rindex[v]) --first;
        bool leaving = leaves[v];
        for (std::size_t i = first; i < stack.size(); ++i) leaving = leaving || leaves[stack[i]];
        if (!leaving) {
          ++bottoms;
          if (live) {
            auto at = [&](std::size_t i) { return marking(i == 0 ? v : stack[first + i - 1], loaded); };
            live = enablesAll(firing_, candidates_, transitions, stack.size() - first + 1, at, fires, candidates);
          }
        }
        root_bottom = !leaving;
        for (std::size_t i = first; i < stack.size(); ++i) rindex[stack[i]] = comp;
        rindex[v] = comp--;
        stack.resize(first);
      } else {
        stack.push_back(v);
      }
      if (!frames.empty()) {
        Frame& parent = frames.back();
        const std::uint32_t rw = rindex[v];
        if (rw < rindex[parent.v]) rindex[parent.v] = rw, parent.root = false;
        if (rw > comp) leaves[parent.v] = true;
        ++parent.pos;
      }
    }
    peak_ = std::max(peak_, bytes() + ids * (sizeof(std::uint32_t) + 1));
    out.live = live;
    out.reversible = bottoms == 1 && root_bottom;
  }

  /// Whether some state that cannot reach the start (unset in `reach`) leads only to states
  /// in which some transition is never enabled: then the net is not live. A seeded walk from
  /// the first such state (its successors cannot reach the start either) goes deep, towards a
  /// bottom component, and the states it reaches from there are searched breadth first, until
  /// every transition was seen enabled (no answer: false) or none is left. Costs a bit per
  /// state and the states searched; the strongly connected components are the fallback.
  bool missesATransition(std::uint64_t ids, const std::vector<std::uint64_t>& reach) {
    std::uint32_t v = 0xffffffffu;
    forEachRun([&](std::uint32_t g, const std::uint32_t*, const std::uint32_t*) {
      if (v == 0xffffffffu && !isSet(reach, g)) v = g;
    });
    if (v == 0xffffffffu) return false;
    // the walk (which state it starts from depends on the threads' timing; the answer does
    // not: where this finds nothing, the components decide)
    std::uint64_t seed = 0x9e3779b97f4a7c15ULL;
    for (int step = 0; step < (1 << 16); ++step) {
      const Run r = runOf(v);
      if (r.begin == r.end) break;
      seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
      const auto n = static_cast<std::uint64_t>(r.end - r.begin);
      v = r.begin[((seed >> 33) * n) >> 31];
    }
    const std::size_t transitions = net_.transitions().size();
    std::vector<bool> fires(transitions, false);
    std::vector<TransitionId> candidates;
    std::vector<std::uint64_t> loaded;  // a state's marking, read back
    std::vector<std::uint64_t> seen((ids + 63) / 64, 0);
    std::vector<std::uint32_t> queue{v};
    set(seen, v);
    std::size_t fire = 0;
    auto held = [&] { peak_ = std::max(peak_, bytes() + seen.size() * 8 + reach.size() * 8 + queue.capacity() * 4); };
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const std::uint32_t w = queue[head];
      fire += markEnabled(firing_, candidates_, marking(w, loaded), fires, candidates);
      if (fire == transitions) {
        held();
        return false;
      }
      const Run r = runOf(w);
      for (const std::uint32_t* e = r.begin; e != r.end; ++e) {
        if (isSet(seen, *e)) continue;
        set(seen, *e);
        queue.push_back(*e);
      }
    }
    held();
    return true;
  }

  /// Calls `f(v, begin, end)` for every state shard `s` expanded: its global id and its
  /// successors'.
  template <typename F>
  static void forEachRunOf(const Shard& s, F&& f) {
    forEachRunAt(s, [&f](std::size_t, std::uint32_t v, const std::uint32_t* begin, const std::uint32_t* end) { f(v, begin, end); });
  }
  /// The same, with where each run starts in the shard's successor slots: `f(at, v, begin, end)`.
  template <typename F>
  static void forEachRunAt(const Shard& s, F&& f) {
    const std::size_t chunks = (s.succ.size() + Succ::chunkElements() - 1) / Succ::chunkElements();
    for (std::size_t c = 0; c < chunks; ++c) {
      const auto [data, size] = s.succ.chunk(c);
      for (std::size_t i = 0; i < size && data[i] != kPad;) {
        const Run r = runIn(data, i, size);
        f(c * Succ::chunkElements() + i, r.v, r.begin, r.end);
        i = static_cast<std::size_t>(r.end - data);
      }
    }
  }
  /// The same for every state expanded.
  template <typename F>
  void forEachRun(F&& f) const {
    for (const Shard& s : shards_) forEachRunOf(s, f);
  }
  /// Runs `f(me)` once on each of the threads (`me` from 0; the calling thread is the last)
  /// and waits for them all.
  template <typename F>
  void onThreads(F&& f) const {
    // (no pass waits on another thread: one that throws, out of memory, leaves the others to
    // end; the first exception goes to the caller once all are joined)
    std::vector<std::exception_ptr> failed(threads_);
    auto run = [&](unsigned me) {
      try {
        f(me);
      } catch (...) {
        failed[me] = std::current_exception();
      }
    };
    std::vector<std::thread> pool;
    for (unsigned me = 0; me + 1 < threads_; ++me) pool.emplace_back(run, me);
    run(threads_ - 1);
    for (auto& t : pool) t.join();
    for (const auto& e : failed) {
      if (e) std::rethrow_exception(e);
    }
  }

  /// The number of states with a path to `s0`, each set in `reach` (a bit per id). First
  /// sweeps over the runs in the order they were written, each marking a state one of whose
  /// successors is marked: a search from the start tends to write a state after those on its
  /// way back, so that a few sweeps mark them all. The sweeps go on while each marks a
  /// hundredth of the states left, or twice what the one before it marked (such growth from
  /// the start's 1 lasts at most log2 of the states / 100 sweeps), and for kWholeSweeps passes
  /// over all runs at most (once fewer than an eighth are left, the sweeps go over a list of
  /// those alone). SmallOperatingSystem's first sweep marks 10 states, the first six 116,000
  /// together, and 17 mark all 4.1 M in less time than reversing its edges takes. Then, where
  /// states are left and the last sweep marked some, breadth first backward from the states
  /// marked: first over predecessors made by undoing the transitions that may have led to
  /// each state, looked up in the tables (what it costs grows with the states reached,
  /// nothing more is held); once a sixteenth of the states are marked, over the edges
  /// reversed (5 bytes an edge and 4 a state for the time it takes, far fewer misses), unless
  /// they would pass ExploreOptions::max_bytes. Drops the tables either way.
  std::uint64_t reachingStart(std::uint64_t ids, std::uint32_t s0, std::uint64_t states, std::vector<std::uint64_t>& reach) {
    reach.assign((ids + 63) / 64, 0);
    auto isMarked = [&](std::uint32_t g) { return isSet(reach, g); };
    auto mark = [&](std::uint32_t g) { set(reach, g); };
    mark(s0);
    std::uint64_t marked = 1;
    // the sweeps: each thread over its own shard's runs, marking with an atomic or (a state
    // marked by both is counted once). Once fewer than an eighth are left, a sweep lists the
    // states it does not mark, and the next sweeps go over the lists alone (HexagonalGrid:
    // after 3 of its 6 sweeps, 5,000 of 2.7 M)
    struct alignas(64) Sweep {
      std::vector<std::size_t> left;  // where the runs of the states left start
      std::uint64_t marked = 0;
    };
    std::vector<Sweep> sweeps(threads_);
    bool listed = false, stuck = false;  // stuck: a sweep marked none, the rest cannot get back
    std::uint64_t last = 1;                // what the sweep before marked (the first: the start)
    unsigned whole = 0;                    // sweeps over all runs so far
    while (marked < states) {
      const std::uint64_t before = marked;
      const bool list = !listed && (states - marked) * 8 < states;
      onThreads([&](unsigned me) {
        Sweep& my = sweeps[me];
        // whether state v, not marked, has a marked successor: then marked
        auto sweep = [&](std::uint32_t v, const std::uint32_t* begin, const std::uint32_t* end) {
          for (const std::uint32_t* e = begin; e != end; ++e) {
            if (isSetShared(reach, *e)) {
              if (claim(reach, v)) ++my.marked;
              return true;
            }
          }
          return false;
        };
        if (listed) {
          std::erase_if(my.left, [&](std::size_t at) {
            const Run r = runAt(shards_[me], at);
            return sweep(r.v, r.begin, r.end);
          });
        } else {
          forEachRunAt(shards_[me], [&](std::size_t at, std::uint32_t v, const std::uint32_t* begin, const std::uint32_t* end) {
            if (!isSetShared(reach, v) && !sweep(v, begin, end) && list) my.left.push_back(at);
          });
        }
      });
      whole += listed ? 0 : 1;
      listed = listed || list;
      for (Sweep& my : sweeps) marked += std::exchange(my.marked, 0);
      stuck = marked == before;
      const std::uint64_t now = marked - before;
      if (now * 100 < states - before && now < 2 * last) break;
      if (!listed && whole >= kWholeSweeps) break;
      last = now;
    }
    std::uint64_t listing = 0;
    for (Sweep& my : sweeps) listing += my.left.capacity() * sizeof(std::size_t), std::vector<std::size_t>().swap(my.left);
    peak_ = std::max(peak_, bytes() + reach.size() * 8 + listing);
    if (marked == states || stuck) {
      dropTables();
      return marked;
    }
    std::vector<std::uint32_t> level;
    level.reserve(marked);
    forEachRun([&](std::uint32_t v, const std::uint32_t*, const std::uint32_t*) {
      if (isMarked(v)) level.push_back(v);
    });
    peak_ = std::max(peak_, bytes() + reach.size() * 8 + level.capacity() * sizeof(std::uint32_t));
    // (a net that is not reversible often stops before the edges are reversed, which would
    // cost what the whole graph holds: Peterson-PT-3 reaches its start from 1,782 of 3.4 M)
    std::uint64_t edges = 0, tables = 0;
    for (const Shard& s : shards_) edges += s.edges.load(), tables += s.store->tableBytes();
    // what reverse() holds: 4 bytes an edge and a state, and a byte an edge while it runs
    const std::uint64_t reversed = (edges + states + 2 * threads_) * sizeof(std::uint32_t) + edges;
    // (their positions are 32 bits: a graph of 2^32 edges or more is searched by lookups)
    const bool reverses = edges < 0xffffffffu && (options_.max_bytes == 0 || bytes() - tables + reversed <= options_.max_bytes);
    const std::uint64_t sixteenth = states / 16 > marked ? states / 16 - marked : 0;
    marked += backward(level, reach, reverses ? sixteenth : states, [&](Next& my, std::size_t begin, std::size_t end, auto reached) {
      lookUpPredecessors(my, level, begin, end, reached);
    });
    dropTables();
    if (level.empty()) return marked;
    return marked + overReversedEdges(level, reach, states);
  }

  /// The rest of reachingStart(): breadth first from `level` over the edges reversed; the
  /// states it marks.
  std::uint64_t overReversedEdges(std::vector<std::uint32_t>& level, std::vector<std::uint64_t>& reach, std::uint64_t states) {
    const std::vector<Into> into = reverse();
    std::uint64_t held = 0;  // and a byte an edge while reversing
    for (const Into& in : into) held += (in.at.capacity() + in.from.capacity()) * sizeof(std::uint32_t) + in.from.size();
    peak_ = std::max(peak_, bytes() + held + reach.size() * 8 + 2 * level.capacity() * sizeof(std::uint32_t));
    const std::uint32_t mask = (1u << shard_bits_) - 1;
    return backward(level, reach, states, [&](Next&, std::size_t begin, std::size_t end, auto reached) {
      // the predecessor runs of the states ahead on their way into the cache
      constexpr std::size_t kAhead = 8;
      auto run = [&](std::uint32_t g) { return &into[g & mask].at[g >> shard_bits_]; };
      for (std::size_t i = begin; i < end; ++i) {
        if (i + 2 * kAhead < end) __builtin_prefetch(run(level[i + 2 * kAhead]));
        if (i + kAhead < end) __builtin_prefetch(into[level[i + kAhead] & mask].from.data() + *run(level[i + kAhead]));
        const std::uint32_t w = level[i];
        const std::uint32_t* from = into[w & mask].from.data();
        for (std::uint32_t k = run(w)[0]; k < run(w)[1]; ++k) reached(from[k]);
      }
    });
  }

  /// Finds where each state's run starts (Shard::first), from the runs in the order they
  /// were written, each thread in its own shard, for what reads a state's run by its id. The
  /// search keeps no such index (8 bytes a state), and the way back to the start needs none.
  void findRunStarts() {
    onThreads([&](unsigned me) {
      Shard& s = shards_[me];
      s.first.clear();
      for (std::size_t i = 0; i < s.store->size(); ++i) s.first.push(0);
      forEachRunAt(s, [&](std::size_t at, std::uint32_t v, const std::uint32_t*, const std::uint32_t*) { s.first[localOf(v)] = at; });
      account(s);
    });
  }

  /// The edges into the states of one shard: local state i's predecessors (global ids) are
  /// from[at[i], at[i + 1]).
  struct Into {
    std::vector<std::uint32_t> at;
    std::vector<std::uint32_t> from;
  };
  /// The edges reversed: each thread those into its own shard's states, no atomics. A pass
  /// over all runs puts each edge in its block of 256 states (its share of the block counted
  /// as the search stored it), with a byte that names its state there: a few lines a block in
  /// the cache, where putting each edge in its place at once would miss for nearly every
  /// edge. Then each block is sorted by its states, in the cache. The other shard's edges go
  /// to a sink, not round a branch (a coin toss). Holds a byte an edge more while it runs.
  std::vector<Into> reverse() const {
    std::vector<Into> into(threads_);
    const std::uint32_t mask = (1u << shard_bits_) - 1;
    onThreads([&](unsigned me) {
      Into& in = into[me];
      const unsigned bits = shard_bits_;
      const std::size_t n = shards_[me].store->size();
      const std::vector<std::uint32_t>& counts = shards_[me].into_blocks;
      const std::size_t blocks = counts.size(), sink = blocks;
      // where each block starts (the start's own record was no edge)
      std::vector<std::uint32_t> start(blocks + 1, 0);
      for (std::size_t b = 0; b < blocks; ++b) start[b + 1] = start[b] + counts[b] - (me == start_ && b == 0 ? 1u : 0u);
      const std::uint32_t total = start[blocks];
      in.from.resize(std::size_t{total} + 1);  // the last one the sink's
      std::vector<std::uint8_t> low(std::size_t{total} + 1);
      std::vector<std::uint32_t> put(start.begin(), start.end());
      std::uint32_t* from = in.from.data();
      forEachRun([&](std::uint32_t v, const std::uint32_t* begin, const std::uint32_t* end) {
        for (const std::uint32_t* e = begin; e != end; ++e) {
          const bool mine = (*e & mask) == me;
          const std::uint32_t local = *e >> bits;
          std::uint32_t& p = put[mine ? local >> kInBlockBits : sink];
          from[p] = v;
          low[p] = static_cast<std::uint8_t>(local);
          p += mine ? 1u : 0u;
        }
      });
      in.from.pop_back();
      in.at.assign(n + 1, total);
      std::vector<std::uint32_t> sorted;
      for (std::size_t b = 0; b < blocks; ++b) {
        const std::uint32_t b0 = start[b], b1 = start[b + 1];
        std::array<std::uint32_t, 257> at{};
        for (std::uint32_t k = b0; k < b1; ++k) ++at[low[k] + 1u];
        for (std::size_t i = 1; i < at.size(); ++i) at[i] += at[i - 1];
        for (std::size_t i = 0; i < 256 && (b << kInBlockBits) + i < n; ++i) in.at[(b << kInBlockBits) + i] = b0 + at[i];
        sorted.resize(b1 - b0);
        for (std::uint32_t k = b0; k < b1; ++k) sorted[at[low[k]]++] = from[k];
        std::copy(sorted.begin(), sorted.end(), from + b0);
      }
    });
    return into;
  }

  /// A thread's share of one level of the backward search, and its scratch.
  struct alignas(64) Next {
    std::vector<std::uint32_t> states;  // the states of the next level it marked first
    std::vector<std::uint64_t> keys;    // the predecessors of its block, to look up
    std::vector<std::uint64_t> hashes;
    std::vector<TransitionId> candidates;
    std::vector<std::uint64_t> loaded;  // a state's marking, read back
  };
  /// Marks in `reach`, breadth first and a level at a time, states with a path to one in
  /// `level` (marked already), until none is left or, after a level, more than `until` are
  /// marked; `level` is then the next level. `block(my, begin, end, reached)` calls
  /// `reached(g)` for predecessors g of the states level[begin, end), at least each one not
  /// marked yet. The threads take a large level's states in blocks and mark what they find
  /// with an atomic or, each keeping those it was first to mark; a level too small to share is
  /// one thread's (no threads started for it). Returns the states it marked.
  template <class Block>
  std::uint64_t backward(std::vector<std::uint32_t>& level, std::vector<std::uint64_t>& reach, std::uint64_t until, Block block) {
    constexpr std::size_t kBlock = 256;
    std::vector<Next> next(threads_);
    std::uint64_t marked = 0;
    while (!level.empty() && marked <= until) {
      std::atomic<std::size_t> taken{0};
      auto share = [&](auto&& f) { level.size() < threads_ * kBlock ? f(0u) : onThreads(f); };
      share([&](unsigned me) {
        Next& my = next[me];
        auto reached = [&](std::uint32_t g) {
          if (claim(reach, g)) my.states.push_back(g);
        };
        for (std::size_t begin; (begin = taken.fetch_add(kBlock, std::memory_order_relaxed)) < level.size();) {
          block(my, begin, std::min(level.size(), begin + kBlock), reached);
        }
      });
      level.clear();
      for (auto& n : next) {
        marked += n.states.size();
        level.insert(level.end(), n.states.begin(), n.states.end());
        n.states.clear();
      }
    }
    return marked;
  }

  /// Calls `reached(g)` for each predecessor g of the states level[begin, end): made by
  /// undoing the transitions that may have led to each, and looked up in its owner's table
  /// (the tables only read now), the slot and then the marking of the lookups ahead on their
  /// way.
  template <class Reached>
  void lookUpPredecessors(Next& my, const std::vector<std::uint32_t>& level, std::size_t begin, std::size_t end, Reached reached) const {
    const std::size_t words = layout_.words();
    my.keys.clear();
    my.hashes.clear();
    for (std::size_t i = begin; i < end; ++i) {
      const std::uint64_t* m = marking(level[i], my.loaded);
      back_.findBackward(m, my.candidates);
      for (const TransitionId t : my.candidates) {
        const std::size_t at = my.keys.size();
        my.keys.resize(at + words);
        if (!firing_.unfire(t, m, my.keys.data() + at) || !firing_.enabled(t, my.keys.data() + at)) {
          my.keys.resize(at);
          continue;
        }
        my.hashes.push_back(shards_[0].store->hash(my.keys.data() + at));
      }
    }
    auto table = [&](std::size_t j) -> const Store& { return *shards_[owner(my.hashes[j])].store; };
    lookUpInRow(
        my.hashes.size(), table, [&](std::size_t j) { return my.hashes[j]; },
        [&](std::size_t j, StateId peeked) {
          const StateId local = table(j).find(my.keys.data() + j * words, my.hashes[j], peeked);
          if (local != kNone) reached(global(owner(my.hashes[j]), local));  // else not reachable: no edge
        });
  }

  /// A shortest firing sequence from `s0` to a dead state: breadth first over the arrays.
  void pathToDeadlock(StateSpace& out, std::uint64_t ids, std::uint32_t s0) {
    std::vector<std::uint32_t> parent(ids, 0xffffffffu);
    std::vector<std::uint32_t> via(ids, 0), queue{s0};
    std::vector<TransitionId> candidates;
    std::vector<std::uint64_t> loaded;  // a state's marking, read back
    parent[s0] = s0;
    peak_ = std::max(peak_, bytes() + ids * 2 * sizeof(std::uint32_t));
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const std::uint32_t v = queue[head];
      const Run r = runOf(v);
      if (r.begin == r.end) {
        for (std::uint32_t x = v; x != s0; x = parent[x]) {
          // the k-th successor comes from the k-th enabled transition
          std::uint32_t k = via[x];
          const std::uint64_t* m = marking(parent[x], loaded);
          candidates_.find(m, firing_, candidates);
          for (TransitionId t : candidates) {
            if (!firing_.enabled(t, m)) continue;
            if (k-- == 0) {
              out.deadlock_path.push_back(t);
              break;
            }
          }
        }
        std::reverse(out.deadlock_path.begin(), out.deadlock_path.end());
        return;
      }
      for (const std::uint32_t* e = r.begin; e != r.end; ++e) {
        if (parent[*e] != 0xffffffffu) continue;
        parent[*e] = v;
        via[*e] = static_cast<std::uint32_t>(e - r.begin);
        queue.push_back(*e);
      }
    }
  }

  const Net& net_;
  const ExploreOptions& options_;
  Layout layout_;
  Candidates candidates_;  // shared: read only once made
  Candidates back_;        // the transitions that may lead to a marking: likewise
  Firing firing_;          // likewise
  unsigned threads_;
  unsigned shard_bits_;  // bits of a state's id that name its shard
  std::vector<Shard> shards_;
  unsigned start_ = 0;
  std::uint32_t root_slot_ = 0;  // where the initial state's id goes
  std::atomic<std::int64_t> pending_{0};  // markings in flight and threads at work
  std::atomic<std::uint64_t> states_{0};
  std::atomic<std::uint64_t> promised_{0};  // tables' growth room() promised, not yet reported
  std::atomic<bool> stop_flag_{false};
  std::mutex halt_mutex_;
  ExploreStop stop_ = ExploreStop::Done;
  std::uint64_t peak_ = 0;
};

}  // namespace

StateSpace exploreParallel(const Net& net, const ExploreOptions& options, const Plan& plan) {
  return Parallel(net, options, plan).run();
}

}  // namespace gdpn::net::detail
