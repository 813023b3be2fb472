// compile() cost: a NetSpec ring of n places and n transitions (place i -> t_i -> place i+1),
// and a page type instanced n times, checked and frozen into a Net. The cost must grow with n, not n squared (issue 15).
// Record results in docs/performance.md.

#include <benchmark/benchmark.h>

#include "gdpn/net/compile.h"
#include "gdpn/net/spec.h"

namespace {

using namespace gdpn::net;

/// One page "main" holding the ring; place 0 holds a token.
NetSpec ringSpec(std::int64_t n) {
  NetSpec spec;
  auto& page = spec.pages.emplace_back();
  page.name = "main";
  page.places.reserve(static_cast<std::size_t>(n));
  page.transitions.reserve(static_cast<std::size_t>(n));
  page.arcs.reserve(2 * static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) {
    auto& p = page.places.emplace_back();
    p.name = "p" + std::to_string(i);
    if (i == 0) p.tokens.push_back({kDefaultSlot, 1, {}});
    page.transitions.emplace_back().name = "t" + std::to_string(i);
  }
  for (std::int64_t i = 0; i < n; ++i) {
    auto& in = page.arcs.emplace_back();
    in.from = "p" + std::to_string(i);
    in.to = "t" + std::to_string(i);
    auto& out = page.arcs.emplace_back();
    out.from = "t" + std::to_string(i);
    out.to = "p" + std::to_string((i + 1) % n);
  }
  return spec;
}

/// Compiles the net that `make(n)` builds, n = the benchmark's argument, as often as timing needs.
void compileEach(benchmark::State& state, NetSpec (*make)(std::int64_t)) {
  const NetSpec spec = make(state.range(0));
  std::size_t places = 0;
  for (auto _ : state) {
    gdpn::core::Diagnostics diags;
    auto net = compile(spec, diags);
    if (!net) state.SkipWithError(diags.str().c_str());
    places = net ? net->places().size() : 0;
    benchmark::DoNotOptimize(net);
  }
  state.counters["places"] = static_cast<double>(places);
}

void BM_CompileRing(benchmark::State& state) { compileEach(state, ringSpec); }
BENCHMARK(BM_CompileRing)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

/// A producer/consumer cell (3 places, 2 transitions, 5 arcs) instanced n times on one page:
/// how models with many places are usually written (issue 18).
NetSpec cellsSpec(std::int64_t n) {
  NetSpec spec;
  auto& cell = spec.page_types.emplace_back();
  cell.name = "cell";
  for (const char* name : {"ready", "buffer", "done"}) cell.places.emplace_back().name = name;
  cell.places[0].tokens.push_back({kDefaultSlot, 1, {}});
  for (const char* name : {"produce", "consume"}) cell.transitions.emplace_back().name = name;
  for (auto [from, to] : {std::pair{"ready", "produce"}, {"produce", "ready"}, {"produce", "buffer"},
                          {"buffer", "consume"}, {"consume", "done"}}) {
    auto& a = cell.arcs.emplace_back();
    a.from = from;
    a.to = to;
  }
  auto& page = spec.pages.emplace_back();
  page.name = "main";
  page.instances.reserve(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) {
    auto& inst = page.instances.emplace_back();
    inst.name = "c" + std::to_string(i);
    inst.type = "cell";
  }
  return spec;
}

void BM_CompileCells(benchmark::State& state) { compileEach(state, cellsSpec); }
BENCHMARK(BM_CompileCells)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(333334)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
