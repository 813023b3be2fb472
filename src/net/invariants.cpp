#include "gdpn/net/invariants.h"

#include <algorithm>
#include <bit>
#include <limits>
#include <map>
#include <numeric>
#include <optional>

#include "gdpn/net/slot.h"

namespace gdpn::net {
namespace {

using Matrix = std::vector<std::vector<std::int64_t>>;

/// One row of the Farkas tableau: the combination `y` of the original rows, what it sums
/// to (`a` = y·A over the columns not yet eliminated), and the support of `y` as bits.
struct Row {
  std::vector<std::int64_t> a;
  std::vector<std::int64_t> y;
  std::vector<std::uint64_t> support;
};

/// The limits of one invariant computation, looked at as the work goes: the first limit
/// reached stops it for good (a time or memory limit stops every system after it too).
class Budget {
 public:
  explicit Budget(const InvariantOptions& options) : options_(options) {}

  /// Records why the work stops (the first reason stays); returns false.
  bool halt(ExploreStop why) {
    if (stop_ == ExploreStop::Done) stop_ = why;
    return false;
  }
  /// True while no limit is reached; looks at the clock and memory and reports progress
  /// every 256 calls.
  bool check(const InvariantProgress& now) {
    if (stop_ != ExploreStop::Done) return false;
    if ((++calls_ & 255u) != 0) return true;
    if (options_.max_bytes != 0 && now.bytes > options_.max_bytes) return halt(ExploreStop::MaxMemory);
    if (options_.deadline && std::chrono::steady_clock::now() >= *options_.deadline) return halt(ExploreStop::TimeLimit);
    if (options_.progress) options_.progress(now);
    return true;
  }
  /// True when a time or memory limit has stopped the work.
  [[nodiscard]] bool exhausted() const { return stop_ == ExploreStop::MaxMemory || stop_ == ExploreStop::TimeLimit; }
  [[nodiscard]] ExploreStop stop() const { return stop_; }
  [[nodiscard]] std::size_t maxRows() const { return options_.max_candidates; }

 private:
  const InvariantOptions& options_;
  ExploreStop stop_ = ExploreStop::Done;
  std::uint32_t calls_ = 0;
};

bool addMul(std::int64_t x, std::int64_t cx, std::int64_t z, std::int64_t cz, std::int64_t& out) {
  std::int64_t p = 0, q = 0;
  return !__builtin_mul_overflow(x, cx, &p) && !__builtin_mul_overflow(z, cz, &q) && !__builtin_add_overflow(p, q, &out);
}

void normalise(Row& r) {
  std::int64_t g = 0;
  for (auto v : r.y) g = std::gcd(g, v);
  if (g <= 1) return;
  for (auto& v : r.y) v /= g;
  for (auto& v : r.a) v /= g;
}

bool subset(const std::vector<std::uint64_t>& x, const std::vector<std::uint64_t>& y) {
  for (std::size_t k = 0; k < x.size(); ++k) {
    if ((x[k] & ~y[k]) != 0) return false;
  }
  return true;
}

/// Keeps the rows whose support contains no other row's support (and one of equal rows).
/// False when `budget` stopped it (the rows are then left as they were).
bool keepMinimal(std::vector<Row>& rows, Budget& budget, InvariantProgress progress) {
  std::vector<std::size_t> count(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (auto w : rows[i].support) count[i] += static_cast<std::size_t>(std::popcount(w));
  }
  std::vector<bool> drop(rows.size(), false);
  progress.rows = rows.size();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!budget.check(progress)) return false;
    for (std::size_t j = 0; j < rows.size() && !drop[i]; ++j) {
      if (i == j || drop[j] || count[j] > count[i] || !subset(rows[j].support, rows[i].support)) continue;
      // a smaller support, or the same row met earlier
      if (count[j] < count[i] || (j < i && rows[j].y == rows[i].y)) drop[i] = true;
    }
  }
  std::size_t out = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (drop[i]) continue;
    if (out != i) rows[out] = std::move(rows[i]);
    ++out;
  }
  rows.resize(out);
  return true;
}

/// The minimal semi-positive y with y·A = 0, where A has one row per variable.
std::vector<Invariant> semiflows(const Matrix& a, std::size_t columns, Budget& budget) {
  if (budget.exhausted()) return {};
  const std::size_t n = a.size();
  const std::size_t words = (n + 63) / 64;
  const std::size_t max_rows = budget.maxRows();
  const std::uint64_t row_bytes = (columns + n + words) * sizeof(std::int64_t) + sizeof(Row);
  InvariantProgress progress{0, columns, n, n * row_bytes};
  std::vector<Row> rows(n);
  for (std::size_t i = 0; i < n; ++i) {
    rows[i].a = a[i];
    rows[i].y.assign(n, 0);
    rows[i].y[i] = 1;
    rows[i].support.assign(words, 0);
    rows[i].support[i / 64] |= std::uint64_t{1} << (i % 64);
  }
  std::vector<bool> done(columns, false);
  for (std::size_t round = 0; round < columns; ++round) {
    // eliminate the column that makes the fewest new rows
    std::size_t best = columns;
    std::size_t best_cost = std::numeric_limits<std::size_t>::max();
    for (std::size_t j = 0; j < columns; ++j) {
      if (done[j]) continue;
      std::size_t pos = 0, neg = 0;
      for (const auto& r : rows) pos += r.a[j] > 0, neg += r.a[j] < 0;
      const std::size_t cost = pos * neg;
      if (cost < best_cost || best == columns) best = j, best_cost = cost;
    }
    const std::size_t j = best;
    done[j] = true;
    progress.round = round;
    std::vector<Row> next;
    std::vector<std::size_t> pos, neg;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (rows[i].a[j] > 0) pos.push_back(i);
      if (rows[i].a[j] < 0) neg.push_back(i);
    }
    // too many candidates: give up before making them (the answer is then partial)
    if (rows.size() - pos.size() - neg.size() + pos.size() * neg.size() > 4 * max_rows) {
      budget.halt(ExploreStop::Candidates);
      return {};
    }
    for (auto& r : rows) {
      if (r.a[j] == 0) next.push_back(std::move(r));
    }
    for (auto p : pos) {
      for (auto q : neg) {
        const Row& x = rows[p];
        const Row& z = rows[q];
        std::int64_t cx = -z.a[j], cz = x.a[j];
        const std::int64_t g = std::gcd(cx, cz);
        cx /= g, cz /= g;
        Row r;
        r.a.resize(columns);
        r.y.resize(n);
        bool ok = true;
        for (std::size_t k = 0; k < columns && ok; ++k) ok = addMul(x.a[k], cx, z.a[k], cz, r.a[k]);
        for (std::size_t k = 0; k < n && ok; ++k) ok = addMul(x.y[k], cx, z.y[k], cz, r.y[k]);
        if (!ok) {
          budget.halt(ExploreStop::Overflow);
          return {};
        }
        r.support.resize(words);
        for (std::size_t k = 0; k < words; ++k) r.support[k] = x.support[k] | z.support[k];
        normalise(r);
        next.push_back(std::move(r));
        progress.rows = rows.size() + next.size();
        progress.bytes = progress.rows * row_bytes;
        if (!budget.check(progress)) return {};
      }
    }
    if (!keepMinimal(next, budget, progress)) return {};
    if (next.size() > max_rows) {
      budget.halt(ExploreStop::Candidates);
      return {};
    }
    rows = std::move(next);
  }
  std::vector<Invariant> out;
  for (const auto& r : rows) {
    Invariant inv;
    for (std::size_t k = 0; k < n; ++k) {
      if (r.y[k] != 0) inv.weights.emplace_back(static_cast<std::uint32_t>(k), r.y[k]);
    }
    out.push_back(std::move(inv));
  }
  std::sort(out.begin(), out.end(), [](const Invariant& x, const Invariant& y) { return x.weights < y.weights; });
  return out;
}

Matrix incidenceMatrix(const Net& net) {
  Matrix c(net.placeSlots().size(), std::vector<std::int64_t>(net.transitions().size(), 0));
  for (const Term& term : net.terms()) {
    if (term.kind == TermKind::Input) c[term.place_slot][term.transition] -= term.weight;
    if (term.kind == TermKind::Output) c[term.place_slot][term.transition] += term.weight;
  }
  return c;
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
/// the place slots.
std::vector<Invariant> slotwise(const Net& net, const Matrix& c, bool slack, Budget& budget) {
  const std::size_t places = net.placeSlots().size();
  const std::size_t transitions = net.transitions().size();
  std::map<SlotId, std::vector<std::uint32_t>> groups;
  for (std::uint32_t ps = 0; ps < places; ++ps) groups[net.placeSlots()[ps].slot].push_back(ps);
  std::vector<Invariant> out;
  for (const auto& [slot, members] : groups) {
    Matrix a;
    for (auto ps : members) a.push_back(c[ps]);
    if (slack) {
      for (std::size_t t = 0; t < transitions; ++t) {
        a.emplace_back(transitions, 0);
        a.back()[t] = 1;
      }
    }
    for (Invariant inv : semiflows(a, transitions, budget)) {
      for (auto& [k, w] : inv.weights) {
        k = k < members.size() ? members[k] : static_cast<std::uint32_t>(places + (k - members.size()));
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
  // the dense incidence matrix and its transpose, within the memory limit
  const std::uint64_t matrix_bytes = 2 * static_cast<std::uint64_t>(places) * transitions * sizeof(std::int64_t);
  if (options.max_bytes != 0 && matrix_bytes > options.max_bytes) {
    out.complete = false;
    out.stop = ExploreStop::MaxMemory;
    return out;
  }
  const Matrix c = incidenceMatrix(net);
  out.p = slotwise(net, c, false, budget);
  Matrix ct(transitions, std::vector<std::int64_t>(places, 0));
  for (std::size_t ps = 0; ps < places; ++ps) {
    for (std::size_t t = 0; t < transitions; ++t) ct[t][ps] = c[ps][t];
  }
  out.t = semiflows(ct, places, budget);
  out.conservative = covers(out.p, places);
  out.consistent = covers(out.t, transitions);

  // y·C <= 0: the semiflows of C with one slack row per transition
  std::vector<Invariant> bounding = out.p;
  if (!out.conservative) {
    const ExploreStop before = budget.stop();
    bounding = slotwise(net, c, true, budget);
    out.structurally_bounded = budget.stop() == before && covers(bounding, places);
  } else {
    out.structurally_bounded = true;
  }
  out.stop = budget.stop();
  out.complete = out.stop == ExploreStop::Done;
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
    for (const Term& term : net.termsOf(k)) {
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
  // depth-first enumeration of elementary circuits, each found once from its smallest slot
  constexpr std::size_t kMaxSteps = 200'000;
  std::size_t steps = 0;
  double best = -1.0;
  std::vector<TransitionId> best_path, path;
  std::vector<PlaceSlotId> on_path;
  bool gave_up = false;
  auto dfs = [&](auto&& self, PlaceSlotId start, PlaceSlotId at, double sum) -> void {
    for (const Edge& e : edges) {
      if (gave_up) return;
      if (e.from != at) continue;
      if (++steps > kMaxSteps) {
        gave_up = true;
        return;
      }
      const double d = e.t < seconds.size() ? seconds[e.t] : 0.0;
      path.push_back(e.t);
      if (e.to == start) {
        if (sum + d > best) {
          best = sum + d;
          best_path = path;
        }
      } else if (e.to > start && std::find(on_path.begin(), on_path.end(), e.to) == on_path.end()) {
        on_path.push_back(e.to);
        self(self, start, e.to, sum + d);
        on_path.pop_back();
      }
      path.pop_back();
    }
  };
  std::vector<PlaceSlotId> starts;
  for (const Edge& e : edges) starts.push_back(e.from);
  std::sort(starts.begin(), starts.end());
  starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
  for (PlaceSlotId start : starts) {
    on_path = {start};
    dfs(dfs, start, start, 0.0);
    if (gave_up) return std::nullopt;
  }
  if (best < 0.0) return std::nullopt;
  return std::make_pair(best, std::move(best_path));
}

}  // namespace

std::vector<CycleBound> cycleBounds(const Net& net, const Invariants& invariants, std::span<const double> seconds,
                                    const InvariantOptions& options, ExploreStop* stop) {
  std::vector<CycleBound> out;
  std::vector<std::int64_t> y(net.placeSlots().size());
  Budget budget(options);
  for (std::size_t i = 0; i < invariants.p.size(); ++i) {
    if (!budget.check({i, invariants.p.size(), out.size(), 0})) break;
    std::fill(y.begin(), y.end(), 0);
    CycleBound b;
    b.invariant = i;
    for (const auto& [k, w] : invariants.p[i].weights) {
      y[k] = w;
      b.tokens += w * net.placeSlots()[k].initial;
    }
    if (b.tokens <= 0) continue;
    double work = 0.0;
    for (TransitionId t = 0; t < net.transitions().size(); ++t) {
      std::int64_t taken = 0;
      for (const Term& term : net.termsOf(t)) {
        if (term.kind == TermKind::Input) taken += y[term.place_slot] * term.weight;
      }
      if (taken == 0) continue;
      b.transitions.push_back(t);
      work += (t < seconds.size() ? seconds[t] : 0.0) * static_cast<double>(taken);
    }
    if (b.transitions.empty()) continue;
    b.seconds = work / static_cast<double>(b.tokens);
    if (b.tokens == 1) {
      if (auto circuit = longestCircuit(net, y, b.transitions, seconds)) {
        b.seconds = circuit->first;
        b.transitions = std::move(circuit->second);
        b.circuit = true;
      }
    }
    out.push_back(std::move(b));
  }
  std::stable_sort(out.begin(), out.end(), [](const CycleBound& x, const CycleBound& z) { return x.seconds > z.seconds; });
  if (stop) *stop = budget.stop();
  return out;
}

double meanSeconds(const Duration& duration) {
  switch (duration.law) {
    case Duration::Law::Uniform:
      return 0.5 * (duration.a + duration.b);
    case Duration::Law::Fixed:
    case Duration::Law::Normal:
    case Duration::Law::Exponential:
      break;
  }
  return duration.a;
}

std::string placeSlotName(const Net& net, PlaceSlotId ps) {
  const PlaceSlot& s = net.placeSlots()[ps];
  const std::string& name = net.places()[s.place].name;
  return s.slot == kDefaultSlot ? name : name + "." + slotName(s.slot);
}

}  // namespace gdpn::net
