// Hybrid nets (issue 60): steps per second of a net of 1,000 continuous places and 1,000
// continuous transitions, built through NetSpec and compile() and stepped with Kernel::step().
// Record results in docs/performance.md.

#include <benchmark/benchmark.h>

#include "gdpn/net/compile.h"
#include "gdpn/net/kernel.h"
#include "gdpn/net/observer.h"
#include "gdpn/net/spec.h"

namespace {

using namespace gdpn::net;

/// Counts the level crossings the kernel reports.
class CrossingCounter final : public NetObserver {
 public:
  void onCross(PlaceId, double, double, bool, std::int64_t) override { ++crossings; }
  std::int64_t crossings = 0;  ///< so far
};

/// An arc on page `page` with a real weight (a continuous place's) or none.
void addArc(PageSpec& page, const std::string& from, const std::string& to, ArcKind kind = ArcKind::Normal,
            std::optional<double> amount = std::nullopt) {
  auto& a = page.arcs.emplace_back();
  a.from = from;
  a.to = to;
  a.kind = kind;
  a.amount = amount;
}

/// A ring of n tanks `x<i>` (5 L each, capacity 20 L), tank i draining into tank i+1 through
/// continuous transition `f<i>`, at a constant rate between 0.5 and 1.4 L/s (`proportional`
/// false) or at `c * x<i>` L/s, c between 0.05 and 0.5 (true: a rate that reads an amount,
/// so CVODE).
/// Each flow runs while discrete place `on<i>` is marked; `stop<i>` (immediate) takes the mark
/// when its tank is below 2 L (an inhibitor arc: a level switch), `go<i>` gives it back at
/// 8 L (a test arc). The rates differ, so tanks fill and empty and cross their switches.
/// Without `switched`, no stop and go: every flow runs, and nothing is crossed once the
/// amounts settle.
NetSpec tankRing(std::int64_t n, bool proportional, bool switched) {
  NetSpec spec;
  auto& page = spec.pages.emplace_back();
  page.name = "main";
  const auto size = static_cast<std::size_t>(n);
  page.places.reserve(3 * size);
  page.transitions.reserve(3 * size);
  page.arcs.reserve(8 * size);
  for (std::int64_t i = 0; i < n; ++i) {
    const std::string x = "x" + std::to_string(i);
    auto& tank = page.places.emplace_back();
    tank.name = x;
    tank.fluid = FluidSpec{.amount = 5.0, .capacity = 20.0, .unit = "L"};
    auto& on = page.places.emplace_back();
    on.name = "on" + std::to_string(i);
    on.tokens.push_back({kDefaultSlot, 1, {}});
    page.places.emplace_back().name = "off" + std::to_string(i);
    auto& flow = page.transitions.emplace_back();
    flow.name = "f" + std::to_string(i);
    flow.flow = FlowSpec{};
    // 0.5 .. 1.4 L/s, or 0.05 .. 0.5 per second times the amount, in a pattern of ten so
    // that neighbours differ
    const auto j = static_cast<double>((i * 7) % 10);
    flow.flow->rate.text = proportional ? std::to_string(0.05 * (1.0 + j)) + " * " + x : std::to_string(0.5 + 0.1 * j);
    if (!switched) continue;
    auto& stop = page.transitions.emplace_back();
    stop.name = "stop" + std::to_string(i);
    stop.duration = Duration{Duration::Law::Immediate, 0.0};
    auto& go = page.transitions.emplace_back();
    go.name = "go" + std::to_string(i);
    go.duration = Duration{Duration::Law::Immediate, 0.0};
  }
  for (std::int64_t i = 0; i < n; ++i) {
    const std::string s = std::to_string(i);
    const std::string x = "x" + s;
    addArc(page, "on" + s, "f" + s, ArcKind::Test);
    addArc(page, x, "f" + s);
    addArc(page, "f" + s, "x" + std::to_string((i + 1) % n));
    if (!switched) continue;
    addArc(page, "on" + s, "stop" + s);
    addArc(page, x, "stop" + s, ArcKind::Inhibitor, 2.0);
    addArc(page, "stop" + s, "off" + s);
    addArc(page, "off" + s, "go" + s);
    addArc(page, x, "go" + s, ArcKind::Test, 8.0);
    addArc(page, "go" + s, "on" + s);
  }
  return spec;
}

/// Steps the ring for the benchmark's iterations at dt = 0.01 s after 1,000 steps; reports
/// steps as items per second, and the crossings and discrete firings per step.
void stepRing(benchmark::State& state, bool proportional, bool switched = true) {
  gdpn::core::Diagnostics diags;
  const auto net = compile(tankRing(state.range(0), proportional, switched), diags);
  if (!net) {
    state.SkipWithError(diags.str().c_str());
    return;
  }
  Kernel k(net, {0.01, 1});
  CrossingCounter counter;
  k.addObserver(&counter);
  k.start();
  for (int i = 0; i < 1000; ++i) k.step();  // 10 s: past the start, where every tank is at 5 L
  const auto crossings = counter.crossings;
  const auto firings = k.startCount();
  for (auto _ : state) k.step();
  const auto steps = static_cast<double>(state.iterations());
  state.SetItemsProcessed(state.iterations());
  state.counters["crossings_per_step"] = static_cast<double>(counter.crossings - crossings) / steps;
  state.counters["firings_per_step"] = static_cast<double>(k.startCount() - firings) / steps;
  k.removeObserver(&counter);
}

// constant rates: amounts advanced exactly, piecewise-linear between crossings
void BM_FluidRingConstant(benchmark::State& state) { stepRing(state, false); }
BENCHMARK(BM_FluidRingConstant)->Arg(1000)->Unit(benchmark::kMicrosecond);

// rates that read amounts (c * x): CVODE over the 1,000 amounts
void BM_FluidRingProportional(benchmark::State& state) { stepRing(state, true); }
BENCHMARK(BM_FluidRingProportional)->Arg(1000)->Unit(benchmark::kMicrosecond);

// the same without the switches: no crossing once settled, so what a CVODE step costs alone
void BM_FluidRingProportionalUnswitched(benchmark::State& state) { stepRing(state, true, false); }
BENCHMARK(BM_FluidRingProportionalUnswitched)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
