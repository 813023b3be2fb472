// An arc's route as the spec keeps it: drawn through its bend points (on a page of positions
// and on one Graphviz lays out), its inscription where `label_at` puts it, picked by any
// segment, and the helpers an editor bends it with (nearest segment, editor units).

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "diagram/diagram_fixtures.h"
#include "gdpn/diagram/layout.h"
#include "gdpn/diagram/painter.h"
#include "gdpn/diagram/spatial_index.h"
#include "gdpn/diagram/svg_canvas.h"

namespace gdpn::diagram {
namespace {

using testing::smallNet;

void expectNear(Point got, Point want) {
  EXPECT_NEAR(got.x, want.x, 1e-9) << "x";
  EXPECT_NEAR(got.y, want.y, 1e-9) << "y";
}

/// smallNet(placed) with src -> go bent down through (0, 2) and (1, 2), editor units.
net::NetSpec bentNet(bool placed) {
  auto spec = smallNet(placed);
  spec.pages[0].arcs[0].via = {{0, 2}, {1, 2}};
  return spec;
}

TEST(DiagramRoute, AnArcRunsThroughItsBendPointsClippedAtTheOutlines) {
  core::Diagnostics diags;
  const auto l = layoutPage(bentNet(true).pages[0], diags);
  ASSERT_FALSE(diags.hasErrors()) << diags.str();
  // src stands at (0, 1), go at (1, 1): down out of src's circle, across, up into go's bar
  const auto& a = l.arcs[0];
  ASSERT_EQ(a.points.size(), 4u);
  EXPECT_TRUE(a.follows_via);
  expectNear(a.points[0], {0, kEditorUnit + kPlaceRadius});
  expectNear(a.points[1], {0, 2 * kEditorUnit});
  expectNear(a.points[2], {kEditorUnit, 2 * kEditorUnit});
  expectNear(a.points[3], {kEditorUnit, kEditorUnit + kBarHeight / 2});
  EXPECT_EQ(a.box.max.y, 2 * kEditorUnit);
  // the other arcs are as they were
  const auto straight = layoutPage(smallNet(true).pages[0], diags);
  for (std::size_t i = 1; i < l.arcs.size(); ++i) EXPECT_EQ(l.arcs[i].points, straight.arcs[i].points) << i;
  EXPECT_FALSE(straight.arcs[0].follows_via);
}

TEST(DiagramRoute, AnArcWithBendPointsIsNoTwinToBendApartFrom) {
  // go -> src beside the bent src -> go: the straight one stays straight
  auto spec = bentNet(true);
  spec.pages[0].arcs.push_back(testing::arc("go", "src"));
  core::Diagnostics diags;
  const auto l = layoutPage(spec.pages[0], diags);
  EXPECT_EQ(l.arcs.back().points.size(), 2u);
  EXPECT_EQ(l.arcs[0].points.size(), 4u);
}

TEST(DiagramRoute, GraphvizKeepsItsRouteForArcsWithoutBendPoints) {
  core::Diagnostics diags;
  const auto plain = layoutPage(smallNet(false).pages[0], diags);
  const auto bent = layoutPage(bentNet(false).pages[0], diags);
  ASSERT_FALSE(diags.hasErrors()) << diags.str();
  ASSERT_TRUE(bent.from_graphviz);
  // the bent arc runs through its bend points, the others keep Graphviz's route
  ASSERT_EQ(bent.arcs[0].points.size(), 4u);
  expectNear(bent.arcs[0].points[1], {0, 2 * kEditorUnit});
  expectNear(bent.arcs[0].points[2], {kEditorUnit, 2 * kEditorUnit});
  for (std::size_t i = 1; i < bent.arcs.size(); ++i) {
    EXPECT_EQ(bent.arcs[i].points, plain.arcs[i].points) << i;
    EXPECT_FALSE(bent.arcs[i].follows_via);
  }
}

TEST(DiagramRoute, PickFindsAnArcByItsSecondSegment) {
  core::Diagnostics diags;
  const auto l = layoutPage(bentNet(true).pages[0], diags);
  const SpatialIndex index(l);
  // half way along the bottom stretch, far from where a straight src -> go would run
  const Point on_second{kEditorUnit / 2, 2 * kEditorUnit + 1.5};
  EXPECT_EQ(index.pick(on_second, 2), (ItemRef{ItemKind::Arc, 0}));
  // and nothing a little below it
  EXPECT_FALSE(index.pick(on_second + Point{0, 10}, 2));
}

TEST(DiagramRoute, NearestSegmentGivesItsIndexAndTheProjection) {
  core::Diagnostics diags;
  const auto l = layoutPage(bentNet(true).pages[0], diags);
  const auto& a = l.arcs[0];
  const SegmentHit hit = nearestSegment(a, {30, 2 * kEditorUnit + 5});
  EXPECT_EQ(hit.segment, 1u);
  expectNear(hit.at, {30, 2 * kEditorUnit});
  EXPECT_NEAR(hit.distance, 5, 1e-9);
  // near the first stretch (down out of src)
  EXPECT_EQ(nearestSegment(a, {-3, 110}).segment, 0u);
  // past the end of the last stretch: its end point
  const SegmentHit last = nearestSegment(a, {kEditorUnit + 4, kEditorUnit});
  EXPECT_EQ(last.segment, 2u);
  expectNear(last.at, a.points.back());
  // a bend put there goes into `via` at the segment's index: the route then runs through it
  auto spec = bentNet(true);
  auto& via = spec.pages[0].arcs[0].via;
  via.insert(via.begin() + static_cast<std::ptrdiff_t>(hit.segment), editorPosition(hit.at + Point{0, 36}));
  const auto again = layoutPage(spec.pages[0], diags);
  ASSERT_EQ(again.arcs[0].points.size(), 5u);
  expectNear(again.arcs[0].points[2], {36, 2.5 * kEditorUnit});
}

TEST(DiagramRoute, BendAtFindsTheBendUnderThePointByItsIndexInVia) {
  core::Diagnostics diags;
  const auto l = layoutPage(bentNet(true).pages[0], diags);
  EXPECT_EQ(bendAt(l.arcs[0], {kEditorUnit + 2, 2 * kEditorUnit - 1}, 4), std::optional<std::size_t>(1));
  EXPECT_EQ(bendAt(l.arcs[0], {1, 2 * kEditorUnit}, 4), std::optional<std::size_t>(0));
  // on the arc but at no bend, and an end point: none
  EXPECT_FALSE(bendAt(l.arcs[0], {kEditorUnit / 2, 2 * kEditorUnit}, 4));
  EXPECT_FALSE(bendAt(l.arcs[0], l.arcs[0].points.front(), 4));
  // an arc bent apart from its twin has no bends of its own
  auto spec = smallNet(true);
  spec.pages[0].arcs.push_back(testing::arc("go", "src"));
  const auto twins = layoutPage(spec.pages[0], diags);
  ASSERT_EQ(twins.arcs[0].points.size(), 3u);
  EXPECT_FALSE(bendAt(twins.arcs[0], twins.arcs[0].points[1], 4));
}

TEST(DiagramRoute, EditorUnitsAreTheNetViewsQuarterSnappedUnits) {
  expectNear(layoutPoint({1.5, -2}), {1.5 * kEditorUnit, -2 * kEditorUnit});
  const auto at = editorPosition({100, -0.1});
  EXPECT_EQ(at, (net::EditorPos{1.5, 0}));
  EXPECT_FALSE(std::signbit(at[1]));
  EXPECT_EQ(editorPosition(layoutPoint({-3.25, 7.75})), (net::EditorPos{-3.25, 7.75}));
}

TEST(DiagramRoute, TheInscriptionStandsWhereLabelAtPutsIt) {
  auto spec = bentNet(true);
  // mid (2, 1) -> stop (3, 1), weight 2: its label half a unit above the arc's middle
  spec.pages[0].arcs[2].label_at = net::EditorPos{0, -0.5};
  core::Diagnostics diags;
  const auto l = layoutPage(spec.pages[0], diags);
  const auto& a = l.arcs[2];
  ASSERT_TRUE(a.label_at);
  const Point middle{(2 * kEditorUnit + kPlaceRadius + 3 * kEditorUnit - kBarWidth / 2) / 2, kEditorUnit};
  expectNear(middleOf(a.points), middle);
  expectNear(*a.label_at, middle + Point{0, -kEditorUnit / 2});
  EXPECT_LE(a.box.min.y, a.label_at->y);
  // dragging the label gives the offset back
  const auto offset = labelOffset(a, *a.label_at + Point{18, 0});
  EXPECT_NEAR(offset[0], 0.25, 1e-12);
  EXPECT_NEAR(offset[1], -0.5, 1e-12);
  // the middle of a bent arc is half its length along it
  expectNear(middleOf(l.arcs[0].points), {kEditorUnit / 2, 2 * kEditorUnit});
  EXPECT_FALSE(l.arcs[0].label_at);

  // the painter draws the weight there (a viewport of one pixel per layout unit)
  SvgCanvas canvas(400, 200);
  const SpatialIndex index(l);
  paintNet(l, index, nullptr, Viewport{{0, 0}, 1.0}, canvas);
  const std::string svg = canvas.svg();
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, std::regex("<text x=\"([-0-9.e]+)\" y=\"[-0-9.e]+\"[^>]*>2</text>"))) << svg;
  EXPECT_NEAR(std::stod(m[1].str()), a.label_at->x, 1e-6);
}

/// The two layouts draw the same: every item where, and every arc along the same points.
void expectSameLayout(const NetLayout& a, const NetLayout& b) {
  ASSERT_EQ(a.places.size(), b.places.size());
  ASSERT_EQ(a.transitions.size(), b.transitions.size());
  ASSERT_EQ(a.arcs.size(), b.arcs.size());
  for (std::size_t i = 0; i < a.places.size(); ++i) EXPECT_EQ(a.places[i].box, b.places[i].box) << a.places[i].name;
  for (std::size_t i = 0; i < a.transitions.size(); ++i) EXPECT_EQ(a.transitions[i].box, b.transitions[i].box) << a.transitions[i].name;
  for (std::size_t i = 0; i < a.arcs.size(); ++i) {
    EXPECT_EQ(a.arcs[i].points, b.arcs[i].points) << "arc " << i;
    EXPECT_EQ(a.arcs[i].box, b.arcs[i].box) << "arc " << i;
    EXPECT_EQ(a.arcs[i].label_at, b.arcs[i].label_at) << "arc " << i;
    EXPECT_EQ(a.arcs[i].follows_via, b.arcs[i].follows_via) << "arc " << i;
  }
  EXPECT_EQ(a.bounds, b.bounds);
}

TEST(DiagramRoute, MovedItemsLaidOutAgainInPlaceDrawAsTheWholePageLaidOutAgain) {
  // a row of places and transitions, twin arcs between two of them, a bent arc with its label
  net::PageSpec page;
  page.name = "main";
  for (int i = 0; i < 6; ++i) {
    page.places.push_back(testing::place("p" + std::to_string(i), 0, net::EditorPos{2.0 * i, 0}));
    page.transitions.push_back(testing::transition("t" + std::to_string(i), 1, net::EditorPos{2.0 * i + 1, 0}));
    page.arcs.push_back(testing::arc("p" + std::to_string(i), "t" + std::to_string(i)));
    if (i > 0) page.arcs.push_back(testing::arc("t" + std::to_string(i - 1), "p" + std::to_string(i)));
  }
  page.arcs.push_back(testing::arc("t2", "p2"));  // twin of p2 -> t2: the two bend apart
  auto bent = testing::arc("p4", "t1");
  bent.via = {{6, 2}, {3, 2}};
  bent.weights = {net::SlotCount{net::kDefaultSlot, 3}};
  bent.label_at = net::EditorPos{0, 0.5};
  page.arcs.push_back(bent);
  core::Diagnostics diags;
  NetLayout l = layoutPage(page, diags);
  ASSERT_FALSE(l.from_graphviz);
  // moves: one place; a transition with a twin arc; the two ends of the bent arc with it (as a
  // group's drag moves its bends)
  const std::vector<std::vector<std::pair<ItemRef, net::EditorPos>>> steps = {
      {{{ItemKind::Place, 0}, {0, 1.5}}},
      {{{ItemKind::Transition, 2}, {5, -1}}},
      {{{ItemKind::Place, 4}, {8, 1}}, {{ItemKind::Transition, 1}, {3, 1}}}};
  for (const auto& step : steps) {
    std::vector<ItemRef> moved;
    for (const auto& [item, at] : step) {
      (item.kind == ItemKind::Place ? page.places[item.index].position : page.transitions[item.index].position) = at;
      moved.push_back(item);
    }
    if (step.size() == 2) {
      for (auto& bend : page.arcs.back().via) bend = {bend[0], bend[1] + 1};
    }
    relayoutMoved(l, page, moved);
    expectSameLayout(l, layoutPage(page, diags));
  }
}

TEST(DiagramTags, APublishedPlaceIsTaggedPortAndAFusionMemberWithItsSet) {
  net::PageSpec page;
  page.name = "cell";
  page.places = {testing::place("enter", 0, net::EditorPos{0, 0}), testing::place("stock", 2, net::EditorPos{2, 0}),
                 testing::place("work", 0, net::EditorPos{4, 0})};
  page.places[1].fusion = "parts";
  page.places[2].fusion = "parts";
  page.references.push_back({"enter", {}});
  page.references.push_back({"work", {}});
  core::Diagnostics diags;
  const auto l = layoutPage(page, diags);
  EXPECT_EQ(l.places[0].tag, "port");
  EXPECT_EQ(l.places[1].tag, "fusion parts");
  EXPECT_EQ(l.places[2].tag, "port, fusion parts");
  // drawn beside their places
  SvgCanvas canvas(400, 200);
  const SpatialIndex index(l);
  paintNet(l, index, nullptr, Viewport{{-60, -60}, 1.0}, canvas);
  const std::string svg = canvas.svg();
  EXPECT_NE(svg.find(">port</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">fusion parts</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">port, fusion parts</text>"), std::string::npos) << svg;
}

}  // namespace
}  // namespace gdpn::diagram
