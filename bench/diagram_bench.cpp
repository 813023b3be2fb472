// The net view's costs: painting the visible part of a page of 10,000 transitions (what the
// IDE does each frame, here onto a canvas that only counts calls and onto the software
// rasteriser), the full page's index, and Graphviz layouts of 100 and 1,000 nodes.

#include <benchmark/benchmark.h>

#include <string>

#include "gdpn/diagram/painter.h"
#include "gdpn/diagram/raster_canvas.h"
#include "grid_page.h"

namespace {

using namespace gdpn::diagram;
namespace net = gdpn::net;
using gdpn::bench::gridPage;

// a state with some of everything: tokens, enabled and occurring transitions
NetState someState(const net::PageSpec& page) {
  NetState s;
  s.places.resize(page.places.size());
  for (std::size_t i = 0; i < page.places.size(); ++i)
    if (!page.places[i].tokens.empty()) s.places[i].push_back({0, net::SlotKind::Control, page.places[i].tokens[0].value, {}});
  s.transitions.resize(page.transitions.size());
  for (std::size_t i = 0; i < s.transitions.size(); ++i) s.transitions[i] = static_cast<Activity>(i % 3);
  s.arcs.resize(page.arcs.size());
  for (std::size_t i = 0; i < s.arcs.size(); ++i) s.arcs[i] = i % 2 == 0;
  return s;
}

// a canvas that draws nothing: the cost of culling and of the painter itself
class CountingCanvas final : public Canvas {
 public:
  int width() const override { return 1280; }
  int height() const override { return 720; }
  void clear(Rgba) override {}
  void fillCircle(Point, double, Rgba) override { ++calls; }
  void strokeCircle(Point, double, double, Rgba) override { ++calls; }
  void fillRect(const Box&, Rgba) override { ++calls; }
  void strokeRect(const Box&, double, Rgba) override { ++calls; }
  void polyline(std::span<const Point>, double, Rgba, bool) override { ++calls; }
  void fillPolygon(std::span<const Point>, Rgba) override { ++calls; }
  void text(Point, std::string_view, double, HAlign, VAlign, Rgba) override { ++calls; }
  std::size_t calls = 0;
};

struct BigPage {
  net::PageSpec page = gridPage(100, 100, true);
  NetLayout layout;
  NetState state;
  BigPage() {
    gdpn::core::Diagnostics diags;
    layout = layoutPage(page, diags);
    state = someState(page);
  }
  // a 1280 x 720 view in the middle of the page, at zoom 1 (names shown)
  [[nodiscard]] Viewport view() const {
    Viewport v;
    v.zoom = 1.0;
    v.origin = {(layout.bounds.min.x + layout.bounds.max.x) / 2 - 640, (layout.bounds.min.y + layout.bounds.max.y) / 2 - 360};
    return v;
  }
};

const BigPage& bigPage() {
  static const BigPage page;
  return page;
}

// painting `view` of the big page onto the counting canvas
void paintCounted(benchmark::State& state, bool whole) {
  const auto& big = bigPage();
  const SpatialIndex index(big.layout);
  CountingCanvas canvas;
  const Viewport view = whole ? fitViewport(big.layout, canvas.width(), canvas.height()) : big.view();
  std::size_t items = 0;
  for (auto _ : state) {
    items = paintNet(big.layout, index, &big.state, view, canvas);
    benchmark::DoNotOptimize(canvas.calls);
  }
  state.counters["items"] = static_cast<double>(items);
}

void BM_PaintVisibleOf10kTransitions_Calls(benchmark::State& state) { paintCounted(state, false); }
BENCHMARK(BM_PaintVisibleOf10kTransitions_Calls)->Unit(benchmark::kMicrosecond);

// zoomed out to show the whole page: every item passes the painter (no names at this zoom)
void BM_PaintWholeOf10kTransitions_Calls(benchmark::State& state) { paintCounted(state, true); }
BENCHMARK(BM_PaintWholeOf10kTransitions_Calls)->Unit(benchmark::kMillisecond);

void BM_PaintVisibleOf10kTransitions_Raster(benchmark::State& state) {
  const auto& big = bigPage();
  const SpatialIndex index(big.layout);
  std::string why;
  auto canvas = RasterCanvas::create(1280, 720, kDefaultFont, why);
  if (!canvas) {
    state.SkipWithError(why.c_str());
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(paintNet(big.layout, index, &big.state, big.view(), *canvas));
}
BENCHMARK(BM_PaintVisibleOf10kTransitions_Raster)->Unit(benchmark::kMillisecond);

void BM_IndexOf10kTransitions(benchmark::State& state) {
  const auto& big = bigPage();
  for (auto _ : state) {
    const SpatialIndex index(big.layout);
    benchmark::DoNotOptimize(&index);
  }
}
BENCHMARK(BM_IndexOf10kTransitions)->Unit(benchmark::kMillisecond);

// Graphviz: a page of `nodes` nodes (half places, half transitions) with no positions (above
// kGraphvizLimit, 2,000, this measures the column layout that replaces Graphviz)
void BM_GraphvizLayout(benchmark::State& state) {
  const int nodes = static_cast<int>(state.range(0));
  const auto page = gridPage(10, nodes / 20, false);
  for (auto _ : state) {
    gdpn::core::Diagnostics diags;
    benchmark::DoNotOptimize(layoutPage(page, diags));
  }
  state.counters["nodes"] = static_cast<double>(page.places.size() + page.transitions.size());
}
BENCHMARK(BM_GraphvizLayout)->Arg(100)->Arg(1000)->Arg(4000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
