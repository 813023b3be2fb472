// Parts: what placing one costs (the library's copy and instance, then the plant made again,
// as the IDE shows it), with 0 to 49 parts already placed; and a line of 7 stations (56
// parts) run headless: model seconds per wall-clock second. One core. Record results in
// docs/performance.md.

#include <benchmark/benchmark.h>

#include "gdpn/model/part_library.h"
#include "gdpn/model/simulation.h"

namespace {

using namespace gdpn;

/// The source tree's parts.
const std::vector<model::LibraryPart>& library() {
  static const auto parts = [] {
    core::Diagnostics diags;
    return model::scanParts({std::string(GDPN_SOURCE_DIR) + "/parts"}, diags);
  }();
  return parts;
}

/// A model of `n` belts in a row.
model::Model belts(int n) {
  model::Model m;
  std::string why;
  const auto* belt = model::findLibraryPart(library(), "belt_conveyor");
  for (int i = 0; i < n; ++i) model::placePart(m, "main", *belt, {2.0 * i, 0, 0}, 0, false, why);
  return m;
}

void BM_PlacePartAndMakeThePlant(benchmark::State& state) {
  const model::Model before = belts(static_cast<int>(state.range(0)));
  const auto* belt = model::findLibraryPart(library(), "belt_conveyor");
  for (auto _ : state) {
    model::Model m = before;
    std::string why;
    model::placePart(m, "main", *belt, {-2, 0, 0}, 0, false, why);
    core::Diagnostics diags;
    auto sim = model::Simulation::create(m, diags);
    benchmark::DoNotOptimize(sim);
  }
}
BENCHMARK(BM_PlacePartAndMakeThePlant)->Arg(0)->Arg(10)->Arg(49)->Unit(benchmark::kMillisecond);

void BM_StationLine(benchmark::State& state) {
  // examples/station's parts, 7 times over along y
  core::Diagnostics diags;
  auto one = model::loadModel(std::string(GDPN_SOURCE_DIR) + "/examples/station/sorting_station.gdpn.yaml", diags);
  if (!one) {
    state.SkipWithError(diags.str().c_str());
    return;
  }
  model::Model m = *one;
  auto& page = m.net.pages.at(0);
  const auto instances = page.instances;
  page.instances.clear();
  for (int k = 0; k < 7; ++k) {
    for (auto inst : instances) {
      inst.name += "_" + std::to_string(k);
      if (!inst.part.empty()) inst.part += "_" + std::to_string(k);
      inst.translation[1] += 4.0 * k;
      page.instances.push_back(inst);
    }
  }
  // the page's own net drives the first station only
  for (auto& a : page.arcs) {
    for (auto* end : {&a.from, &a.to}) {
      if (end->find('/') != std::string::npos) *end = end->substr(0, end->find('/')) + "_0" + end->substr(end->find('/'));
    }
  }
  for (auto& p : page.places) {
    for (auto& s : p.sensors) s.path = s.path.substr(0, s.path.find('/')) + "_0" + s.path.substr(s.path.find('/'));
  }
  for (auto& t : page.transitions) {
    for (const auto& inst : instances) {
      const std::string from = "sim.part(\"" + inst.name + "\")", to = "sim.part(\"" + inst.name + "_0\")";
      for (auto pos = t.pre_fire.code.find(from); pos != std::string::npos; pos = t.pre_fire.code.find(from, pos + 1)) {
        t.pre_fire.code.replace(pos, from.size(), to);
      }
    }
  }
  double simulated = 0;
  for (auto _ : state) {
    auto sim = model::Simulation::create(m, diags);
    if (!sim) {
      state.SkipWithError(diags.str().c_str());
      return;
    }
    sim->setLogEcho(false);
    simulated += sim->run({20.0, std::nullopt}).time;
  }
  state.counters["model_s_per_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  state.counters["parts"] = static_cast<double>(page.instances.size());
}
BENCHMARK(BM_StationLine)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
