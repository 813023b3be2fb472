#include "gdpn/net/analysis.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace gdpn::net {
namespace {

using Count = std::int32_t;

/// Markings stored end to end in one arena; an open-addressing table of their indices.
class MarkingSet {
 public:
  explicit MarkingSet(std::size_t width) : width_(width) { table_.assign(1024, kEmpty); }

  /// The index of `m`, adding it when new; `added` says which.
  std::uint32_t insert(const Count* m, bool& added) {
    if ((count_ + 1) * 2 > table_.size()) grow();
    const std::uint64_t h = hash(m);
    for (std::size_t i = h & (table_.size() - 1);; i = (i + 1) & (table_.size() - 1)) {
      const std::uint32_t s = table_[i];
      if (s == kEmpty) {
        table_[i] = static_cast<std::uint32_t>(count_);
        arena_.insert(arena_.end(), m, m + width_);
        added = true;
        return static_cast<std::uint32_t>(count_++);
      }
      if (std::memcmp(at(s), m, width_ * sizeof(Count)) == 0) {
        added = false;
        return s;
      }
    }
  }
  const Count* at(std::uint32_t s) const { return arena_.data() + std::size_t{s} * width_; }
  std::size_t size() const { return count_; }

 private:
  static constexpr std::uint32_t kEmpty = 0xffffffffu;
  std::uint64_t hash(const Count* m) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (std::size_t k = 0; k < width_; ++k) {
      h ^= static_cast<std::uint32_t>(m[k]);
      h *= 0xff51afd7ed558ccdULL;
      h ^= h >> 32;
    }
    return h;
  }
  void grow() {
    std::vector<std::uint32_t> bigger(table_.size() * 2, kEmpty);
    for (std::uint32_t s = 0; s < count_; ++s) {
      for (std::size_t i = hash(at(s)) & (bigger.size() - 1);; i = (i + 1) & (bigger.size() - 1)) {
        if (bigger[i] == kEmpty) {
          bigger[i] = s;
          break;
        }
      }
    }
    table_.swap(bigger);
  }
  std::size_t width_;
  std::size_t count_ = 0;
  std::vector<Count> arena_;
  std::vector<std::uint32_t> table_;
};

bool enabledIn(const Net& net, TransitionId t, const Count* m) {
  for (const Term& term : net.termsOf(t)) {
    const Count v = m[term.place_slot];
    switch (term.kind) {
      case TermKind::Input:
      case TermKind::Test:
        if (v < term.weight) return false;
        break;
      case TermKind::Inhibitor:
        if (v >= term.weight) return false;
        break;
      case TermKind::Output: {
        const auto cap = net.placeSlots()[term.place_slot].capacity;
        if (cap != kUnbounded && v - term.take + term.weight > cap) return false;
        break;
      }
      case TermKind::Condition:
        break;  // sensor conditions are free to be either: explore as if true
    }
  }
  return true;
}

/// Fires `t` in `m`; false when a count would leave the 32-bit range the search stores.
bool fire(const Net& net, TransitionId t, Count* m) {
  for (const Term& term : net.termsOf(t)) {
    if (term.kind == TermKind::Input) m[term.place_slot] -= term.weight;
    if (term.kind == TermKind::Output) {
      const std::int64_t v = std::int64_t{m[term.place_slot]} + term.weight;
      if (v > std::numeric_limits<Count>::max()) return false;
      m[term.place_slot] = static_cast<Count>(v);
    }
  }
  return true;
}

}  // namespace

StateSpace explore(const Net& net, const ExploreOptions& options) {
  StateSpace out;
  const std::size_t width = net.placeSlots().size();
  const std::size_t transitions = net.transitions().size();
  MarkingSet set(width);
  std::vector<Count> m(width), next(width);
  for (std::size_t ps = 0; ps < width; ++ps) {
    // counts beyond 32 bits are more than any exploration can hold: answer "partial"
    if (net.placeSlots()[ps].initial > std::numeric_limits<Count>::max()) {
      out.complete = false;
      out.live = out.reversible = false;
      return out;
    }
    m[ps] = static_cast<Count>(net.placeSlots()[ps].initial);
  }
  bool added = false;
  set.insert(m.data(), added);
  std::vector<std::uint32_t> parent{0};
  std::vector<TransitionId> via{0};
  // the graph, kept for the SCCs: successors and the transition of each edge, per state
  std::vector<std::uint64_t> first{0};
  std::vector<std::uint32_t> succ;
  std::vector<TransitionId> label;
  out.fired.assign(transitions, false);
  std::vector<Count> low(width), high(width);
  std::copy(m.begin(), m.end(), low.begin());
  std::copy(m.begin(), m.end(), high.begin());
  std::int64_t deadlock_state = -1;

  for (std::uint32_t s = 0; s < set.size(); ++s) {
    std::copy(set.at(s), set.at(s) + width, m.begin());
    // bounds and constants
    std::int64_t total = 0;
    for (std::size_t k = 0; k < width; ++k) {
      low[k] = std::min(low[k], m[k]);
      high[k] = std::max(high[k], m[k]);
      total += m[k];
    }
    out.max_marking = std::max(out.max_marking, total);
    bool any = false;
    for (TransitionId t = 0; t < transitions; ++t) {
      if (!enabledIn(net, t, m.data())) continue;
      any = true;
      out.fired[t] = true;
      next = m;
      if (!fire(net, t, next.data())) {
        out.complete = false;
        break;
      }
      const auto target = set.insert(next.data(), added);
      if (added) {
        parent.push_back(s);
        via.push_back(t);
      }
      succ.push_back(target);
      label.push_back(t);
    }
    first.push_back(succ.size());
    if (!any && deadlock_state < 0) deadlock_state = s;
    if (!out.complete || set.size() > options.max_states) {
      out.complete = false;
      break;
    }
  }
  out.states = first.size() - 1;  // states whose successors are known
  if (!out.complete) out.states = set.size();
  out.edges = succ.size();
  out.deadlock = deadlock_state >= 0;
  for (auto s = deadlock_state; s > 0; s = parent[static_cast<std::size_t>(s)]) {
    out.deadlock_path.push_back(via[static_cast<std::size_t>(s)]);
  }
  std::reverse(out.deadlock_path.begin(), out.deadlock_path.end());

  // per place: bounds and constancy (all slots of a place together)
  const auto places = net.places();
  out.place_bound.assign(places.size(), 0);
  for (PlaceId p = 0; p < places.size(); ++p) {
    bool constant = true;
    for (auto ps = places[p].slots_begin; ps < places[p].slots_end; ++ps) {
      out.place_bound[p] += high[ps];
      constant = constant && low[ps] == high[ps];
    }
    if (constant) out.constant_places.push_back(p);
    out.max_place = std::max(out.max_place, out.place_bound[p]);
  }
  out.one_safe = out.max_place <= 1;
  out.quasi_live = std::all_of(out.fired.begin(), out.fired.end(), [](bool b) { return b; });
  if (!out.complete) {
    out.live = out.reversible = false;
    return out;
  }

  // strongly connected components (iterative Tarjan); live and reversible are read off the
  // bottom ones (those no edge leaves)
  const std::size_t n = out.states;
  std::vector<std::uint32_t> index(n, 0xffffffffu), lowlink(n, 0), comp(n, 0xffffffffu);
  std::vector<std::uint32_t> stack, call;
  std::vector<std::uint64_t> edge_at(n, 0);
  std::vector<bool> on_stack(n, false);
  std::uint32_t counter = 0, comps = 0;
  for (std::uint32_t root = 0; root < n; ++root) {
    if (index[root] != 0xffffffffu) continue;
    call.push_back(root);
    index[root] = lowlink[root] = counter++;
    stack.push_back(root);
    on_stack[root] = true;
    edge_at[root] = first[root];
    while (!call.empty()) {
      const std::uint32_t v = call.back();
      if (edge_at[v] < first[v + 1]) {
        const std::uint32_t w = succ[edge_at[v]++];
        if (index[w] == 0xffffffffu) {
          index[w] = lowlink[w] = counter++;
          stack.push_back(w);
          on_stack[w] = true;
          edge_at[w] = first[w];
          call.push_back(w);
        } else if (on_stack[w]) {
          lowlink[v] = std::min(lowlink[v], index[w]);
        }
        continue;
      }
      call.pop_back();
      if (!call.empty()) lowlink[call.back()] = std::min(lowlink[call.back()], lowlink[v]);
      if (lowlink[v] == index[v]) {
        std::uint32_t w = 0;
        do {
          w = stack.back();
          stack.pop_back();
          on_stack[w] = false;
          comp[w] = comps;
        } while (w != v);
        ++comps;
      }
    }
  }
  std::vector<bool> bottom(comps, true);
  std::vector<std::vector<bool>> fires(comps);
  for (std::uint32_t v = 0; v < n; ++v) {
    for (auto e = first[v]; e < first[v + 1]; ++e) {
      if (comp[succ[e]] != comp[v]) {
        bottom[comp[v]] = false;
      } else {
        auto& f = fires[comp[v]];
        if (f.empty()) f.assign(transitions, false);
        f[label[e]] = true;
      }
    }
  }
  std::uint32_t bottoms = 0;
  for (std::uint32_t c = 0; c < comps; ++c) {
    if (!bottom[c]) continue;
    ++bottoms;
    const auto& f = fires[c];
    const bool all = transitions == 0 || (!f.empty() && std::all_of(f.begin(), f.end(), [](bool b) { return b; }));
    out.live = out.live && all;
  }
  out.reversible = bottoms == 1 && bottom[comp[0]];
  return out;
}

}  // namespace gdpn::net
