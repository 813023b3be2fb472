// The IDE's edit commands on the factory (examples/factory): applying one, undoing it and
// redoing it, each timed alone (issue 17: under 5 ms for an undo or a redo). The document
// stays the same size: each iteration applies, undoes and redoes, then undoes again.
// Record results in docs/performance.md.

#include <benchmark/benchmark.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include "gdpn/ide/document.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/ide/scene_edit.h"
#include "gdpn/ide/set_field.h"

namespace {

using namespace gdpn::ide;

std::unique_ptr<Document> factory() {
  gdpn::core::Diagnostics diags;
  auto doc = Document::open(std::string(GDPN_SOURCE_DIR) + "/examples/factory/factory.gdpn.yaml", diags);
  if (!doc) std::abort();
  return doc;
}

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// Times `make()`'s command three ways: arg 0 applies it, 1 undoes it, 2 redoes it.
void timeCommand(benchmark::State& state, const std::function<std::unique_ptr<Command>()>& make) {
  auto doc = factory();
  const auto phase = state.range(0);
  for (auto _ : state) {
    auto command = make();
    auto t = std::chrono::steady_clock::now();
    if (!doc->execute(std::move(command)).empty()) std::abort();
    const double apply = since(t);
    t = std::chrono::steady_clock::now();
    doc->undo();
    const double undo = since(t);
    t = std::chrono::steady_clock::now();
    doc->redo();
    const double redo = since(t);
    doc->undo();
    state.SetIterationTime(phase == 0 ? apply : phase == 1 ? undo : redo);
  }
  state.SetLabel(phase == 0 ? "apply" : phase == 1 ? "undo" : "redo");
}

void SetField(benchmark::State& state) {
  timeCommand(state, [] {
    return std::make_unique<SetFieldCommand>("arm/turn", "vel1", gdpn::scene::FieldValue{120.0});
  });
}

void MovePlace(benchmark::State& state) {
  timeCommand(state, [] {
    auto e = makeNetEdit(NetEditKind::Move, "factory", "P3", {}, {4.0, 2.0});
    return std::make_unique<NetEditCommand>(e);
  });
}

void AddArc(benchmark::State& state) {
  timeCommand(state, [] { return std::make_unique<NetEditCommand>(makeNetEdit(NetEditKind::AddArc, "factory", "P3", "pickup")); });
}

void SetTransition(benchmark::State& state) {
  auto doc = factory();
  const auto* page = findPage(doc->editableNet(), "factory");
  gdpn::net::TransitionSpec t;
  for (const auto& x : page->transitions) {
    if (x.name == "deliver") t = x;
  }
  t.duration.a = 2.5;
  timeCommand(state, [t] {
    auto e = makeNetEdit(NetEditKind::SetTransition, "factory", "deliver");
    e.transition = t;
    return std::make_unique<NetEditCommand>(e);
  });
}

void AddNode(benchmark::State& state) {
  timeCommand(state, [] { return std::make_unique<SceneEditCommand>(SceneEdit{SceneEditKind::Add, "line", "Cube", {}, false, {}}); });
}

void DuplicateSubtree(benchmark::State& state) {
  timeCommand(state, [] { return std::make_unique<SceneEditCommand>(SceneEdit{SceneEditKind::Duplicate, "arm", {}, {}, false, {}}); });
}

void DeleteTokenNode(benchmark::State& state) {
  // a node the marking holds: the scene and the net both change
  timeCommand(state, [] {
    return std::make_unique<SceneEditCommand>(SceneEdit{SceneEditKind::Delete, "boxes/b05", {}, {}, true, {}});
  });
}

}  // namespace

BENCHMARK(SetField)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(MovePlace)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(AddArc)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(SetTransition)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(AddNode)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(DuplicateSubtree)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(DeleteTokenNode)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
