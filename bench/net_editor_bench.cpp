// The net editor on a large page (issue 57): a rubber band selecting 1,000 items of a page of
// 10,000 transitions, and a frame of dragging them (the move edit, then what moved laid out
// again and the page indexed again, as the net view does in a drag), and the whole page laid
// out again (what any other edit costs). Goal: each within a frame (16 ms). Record results in
// docs/performance.md.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "gdpn/diagram/layout.h"
#include "gdpn/diagram/spatial_index.h"
#include "gdpn/ide/document.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/model/model.h"
#include "grid_page.h"

namespace {

using namespace gdpn;

/// A page of 100 x 100 transitions, each feeding a place to its right that feeds the next
/// transition, with positions (the net view's benchmark page, bench/diagram_bench.cpp).
model::Model gridModel() {
  model::Model m;
  m.net.pages.push_back(bench::gridPage(100, 100, true));
  return m;
}

/// The grid model as a document (its file written to the temporary folder).
std::unique_ptr<ide::Document> gridDocument() {
  const auto path = (std::filesystem::temp_directory_path() / "gdpn-net-editor-bench.gdpn.yaml").string();
  std::ofstream(path) << model::writeModel(gridModel());
  core::Diagnostics diags;
  auto doc = ide::Document::open(path, diags);
  std::filesystem::remove(path);
  if (!doc) std::abort();
  return doc;
}

/// The band over the grid's first `columns` columns and `rows` rows, layout units.
diagram::Box band(int columns, int rows) {
  const double u = diagram::kEditorUnit;
  return {{-0.5 * u, -0.5 * u}, {(2.0 * columns - 0.5) * u, (rows - 0.5) * u}};
}

// 13 columns x 20 rows: 260 transitions, 260 places and 500 arcs wholly inside (1,020 items)
constexpr int kColumns = 13, kRows = 20;

void BM_RubberBand1000Of10k(benchmark::State& state) {
  auto doc = gridDocument();
  core::Diagnostics diags;
  const auto layout = diagram::layoutPage(doc->model().net.pages.front(), diags);
  const diagram::SpatialIndex index(layout);
  std::size_t chosen = 0;
  for (auto _ : state) {
    // the band let go: what it holds, named as the selection names them, selected
    const auto items = index.within(band(kColumns, kRows));
    std::vector<ide::Selection> all;
    all.reserve(items.size());
    for (const auto item : items) {
      switch (item.kind) {
        case diagram::ItemKind::Place: all.push_back({ide::SelectionKind::Place, "grid/" + layout.places[item.index].name}); break;
        case diagram::ItemKind::Transition:
          all.push_back({ide::SelectionKind::Transition, "grid/" + layout.transitions[item.index].name});
          break;
        case diagram::ItemKind::Instance: break;
        case diagram::ItemKind::Arc: {
          const auto& a = doc->model().net.pages.front().arcs[layout.arcs[item.index].spec_index];
          all.push_back({ide::SelectionKind::Arc, ide::arcName("grid", a.from, a.to, a.kind)});
          break;
        }
      }
    }
    doc->selectAll(all);
    chosen = doc->selectedCount();
    benchmark::DoNotOptimize(chosen);
  }
  state.counters["items"] = static_cast<double>(chosen);
}

void BM_MoveFrame1000Of10k(benchmark::State& state) {
  auto doc = gridDocument();
  // the constructs of the band: 520 places and transitions (with their 500 arcs, 1,020 items)
  std::vector<std::pair<std::string, net::EditorPos>> from;
  for (int y = 0; y < kRows; ++y) {
    for (int x = 0; x < kColumns; ++x) {
      const auto id = std::to_string(x) + "_" + std::to_string(y);
      from.emplace_back("t" + id, net::EditorPos{2.0 * x, 1.0 * y});
      from.emplace_back("p" + id, net::EditorPos{2.0 * x + 1, 1.0 * y});
    }
  }
  core::Diagnostics diags;
  auto layout = diagram::layoutPage(doc->model().net.pages.front(), diags);
  std::vector<diagram::ItemRef> moved;
  for (int y = 0; y < kRows; ++y) {
    for (int x = 0; x < kColumns; ++x) {
      const auto index = static_cast<std::uint32_t>(y * 100 + x);  // the grid's order: row by row
      moved.push_back({diagram::ItemKind::Transition, index});
      moved.push_back({diagram::ItemKind::Place, index});
    }
  }
  double step = 0, edit = 0, drawn = 0, frames = 0;
  for (auto _ : state) {
    // one frame of the drag: the move (merged into the drag's step), the page laid out again
    step += 0.25;
    auto e = ide::makeNetEdit(ide::NetEditKind::MoveMany, "grid", {});
    for (const auto& [name, at] : from) e.moves.emplace_back(name, net::EditorPos{at[0], at[1] + step});
    e.drag = 1;
    const auto t0 = std::chrono::steady_clock::now();
    if (!doc->execute(std::make_unique<ide::NetEditCommand>(std::move(e))).empty()) std::abort();
    const auto t1 = std::chrono::steady_clock::now();
    // what moved laid out again in place, and the page indexed again, as the net view does
    diagram::relayoutMoved(layout, doc->model().net.pages.front(), moved);
    const diagram::SpatialIndex index(layout);
    benchmark::DoNotOptimize(index.within(band(1, 1)));
    edit += std::chrono::duration<double>(t1 - t0).count();
    drawn += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    ++frames;
  }
  state.counters["moved"] = static_cast<double>(from.size());
  // of a frame: the edit, and the layout with its index, milliseconds
  state.counters["edit_ms"] = 1e3 * edit / std::max(frames, 1.0);
  state.counters["layout_ms"] = 1e3 * drawn / std::max(frames, 1.0);
}

void BM_LayoutWhole10k(benchmark::State& state) {
  const auto page = gridModel().net.pages.front();
  for (auto _ : state) {
    core::Diagnostics diags;
    const auto layout = diagram::layoutPage(page, diags);
    const diagram::SpatialIndex index(layout);
    benchmark::DoNotOptimize(index.within(band(1, 1)));
  }
}

}  // namespace

BENCHMARK(BM_LayoutWhole10k)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RubberBand1000Of10k)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MoveFrame1000Of10k)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
