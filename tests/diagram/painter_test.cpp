// The net drawn: what the SVG holds for a small net in each state, the raster canvas against
// a golden picture (with the render tests' tolerance), viewport culling, and bad output.
// GDPN_UPDATE_GOLDEN=1 rewrites the golden picture.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "diagram/diagram_fixtures.h"
#include "gdpn/diagram/painter.h"
#include "gdpn/diagram/picture.h"
#include "gdpn/diagram/raster_canvas.h"
#include "gdpn/diagram/svg_canvas.h"
#include "gdpn/net/compile.h"
#include "gdpn/platform/png.h"

namespace gdpn::diagram {
namespace {

namespace fs = std::filesystem;
using testing::smallNet;
using testing::tempFile;

struct Drawn {
  net::NetSpec spec = smallNet(true);
  NetLayout layout;
  std::shared_ptr<const net::Net> net;
  std::unique_ptr<net::Kernel> kernel;
  Drawn() {
    core::Diagnostics diags;
    layout = layoutPage(spec.pages[0], diags);
    net = net::compile(spec, diags);
    EXPECT_TRUE(net) << diags.str();
    kernel = std::make_unique<net::Kernel>(net, net::KernelSettings{0.5, 1});
  }
  [[nodiscard]] NetState state() const { return netStateOf(*kernel, findViewOrDie()); }
  [[nodiscard]] PageView findViewOrDie() const {
    core::Diagnostics diags;
    return findView(spec, "main", diags);
  }
  [[nodiscard]] std::string svg(int width = 400, int height = 160) const {
    const auto s = state();
    SvgCanvas canvas(width, height);
    const SpatialIndex index(layout);
    paintNet(layout, index, &s, fitViewport(layout, width, height), canvas);
    return canvas.svg();
  }
};

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(DiagramNetState, FollowsTheKernel) {
  Drawn d;
  auto s = d.state();
  ASSERT_EQ(s.places.size(), 5u);
  ASSERT_EQ(s.places[0].size(), 1u);
  EXPECT_EQ(s.places[0][0].count, 1);
  EXPECT_EQ(s.places[0][0].kind, net::SlotKind::Control);
  EXPECT_TRUE(s.places[1].empty());
  EXPECT_EQ(s.transitions[0], Activity::Enabled);
  EXPECT_EQ(s.transitions[1], Activity::Idle);
  EXPECT_EQ(s.arcs[0], true);    // src has its token
  EXPECT_EQ(s.arcs[2], false);   // mid has none of the 2 stop needs
  EXPECT_EQ(s.arcs[5], true);    // done is empty: the inhibitor allows go
  d.kernel->start();
  s = d.state();
  EXPECT_EQ(s.transitions[0], Activity::Occurring);
  EXPECT_TRUE(s.places[0].empty());
}

TEST(DiagramSvg, SmallNetHasItsShapesNamesAndColours) {
  Drawn d;
  const std::string svg = d.svg();
  EXPECT_TRUE(svg.starts_with("<?xml")) << svg;
  EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
  // five places (white discs with an outline), token dots in src and gate, the inhibitor's small circle
  EXPECT_EQ(count(svg, "<circle"), 5u * 2 + 2 + 1) << svg;
  // names and the weight 2
  for (const char* name : {">src<", ">mid<", ">done<", ">gate<", ">block<", ">go<", ">stop<", ">2<"}) EXPECT_NE(svg.find(name), std::string::npos) << name;
  // go is enabled (a green bar), stop idle (dark grey)
  EXPECT_NE(svg.find("fill=\"#2ca02c\"/>"), std::string::npos);
  EXPECT_NE(svg.find("<rect") , std::string::npos);
  EXPECT_NE(svg.find(svgColour(colours::kIdle)), std::string::npos);
  EXPECT_EQ(svg.find(svgColour(colours::kOccurring)), std::string::npos);
  // the test arc is dashed; normal arcs end in arrowheads (one polygon each: four normal arcs)
  EXPECT_EQ(count(svg, "stroke-dasharray"), 1u);
  EXPECT_EQ(count(svg, "<polygon"), 4u);
  // once go has started it is red
  d.kernel->start();
  const std::string later = d.svg();
  EXPECT_NE(later.find("fill=\"" + svgColour(colours::kOccurring) + "\""), std::string::npos);
  EXPECT_EQ(d.svg(), later) << "the same state must give the same bytes";
}

/// Hooks whose guards are all false; no other script does anything.
class ClosedGuards : public net::ScriptHooks {
 public:
  bool guard(net::TransitionId) override { return false; }
  bool eligible(net::TermId, net::NodeRef) override { return true; }
  void preFire(net::TransitionId) override {}
  void inFire(net::TransitionId) override {}
  void postFire(net::TransitionId) override {}
  void onDeposit(net::PlaceSlotId, const net::NodeRef*) override {}
  void onRemove(net::PlaceSlotId, const net::NodeRef*) override {}
  [[nodiscard]] bool halted() const override { return false; }
};

TEST(DiagramNetState, AGuardFalseWhereTheMarkingSufficesIsHeldBackNotEnabled) {
  Drawn d;
  d.spec.pages[0].transitions[0].guard.code = "False";  // go: src has its token, block none
  core::Diagnostics diags;
  d.net = net::compile(d.spec, diags);
  ASSERT_TRUE(d.net) << diags.str();
  d.kernel = std::make_unique<net::Kernel>(d.net, net::KernelSettings{0.5, 1});
  ClosedGuards hooks;
  d.kernel->setHooks(&hooks);
  // before the first firing phase its guard is unknown: waiting, not enabled
  EXPECT_EQ(d.state().transitions[0], Activity::Waiting);
  d.kernel->start();
  const auto s = d.state();
  EXPECT_EQ(s.transitions[0], Activity::HeldBack);
  EXPECT_EQ(s.readiness[0], net::Readiness::Guard);
  EXPECT_EQ(s.transitions[1], Activity::Idle);
  EXPECT_EQ(s.readiness[1], net::Readiness::Tokens);
  // drawn amber, outlined in the enabled colour (its marking suffices); no green bar
  const std::string svg = d.svg();
  EXPECT_NE(svg.find("fill=\"" + svgColour(colours::kHeldBack) + "\"/>"), std::string::npos) << svg;
  EXPECT_TRUE(std::regex_search(svg, std::regex("<rect[^>]*fill=\"none\" stroke=\"" + svgColour(colours::kEnabled) + "\"")))
      << svg;
  EXPECT_FALSE(std::regex_search(svg, std::regex("<rect[^>]*fill=\"" + svgColour(colours::kEnabled) + "\"/>"))) << svg;
}

TEST(DiagramNetState, ABindingMadeOnceReadsTheSameStateAsTheNames) {
  Drawn d;
  const auto binding = bindPage(*d.net, d.findViewOrDie());
  ASSERT_EQ(binding.places.size(), 5u);
  for (const auto id : binding.places) EXPECT_TRUE(id.has_value());
  const auto same = [&] {
    const auto a = d.state(), b = netStateOf(*d.kernel, binding);
    EXPECT_EQ(a.transitions, b.transitions);
    EXPECT_EQ(a.arcs, b.arcs);
    ASSERT_EQ(a.places.size(), b.places.size());
    for (std::size_t i = 0; i < a.places.size(); ++i) {
      ASSERT_EQ(a.places[i].size(), b.places[i].size());
      for (std::size_t k = 0; k < a.places[i].size(); ++k) EXPECT_EQ(a.places[i][k].count, b.places[i][k].count);
    }
  };
  same();
  d.kernel->start();  // the binding holds as the marking moves
  same();
}

TEST(DiagramSvg, ZoomedFarOutPlacesAreSquaresInTheirTokensColourAndArcsHairlines) {
  Drawn d;
  const auto s = d.state();
  SvgCanvas canvas(400, 160);
  const SpatialIndex index(d.layout);
  Viewport far = fitViewport(d.layout, 400, 160);
  far.zoom = 2.0 / kPlaceRadius;  // a place 2 pixels in radius
  paintNet(d.layout, index, &s, far, canvas);
  const std::string svg = canvas.svg();
  // no discs, no arrowheads, no names: five squares among the rects, src's and gate's in the
  // control tokens' colour
  EXPECT_EQ(count(svg, "<circle"), 0u) << svg;
  EXPECT_EQ(count(svg, "<polygon"), 0u);
  EXPECT_EQ(svg.find(">src<"), std::string::npos);
  EXPECT_EQ(count(svg, "fill=\"" + svgColour(colours::kControl) + "\""), 2u) << svg;
  EXPECT_EQ(count(svg, "fill=\"" + svgColour(colours::kOutline) + "\""), 3u) << svg;
}

TEST(DiagramSvg, TextIsEscapedAndNeverTooSmall) {
  Drawn d;
  d.layout.places[0].name = "a<b&c";
  const std::string svg = d.svg();
  EXPECT_NE(svg.find(">a&lt;b&amp;c<"), std::string::npos);
  // zoomed far out: no names at all rather than unreadable ones
  const auto s = d.state();
  SvgCanvas tiny(400, 160);
  Viewport far;
  far.zoom = 0.2;
  paintNet(d.layout, SpatialIndex(d.layout), &s, far, tiny);
  EXPECT_EQ(tiny.svg().find("<text"), std::string::npos);
  const std::regex size("font-size=\"([0-9.]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), size); it != std::sregex_iterator(); ++it)
    EXPECT_GE(std::stod((*it)[1]), kMinFontPx);
}

TEST(DiagramRaster, ShapesLandWhereAsked) {
  std::string why;
  auto c = RasterCanvas::create(64, 32, kDefaultFont, why);
  ASSERT_TRUE(c) << why;
  c->clear(colours::kBackground);
  c->fillCircle({16, 16}, 8.2, colours::kOccurring);
  c->fillRect({{40, 8}, {48, 24}}, colours::kEnabled);
  EXPECT_EQ(c->at(16, 16), colours::kOccurring);
  EXPECT_EQ(c->at(44, 16), colours::kEnabled);
  EXPECT_EQ(c->at(2, 2), colours::kBackground);
  // the disc's edge is blended, not jagged: a pixel straddling it is between the colours
  const Rgba edge = c->at(24, 16);
  EXPECT_GT(edge.g, colours::kOccurring.g);
  EXPECT_LT(edge.g, 255);
  EXPECT_GT(c->textWidth("stop", 12), 20.0);
  EXPECT_FALSE(RasterCanvas::create(64, 32, "/no/such/font.ttf", why));
  EXPECT_NE(why.find("/no/such/font.ttf"), std::string::npos);
  EXPECT_FALSE(RasterCanvas::create(0, 32, kDefaultFont, why));
}

TEST(DiagramRaster, PngMatchesGolden) {
  Drawn d;
  d.kernel->start();
  const auto s = d.state();
  const auto out = tempFile("golden.png");
  std::string why;
  ASSERT_TRUE(writeNetPicture(d.layout, &s, 360, 180, out, why)) << why;
  int w = 0, h = 0, gw = 0, gh = 0;
  std::vector<std::uint8_t> rgb, golden_rgb;
  ASSERT_TRUE(platform::readPng(out, w, h, rgb, why)) << why;
  fs::remove(out);
  // golden: tests/data/golden/net_small.png, drawn by this test from testing::smallNet(true)
  // at time 0 after the start (go occurring), 360 x 180
  const auto golden = (fs::path(GDPN_SOURCE_DIR) / "tests" / "data" / "golden" / "net_small.png").string();
  if (std::getenv("GDPN_UPDATE_GOLDEN") != nullptr) {
    ASSERT_TRUE(platform::writePng(golden, w, h, rgb, why)) << why;
    return;
  }
  ASSERT_TRUE(platform::readPng(golden, gw, gh, golden_rgb, why)) << golden << ": " << why;
  ASSERT_EQ(gw, w);
  ASSERT_EQ(gh, h);
  // the render tests' tolerance: at most 0.5 % of pixels off by more than 24 in a channel,
  // and a mean difference under 1.5
  std::size_t off = 0;
  double total = 0;
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    int worst = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const int diff = std::abs(static_cast<int>(rgb[i + k]) - static_cast<int>(golden_rgb[i + k]));
      worst = std::max(worst, diff);
      total += diff;
    }
    off += worst > 24 ? 1 : 0;
  }
  const double pixels = static_cast<double>(rgb.size() / 3);
  EXPECT_LE(static_cast<double>(off), 0.005 * pixels);
  EXPECT_LT(total / static_cast<double>(rgb.size()), 1.5);
}

/// A grid of `columns` x `rows` transitions, each with a place to its right.
net::PageSpec gridPage(int columns, int rows) {
  net::PageSpec page;
  page.name = "grid";
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < columns; ++x) {
      const auto id = std::to_string(x) + "_" + std::to_string(y);
      page.transitions.push_back(testing::transition("t" + id, 1, net::EditorPos{2.0 * x, 1.0 * y}));
      page.places.push_back(testing::place("p" + id, 0, net::EditorPos{2.0 * x + 1, 1.0 * y}));
      page.arcs.push_back(testing::arc("t" + id, "p" + id));
    }
  return page;
}

TEST(DiagramCulling, ViewportReturnsOnlyTheVisibleItems) {
  const auto page = gridPage(50, 20);
  core::Diagnostics diags;
  const auto layout = layoutPage(page, diags);
  const SpatialIndex index(layout);
  // a view around the transitions of columns 3-4 and rows 5-6
  const Box view{{3 * 2 * kEditorUnit - 10, 5 * kEditorUnit - 10}, {4 * 2 * kEditorUnit + 10, 6 * kEditorUnit + 10}};
  const auto items = index.query(view);
  std::size_t transitions = 0;
  for (const ItemRef r : items) {
    EXPECT_TRUE(layout.boxOf(r).overlaps(view));
    transitions += r.kind == ItemKind::Transition ? 1 : 0;
  }
  EXPECT_EQ(transitions, 4u);
  // and nothing visible is missed
  std::size_t expected = 0;
  for (std::uint32_t i = 0; i < layout.places.size(); ++i) expected += layout.places[i].box.overlaps(view) ? 1u : 0u;
  for (std::uint32_t i = 0; i < layout.transitions.size(); ++i) expected += layout.transitions[i].box.overlaps(view) ? 1u : 0u;
  for (std::uint32_t i = 0; i < layout.arcs.size(); ++i) expected += layout.arcs[i].box.overlaps(view) ? 1u : 0u;
  EXPECT_EQ(items.size(), expected);
  EXPECT_TRUE(index.query({{-1e6, -1e6}, {-1e5, -1e5}}).empty());
  EXPECT_EQ(index.query(layout.bounds).size(), layout.places.size() + layout.transitions.size() + layout.arcs.size());
}

TEST(DiagramCulling, ARubberBandTakesWhatLiesWhollyInside) {
  core::Diagnostics diags;
  const auto page = gridPage(10, 10);
  const auto layout = layoutPage(page, diags);
  const SpatialIndex index(layout);
  // the band around the transitions of columns 3-4 and rows 5-6, cutting the arcs that leave
  const double m = 0.4 * kEditorUnit;
  const Box band{{3 * 2 * kEditorUnit - m, 5 * kEditorUnit - m}, {4 * 2 * kEditorUnit + m, 6 * kEditorUnit + m}};
  const auto items = index.within(band);
  std::size_t expected = 0;
  const auto whole = [&](const Box& b) {
    return b.min.x >= band.min.x && b.min.y >= band.min.y && b.max.x <= band.max.x && b.max.y <= band.max.y ? 1u : 0u;
  };
  for (const auto& p : layout.places) expected += whole(p.box);
  for (const auto& t : layout.transitions) expected += whole(t.box);
  for (const auto& a : layout.arcs) expected += whole(a.box);
  EXPECT_EQ(items.size(), expected);
  std::size_t transitions = 0;
  for (const ItemRef r : items) {
    EXPECT_EQ(whole(layout.boxOf(r)), 1u);
    transitions += r.kind == ItemKind::Transition ? 1 : 0;
  }
  EXPECT_EQ(transitions, 4u);
  EXPECT_LT(items.size(), index.query(band).size());  // the items the band only touches are left out
  EXPECT_EQ(index.within(layout.bounds).size(), layout.places.size() + layout.transitions.size() + layout.arcs.size());
}

TEST(DiagramCulling, PickFindsWhatIsUnderTheMouse) {
  Drawn d;
  const SpatialIndex index(d.layout);
  const auto& l = d.layout;
  EXPECT_EQ(index.pick(l.places[1].centre, 2), (ItemRef{ItemKind::Place, 1}));
  EXPECT_EQ(index.pick(l.transitions[0].centre + Point{0, kBarHeight / 2 - 1}, 2), (ItemRef{ItemKind::Transition, 0}));
  // half way along src -> go: the arc
  const Point mid = (l.arcs[0].points.front() + l.arcs[0].points.back()) * 0.5;
  EXPECT_EQ(index.pick(mid + Point{0, 1.5}, 2), (ItemRef{ItemKind::Arc, 0}));
  // inside a place's square but outside its circle, and far from everything: nothing
  EXPECT_FALSE(index.pick(l.places[1].box.min + Point{1, 1}, 1));
  EXPECT_FALSE(index.pick({-500, -500}, 2));
}

TEST(DiagramViewport, ZoomKeepsThePointUnderTheMouseAndPanFollowsTheDrag) {
  Viewport v{{100, 50}, 1.5};
  const Point mouse{320, 200};
  const Point under = v.toLayout(mouse);
  const Viewport in = v.zoomedAbout(mouse, 2.0);
  EXPECT_DOUBLE_EQ(in.zoom, 3.0);
  EXPECT_NEAR(in.toLayout(mouse).x, under.x, 1e-9);
  EXPECT_NEAR(in.toLayout(mouse).y, under.y, 1e-9);
  const Viewport moved = v.panned({30, -12});
  EXPECT_NEAR(moved.toScreen(under).x, mouse.x + 30, 1e-9);
  EXPECT_NEAR(moved.toScreen(under).y, mouse.y - 12, 1e-9);
  // fitting shows every shape and name inside the canvas
  Drawn d;
  const Viewport fit = fitViewport(d.layout, 400, 160);
  const Box b = drawnBounds(d.layout);
  EXPECT_GE(fit.toScreen(b.min).x, 0.0);
  EXPECT_GE(fit.toScreen(b.min).y, 0.0);
  EXPECT_LE(fit.toScreen(b.max).x, 400.0);
  EXPECT_LE(fit.toScreen(b.max).y, 160.0);
}

TEST(DiagramPicture, EmptyPageGivesAnEmptyPicture) {
  net::PageSpec page;
  page.name = "empty";
  core::Diagnostics diags;
  const auto layout = layoutPage(page, diags);
  EXPECT_FALSE(diags.hasErrors());
  std::string why;
  const auto out = tempFile("empty.png");
  EXPECT_TRUE(writeNetPicture(layout, nullptr, 100, 60, out, why)) << why;
  fs::remove(out);
  EXPECT_TRUE(SpatialIndex(layout).query({{-1e9, -1e9}, {1e9, 1e9}}).empty());
}

TEST(DiagramPicture, BadOutputIsReportedAndLeavesNothing) {
  Drawn d;
  const auto s = d.state();
  std::string why;
  EXPECT_FALSE(writeNetPicture(d.layout, &s, 200, 100, "/nonexistent_dir_gdpn/net.svg", why));
  EXPECT_NE(why.find("/nonexistent_dir_gdpn"), std::string::npos) << why;
  why.clear();
  EXPECT_FALSE(writeNetPicture(d.layout, &s, 200, 100, tempFile("net.jpg"), why));
  EXPECT_NE(why.find(".svg or .png"), std::string::npos) << why;
  EXPECT_FALSE(fs::exists(tempFile("net.jpg")));
  // a good one replaces the old file whole
  const auto out = tempFile("net.svg");
  std::ofstream(out) << "old";
  ASSERT_TRUE(writeNetPicture(d.layout, &s, 200, 100, out, why)) << why;
  std::stringstream text;
  text << std::ifstream(out).rdbuf();
  EXPECT_TRUE(text.str().starts_with("<?xml"));
  fs::remove(out);
}

}  // namespace
}  // namespace gdpn::diagram
