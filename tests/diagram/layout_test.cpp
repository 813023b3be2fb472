// Net layout: positions from the spec honoured, Graphviz for pages without them, the same
// layout for the same spec, arcs to instances ending at the box, pages found by name.

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "diagram/diagram_fixtures.h"
#include "gdpn/diagram/layout.h"

namespace gdpn::diagram {
namespace {

using testing::smallNet;

// every number of a layout, in order, as text: two layouts are the same when these are
std::string dump(const NetLayout& l) {
  std::string s;
  auto p = [&](Point q) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g,%.17g ", q.x, q.y);
    s += text;
  };
  for (const auto& n : l.places) p(n.centre);
  for (const auto& n : l.transitions) p(n.centre);
  for (const auto& n : l.instances) p(n.centre);
  for (const auto& a : l.arcs) {
    for (const Point& q : a.points) p(q);
    s += "\n";
  }
  return s;
}

TEST(DiagramLayout, PositionsFromTheSpecAreHonoured) {
  core::Diagnostics diags;
  const auto spec = smallNet(true);
  const auto l = layoutPage(spec.pages[0], diags);
  ASSERT_FALSE(diags.hasErrors()) << diags.str();
  EXPECT_FALSE(l.from_graphviz);
  ASSERT_EQ(l.places.size(), 5u);
  EXPECT_EQ(l.places[1].centre, (Point{2 * kEditorUnit, kEditorUnit}));
  EXPECT_EQ(l.transitions[1].centre, (Point{3 * kEditorUnit, kEditorUnit}));
  EXPECT_DOUBLE_EQ(l.places[0].box.width(), 2 * kPlaceRadius);
  // the arc src -> go leaves src's circle and ends on go's bar
  const auto& a = l.arcs[0];
  EXPECT_NEAR(a.points.front().x, kPlaceRadius, 1e-9);
  EXPECT_NEAR(a.points.back().x, kEditorUnit - kBarWidth / 2, 1e-9);
  EXPECT_EQ(a.weight, 1);
  EXPECT_EQ(l.arcs[2].weight, 2);
  EXPECT_EQ(l.arcs[4].kind, net::ArcKind::Test);
}

TEST(DiagramLayout, ArcsBetweenTheSameItemsBendApart) {
  core::Diagnostics diags;
  const auto spec = smallNet(true);
  const auto l = layoutPage(spec.pages[0], diags);
  // an arc alone between its two items is straight
  EXPECT_EQ(l.arcs[4].points.size(), 2u);
  net::PageSpec twin = spec.pages[0];
  twin.arcs.push_back(testing::arc("mid", "go"));
  const auto t = layoutPage(twin, diags);
  ASSERT_EQ(t.arcs[1].points.size(), 3u);  // go -> mid bends
  ASSERT_EQ(t.arcs.back().points.size(), 3u);  // mid -> go bends the other way
  EXPECT_LT((t.arcs[1].points[1].y - kEditorUnit) * (t.arcs.back().points[1].y - kEditorUnit), 0.0);
}

TEST(DiagramLayout, SameSpecSameLayoutByteForByte) {
  for (const bool placed : {true, false}) {
    core::Diagnostics diags;
    const auto spec = smallNet(placed);
    const auto a = layoutPage(spec.pages[0], diags);
    const auto b = layoutPage(spec.pages[0], diags);
    ASSERT_FALSE(diags.hasErrors()) << diags.str();
    EXPECT_EQ(dump(a), dump(b)) << (placed ? "positions" : "Graphviz");
    EXPECT_EQ(a.from_graphviz, !placed);
  }
}

TEST(DiagramLayout, GraphvizPutsEveryNodeApart) {
  core::Diagnostics diags;
  // a page of 40 places and 40 transitions in a ring with chords, no positions
  net::PageSpec page;
  page.name = "ring";
  for (int i = 0; i < 40; ++i) {
    page.places.push_back(testing::place("p" + std::to_string(i), i == 0 ? 1 : 0));
    page.transitions.push_back(testing::transition("t" + std::to_string(i)));
  }
  for (int i = 0; i < 40; ++i) {
    page.arcs.push_back(testing::arc("p" + std::to_string(i), "t" + std::to_string(i)));
    page.arcs.push_back(testing::arc("t" + std::to_string(i), "p" + std::to_string((i + 1) % 40)));
    if (i % 7 == 0) page.arcs.push_back(testing::arc("t" + std::to_string(i), "p" + std::to_string((i + 13) % 40)));
  }
  page.places[3].position = net::EditorPos{100, 100};  // one position is not enough: Graphviz lays out all
  const auto l = layoutPage(page, diags);
  ASSERT_FALSE(diags.hasErrors()) << diags.str();
  EXPECT_TRUE(l.from_graphviz);
  std::vector<Box> boxes;
  for (const auto& p : l.places) boxes.push_back(p.box);
  for (const auto& t : l.transitions) boxes.push_back(t.box);
  std::set<std::pair<double, double>> centres;
  for (const auto& p : l.places) centres.insert({p.centre.x, p.centre.y});
  for (const auto& t : l.transitions) centres.insert({t.centre.x, t.centre.y});
  EXPECT_EQ(centres.size(), 80u);
  // no two shapes overlap
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      EXPECT_FALSE(boxes[i].overlaps(boxes[j])) << i << " and " << j;
  // every arc has a polyline that starts near its source and ends near its target
  for (const auto& a : l.arcs) {
    ASSERT_GE(a.points.size(), 2u);
    const Box& from = l.boxOf(a.from);
    const Box& to = l.boxOf(a.to);
    auto near = [](const Box& b, Point p) {
      return p.x >= b.min.x - 2 && p.x <= b.max.x + 2 && p.y >= b.min.y - 2 && p.y <= b.max.y + 2;
    };
    EXPECT_TRUE(near(from, a.points.front()));
    EXPECT_TRUE(near(to, a.points.back()));
  }
  // all of it inside the bounds, which start at the margin
  for (const auto& b : boxes) {
    EXPECT_GE(b.min.x, l.bounds.min.x);
    EXPECT_LE(b.max.y, l.bounds.max.y);
  }
}

TEST(DiagramLayout, PagesTooLargeForGraphvizGoInColumns) {
  net::PageSpec page;
  page.name = "big";
  const int n = static_cast<int>(kGraphvizLimit) / 2 + 1;
  for (int i = 0; i < n; ++i) {
    page.places.push_back(testing::place("p" + std::to_string(i)));
    page.transitions.push_back(testing::transition("t" + std::to_string(i)));
    page.arcs.push_back(testing::arc("p" + std::to_string(i), "t" + std::to_string(i)));
    page.arcs.push_back(testing::arc("t" + std::to_string(i), "p" + std::to_string((i + 1) % n)));
  }
  core::Diagnostics diags;
  const auto l = layoutPage(page, diags);
  EXPECT_FALSE(diags.hasErrors());
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_NE(diags.all()[0].message.find("laid out in columns"), std::string::npos) << diags.str();
  EXPECT_FALSE(l.from_graphviz);
  std::set<std::pair<double, double>> centres;
  for (const auto& p : l.places) centres.insert({p.centre.x, p.centre.y});
  for (const auto& t : l.transitions) centres.insert({t.centre.x, t.centre.y});
  EXPECT_EQ(centres.size(), 2u * static_cast<std::size_t>(n));
  // a ring: each step one column further right
  EXPECT_LT(l.places[0].centre.x, l.transitions[0].centre.x);
  EXPECT_LT(l.transitions[0].centre.x, l.places[1].centre.x);
  core::Diagnostics again;
  EXPECT_EQ(dump(l), dump(layoutPage(page, again)));
}

TEST(DiagramLayout, ArcsToLinksEndAtTheInstanceBox) {
  core::Diagnostics diags;
  net::NetSpec spec;
  net::PageSpec type;
  type.name = "cell";
  type.references = {{"enter", {}}, {"exit", {}}};
  type.places = {testing::place("enter"), testing::place("exit")};
  type.transitions = {testing::transition("work")};
  type.arcs = {testing::arc("enter", "work"), testing::arc("work", "exit")};
  net::PageSpec line;
  line.name = "line";
  line.places = {testing::place("in", 3, net::EditorPos{0, 0})};
  line.transitions = {testing::transition("load", 1, net::EditorPos{1, 0})};
  net::InstanceSpec cell;
  cell.name = "cellA";
  cell.type = "cell";
  cell.position = net::EditorPos{3, 0};
  line.instances = {cell};
  line.arcs = {testing::arc("in", "load"), testing::arc("load", "cellA/enter")};
  spec.pages = {line};
  spec.page_types = {type};
  const auto l = layoutPage(spec.pages[0], diags);
  ASSERT_EQ(l.arcs.size(), 2u);
  EXPECT_EQ(l.arcs[1].to.kind, ItemKind::Instance);
  EXPECT_EQ(l.arcs[1].link, "enter");
  EXPECT_NEAR(l.arcs[1].points.back().x, l.instances[0].box.min.x, 1e-9);
  // the instance's page type, and the view's prefix
  const auto view = findView(spec, "line/cellA", diags);
  ASSERT_NE(view.page, nullptr);
  EXPECT_EQ(view.page->name, "cell");
  EXPECT_EQ(view.prefix, "line/cellA");
  EXPECT_EQ(findView(spec, "", diags).page->name, "line");
  EXPECT_EQ(findView(spec, "cell", diags).prefix, "");
  EXPECT_FALSE(diags.hasErrors()) << diags.str();
}

TEST(DiagramLayout, InscriptionsNameSlotsOnlyWhenTheyMatter) {
  using net::SlotCount;
  EXPECT_EQ(inscription({}), "");
  EXPECT_EQ(inscription({SlotCount{0, 1, {}}}), "");
  EXPECT_EQ(inscription({SlotCount{0, 3, {}}}), "3");
  EXPECT_EQ(inscription({SlotCount{12, 1, {}}, SlotCount{8, 1, {}}, SlotCount{9, 1, {}}, SlotCount{10, 1, {}},
                         SlotCount{11, 1, {}}}),
            "b0..b4");
  EXPECT_EQ(inscription({SlotCount{0, 1, {}}, SlotCount{1, 1, {}}}), "a0+a1");
  EXPECT_EQ(inscription({SlotCount{1, 2, {}}, SlotCount{16, 1, {}}}), "2\u00b7a1+c0");
}

TEST(DiagramLayout, UnknownPageIsALocatedErrorListingThePages) {
  core::Diagnostics diags;
  const auto spec = smallNet(true);
  const core::SourceLoc where{"<command line>", 1, 12};
  const auto view = findView(spec, "mian", diags, where);
  EXPECT_EQ(view.page, nullptr);
  ASSERT_EQ(diags.errorCount(), 1u);
  EXPECT_EQ(diags.all()[0].loc.line, 1);
  EXPECT_EQ(diags.all()[0].loc.column, 12);
  EXPECT_NE(diags.all()[0].message.find("no page or page type 'mian'; the pages are: main"), std::string::npos)
      << diags.all()[0].message;
  core::Diagnostics inner;
  EXPECT_EQ(findView(spec, "main/nothing", inner, where).page, nullptr);
  EXPECT_NE(inner.str().find("'main' has no instance 'nothing'"), std::string::npos) << inner.str();
}

}  // namespace
}  // namespace gdpn::diagram
