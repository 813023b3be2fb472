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

/// The sensor phase of the scene of model text `text`, timed step by step (10 ms each).
void senseEachStep(benchmark::State& state, const std::string& text) {
  core::Diagnostics diags;
  auto m = model::parseModel(text, "bench.gdpn.yaml", diags);
  auto s = m->scene->clone();
  auto world = physics::World::create(*s, ".", 1, diags);
  sensors::Hub hub(*s, world.get());
  double now = 0;
  for (auto _ : state) {
    now += 0.01;
    benchmark::DoNotOptimize(hub.update(now));
  }
}

void BM_SensorPhase(benchmark::State& state) {
  senseEachStep(state, scene(static_cast<int>(state.range(0)), static_cast<double>(state.range(1)) / 100.0));
  state.counters["regions"] = static_cast<double>(state.range(0));
  state.counters["overlapping_pct"] = static_cast<double>(state.range(1));
}
BENCHMARK(BM_SensorPhase)
    ->Args({100, 0})->Args({1000, 0})->Args({1000, 10})->Args({1000, 100})
    ->Unit(benchmark::kMicrosecond);

/// One scan of a 360-ray LaserScan (issue 23) in a room of four walls with `n` boxes about:
/// the time per scan, each ray tested against the shapes near the fan.
void BM_LaserScan(benchmark::State& state) {
  std::string t = "gdpn: 1\nscene:\n  - World: {gravity: [0, 0, 0]}\n";
  for (const char* wall : {"[5.5, 0, 0], children: [{Cube: {size: [1, 12, 2]}}]", "[-5.5, 0, 0], children: [{Cube: {size: [1, 12, 2]}}]",
                           "[0, 5.5, 0], children: [{Cube: {size: [12, 1, 2]}}]", "[0, -5.5, 0], children: [{Cube: {size: [12, 1, 2]}}]"}) {
    t += std::string("  - Transform: {translation: ") + wall + "}\n";
  }
  for (int i = 0; i < state.range(0); ++i) {
    const double a = i * 2.4, r = 1.5 + (i % 5) * 0.7;
    t += "  - Transform: {translation: [" + core::formatDouble(r * std::cos(a)) + ", " + core::formatDouble(r * std::sin(a)) +
         ", 0], children: [{Body: {mass: 1, children: [{Cube: {size: [0.3, 0.3, 0.3]}}]}}]}\n";
  }
  t += "  - LaserScan: {name: lidar, count: 360, length: 10, rate: 0}\n";
  senseEachStep(state, t);
  state.counters["boxes"] = static_cast<double>(state.range(0));
}
BENCHMARK(BM_LaserScan)->Arg(0)->Arg(20)->Arg(200)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
