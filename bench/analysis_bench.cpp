// Full state-space exploration of the two large conformance nets (Kanban-PT-00005,
// SwimmingPool-PT-02): states per second and bytes per state; and a reachability query whose
// witness lies 10 firings deep among 10^7 markings, answered on the fly with stubborn sets.
// Record results in docs/performance.md.

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "gdpn/net/analysis.h"
#include "gdpn/net/builder.h"
#include "gdpn/net/query.h"
#include "gdpn/net/coloured_search.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/pnml.h"
#include "gdpn/net/unfold.h"

namespace {

using namespace gdpn;

void BM_Explore(benchmark::State& state, const char* model, std::uint64_t expected, unsigned threads) {
  const auto path = std::filesystem::path(GDPN_SOURCE_DIR) / "tests" / "data" / "conformance" /
                    (std::string(model) + ".pnml");
  core::Diagnostics diags;
  auto spec = net::loadPnml(path.string(), diags);
  if (!spec) {
    state.SkipWithError(diags.str().c_str());
    return;
  }
  auto n = net::compile(*spec, diags);
  std::uint64_t states = 0, search_bytes = 0;
  for (auto _ : state) {
    net::ExploreOptions o;
    o.threads = threads;
    const auto s = net::explore(*n, o);
    states = s.states;
    search_bytes = s.peak_bytes;
  }
  if (states != expected) state.SkipWithError("wrong number of states");
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["states"] = static_cast<double>(states);
  state.counters["states_per_s"] =
      benchmark::Counter(static_cast<double>(states) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["search_bytes_per_state"] = static_cast<double>(search_bytes) / static_cast<double>(states);
  state.counters["peak_rss_bytes_per_state"] = static_cast<double>(usage.ru_maxrss) * 1024.0 / static_cast<double>(states);
}
// A coloured contest net searched natively (over markings with values) and unfolded, in
// turns (unfolded, native, unfolded, native, ...: five pairs, so that the machine's drift falls
// on both alike): the searches' states per second, medians of the five, and their ratio. The
// unfolding and compiling are not timed (done once, as the coloured net's compiling is).
void BM_ColouredNativeAgainstUnfolded(benchmark::State& state, const char* model, std::uint64_t expected) {
  const auto path = std::filesystem::path(GDPN_SOURCE_DIR) / "tests" / "data" / "conformance-col" / model / "model.pnml";
  core::Diagnostics diags;
  auto spec = net::loadPnml(path.string(), diags);
  auto unfolded = spec ? net::unfold(*spec, diags) : std::nullopt;
  auto coloured = spec ? net::compile(*spec, diags) : nullptr;
  auto plain = unfolded ? net::compile(unfolded->net, diags) : nullptr;
  if (!coloured || !plain) {
    state.SkipWithError(diags.str().c_str());
    return;
  }
  std::vector<double> native_rate, unfolded_rate;
  std::uint64_t native_bytes = 0, unfolded_bytes = 0;
  for (auto _ : state) {
    for (int pair = 0; pair < 5; ++pair) {
      auto t0 = std::chrono::steady_clock::now();
      const auto u = net::explore(*plain);
      auto t1 = std::chrono::steady_clock::now();
      const auto n = net::exploreColoured(*coloured);
      auto t2 = std::chrono::steady_clock::now();
      if (u.states != expected || n.states != expected) {
        state.SkipWithError("wrong number of states");
        return;
      }
      unfolded_rate.push_back(static_cast<double>(u.states) / std::chrono::duration<double>(t1 - t0).count());
      native_rate.push_back(static_cast<double>(n.states) / std::chrono::duration<double>(t2 - t1).count());
      native_bytes = n.peak_bytes;
      unfolded_bytes = u.peak_bytes;
    }
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  state.counters["native_states_per_s"] = median(native_rate);
  state.counters["unfolded_states_per_s"] = median(unfolded_rate);
  state.counters["native_over_unfolded"] = median(native_rate) / median(unfolded_rate);
  state.counters["native_bytes_per_state"] = static_cast<double>(native_bytes) / static_cast<double>(expected);
  state.counters["unfolded_bytes_per_state"] = static_cast<double>(unfolded_bytes) / static_cast<double>(expected);
}
// 7 independent rings of 10 places, one token each: 10^7 markings. `EF (r0/p9 = 1 and r1/p1 =
// 1)`: 9 firings of ring 0 and one of ring 1; the state equation tried first (it cannot refute
// it), then the search.
void BM_QueryWitnessTenFiringsDeep(benchmark::State& state) {
  net::NetBuilder b;
  for (int r = 0; r < 7; ++r) {
    std::vector<net::PlaceId> ps;
    for (int i = 0; i < 10; ++i) ps.push_back(b.addPlace("r" + std::to_string(r) + "/p" + std::to_string(i)));
    b.setSlot(ps[0], net::kDefaultSlot, net::SlotKind::Control, net::kUnbounded, 1);
    for (std::size_t i = 0; i < 10; ++i) {
      const auto t = b.addTransition("r" + std::to_string(r) + "/t" + std::to_string(i));
      b.addInput(ps[i], t);
      b.addOutput(t, ps[(i + 1) % 10]);
    }
  }
  const auto n = b.freeze();
  net::QueryError error;
  const auto f = net::parseQuery(*n, "EF (r0/p9 = 1 and r1/p1 = 1)", error);
  net::QueryAnswer a;
  if (!f) {
    state.SkipWithError(error.message.c_str());
    return;
  }
  for (auto _ : state) a = net::answerQuery(*n, *f);
  if (a.verdict != net::Verdict::True || a.path.size() != 10) state.SkipWithError("wrong answer");
  state.counters["markings"] = static_cast<double>(a.states);
}

BENCHMARK(BM_QueryWitnessTenFiringsDeep)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

BENCHMARK_CAPTURE(BM_ColouredNativeAgainstUnfolded, SharedMemory_COL_000010, "SharedMemory-COL-000010", 1830519)
    ->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ColouredNativeAgainstUnfolded, SharedMemory_COL_000005, "SharedMemory-COL-000005", 1863)
    ->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Explore, Kanban_PT_00005, "Kanban-PT-00005", 2546432, 1)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Explore, SwimmingPool_PT_02, "SwimmingPool-PT-02", 3408031, 1)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Explore, Kanban_PT_00005_2threads, "Kanban-PT-00005", 2546432, 2)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Explore, SwimmingPool_PT_02_2threads, "SwimmingPool-PT-02", 3408031, 2)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
