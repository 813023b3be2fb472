// Script overhead: firings per second when every transition runs a trivial pre_fire, and a
// model whose scripts do nothing against the same model without scripts; the cost of one
// script call, a one-line pre_fire against none, timed in turns.
// Record results in docs/performance.md.

#include <benchmark/benchmark.h>

#include <time.h>

#include "gdpn/model/simulation.h"

namespace {

using namespace gdpn;

/// A ring of n places and n one-step transitions holding n/10 tokens; `pre_fire` (if not
/// empty) on every transition, `globals` as the model's globals.
model::Model ring(int n, const std::string& pre_fire, const std::string& globals) {
  model::Model m;
  m.path = "bench.gdpn.yaml";
  m.settings.dt = 0.01;
  net::PageSpec page;
  page.name = "main";
  for (int i = 0; i < n; ++i) {
    net::PlaceSpec p;
    p.name = "p" + std::to_string(i);
    if (i % 10 == 0) p.tokens.push_back({net::kDefaultSlot, 1, {}});
    page.places.push_back(p);
    net::TransitionSpec t;
    t.name = "t" + std::to_string(i);
    t.pre_fire.code = pre_fire;
    t.pre_fire.loc = {"bench.gdpn.yaml", 1, 1};
    page.transitions.push_back(t);
    net::ArcSpec in, out;
    in.from = p.name;
    in.to = t.name;
    out.from = t.name;
    out.to = "p" + std::to_string((i + 1) % n);
    page.arcs.push_back(in);
    page.arcs.push_back(out);
  }
  m.net.pages.push_back(page);
  m.net.globals.code = globals;
  m.net.globals.loc = {"bench.gdpn.yaml", 1, 1};
  return m;
}

void runRing(benchmark::State& state, const std::string& pre_fire, const std::string& globals) {
  core::Diagnostics diags;
  auto sim = model::Simulation::create(ring(static_cast<int>(state.range(0)), pre_fire, globals), diags);
  if (!sim) {
    state.SkipWithError(diags.str().c_str());
    return;
  }
  sim->start();
  const auto before = sim->kernel().startCount();
  for (auto _ : state) sim->step();
  const auto firings = static_cast<double>(sim->kernel().startCount() - before);
  state.counters["firings_per_s"] = benchmark::Counter(firings, benchmark::Counter::kIsRate);
}

// every transition's pre_fire increments a shared counter
void BM_ScriptedFirings(benchmark::State& state) { runRing(state, "n += 1\n", "n = 0\n"); }
BENCHMARK(BM_ScriptedFirings)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// scripts that do nothing, against no scripts at all, on the same ring
void BM_EmptyScripts(benchmark::State& state) { runRing(state, "pass\n", ""); }
BENCHMARK(BM_EmptyScripts)->Arg(1000)->Unit(benchmark::kMicrosecond);

void BM_NoScripts(benchmark::State& state) { runRing(state, "", ""); }
BENCHMARK(BM_NoScripts)->Arg(1000)->Unit(benchmark::kMicrosecond);

/// This thread's CPU time, s: a shared machine's other work does not count.
double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The cost of one script call: the ring of 1,000 with `pre_fire` on every transition and the
/// same ring without, stepped in turns (A B A B, 20 steps each) so that the machine's drift
/// falls on both; `ns_per_call` is the difference of their CPU times a firing, ns.
void callCost(benchmark::State& state, const std::string& pre_fire, const std::string& globals) {
  core::Diagnostics diags;
  auto scripted = model::Simulation::create(ring(1000, pre_fire, globals), diags);
  auto bare = model::Simulation::create(ring(1000, "", ""), diags);
  if (!scripted || !bare) {
    state.SkipWithError(diags.str().c_str());
    return;
  }
  scripted->start();
  bare->start();
  double seconds[2] = {0, 0}, firings[2] = {0, 0};
  model::Simulation* sims[2] = {scripted.get(), bare.get()};
  for (auto _ : state) {
    for (int k = 0; k < 2; ++k) {
      const auto before = sims[k]->kernel().startCount();
      const double t0 = cpuSeconds();
      for (int i = 0; i < 20; ++i) sims[k]->step();
      seconds[k] += cpuSeconds() - t0;
      firings[k] += static_cast<double>(sims[k]->kernel().startCount() - before);
    }
  }
  state.counters["ns_per_firing_scripted"] = 1e9 * seconds[0] / firings[0];
  state.counters["ns_per_firing_bare"] = 1e9 * seconds[1] / firings[1];
  state.counters["ns_per_call"] = 1e9 * (seconds[0] / firings[0] - seconds[1] / firings[1]);
}

// a one-line pre_fire that assigns a global, and one that does nothing
void BM_CallCostIncrement(benchmark::State& state) { callCost(state, "n += 1\n", "n = 0\n"); }
BENCHMARK(BM_CallCostIncrement)->Unit(benchmark::kMicrosecond);
void BM_CallCostPass(benchmark::State& state) { callCost(state, "pass\n", ""); }
BENCHMARK(BM_CallCostPass)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
