#include "gdpn/net/analysis.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <memory>

#include "gdpn/net/invariants.h"
#include "detail/marking_store.h"

namespace gdpn::net {
namespace {

using namespace detail;

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
  std::unique_ptr<Observed> seen_;
  std::vector<bool> fired_;
  bool deadlock_ = false;
  bool live_ = true;
  std::uint32_t bottoms_ = 0;
  bool root_bottom_ = false;
  std::uint64_t peak_ = 0;
};

Search::Expand Search::fire(TransitionId t, const std::uint64_t* m, std::uint64_t* out, bool& enabled) {
  std::size_t field = 0;
  const Fired f = fireInto(net_, store_->layout(), t, m, out, field);
  enabled = f != Fired::NotEnabled;
  if (f != Fired::TooBig) return Expand::Ok;
  return widen(field) ? Expand::Widened : Expand::Overflow;
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
  seen_->note(store_->layout(), store_->at(s));
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
      std::size_t fire = markEnabled(net_, store_->layout(), store_->at(v), union_);
      for (std::size_t i = first; i < size; ++i) fire += markEnabled(net_, store_->layout(), store_->at(stack_[i]), union_);
      live_ = fire == union_.size();
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

  const Plan p = plan(net_, options_);
  if (p.overflow) return overflowAnswer(net_);
  if (options_.threads > 1 && !p.cover) return exploreParallel(net_, options_, p);
  cover_ = p.cover;
  accel_ = p.accel;
  store_ = std::make_unique<Store>(Layout(p.bits, p.omega));
  std::vector<std::uint64_t> key(store_->words());
  std::size_t bad = 0;
  store_->layout().pack(p.m0.data(), key.data(), bad);
  seen_ = std::make_unique<Observed>(width);
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
        if (options_.deadline && std::chrono::steady_clock::now() >= *options_.deadline) {
          stop_ = ExploreStop::TimeLimit, running = false;
        }
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
  summarise(net_, *seen_, out);
  out.deadlock = deadlock_;
  if (out.decided) {
    out.live = live_;
    out.reversible = bottoms_ == 1 && root_bottom_;
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
