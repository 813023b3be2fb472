// The examples headless, as `gdpn run --quiet` runs them: model seconds per wall-clock second
// (the real-time factor) for the factory's whole 120 s and for the vehicles' crossing. One
// core. Record results in docs/performance.md.

#include <benchmark/benchmark.h>

#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"

namespace {

using namespace gdpn;

void BM_Headless(benchmark::State& state, const char* relative, double until) {
  core::Diagnostics diags;
  const auto path = model::resolveModelPath(std::string(GDPN_SOURCE_DIR) + "/" + relative, diags);
  auto m = path ? model::loadModel(*path, diags) : std::nullopt;
  if (!m) {
    state.SkipWithError(diags.str().c_str());
    return;
  }
  double simulated = 0.0;
  for (auto _ : state) {
    auto sim = model::Simulation::create(*m, diags);  // a fresh plant each time: the same run
    if (!sim) {
      state.SkipWithError(diags.str().c_str());
      return;
    }
    const auto outcome = sim->run({until, std::nullopt});
    simulated += outcome.time;
  }
  state.counters["model_s_per_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_Headless, Factory120s, "examples/factory", 120.0)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Headless, Vehicles, "examples/vehicles", 60.0)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Headless, Station120s, "examples/station", 120.0)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
