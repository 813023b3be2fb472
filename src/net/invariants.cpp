#include "gdpn/net/invariants.h"

#include <algorithm>
#include <unordered_map>
#include <bit>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <queue>
#include <set>
#include <span>

#include "gdpn/net/slot.h"
#include "gdpn/net/state_equation.h"

namespace gdpn::net {
namespace {

/// The limits of one invariant computation, looked at as the work goes: the first limit
/// reached stops it for good (a time or memory limit stops every system after it too).
class Budget {
 public:
  explicit Budget(const InvariantOptions& options) : options_(options) {}

  /// Records why the work stops (the first reason stays); returns false. Too many candidates
  /// or an overflow stop one system; a time or memory limit stops them all.
  bool halt(ExploreStop why) {
    if (stop_ == ExploreStop::Done) stop_ = why;
    ++halts_;
    return false;
  }
  /// True while no time or memory limit is reached; looks at the clock and memory and reports
  /// progress every 256 calls.
  bool check(const InvariantProgress& now) {
    if (exhausted()) return false;
    if ((++calls_ & 255u) != 0) return true;
    if (options_.max_bytes != 0 && now.bytes > options_.max_bytes) return halt(ExploreStop::MaxMemory);
    if (options_.deadline && std::chrono::steady_clock::now() >= *options_.deadline) return halt(ExploreStop::TimeLimit);
    if (options_.progress) options_.progress(now);
    return true;
  }
  /// True when a time or memory limit has stopped the work.
  [[nodiscard]] bool exhausted() const { return stop_ == ExploreStop::MaxMemory || stop_ == ExploreStop::TimeLimit; }
  [[nodiscard]] ExploreStop stop() const { return stop_; }
  /// How many systems were stopped so far.
  [[nodiscard]] std::size_t halts() const { return halts_; }
  [[nodiscard]] std::size_t maxRows() const { return options_.max_candidates; }
  [[nodiscard]] bool reuseAlike() const { return options_.reuse_alike; }

 private:
  const InvariantOptions& options_;
  ExploreStop stop_ = ExploreStop::Done;
  std::size_t halts_ = 0;
  std::uint32_t calls_ = 0;
};

/// A sparse vector: (index, value) pairs, sorted by index, no zero values.
using Sparse = std::vector<std::pair<std::uint32_t, std::int64_t>>;

/// One row of the Farkas tableau: the combination `y` of the original rows (its indices are
/// its support) and what it sums to over the columns (`a` = y·A).
struct Row {
  Sparse a;
  Sparse y;
  bool alive = true;
  std::uint64_t signature = 0;  ///< bit i % 64 for each i in the support: a quick subset test
};

std::uint64_t signatureOf(const Sparse& y) {
  std::uint64_t s = 0;
  for (const auto& [i, v] : y) s |= std::uint64_t{1} << (i % 64);
  return s;
}

bool addMul(std::int64_t x, std::int64_t cx, std::int64_t z, std::int64_t cz, std::int64_t& out) {
  std::int64_t p = 0, q = 0;
  return !__builtin_mul_overflow(x, cx, &p) && !__builtin_mul_overflow(z, cz, &q) && !__builtin_add_overflow(p, q, &out);
}

/// cx·x + cz·z into `out`, zeros dropped; false on 64-bit overflow.
bool combine(const Sparse& x, std::int64_t cx, const Sparse& z, std::int64_t cz, Sparse& out) {
  out.clear();
  out.reserve(x.size() + z.size());
  std::size_t i = 0, k = 0;
  while (i < x.size() || k < z.size()) {
    std::uint32_t index = 0;
    std::int64_t v = 0;
    if (k == z.size() || (i < x.size() && x[i].first < z[k].first)) {
      index = x[i].first;
      if (!addMul(x[i++].second, cx, 0, 0, v)) return false;
    } else if (i == x.size() || z[k].first < x[i].first) {
      index = z[k].first;
      if (!addMul(0, 0, z[k++].second, cz, v)) return false;
    } else {
      index = x[i].first;
      if (!addMul(x[i++].second, cx, z[k++].second, cz, v)) return false;
    }
    if (v != 0) out.emplace_back(index, v);
  }
  return true;
}

/// A row of the incidence matrix with plain indices, for the algebra.
template <class IdType>
Sparse indexed(const std::vector<std::pair<IdType, std::int64_t>>& row) {
  Sparse out;
  out.reserve(row.size());
  for (const auto& [id, v] : row) out.emplace_back(id.index(), v);
  return out;
}

std::int64_t valueAt(const Sparse& v, std::uint32_t index) {
  const auto it = std::lower_bound(v.begin(), v.end(), std::make_pair(index, std::numeric_limits<std::int64_t>::min()));
  return it != v.end() && it->first == index ? it->second : 0;
}

/// True when the indices of `x` all occur in the sorted `set`.
bool within(const Sparse& x, std::span<const std::uint32_t> set) {
  std::size_t k = 0;
  for (const auto& [i, v] : x) {
    while (k < set.size() && set[k] < i) ++k;
    if (k == set.size() || set[k] != i) return false;
  }
  return true;
}

void normalise(Row& r) {
  std::int64_t g = 0;
  for (const auto& [i, v] : r.y) g = std::gcd(g, v);
  if (g <= 1) return;
  for (auto& [i, v] : r.y) v /= g;
  for (auto& [i, v] : r.a) v /= g;
}

/// The minimal semi-positive y with y·A = 0 for one connected system: `a` has one sparse row
/// per variable over `columns` columns. The Farkas algorithm on sparse rows: it eliminates
/// the column that makes the fewest new rows first (the counts kept as rows come and go),
/// and combines a positive and a negative row only when no other row's support lies within
/// the union of theirs (the combinatorial adjacency test), so every row it makes is minimal.
/// Empty, with the reason in `budget`, when a limit stopped it; `held` is the memory the
/// invariants found before hold, bytes (counted against the limit too).
std::vector<Sparse> farkas(const std::vector<Sparse>& a, std::size_t columns, Budget& budget, InvariantProgress& progress,
                           std::uint64_t held) {
  const std::size_t n = a.size();
  std::vector<Row> rows(n);
  std::vector<std::vector<std::uint32_t>> by_column(columns);  // rows with an entry in the column (dead ones too)
  std::vector<std::vector<std::uint32_t>> by_first(n);         // rows by the first index of their support
  std::vector<std::uint64_t> pos(columns, 0), neg(columns, 0);
  std::vector<bool> done(columns, false);
  // (new rows it would make, column), smallest first; an entry whose cost is out of date is
  // skipped when it comes up (the counts change as rows come and go; the columns they
  // touched are queued again once per round)
  using Entry = std::pair<std::uint64_t, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  std::vector<std::uint32_t> touched;
  std::vector<bool> is_touched(columns, false);
  std::size_t live = 0;
  std::uint64_t bytes = 0;
  auto rowBytes = [](const Row& r) { return sizeof(Row) + (r.a.size() + r.y.size()) * sizeof(Sparse::value_type); };
  // adds (+1) or removes (-1) a row's entries from the counts
  auto count = [&](const Row& r, int sign) {
    for (const auto& [c, v] : r.a) {
      if (done[c]) continue;
      auto& side = v > 0 ? pos[c] : neg[c];
      side = sign > 0 ? side + 1 : side - 1;
      if (!is_touched[c]) is_touched[c] = true, touched.push_back(c);
    }
  };
  auto requeue = [&] {
    for (auto c : touched) {
      is_touched[c] = false;
      if (!done[c] && pos[c] + neg[c] > 0) queue.push({pos[c] * neg[c], c});
    }
    touched.clear();
  };
  auto add = [&](Row r) {
    const auto id = static_cast<std::uint32_t>(rows.size());
    r.signature = signatureOf(r.y);
    for (const auto& [c, v] : r.a) {
      if (!done[c]) by_column[c].push_back(id);
    }
    by_first[r.y.front().first].push_back(id);
    bytes += rowBytes(r);
    ++live;
    count(r, +1);
    rows.push_back(std::move(r));
  };
  rows.clear();
  rows.reserve(n);
  for (std::size_t i = 0; i < n; ++i) add(Row{a[i], {{static_cast<std::uint32_t>(i), 1}}, true});
  requeue();

  std::vector<std::uint32_t> p_rows, n_rows, support;
  std::vector<Row> made;
  for (std::size_t round = 0; !queue.empty();) {
    const auto [cost, j] = queue.top();
    queue.pop();
    if (done[j] || cost != pos[j] * neg[j] || pos[j] + neg[j] == 0) continue;
    p_rows.clear();
    n_rows.clear();
    for (auto id : by_column[j]) {
      if (!rows[id].alive) continue;
      (valueAt(rows[id].a, j) > 0 ? p_rows : n_rows).push_back(id);
    }
    done[j] = true;
    by_column[j] = {};
    progress.round = round++;
    // too many candidates: give up before making them (the answer is then partial)
    if (live - p_rows.size() - n_rows.size() + p_rows.size() * n_rows.size() > 4 * budget.maxRows()) {
      budget.halt(ExploreStop::Candidates);
      return {};
    }
    made.clear();
    for (auto p : p_rows) {
      for (auto q : n_rows) {
        const Row& x = rows[p];
        const Row& z = rows[q];
        support.clear();
        for (const auto& [i, v] : x.y) support.push_back(i);
        for (const auto& [i, v] : z.y) support.push_back(i);
        std::sort(support.begin(), support.end());
        support.erase(std::unique(support.begin(), support.end()), support.end());
        const std::uint64_t outside = ~(x.signature | z.signature);
        bool adjacent = true;
        for (std::size_t s = 0; s < support.size() && adjacent; ++s) {
          auto& bucket = by_first[support[s]];
          std::erase_if(bucket, [&](std::uint32_t w) { return !rows[w].alive; });
          for (auto w : bucket) {
            if (w == p || w == q || (rows[w].signature & outside) != 0 || !within(rows[w].y, std::span(support).subspan(s))) {
              continue;
            }
            adjacent = false;
            break;
          }
        }
        progress.rows = live + made.size();
        progress.bytes = held + bytes;
        if (!budget.check(progress)) return {};
        if (!adjacent) continue;
        std::int64_t cx = -valueAt(z.a, j), cz = valueAt(x.a, j);
        const std::int64_t g = std::gcd(cx, cz);
        cx /= g, cz /= g;
        Row r;
        if (!combine(x.a, cx, z.a, cz, r.a) || !combine(x.y, cx, z.y, cz, r.y)) {
          budget.halt(ExploreStop::Overflow);
          return {};
        }
        normalise(r);
        bytes += rowBytes(r);
        made.push_back(std::move(r));
      }
    }
    for (auto id : p_rows) rows[id].alive = false;
    for (auto id : n_rows) rows[id].alive = false;
    for (auto ids : {&p_rows, &n_rows}) {
      for (auto id : *ids) {
        count(rows[id], -1);
        bytes -= rowBytes(rows[id]);
        --live;
        rows[id] = Row{{}, {}, false};
      }
    }
    for (auto& r : made) add(std::move(r));
    requeue();
    if (live > budget.maxRows()) {
      budget.halt(ExploreStop::Candidates);
      return {};
    }
  }
  std::vector<Sparse> out;
  for (auto& r : rows) {
    if (r.alive) out.push_back(std::move(r.y));
  }
  return out;
}

/// The minimal semiflows of y·A = 0 for `a` (one sparse row per variable over `columns`
/// columns), solved per connected component of the variables and columns that share an
/// entry: the minimal semiflows of a sum of independent systems are those of its parts.
/// Components alike (the same entries, their variables and columns in the same order, as
/// in the instances of one page type) are solved once. A part with too many candidates is
/// left out and the others solved; a time or memory limit stops all. Invariants found are
/// kept (the answer is then partial).
std::vector<Invariant> semiflows(const std::vector<Sparse>& a, std::size_t columns, Budget& budget) {
  const std::size_t n = a.size();
  std::vector<std::uint32_t> parent(n + columns);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (std::size_t i = 0; i < n; ++i) {
    for (const auto& [c, v] : a[i]) {
      const auto x = find(static_cast<std::uint32_t>(i)), y = find(static_cast<std::uint32_t>(n + c));
      if (x != y) parent[std::max(x, y)] = std::min(x, y);
    }
  }
  // the components, each listing its variables in order (a component is named by its first)
  std::vector<std::vector<std::uint32_t>> members(n);
  for (std::uint32_t i = 0; i < n; ++i) members[find(i)].push_back(i);
  std::map<std::vector<std::int64_t>, std::vector<Sparse>> solved;  // by the component's entries, local indices
  std::vector<Invariant> out;
  std::vector<std::uint32_t> cols;
  std::vector<std::uint32_t> local(columns, 0);
  InvariantProgress progress{0, columns, n, 0};
  std::uint64_t held = 0;  // what the invariants found so far hold, bytes
  for (std::uint32_t root = 0; root < n && !budget.exhausted(); ++root) {
    const auto& vars = members[root];
    if (vars.empty()) continue;
    cols.clear();
    for (auto i : vars) {
      for (const auto& [c, v] : a[i]) cols.push_back(c);
    }
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
    for (std::uint32_t k = 0; k < cols.size(); ++k) local[cols[k]] = k;
    std::vector<std::int64_t> key{static_cast<std::int64_t>(vars.size()), static_cast<std::int64_t>(cols.size())};
    std::vector<Sparse> system;
    system.reserve(vars.size());
    for (auto i : vars) {
      key.push_back(static_cast<std::int64_t>(a[i].size()));
      Sparse row;
      for (const auto& [c, v] : a[i]) {
        row.emplace_back(local[c], v);
        key.push_back(local[c]);
        key.push_back(v);
      }
      system.push_back(std::move(row));
    }
    auto it = budget.reuseAlike() ? solved.find(key) : solved.end();
    if (it == solved.end()) {
      if (!budget.reuseAlike()) solved.clear();
      const std::size_t halts = budget.halts();
      auto found = farkas(system, cols.size(), budget, progress, held);
      if (budget.halts() != halts) continue;  // this part is left out: the answer is partial
      it = solved.emplace(std::move(key), std::move(found)).first;
    }
    for (const Sparse& y : it->second) {
      Invariant inv;
      for (const auto& [k, w] : y) inv.weights.emplace_back(vars[k], w);
      held += sizeof(Invariant) + inv.weights.size() * sizeof(inv.weights[0]);
      out.push_back(std::move(inv));
    }
  }
  std::sort(out.begin(), out.end(), [](const Invariant& x, const Invariant& y) { return x.weights < y.weights; });
  return out;
}

/// True when the union of the supports covers every index below `n`.
bool covers(const std::vector<Invariant>& invs, std::size_t n) {
  std::vector<bool> seen(n, false);
  for (const auto& inv : invs) {
    for (const auto& [k, w] : inv.weights) {
      if (k < n) seen[k] = true;
    }
  }
  return std::all_of(seen.begin(), seen.end(), [](bool b) { return b; });
}

/// The semiflows of C (rows: place slots; with `slack`, one more row per transition with a 1
/// in its column, for y·C <= 0), computed slot by slot: a token of slot b0 stays a b0 token,
/// so the place slots of one slot are a system of their own. Slack rows are numbered after
/// the place slots, by transition.
std::vector<Invariant> slotwise(const Net& net, const Incidence& c, bool slack, Budget& budget) {
  const std::size_t places = net.placeSlots().size();
  const std::size_t transitions = net.transitions().size();
  std::map<SlotId, std::vector<std::uint32_t>> groups;
  for (std::uint32_t ps = 0; ps < places; ++ps) groups[net.placeSlots()[ps].slot].push_back(ps);
  std::vector<Invariant> out;
  for (const auto& [slot, members] : groups) {
    std::vector<Sparse> a;
    std::vector<std::uint32_t> slacks;  // the transitions of the slack rows, in order
    for (auto ps : members) {
      a.push_back(indexed(c.by_place[ps]));
      if (slack) {
        for (const auto& [t, v] : c.by_place[ps]) slacks.push_back(t);
      }
    }
    std::sort(slacks.begin(), slacks.end());
    slacks.erase(std::unique(slacks.begin(), slacks.end()), slacks.end());
    for (auto t : slacks) a.push_back({{t, 1}});
    for (Invariant inv : semiflows(a, transitions, budget)) {
      for (auto& [k, w] : inv.weights) {
        k = k < members.size() ? members[k] : static_cast<std::uint32_t>(places + slacks[k - members.size()]);
      }
      std::sort(inv.weights.begin(), inv.weights.end());
      // a slack-only row (a transition that changes no place of this slot) says nothing
      if (inv.weights.front().first < places) out.push_back(std::move(inv));
    }
  }
  std::sort(out.begin(), out.end(), [](const Invariant& x, const Invariant& y) { return x.weights < y.weights; });
  out.erase(std::unique(out.begin(), out.end(), [](const Invariant& x, const Invariant& y) { return x.weights == y.weights; }),
            out.end());
  return out;
}

}  // namespace

Incidence incidenceMatrix(const Net& net) {
  Incidence c;
  c.by_place.resize(net.placeSlots().size());
  c.by_transition.resize(net.transitions().size());
  for (TransitionId t{0}; t < net.transitions().size(); ++t) {
    auto& row = c.by_transition[t];
    for (const Term& term : net.termsOf(t)) {
      if (term.kind == TermKind::Input) row.emplace_back(term.place_slot, -std::int64_t{term.weight});
      if (term.kind == TermKind::Output) row.emplace_back(term.place_slot, term.weight);
    }
    std::sort(row.begin(), row.end());
    std::remove_reference_t<decltype(row)> merged;
    for (const auto& [ps, v] : row) {
      if (!merged.empty() && merged.back().first == ps) {
        merged.back().second += v;
      } else {
        merged.emplace_back(ps, v);
      }
    }
    std::erase_if(merged, [](const auto& e) { return e.second == 0; });
    row = std::move(merged);
    for (const auto& [ps, v] : row) c.by_place[ps].emplace_back(t, v);
  }
  return c;
}

std::int64_t incidence(const Net& net, PlaceSlotId ps, TransitionId t) {
  std::int64_t c = 0;
  for (const Term& term : net.termsOf(t)) {
    if (term.place_slot != ps) continue;
    if (term.kind == TermKind::Input) c -= term.weight;
    if (term.kind == TermKind::Output) c += term.weight;
  }
  return c;
}

Invariants invariants(const Net& net, const InvariantOptions& options) {
  Invariants out;
  const std::size_t places = net.placeSlots().size();
  const std::size_t transitions = net.transitions().size();
  out.bound.assign(places, -1);
  Budget budget(options);
  const Incidence c = incidenceMatrix(net);
  std::vector<Sparse> by_place, by_transition;
  by_place.reserve(c.by_place.size());
  for (const auto& row : c.by_place) by_place.push_back(indexed(row));
  by_transition.reserve(c.by_transition.size());
  for (const auto& row : c.by_transition) by_transition.push_back(indexed(row));
  std::size_t halts = budget.halts();
  out.p = slotwise(net, c, false, budget);
  out.p_complete = budget.halts() == halts;
  halts = budget.halts();
  out.t = semiflows(by_transition, places, budget);
  out.t_complete = budget.halts() == halts && !budget.exhausted();
  // yes or no from the lists where they are whole; where one was cut, from a linear program
  // (some y >= 1 with y·C = 0 exists or not), which a long list does not hold up
  auto byProgram = [&out](const std::vector<Sparse>& rows, std::size_t columns, bool equality, bool listed) {
    if (listed) return true;
    const std::optional<bool> found = positiveSolution(rows, columns, equality);
    out.decided = out.decided && found.has_value();
    return found.value_or(false);
  };
  out.conservative = covers(out.p, places);
  if (!out.p_complete) out.conservative = byProgram(by_place, transitions, true, out.conservative);
  out.consistent = covers(out.t, transitions);
  if (!out.t_complete) out.consistent = byProgram(by_transition, places, true, out.consistent);

  // y·C <= 0: the semiflows of C with one slack row per transition, for the bounds they give;
  // their list may be cut (its own budget: the answer above stays whole), and then the
  // program says whether the net is structurally bounded
  std::vector<Invariant> bounding = out.p;
  if (!out.conservative) {
    Budget slack_budget(options);
    auto slack = slotwise(net, c, true, slack_budget);
    const bool whole = slack_budget.halts() == 0;
    out.structurally_bounded = whole ? covers(slack, places) : byProgram(by_place, transitions, false, false);
    bounding.insert(bounding.end(), std::make_move_iterator(slack.begin()), std::make_move_iterator(slack.end()));
    if (slack_budget.exhausted()) budget.halt(slack_budget.stop());  // a time or memory limit stops all
  } else {
    out.structurally_bounded = true;
  }
  out.stop = budget.stop();
  out.complete = out.stop == ExploreStop::Done;
  if (!out.complete && out.p_complete && out.t_complete) out.p_complete = out.t_complete = false;  // a limit cut the rest
  // y·M <= y·M0 in every reachable marking M, so M(p) <= y·M0 / y(p)
  for (const auto& inv : bounding) {
    std::int64_t total = 0;
    bool ok = true;
    for (const auto& [k, w] : inv.weights) {
      if (k >= places) continue;
      std::int64_t term = 0;
      ok = ok && !__builtin_mul_overflow(w, net.placeSlots()[k].initial, &term) && !__builtin_add_overflow(total, term, &total);
    }
    if (!ok) continue;
    for (const auto& [k, w] : inv.weights) {
      if (k >= places) continue;
      const std::int64_t b = total / w;
      if (out.bound[k] < 0 || b < out.bound[k]) out.bound[k] = b;
    }
  }
  return out;
}

std::vector<Invariant> semiflowsOf(const std::vector<std::vector<std::pair<std::uint32_t, std::int64_t>>>& rows,
                                   std::size_t columns, const InvariantOptions& options, ExploreStop* stop) {
  Budget budget(options);
  auto out = semiflows(rows, columns, budget);
  if (stop != nullptr) *stop = budget.stop();
  return out;
}

bool isPInvariant(const Net& net, const Invariant& y) {
  std::vector<std::int64_t> sum(net.transitions().size(), 0);
  for (const auto& [k, w] : y.weights) {
    if (w <= 0 || k >= net.placeSlots().size()) return false;
  }
  for (const Term& term : net.terms()) {
    for (const auto& [k, w] : y.weights) {
      if (k != term.place_slot) continue;
      if (term.kind == TermKind::Input) sum[term.transition] -= w * term.weight;
      if (term.kind == TermKind::Output) sum[term.transition] += w * term.weight;
    }
  }
  return !y.weights.empty() && std::all_of(sum.begin(), sum.end(), [](std::int64_t v) { return v == 0; });
}

bool isTInvariant(const Net& net, const Invariant& x) {
  std::vector<std::int64_t> sum(net.placeSlots().size(), 0);
  for (const auto& [k, w] : x.weights) {
    if (w <= 0 || k >= net.transitions().size()) return false;
    for (const Term& term : net.termsOf(TransitionId{k})) {
      if (term.kind == TermKind::Input) sum[term.place_slot] -= w * term.weight;
      if (term.kind == TermKind::Output) sum[term.place_slot] += w * term.weight;
    }
  }
  return !x.weights.empty() && std::all_of(sum.begin(), sum.end(), [](std::int64_t v) { return v == 0; });
}

namespace {

/// For a P-invariant that carries one token through a state machine (every transition that
/// takes from it takes one token from one of its slots and puts one into one), the token's
/// round trips are its elementary circuits: finds the longest (seconds), or nothing when the
/// invariant is not such a state machine or the circuits are too many to list.
std::optional<std::pair<double, std::vector<TransitionId>>> longestCircuit(const Net& net, std::span<const std::int64_t> y,
                                                                        std::span<const TransitionId> transitions,
                                                                        std::span<const double> seconds) {
  struct Edge {
    PlaceSlotId from, to;
    TransitionId t;
  };
  std::vector<Edge> edges;
  for (TransitionId t : transitions) {
    std::optional<PlaceSlotId> from, to;
    for (const Term& term : net.termsOf(t)) {
      if (y[term.place_slot] == 0 || (term.kind != TermKind::Input && term.kind != TermKind::Output)) continue;
      auto& end = term.kind == TermKind::Input ? from : to;
      if (y[term.place_slot] != 1 || term.weight != 1 || end) return std::nullopt;
      end = term.place_slot;
    }
    if (!from || !to) return std::nullopt;
    edges.push_back({*from, *to, t});
  }
  // depth-first enumeration of elementary circuits, each found once from its smallest slot;
  // the edges out of a slot in transition order, the path on an explicit stack (a circuit
  // may run through a hundred thousand places)
  std::stable_sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& z) { return x.from < z.from; });
  auto outOf = [&](PlaceSlotId at) {
    const auto first = std::lower_bound(edges.begin(), edges.end(), at, [](const Edge& e, PlaceSlotId v) { return e.from < v; });
    const auto last = std::upper_bound(first, edges.end(), at, [](PlaceSlotId v, const Edge& e) { return v < e.from; });
    return std::make_pair(static_cast<std::size_t>(first - edges.begin()), static_cast<std::size_t>(last - edges.begin()));
  };
  constexpr std::size_t kMaxSteps = 200'000;
  std::size_t steps = 0;
  double best = -1.0;
  std::vector<TransitionId> best_path, path;
  std::set<PlaceSlotId> on_path;
  struct Frame {
    PlaceSlotId at;         // the slot
    std::size_t next, end;  // the edges still to follow out of it
    double sum;             // seconds from the start to this slot
  };
  std::vector<Frame> stack;
  std::vector<PlaceSlotId> starts;
  for (const Edge& e : edges) starts.push_back(e.from);
  starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
  for (PlaceSlotId start : starts) {
    on_path = {start};
    const auto [first, last] = outOf(start);
    stack = {{start, first, last, 0.0}};
    while (!stack.empty()) {
      Frame& top = stack.back();
      if (top.next == top.end) {
        if (stack.size() > 1) {
          on_path.erase(top.at);
          path.pop_back();
        }
        stack.pop_back();
        continue;
      }
      const Edge& e = edges[top.next++];
      if (++steps > kMaxSteps) return std::nullopt;
      const double sum = top.sum + (e.t < seconds.size() ? seconds[e.t] : 0.0);
      if (e.to == start) {
        if (sum > best) {
          best = sum;
          best_path = path;
          best_path.push_back(e.t);
        }
      } else if (e.to > start && !on_path.contains(e.to)) {
        on_path.insert(e.to);
        path.push_back(e.t);
        const auto [f, l] = outOf(e.to);
        stack.push_back({e.to, f, l, sum});
      }
    }
  }
  if (best < 0.0) return std::nullopt;
  return std::make_pair(best, std::move(best_path));
}

}  // namespace

namespace {

/// Whether the tokens of P-invariant `weights` (`y` its weights by place slot) can come back to
/// each of its place slots: from the first, every one is reached through the transitions that
/// take from one and put on another (`takers`), and every one reaches the first back.
bool comesBack(const Net& net, const std::vector<std::pair<std::uint32_t, std::int64_t>>& weights,
               std::span<const std::int64_t> y,
               const std::vector<std::vector<std::pair<TransitionId, std::int64_t>>>& takers) {
  if (weights.size() <= 1) {
    // one place slot: a cycle when a transition takes from it and puts back on it
    if (weights.empty()) return false;
    const auto k = weights.front().first;
    return std::any_of(takers[k].begin(), takers[k].end(), [&](const auto& tn) {
      const auto& terms = net.termsOf(tn.first);
      return std::any_of(terms.begin(), terms.end(),
                         [&](const Term& term) { return term.kind == TermKind::Output && term.place_slot == k; });
    });
  }
  // the invariant's own graph, place slot to place slot, forwards and backwards
  std::unordered_map<std::uint32_t, std::size_t> at;
  for (std::size_t i = 0; i < weights.size(); ++i) at.emplace(weights[i].first, i);
  std::vector<std::vector<std::size_t>> next(weights.size()), back(weights.size());
  for (std::size_t i = 0; i < weights.size(); ++i) {
    for (const auto& [t, n] : takers[weights[i].first]) {
      for (const Term& term : net.termsOf(t)) {
        if (term.kind != TermKind::Output || y[term.place_slot] == 0) continue;
        const std::size_t j = at.at(term.place_slot);
        next[i].push_back(j);
        back[j].push_back(i);
      }
    }
  }
  const auto reachesAll = [&](const std::vector<std::vector<std::size_t>>& edges) {
    std::vector<char> seen(weights.size(), 0);
    std::vector<std::size_t> todo{0};
    seen[0] = 1;
    std::size_t reached = 1;
    while (!todo.empty()) {
      const std::size_t i = todo.back();
      todo.pop_back();
      for (std::size_t j : edges[i]) {
        if (!seen[j]) {
          seen[j] = 1;
          ++reached;
          todo.push_back(j);
        }
      }
    }
    return reached == weights.size();
  };
  return reachesAll(next) && reachesAll(back);
}

}  // namespace

std::vector<CycleBound> cycleBounds(const Net& net, const Invariants& invariants, std::span<const double> seconds,
                                    const InvariantOptions& options, ExploreStop* stop) {
  std::vector<CycleBound> out;
  const std::size_t places = net.placeSlots().size();
  // what each place slot's tokens feed: (transition, tokens taken), so that an invariant's
  // transitions are found from its places, not by looking at every transition
  std::vector<std::vector<std::pair<TransitionId, std::int64_t>>> takers(places);
  for (TransitionId t{0}; t < net.transitions().size(); ++t) {
    for (const Term& term : net.termsOf(t)) {
      if (term.kind == TermKind::Input) takers[term.place_slot].emplace_back(t, term.weight);
    }
  }
  std::vector<std::int64_t> y(places, 0);
  std::vector<std::int64_t> taken(net.transitions().size(), 0);
  Budget budget(options);
  for (std::size_t i = 0; i < invariants.p.size(); ++i) {
    if (!budget.check({i, invariants.p.size(), out.size(), 0})) break;
    const auto& weights = invariants.p[i].weights;
    CycleBound b;
    b.invariant = i;
    for (const auto& [k, w] : weights) b.tokens += w * net.placeSlots()[k].initial;
    if (b.tokens <= 0) continue;
    for (const auto& [k, w] : weights) {
      y[k] = w;
      for (const auto& [t, n] : takers[k]) {
        if (taken[t] == 0) b.transitions.push_back(t);
        taken[t] += w * n;
      }
    }
    std::sort(b.transitions.begin(), b.transitions.end());
    // a cycle only when its tokens come back: every place of it reaches every other through
    // its transitions (a flow that ends in a sink, a transition that fires once, is none)
    if (!comesBack(net, weights, y, takers)) {
      for (TransitionId t : b.transitions) taken[t] = 0;
      for (const auto& [k, w] : weights) y[k] = 0;
      continue;
    }
    // a choice: a place slot of it feeding two or more transitions
    bool choice = false;
    for (const auto& [k, w] : weights) choice = choice || takers[k].size() > 1;
    double work = 0.0;
    for (TransitionId t : b.transitions) {
      work += (t < seconds.size() ? seconds[t] : 0.0) * static_cast<double>(taken[t]);
      taken[t] = 0;
    }
    if (!b.transitions.empty()) {
      b.seconds = work / static_cast<double>(b.tokens);
      if (b.tokens == 1) {
        if (auto circuit = longestCircuit(net, y, b.transitions, seconds)) {
          b.seconds = circuit->first;
          b.transitions = std::move(circuit->second);
          b.circuit = true;
          b.alternatives = choice;
        }
      }
      if (choice && !b.circuit) {
        b.flow = true;
        b.seconds = 0.0;
      }
      b.immediate = std::all_of(b.transitions.begin(), b.transitions.end(), [&](TransitionId t) {
        return meanSeconds(net.transitions()[t].duration) <= 0.0;
      });
      if (b.immediate) b.seconds = 0.0;
      out.push_back(std::move(b));
    }
    for (const auto& [k, w] : weights) y[k] = 0;
  }
  std::stable_sort(out.begin(), out.end(), [](const CycleBound& x, const CycleBound& z) { return x.seconds > z.seconds; });
  if (stop) *stop = budget.stop();
  return out;
}

double meanSeconds(const DurationLaw& duration) {
  switch (duration.law) {
    case Duration::Law::Uniform:
      return 0.5 * (duration.a + duration.b);
    case Duration::Law::Immediate:
      return 0.0;
    case Duration::Law::Fixed:
    case Duration::Law::Normal:
    case Duration::Law::Exponential:
      break;
  }
  return duration.a;
}

std::string placeSlotName(const Net& net, PlaceSlotId ps) {
  const PlaceSlot& s = net.placeSlots()[ps];
  const std::string name = net.placeName(s.place);
  return s.slot == kDefaultSlot ? name : name + "." + slotName(s.slot);
}

}  // namespace gdpn::net
