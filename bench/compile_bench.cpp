// compile() cost: a NetSpec ring of n places and n transitions (place i -> t_i -> place i+1),
// checked and frozen into a Net. The cost must grow with n, not n squared (issue 15).
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

void BM_CompileRing(benchmark::State& state) {
  const auto n = state.range(0);
  const NetSpec spec = ringSpec(n);
  for (auto _ : state) {
    gdpn::core::Diagnostics diags;
    auto net = compile(spec, diags);
    if (!net) state.SkipWithError(diags.str().c_str());
    benchmark::DoNotOptimize(net);
  }
  state.counters["places"] = static_cast<double>(n);
}
BENCHMARK(BM_CompileRing)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
