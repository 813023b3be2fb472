// `gdpn render --net` as a user runs it: a picture of a page's net at a time, and the
// errors for an unknown page, a wrong extension and an output that cannot be written.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "diagram/diagram_fixtures.h"
#include "support/cli.h"

namespace gdpn::diagram {
namespace {

using gdpn::testing::runGdpn;
using testing::tempFile;

std::string slurp(const std::string& path) {
  std::stringstream s;
  s << std::ifstream(path).rdbuf();
  return s.str();
}

TEST(RenderNetCli, DrawsThePageAtTheTimeAsked) {
  const auto out = tempFile("two_cells.svg");
  const auto r = runGdpn("render examples/basics/two_cells --net --at 3 -o " + out);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("at t = 3 s"), std::string::npos) << r.out;
  const auto svg = slurp(out);
  for (const char* text : {">infeed<", ">cellA<", ">: cell<", ">enter<", ">load_a<"})
    EXPECT_NE(svg.find(text), std::string::npos) << text;
  std::filesystem::remove(out);
  // inside an instance: its page type's constructs with that instance's marking
  const auto inner = tempFile("cellA.png");
  const auto r2 = runGdpn("render examples/basics/two_cells --net --page line/cellA --at 3 -o " + inner + " --size 400x200");
  ASSERT_EQ(r2.code, 0) << r2.out;
  EXPECT_TRUE(slurp(inner).starts_with("\x89PNG"));
  std::filesystem::remove(inner);
}

TEST(RenderNetCli, AGuardFalseIsDrawnHeldBackAsInTheIde) {
  // t's marking suffices from the start; its guard is false until 0.5 s
  const auto model = tempFile("guarded.gdpn.yaml");
  std::ofstream(model) << R"Y(gdpn: 1
scene:
  - Cube: {name: c, size: [1, 1, 1]}
pages:
  main:
    places:
      a: {tokens: 1}
      b: {}
    transitions:
      t: {duration: 10, guard: "sim.time >= 0.5"}
    arcs:
      - a -> t
      - t -> b
)Y";
  const auto out = tempFile("guarded.svg");
  ASSERT_EQ(runGdpn("render '" + model + "' --net --at 0.1 -o " + out).code, 0);
  const auto held = slurp(out);
  EXPECT_NE(held.find("fill=\"#e6ab02\"/>"), std::string::npos) << held;  // colours::kHeldBack
  ASSERT_EQ(runGdpn("render '" + model + "' --net --at 1 -o " + out).code, 0);
  const auto started = slurp(out);
  EXPECT_EQ(started.find("#e6ab02"), std::string::npos) << started;
  EXPECT_NE(started.find("fill=\"#d62728\"/>"), std::string::npos) << started;  // occurring
  std::filesystem::remove(out);
  std::filesystem::remove(model);
}

TEST(RenderNetCli, TwoRunsGiveTheSameBytes) {
  // two_cells has no positions on its page: Graphviz lays it out, in two processes
  const auto a = tempFile("run1.svg"), b = tempFile("run2.svg");
  ASSERT_EQ(runGdpn("render examples/basics/two_cells --net --at 2 -o " + a).code, 0);
  ASSERT_EQ(runGdpn("render examples/basics/two_cells --net --at 2 -o " + b).code, 0);
  EXPECT_EQ(slurp(a), slurp(b));
  EXPECT_FALSE(slurp(a).empty());
  std::filesystem::remove(a);
  std::filesystem::remove(b);
}

TEST(RenderNetCli, UnknownPageListsThePages) {
  const auto out = tempFile("nope.svg");
  const auto r = runGdpn("render examples/factory --net --page nope -o " + out);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("error: --page 'nope': no page or page type 'nope'; the pages are: factory; the page types are: station"),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(RenderNetCli, BadOutputsAreRefused) {
  auto r = runGdpn("render examples/basics/figure31 --net -o " + tempFile("net.jpg"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find(".svg or .png"), std::string::npos) << r.out;
  r = runGdpn("render examples/basics/figure31 --net -o /nonexistent_dir_gdpn/net.png");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("/nonexistent_dir_gdpn/net.png: error: cannot create a file in the folder"), std::string::npos) << r.out;
  r = runGdpn("render examples/basics/figure31 --net --camera cam -o " + tempFile("cam.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("error: --camera draws the plant; it does not go with --net"), std::string::npos) << r.out;
  r = runGdpn("render examples/basics/figure31 --page main -o " + tempFile("page.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("error: --page chooses the page of the net: add --net"), std::string::npos) << r.out;
  r = runGdpn("render examples/basics/figure31 --net --size 10x10 -o " + tempFile("small.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--size '10x10'"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace gdpn::diagram
