// Spawn cost: n copies of a small template (a Body with a Cube) spawned under one parent, the
// physics on, as a script's sim.node(...).spawn(...) does. A spawn must cost the same however
// many siblings the copy gets (issue 15: naming the copies was cubic in n).
// Record results in docs/performance.md.

#include <benchmark/benchmark.h>

#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"

namespace {

using namespace gdpn;

constexpr const char* kModel = R"Y(gdpn: 1
scene:
  - World: {gravity: [0, 0, 0], auto_disable: true}
  - Group:
      name: store
      children: [{Body: {name: box, mass: 0.5, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}}]
  - Group: {name: area}
pages:
  main:
    places:
      idle: {tokens: 1}
)Y";

// n spawns of store/box under area, each at its own place on a grid (all bodies apart)
void BM_Spawn(benchmark::State& state) {
  const auto n = state.range(0);
  core::Diagnostics diags;
  auto model = model::parseModel(kModel, "bench.gdpn.yaml", diags);
  if (!model) {
    state.SkipWithError(diags.str().c_str());
    return;
  }
  for (auto _ : state) {
    state.PauseTiming();
    auto sim = model::Simulation::create(*model, diags);
    scene::Node* templ = sim->plant()->find("store/box");
    scene::Node* area = sim->plant()->find("area");
    state.ResumeTiming();
    std::string why;
    for (std::int64_t i = 0; i < n; ++i) {
      const core::Vec3 at{static_cast<double>(i % 1000), static_cast<double>(i / 1000), 0.5};
      if (!sim->spawn(*templ, *area, at, why)) state.SkipWithError(why.c_str());
    }
    state.PauseTiming();
    sim.reset();
    state.ResumeTiming();
  }
  state.counters["spawns_per_s"] =
      benchmark::Counter(static_cast<double>(n * static_cast<std::int64_t>(state.iterations())),
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Spawn)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
