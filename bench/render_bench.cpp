// Headless frames per second at 1280x720 on this machine's renderer (Mesa llvmpipe without a
// GPU): plant scenes from the examples, and a 2049 x 2049 terrain seen from low and far.
// Triangles drawn per frame are reported. Record results in docs/performance.md.

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"
#include "gdpn/platform/headless_context.h"
#include "gdpn/platform/png.h"
#include "gdpn/platform/target.h"
#include "gdpn/render/renderer.h"

namespace {

using namespace gdpn;
namespace fs = std::filesystem;

void frames(benchmark::State& state, const scene::Scene& scene, const std::string& dir, const render::Camera& camera,
            int samples) {
  std::string why;
  auto context = platform::createHeadlessContext(why);
  if (!context) {
    state.SkipWithError(why.c_str());
    return;
  }
  platform::Target target(1280, 720, samples);
  render::Renderer renderer(dir);
  render::DrawOptions o;
  render::DrawStats stats = renderer.draw(scene, camera, o);  // uploads shapes, meshes and terrains once
  benchmark::DoNotOptimize(target.readRgb());
  for (auto _ : state) {
    stats = renderer.draw(scene, camera, o);
    auto rgb = target.readRgb();  // waits for the frame to finish
    benchmark::DoNotOptimize(rgb.data());
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["triangles"] = static_cast<double>(stats.triangles);
  state.counters["draw_calls"] = static_cast<double>(stats.draw_calls);
  state.SetLabel(context->renderer());
}

void BM_Example(benchmark::State& state, const char* relative, int samples) {
  core::Diagnostics diags;
  const auto path = model::resolveModelPath(std::string(GDPN_SOURCE_DIR) + "/" + relative, diags);
  auto m = path ? model::loadModel(*path, diags) : std::nullopt;
  auto sim = m ? model::Simulation::create(*m, diags) : nullptr;
  if (!sim) {
    state.SkipWithError(diags.str().c_str());
    return;
  }
  sim->run({20.0, std::nullopt});  // things on the move
  std::string why;
  frames(state, *sim->plant(), fs::path(*path).parent_path().string(), render::chooseCamera(*sim->plant(), "", 2.0, why),
         samples);
}
BENCHMARK_CAPTURE(BM_Example, Factory_4x, "examples/factory", 4)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Example, Factory_1x, "examples/factory", 1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Example, Feeder_4x, "examples/plant/feeder", 4)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Example, Sorting_4x, "examples/sorting", 4)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Example, Sorting_1x, "examples/sorting", 1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Terrain2049(benchmark::State& state, double distance) {
  // a 2049 x 2049 elevation image (sums of waves), 4 km across
  const auto dir = fs::temp_directory_path() / "gdpn_render_bench";
  fs::create_directories(dir);
  const auto png = (dir / "dem2049.png").string();
  if (!fs::exists(png)) {
    const int n = 2049;
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(n) * n * 3);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const double x = i / 2048.0, y = j / 2048.0;
        const double h = 0.5 + 0.2 * std::sin(9 * x) * std::cos(7 * y) + 0.15 * std::sin(31 * x + 3 * y) +
                         0.1 * std::cos(57 * y - 11 * x);
        const auto v = static_cast<std::uint8_t>(std::clamp(h, 0.0, 1.0) * 255);
        const auto k = (static_cast<std::size_t>(j) * n + static_cast<std::size_t>(i)) * 3;
        rgb[k] = rgb[k + 1] = rgb[k + 2] = v;
      }
    }
    std::string why;
    platform::writePng(png, n, n, rgb, why);
  }
  core::Diagnostics diags;
  auto m = model::parseModel(
      "gdpn: 1\nscene:\n  - Light: {kind: directional}\n  - Terrain: {file: dem2049.png, width: 4000, depth: 4000, "
      "height_scale: 1.5}\n",
      (dir / "terrain.gdpn.yaml").string(), diags);
  auto sim = m ? model::Simulation::create(*m, diags) : nullptr;
  if (!sim) {
    state.SkipWithError(diags.str().c_str());
    return;
  }
  render::Camera camera;
  camera.eye = {0, -distance, distance * 0.35};
  camera.target = {0, 0, 150};
  camera.far = 20000;
  frames(state, *sim->plant(), dir.string(), camera, 1);
}
BENCHMARK_CAPTURE(BM_Terrain2049, Low_300m, 300.0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Terrain2049, Far_3000m, 3000.0)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
