// Full state-space exploration of the two large conformance nets (Kanban-PT-00005,
// SwimmingPool-PT-02): states per second and bytes per state; and a reachability query whose
// witness lies 10 firings deep among 10^7 markings, answered on the fly with stubborn sets.
// Record results in docs/performance.md.

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <filesystem>

#include "gdpn/net/analysis.h"
#include "gdpn/net/builder.h"
#include "gdpn/net/query.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/pnml.h"

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

BENCHMARK_CAPTURE(BM_Explore, Kanban_PT_00005, "Kanban-PT-00005", 2546432, 1)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Explore, SwimmingPool_PT_02, "SwimmingPool-PT-02", 3408031, 1)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Explore, Kanban_PT_00005_2threads, "Kanban-PT-00005", 2546432, 2)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Explore, SwimmingPool_PT_02_2threads, "SwimmingPool-PT-02", 3408031, 2)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
