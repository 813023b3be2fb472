// Sensor phase cost: many collision regions and many moving bodies. The broad phase keeps the
// cost with the pairs that overlap, not regions times bodies.
// Record results in docs/performance.md.

#include <benchmark/benchmark.h>

#include <cmath>

#include "gdpn/core/text.h"
#include "gdpn/model/model.h"
#include "gdpn/sensors/hub.h"

namespace {

using namespace gdpn;

/// `n` small regions in a grid, and `n` bodies flying through the grid without gravity.
/// `overlap` in [0, 1]: the share of bodies placed inside a region.
std::string scene(int n, double overlap) {
  std::string t = "gdpn: 1\nscene:\n  - World: {gravity: [0, 0, 0], auto_disable: false}\n";
  const int side = static_cast<int>(std::ceil(std::sqrt(n)));
  for (int i = 0; i < n; ++i) {
    const double x = (i % side) * 2.0, y = (i / side) * 2.0;
    t += "  - Transform: {translation: [" + core::formatDouble(x) + ", " + core::formatDouble(y) +
         ", 0], children: [{Region: {size: [0.5, 0.5, 0.5]}}]}\n";
  }
  const int inside = static_cast<int>(overlap * n);
  for (int i = 0; i < n; ++i) {
    const double x = (i % side) * 2.0 + (i < inside ? 0.0 : 1.0), y = (i / side) * 2.0;
    t += "  - Transform: {translation: [" + core::formatDouble(x) + ", " + core::formatDouble(y) +
         ", 0], children: [{Body: {mass: 1, children: [{Sphere: {radius: 0.1}}]}}]}\n";
  }
  return t;
}

void BM_SensorPhase(benchmark::State& state) {
  core::Diagnostics diags;
  auto m = model::parseModel(scene(static_cast<int>(state.range(0)), static_cast<double>(state.range(1)) / 100.0),
                             "bench.gdpn.yaml", diags);
  auto s = m->scene->clone();
  auto world = physics::World::create(*s, ".", 1, diags);
  sensors::Hub hub(*s, world.get());
  double now = 0;
  for (auto _ : state) {
    now += 0.01;
    benchmark::DoNotOptimize(hub.update(now));
  }
  state.counters["regions"] = static_cast<double>(state.range(0));
  state.counters["overlapping_pct"] = static_cast<double>(state.range(1));
}
BENCHMARK(BM_SensorPhase)
    ->Args({100, 0})->Args({1000, 0})->Args({1000, 10})->Args({1000, 100})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
