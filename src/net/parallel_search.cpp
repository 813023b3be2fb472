// The parallel state-space search. Each thread owns the markings whose hash falls to it
// (a store of its own), expands them, and sends each successor to its owner's inbox; the
// search ends when no marking is in flight. A second parallel pass writes the graph as
// arrays (successors in transition order), and one thread then finds its strongly connected
// components and the shortest path to a deadlock over those arrays, as the sequential
// search does over the implicit graph. The answers are the same as the sequential search's.

#include <atomic>
#include <mutex>
#include <thread>

#include "detail/marking_store.h"

namespace gdpn::net::detail {
namespace {

struct Shard {
  std::unique_ptr<Store> store;
  std::mutex inbox_mutex;
  std::vector<std::uint64_t> inbox;  // packed markings waiting to be stored
  std::vector<StateId> work;         // stored, not yet expanded
  std::unique_ptr<Observed> seen;
  std::vector<bool> fired;
  std::atomic<std::uint64_t> edges{0};
  std::atomic<std::uint64_t> bytes{0};  // what the store holds, as its thread last saw
  // the graph, written by the second pass: successors of local state i lie in
  // succ[first[i] .. first[i + 1])
  std::vector<std::uint64_t> first;
  std::vector<std::uint32_t> succ;
};

class Parallel {
 public:
  Parallel(const Net& net, const ExploreOptions& options, const Plan& plan)
      : net_(net),
        options_(options),
        layout_(Layout::omegaOrBounded(plan.bits, plan.omega)),
        candidates_(net),
        firing_(net),
        threads_(options.threads),
        shards_(options.threads) {
    candidates_.use(layout_);
    firing_.use(layout_);
    for (auto& s : shards_) {
      s.store = std::make_unique<Store>(layout_);
      s.seen = std::make_unique<Observed>(layout_);
      s.fired.assign(net.transitions().size(), false);
    }
    std::vector<std::uint64_t> key(layout_.words());
    std::size_t bad = 0;
    layout_.pack(plan.m0.data(), key.data(), bad);
    const std::uint64_t h = shards_[0].store->hash(key.data());
    start_ = owner(h);
    shards_[start_].inbox = key;
    outstanding_ = 1;
    active_ = options.threads;
  }

  StateSpace run() {
    StateSpace out;
    std::vector<std::thread> pool;
    for (unsigned s = 0; s < threads_; ++s) pool.emplace_back([this, s] { explore(s); });
    for (auto& t : pool) t.join();
    out.fired.assign(net_.transitions().size(), false);
    Observed seen(layout_);
    std::uint64_t largest = 0;
    for (auto& s : shards_) {
      out.states += s.store->size();
      out.edges += s.edges.load();
      for (std::size_t t = 0; t < s.fired.size(); ++t) out.fired[t] = out.fired[t] || s.fired[t];
      seen.merge(*s.seen);
      largest = std::max<std::uint64_t>(largest, s.store->size());
    }
    if (stop_ == ExploreStop::Done && largest * threads_ >= 0xfffffff0u) stop_ = ExploreStop::MaxStates;
    out.stop = stop_;
    out.complete = stop_ == ExploreStop::Done;
    if (out.complete) {
      pool.clear();
      for (unsigned s = 0; s < threads_; ++s) pool.emplace_back([this, s] { writeGraph(s); });
      for (auto& t : pool) t.join();
      components(out, largest * threads_);
    }
    seen.settle(layout_);
    summarise(net_, seen, out);
    out.peak_bytes = std::max(peak_, bytes());
    return out;
  }

 private:
  unsigned owner(std::uint64_t h) const { return static_cast<unsigned>(((h >> 32) * threads_) >> 32); }
  std::uint32_t global(unsigned shard, StateId local) const { return local * threads_ + shard; }

  /// Memory held, as each thread last reported it (safe to call while they run).
  std::uint64_t bytes() const {
    std::uint64_t b = 0;
    for (const auto& s : shards_) b += s.bytes.load(std::memory_order_relaxed);
    return b;
  }
  static void account(Shard& s) {
    s.bytes.store(s.store->bytes() + s.work.capacity() * sizeof(StateId) + s.first.capacity() * sizeof(std::uint64_t) +
                      s.succ.capacity() * sizeof(std::uint32_t),
                  std::memory_order_relaxed);
  }

  /// Stores `key` in shard `s` (its own thread); a new marking becomes work.
  void store(Shard& s, const std::uint64_t* key, std::uint64_t h) {
    bool added = false;
    const StateId id = s.store->insert(key, h, added);
    if (!added) return;
    s.seen->note(layout_, s.store->at(id));
    s.work.push_back(id);
    states_.fetch_add(1, std::memory_order_relaxed);
  }

  void explore(unsigned me) {
    // Markings in flight between threads are counted in outstanding_ (added by the sender
    // before they reach an inbox, taken off by the receiver after storing them); threads
    // with work are counted in active_. All is done when both are zero, read in that order.
    Shard& s = shards_[me];
    const std::size_t words = layout_.words();
    const std::size_t transitions = net_.transitions().size();
    std::vector<std::vector<std::uint64_t>> outbox(threads_);
    std::vector<std::uint64_t> batch, keys(transitions * words), hashes(transitions);
    std::vector<TransitionId> candidates;
    auto flush = [&](unsigned to) {
      if (outbox[to].empty()) return;
      outstanding_.fetch_add(static_cast<std::int64_t>(outbox[to].size() / words));
      std::lock_guard lock(shards_[to].inbox_mutex);
      auto& in = shards_[to].inbox;
      in.insert(in.end(), outbox[to].begin(), outbox[to].end());
      outbox[to].clear();
    };
    bool active = true;
    std::uint64_t next_report = 1 << 12;
    while (!stop_flag_.load(std::memory_order_relaxed)) {
      batch.clear();
      {
        std::lock_guard lock(s.inbox_mutex);
        batch.swap(s.inbox);
      }
      if (!batch.empty()) {
        if (!active) active_.fetch_add(1), active = true;
        for (std::size_t i = 0; i < batch.size(); i += words) store(s, &batch[i], s.store->hash(&batch[i]));
        outstanding_.fetch_sub(static_cast<std::int64_t>(batch.size() / words));
      }
      for (int n = 0; n < 1024 && !s.work.empty(); ++n) {
        const StateId v = s.work.back();
        s.work.pop_back();
        // all successors first, their table slots fetched while the next are made
        std::size_t count = 0;
        candidates_.find(s.store->at(v), firing_, candidates);
        for (TransitionId t : candidates) {
          std::size_t field = 0;
          std::uint64_t* out = keys.data() + count * words;
          const Fired f = firing_.fire(t, s.store->at(v), out, field);
          if (f == Fired::NotEnabled) continue;
          if (f == Fired::TooBig) {
            halt(ExploreStop::Overflow);
            break;
          }
          s.fired[t] = true;
          hashes[count] = s.store->hash(out);
          if (owner(hashes[count]) == me) s.store->prefetch(hashes[count]);
          ++count;
        }
        s.edges.fetch_add(count, std::memory_order_relaxed);
        for (std::size_t i = 0; i < count; ++i) {
          const std::uint64_t* key = keys.data() + i * words;
          const unsigned to = owner(hashes[i]);
          if (to == me) {
            store(s, key, hashes[i]);
          } else {
            outbox[to].insert(outbox[to].end(), key, key + words);
            if (outbox[to].size() >= 1024 * words) flush(to);
          }
        }
      }
      account(s);
      // limits and progress, looked at by the first thread
      const std::uint64_t states = states_.load(std::memory_order_relaxed);
      if (states > options_.max_states) halt(ExploreStop::MaxStates);
      if (me == 0 && states >= next_report) {
        next_report = states + (1 << 12);
        const std::uint64_t b = bytes();
        peak_ = std::max(peak_, b);
        if (options_.progress) {
          std::uint64_t edges = 0;
          for (const auto& x : shards_) edges += x.edges.load(std::memory_order_relaxed);
          options_.progress({states, edges, b});
        }
        if (options_.max_bytes != 0 && b > options_.max_bytes) halt(ExploreStop::MaxMemory);
        if (options_.deadline && std::chrono::steady_clock::now() >= *options_.deadline) halt(ExploreStop::TimeLimit);
      }
      if (s.work.empty() && batch.empty()) {
        for (unsigned to = 0; to < threads_; ++to) flush(to);
        if (active) active_.fetch_sub(1), active = false;
        if (outstanding_.load() == 0 && active_.load() == 0) break;
        std::this_thread::yield();
      }
    }
  }

  void halt(ExploreStop why) {
    std::lock_guard lock(halt_mutex_);
    if (stop_ == ExploreStop::Done) stop_ = why;
    stop_flag_ = true;
  }

  void writeGraph(unsigned me) {
    Shard& s = shards_[me];
    const std::size_t words = layout_.words();
    const std::size_t transitions = net_.transitions().size();
    std::vector<std::uint64_t> keys(transitions * words), hashes(transitions);
    std::vector<TransitionId> candidates;
    s.first.reserve(s.store->size() + 1);
    s.succ.reserve(s.edges.load());
    for (StateId v = 0; v < s.store->size(); ++v) {
      s.first.push_back(s.succ.size());
      std::size_t count = 0;
      candidates_.find(s.store->at(v), firing_, candidates);
      for (TransitionId t : candidates) {
        std::size_t field = 0;
        std::uint64_t* out = keys.data() + count * words;
        if (firing_.fire(t, s.store->at(v), out, field) != Fired::Ok) continue;
        hashes[count] = s.store->hash(out);
        shards_[owner(hashes[count])].store->prefetch(hashes[count]);
        ++count;
      }
      for (std::size_t i = 0; i < count; ++i) {
        const unsigned to = owner(hashes[i]);
        s.succ.push_back(global(to, shards_[to].store->find(keys.data() + i * words, hashes[i])));
      }
    }
    s.first.push_back(s.succ.size());
    account(s);
  }

  const std::uint32_t* succBegin(std::uint32_t g) const {
    const Shard& s = shards_[g % threads_];
    return s.succ.data() + s.first[g / threads_];
  }
  const std::uint32_t* succEnd(std::uint32_t g) const {
    const Shard& s = shards_[g % threads_];
    return s.succ.data() + s.first[g / threads_ + 1];
  }
  const std::uint64_t* marking(std::uint32_t g) const { return shards_[g % threads_].store->at(g / threads_); }

  /// Strongly connected components over the arrays (Pearce's variant of Tarjan's
  /// algorithm, as in the sequential search), then the shortest path to a deadlock.
  void components(StateSpace& out, std::uint64_t ids) {
    const std::size_t transitions = net_.transitions().size();
    std::vector<std::uint32_t> rindex(ids, 0);
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
    bool live = true, root_bottom = false, deadlock = false;
    std::vector<bool> fires(transitions);
    std::vector<TransitionId> candidates;
    const std::uint32_t s0 = global(start_, 0);
    auto visit = [&](std::uint32_t v) {
      rindex[v] = index++;
      frames.push_back({v, succBegin(v), succEnd(v), true});
      if (succBegin(v) == succEnd(v)) deadlock = true;
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
            std::fill(fires.begin(), fires.end(), false);
            std::size_t fire = markEnabled(firing_, candidates_, marking(v), fires, candidates);
            for (std::size_t i = first; i < stack.size(); ++i) {
              fire += markEnabled(firing_, candidates_, marking(stack[i]), fires, candidates);
            }
            live = fire == transitions;
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
    out.deadlock = deadlock;
    out.live = live;
    out.reversible = bottoms == 1 && root_bottom;
    if (!deadlock) return;
    // breadth first over the arrays: the first dead state met, and how it was reached
    std::vector<std::uint32_t>& parent = rindex;
    std::fill(parent.begin(), parent.end(), 0xffffffffu);
    std::vector<std::uint32_t> via(ids, 0), queue{s0};
    parent[s0] = s0;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const std::uint32_t v = queue[head];
      if (succBegin(v) == succEnd(v)) {
        for (std::uint32_t x = v; x != s0; x = parent[x]) {
          // the k-th successor comes from the k-th enabled transition
          std::uint32_t k = via[x];
          candidates_.find(marking(parent[x]), firing_, candidates);
          for (TransitionId t : candidates) {
            if (!firing_.enabled(t, marking(parent[x]))) continue;
            if (k-- == 0) {
              out.deadlock_path.push_back(t);
              break;
            }
          }
        }
        std::reverse(out.deadlock_path.begin(), out.deadlock_path.end());
        return;
      }
      for (const std::uint32_t* e = succBegin(v); e != succEnd(v); ++e) {
        if (parent[*e] != 0xffffffffu) continue;
        parent[*e] = v;
        via[*e] = static_cast<std::uint32_t>(e - succBegin(v));
        queue.push_back(*e);
      }
    }
  }

  const Net& net_;
  const ExploreOptions& options_;
  Layout layout_;
  Candidates candidates_;  // shared: read only once made
  Firing firing_;          // likewise
  unsigned threads_;
  std::vector<Shard> shards_;
  unsigned start_ = 0;
  std::atomic<std::int64_t> outstanding_{0};
  std::atomic<std::int64_t> active_{0};
  std::atomic<std::uint64_t> states_{0};
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
