// Simulation speed of coloured nets that cannot be unfolded (issue 59): a colour set of 10^6
// integers and a record with a string field, many tokens in flight, run headless by the kernel.
// Reports bindings (occurrences, each in one binding) per second. Record results in
// docs/performance.md, *Coloured simulation*.

#include <benchmark/benchmark.h>

#include <iostream>

#include "gdpn/net/compile.h"
#include "gdpn/net/kernel.h"

namespace {

using namespace gdpn::net;

gdpn::core::SourceLoc at(int line) { return gdpn::core::SourceLoc{"colour_bench", line, 1}; }

/// Jobs lo..hi-1 as a multiset sum, nested as a balanced tree (the parser limits nesting).
std::string jobSum(std::int64_t lo, std::int64_t hi) {
  if (hi - lo == 1) return "1'{id = " + std::to_string(lo * 100) + ", name = \"job" + std::to_string(lo) + "\"}";
  const std::int64_t mid = lo + (hi - lo) / 2;
  return "(" + jobSum(lo, mid) + ") ++ (" + jobSum(mid, hi) + ")";
}

/// A job shop's worth of value tokens, written as specs: `jobs` jobs, each a record {id: N,
/// name: string} with N the range 0..999999 (10^6 values: the record set is not finite, so
/// the net cannot be unfolded). Every transition lasts one step and has unlimited servers, so
/// every job moves every step:
///   work:  queue --j--> work --{id = j.id + 1, name = j.name}--> busy   when j.id < 999999
///   check: busy --j--> check --j--> queue
/// With `stamp`, check also puts `n` on place stamps, a variable of the built-in (not finite)
/// int that no arc binds but the condition fixes (`n = j.id * 2`), and drain takes the stamps.
std::shared_ptr<const Net> pipeline(std::int64_t jobs, bool stamp) {
  NetSpec spec;
  int line = 0;
  spec.pages.push_back(PageSpec{"main", at(++line), {}, {}, {}, {}, {}, {}});
  PageSpec& page = spec.pages[0];
  ColourSetSpec n;
  n.name = "N";
  n.loc = at(++line);
  n.kind = ColourKind::Integer;
  n.range = true;
  n.lo = 0;
  n.hi = 999'999;
  spec.colours.push_back(n);
  ColourSetSpec job;
  job.name = "Job";
  job.loc = at(++line);
  job.kind = ColourKind::Record;
  job.components = {"N", "string"};
  job.fields = {"id", "name"};
  spec.colours.push_back(job);
  spec.variables.push_back({"j", "Job", at(++line)});
  spec.variables.push_back({"n", "int", at(++line)});

  auto place = [&](const std::string& name, const std::string& colour, std::string values) {
    PlaceSpec p;
    p.name = name;
    p.loc = at(++line);
    p.colours.push_back({kDefaultSlot, colour, at(line)});
    if (!values.empty()) p.values.push_back({kDefaultSlot, std::move(values), at(line)});
    page.places.push_back(std::move(p));
  };
  auto transition = [&](const std::string& name, const std::string& when) {
    TransitionSpec t;
    t.name = name;
    t.loc = at(++line);
    t.duration = Duration(Duration::Law::Fixed, 1.0);
    t.servers = kUnlimitedServers;
    if (!when.empty()) t.when = {kDefaultSlot, when, at(line)};
    page.transitions.push_back(std::move(t));
  };
  auto arc = [&](const std::string& from, const std::string& to, const std::string& inscription) {
    ArcSpec a;
    a.from = from;
    a.to = to;
    a.loc = at(++line);
    a.inscriptions.push_back({kDefaultSlot, inscription, at(line)});
    page.arcs.push_back(std::move(a));
  };

  // the jobs spread over the range, 100 apart: each runs for a long while before it stops
  place("queue", "Job", jobSum(0, jobs));
  place("busy", "Job", {});
  transition("work", "j.id < 999999");
  transition("check", stamp ? "n = j.id * 2" : "");
  arc("queue", "work", "j");
  arc("work", "busy", "{id = j.id + 1, name = j.name}");
  arc("busy", "check", "j");
  arc("check", "queue", "j");
  if (stamp) {
    place("stamps", "int", {});
    transition("drain", "");
    arc("check", "stamps", "n");
    arc("stamps", "drain", "n");
  }
  gdpn::core::Diagnostics diags;
  auto net = compile(spec, diags);
  if (!net || diags.hasErrors()) {
    diags.print(std::cerr);
    return nullptr;
  }
  return net;
}

/// Steps a kernel on `net` and reports its bindings (starts) per second and per step.
void run(benchmark::State& state, const std::shared_ptr<const Net>& net) {
  if (!net) {
    state.SkipWithError("the net did not compile");
    return;
  }
  Kernel k(net, {1.0, 1});
  k.start();
  for (int i = 0; i < 3; ++i) k.step();  // past the first wave
  const auto before = k.startCount();
  for (auto _ : state) k.step();
  const auto firings = static_cast<double>(k.startCount() - before);
  state.counters["bindings_per_s"] = benchmark::Counter(firings, benchmark::Counter::kIsRate);
  state.counters["bindings_per_step"] = firings / static_cast<double>(state.iterations());
}

// N jobs going round work and check: N bindings of each per two steps
void BM_ColouredPipeline(benchmark::State& state) { run(state, pipeline(state.range(0), false)); }
BENCHMARK(BM_ColouredPipeline)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

// the same with a variable the condition fixes, of the built-in int
void BM_ColouredConditionFixed(benchmark::State& state) { run(state, pipeline(state.range(0), true)); }
BENCHMARK(BM_ColouredConditionFixed)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
