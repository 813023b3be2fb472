// Kernel speed without scripts: firings per second on large rings, the cost of a step at
// constant activity as the net grows, and memory per place and transition.
// Record results in docs/performance.md.

#include <benchmark/benchmark.h>

#include "gdpn/net/builder.h"
#include "gdpn/net/kernel.h"

namespace {

using namespace gdpn::net;

/// "prefix" followed by the decimal digits of i.
std::string numbered(const char* prefix, std::int64_t i) {
  std::string name(prefix);
  name += std::to_string(i);
  return name;
}

/// A ring of n places and n transitions (place i -> t_i -> place i+1) holding `tokens` tokens,
/// one on every `every`-th place from place 0 (0: spread evenly over the ring). Every
/// transition lasts one step.
std::shared_ptr<const Net> ring(std::int64_t n, std::int64_t tokens, std::int64_t every = 0) {
  NetBuilder b;
  if (every <= 0) every = std::max<std::int64_t>(1, n / std::max<std::int64_t>(1, tokens));
  for (std::int64_t i = 0; i < n; ++i) {
    const auto p = b.addPlace(numbered("p", i));
    b.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, (i % every == 0 && i / every < tokens) ? 1 : 0);
  }
  for (std::int64_t i = 0; i < n; ++i) {
    const auto t = b.addTransition(numbered("t", i));
    b.addInput(static_cast<PlaceId>(i), t);
    b.addOutput(t, static_cast<PlaceId>((i + 1) % n));
  }
  return b.freeze();
}

/// Steps `k` for the benchmark's iterations and reports its firings per second and per step.
void stepAndCount(benchmark::State& state, Kernel& k) {
  const auto before = k.startCount();
  for (auto _ : state) k.step();
  const auto firings = static_cast<double>(k.startCount() - before);
  state.counters["firings_per_s"] = benchmark::Counter(firings, benchmark::Counter::kIsRate);
  state.counters["firings_per_step"] = firings / static_cast<double>(state.iterations());
}

// ring of N places and N transitions holding N/10 tokens: every step, N/10 firings
void BM_RingFirings(benchmark::State& state) {
  const auto n = state.range(0);
  Kernel k(ring(n, n / 10), {0.01, 1});
  k.start();
  stepAndCount(state, k);
}
BENCHMARK(BM_RingFirings)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMicrosecond);

// one station with unlimited servers and N parts going round it (P -> T -> P), each occurrence
// lasting a drawn 0.5 to 1.5 s at dt = 0.01 s: about N/100 occurrences complete and as many
// start each step, with N running at once. The cost per firing should not grow with N.
void BM_UnlimitedServersFirings(benchmark::State& state) {
  const auto n = state.range(0);
  NetBuilder b;
  const auto p = b.addPlace("parts");
  b.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, n);
  const auto t = b.addTransition("station", Duration{Duration::Law::Uniform, 0.5, 1.5, {}});
  b.setServers(t, kUnlimitedServers);
  b.addInput(p, t);
  b.addOutput(t, p);
  Kernel k(b.freeze(), {0.01, 1});
  k.start();
  for (int i = 0; i < 200; ++i) k.step();  // past the first wave: starts spread over the steps
  stepAndCount(state, k);
}
BENCHMARK(BM_UnlimitedServersFirings)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);

// N instances of P -> I (immediate, priority 1) -> Q -> T (one step) -> P, one token each: every other
// step N immediate occurrences in one firing phase, each ending a round. The cost per
// firing should not grow with N.
void BM_ImmediateInstancesFirings(benchmark::State& state) {
  const auto n = state.range(0);
  NetBuilder b;
  for (std::int64_t i = 0; i < n; ++i) {
    const auto p = b.addPlace(numbered("p", i)), q = b.addPlace(numbered("q", i));
    b.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, 1);
    b.setSlot(q, kDefaultSlot, SlotKind::Control, kUnbounded, 0);
    const auto imm = b.addTransition(numbered("i", i), Duration{Duration::Law::Immediate, 0.0, 0.0, {}}, 1);
    const auto t = b.addTransition(numbered("t", i));
    b.addInput(p, imm);
    b.addOutput(imm, q);
    b.addInput(q, t);
    b.addOutput(t, p);
  }
  Kernel k(b.freeze(), {0.01, 1});
  k.start();
  stepAndCount(state, k);
}
BENCHMARK(BM_ImmediateInstancesFirings)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);

// constant activity (100 tokens circulating) in nets of growing size: a step must cost the same
void BM_StepConstantActivity(benchmark::State& state) {
  const auto n = state.range(0);
  Kernel k(ring(n, 100), {0.01, 1});
  k.start();
  for (auto _ : state) k.step();
  state.counters["transitions"] = static_cast<double>(n);
}
BENCHMARK(BM_StepConstantActivity)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kNanosecond);

// the same 100 tokens on a ring of 10^6, each k transitions apart: a line is read again k steps
// after its last use, so the step's cost shows where its lines come from (k = 8: the caches)
void BM_StepTokensApart(benchmark::State& state) {
  Kernel k(ring(1000000, 100, state.range(0)), {0.01, 1});
  k.start();
  for (auto _ : state) k.step();
}
BENCHMARK(BM_StepTokensApart)->Arg(8)->Arg(64)->Arg(251)->Arg(1009)->Arg(9973)->Unit(benchmark::kNanosecond);

// bytes of the frozen net and of the kernel's state, per place and per transition of a ring
// (one place, one transition and two arc terms per element)
void BM_Memory(benchmark::State& state) {
  const auto n = state.range(0);
  std::size_t net_bytes = 0, kernel_bytes = 0, place_bytes = 0;
  for (auto _ : state) {
    auto net = ring(n, n / 10);
    Kernel k(net, {0.01, 1});
    net_bytes = net->memoryBytes();
    kernel_bytes = k.memoryBytes();
    NetBuilder places_only;
    for (std::int64_t i = 0; i < n; ++i) {
      const auto p = places_only.addPlace(numbered("p", i));
      places_only.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, 0);
    }
    auto pn = places_only.freeze();
    Kernel pk(pn, {0.01, 1});
    place_bytes = pn->memoryBytes() + pk.memoryBytes() - 4096 * sizeof(std::vector<TransitionId>);
  }
  const double N = static_cast<double>(n);
  state.counters["net_B_per_element"] = static_cast<double>(net_bytes) / N;
  state.counters["state_B_per_element"] = static_cast<double>(kernel_bytes) / N;
  state.counters["B_per_place"] = static_cast<double>(place_bytes) / N;
  state.counters["B_per_transition"] = (static_cast<double>(net_bytes + kernel_bytes) - static_cast<double>(place_bytes)) / N;
}
BENCHMARK(BM_Memory)->Arg(100000)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
