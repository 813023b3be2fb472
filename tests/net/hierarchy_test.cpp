// Hierarchy (semantics §9): page types with references, instances with links, qualified names.

#include <gtest/gtest.h>

#include "gdpn/net/compile.h"
#include "gdpn/net/kernel.h"
#include "support/spec_helpers.h"

namespace gdpn::net {
namespace {

using namespace gdpn::testing;

/// A cell: takes a part from `enter`, works `work_s` seconds with its one machine, puts it on `exit`.
PageSpec cellType() {
  PageSpec cell;
  cell.name = "cell";
  cell.references = {{"enter", {}}, {"exit", {}}};
  cell.places = {place("enter"), place("machine", 1), place("exit")};
  cell.transitions = {transition("work", 2.0)};
  cell.arcs = {arc("enter", "work"), arc("machine", "work"), arc("work", "exit"), arc("work", "machine")};
  return cell;
}

std::int64_t marking(const Kernel& k, const std::string& place) {
  const auto p = k.net().findPlace(place);
  if (!p) {
    ADD_FAILURE() << "no place " << place;
    return -1;
  }
  return k.placeTokens(*p);
}

TEST(Hierarchy, TwoInstancesKeepIndependentMarkings) {
  NetSpec spec;
  spec.page_types = {cellType()};
  PageSpec line;
  line.name = "line";
  line.places = {place("parts_a", 3), place("parts_b", 1)};
  line.instances = {{"cellA", "cell", {}, {}, {}}, {"cellB", "cell", {}, {}, {}}};
  line.transitions = {transition("feed_a"), transition("feed_b")};
  line.arcs = {arc("parts_a", "feed_a"), arc("feed_a", "cellA/enter"), arc("parts_b", "feed_b"),
               arc("feed_b", "cellB/enter")};
  spec.pages = {line};
  core::Diagnostics diags;
  auto net = compile(spec, diags);
  ASSERT_TRUE(net) << diags.str();

  // qualified names, one copy of every construct per instance
  EXPECT_TRUE(net->findPlace("line/cellA/machine"));
  EXPECT_TRUE(net->findPlace("line/cellB/machine"));
  EXPECT_TRUE(net->findTransition("line/cellA/work"));
  EXPECT_EQ(net->places().size(), 2u + 2 * 3u);
  EXPECT_EQ(net->transitions().size(), 2u + 2 * 1u);

  Kernel k(net, {1.0, 1});
  k.start();
  for (int i = 0; i < 20; ++i) k.step();
  // cell A worked three parts, cell B one; each machine token stayed home
  EXPECT_EQ(marking(k, "line/cellA/exit"), 3);
  EXPECT_EQ(marking(k, "line/cellB/exit"), 1);
  EXPECT_EQ(marking(k, "line/cellA/machine"), 1);
  EXPECT_EQ(marking(k, "line/cellB/machine"), 1);
}

TEST(Hierarchy, NestedInstancesQualifyEveryLevel) {
  NetSpec spec;
  PageSpec pair;
  pair.name = "pair";
  pair.references = {{"in", {}}, {"out", {}}};
  pair.places = {place("in"), place("mid"), place("out")};
  pair.instances = {{"first", "cell", {}, {}, {}}, {"second", "cell", {}, {}, {}}};
  pair.transitions = {transition("t_in"), transition("t_mid"), transition("t_out")};
  pair.arcs = {arc("in", "t_in"), arc("t_in", "first/enter"), arc("first/exit", "t_mid"),
               arc("t_mid", "second/enter"), arc("second/exit", "t_out"), arc("t_out", "out")};
  spec.page_types = {cellType(), pair};
  PageSpec top;
  top.name = "top";
  top.places = {place("src", 2), place("dst")};
  top.instances = {{"p", "pair", {}, {}, {}}};
  top.transitions = {transition("go"), transition("back")};
  top.arcs = {arc("src", "go"), arc("go", "p/in"), arc("p/out", "back"), arc("back", "dst")};
  spec.pages = {top};
  core::Diagnostics diags;
  auto net = compile(spec, diags);
  ASSERT_TRUE(net) << diags.str();
  EXPECT_TRUE(net->findPlace("top/p/second/machine"));
  Kernel k(net, {1.0, 1});
  k.start();
  for (int i = 0; i < 40 && !k.dead(); ++i) k.step();
  EXPECT_EQ(marking(k, "top/dst"), 2);
  EXPECT_TRUE(k.dead());
}

TEST(Hierarchy, APageTypeThatContainsItselfIsAnError) {
  NetSpec spec;
  PageSpec a;
  a.name = "a";
  a.instances = {{"inner", "b", {"m.gdpn.yaml", 3, 5}, {}, {}}};
  PageSpec b;
  b.name = "b";
  b.instances = {{"back", "a", {"m.gdpn.yaml", 7, 5}, {}, {}}};
  spec.page_types = {a, b};
  PageSpec top;
  top.name = "top";
  top.instances = {{"x", "a", {}, {}, {}}};
  spec.pages = {top};
  core::Diagnostics diags;
  EXPECT_FALSE(compile(spec, diags));
  EXPECT_NE(diags.str().find("m.gdpn.yaml:7:5: error: page type 'a' contains itself (a -> b -> a)"),
            std::string::npos)
      << diags.str();
}

TEST(Hierarchy, NodeTokensInAPageTypeAreQualifiedByTheInstance) {
  NetSpec spec;
  PageSpec station;
  station.name = "station";
  PlaceSpec devices = place("devices");
  devices.nodes.push_back({24, {"rod", "door"}, {}});
  station.places = {devices};
  spec.page_types = {station};
  PageSpec line;
  line.name = "line";
  line.instances = {{"stationA", "station", {}, {}, {}}, {"stationB", "station", {}, {}, {}}};
  spec.pages = {line};
  core::Diagnostics diags;
  auto net = compile(spec, diags);
  ASSERT_TRUE(net) << diags.str();
  std::vector<std::string> names(net->nodeNames().begin(), net->nodeNames().end());
  EXPECT_EQ(names, (std::vector<std::string>{"stationA/rod", "stationA/door", "stationB/rod", "stationB/door"}));
}

TEST(Hierarchy, ParallelArcsInAPageTypeAreReportedOnceAndArcsToALinkCount) {
  NetSpec spec;
  PageSpec cell = cellType();
  cell.arcs.push_back(arc("enter", "work"));  // a second arc enter -> work
  spec.page_types = {cell};
  PageSpec line;
  line.name = "line";
  line.places = {place("parts", 2)};
  line.instances = {{"cellA", "cell", {}, {}, {}}, {"cellB", "cell", {}, {}, {}}};
  line.transitions = {transition("feed")};
  // feed puts a part into both cells (not parallel: two places), and twice into cell A (parallel)
  line.arcs = {arc("parts", "feed"), arc("feed", "cellA/enter"), arc("feed", "cellB/enter"), arc("feed", "cellA/enter")};
  spec.pages = {line};
  core::Diagnostics diags;
  EXPECT_FALSE(compile(spec, diags));
  const std::string all = diags.str();
  const std::string in_type = "error: a second arc from 'cell/enter' to 'cell/work' on slot a0";
  const std::string to_link = "error: a second arc from 'line/feed' to 'line/cellA/enter' on slot a0";
  EXPECT_NE(all.find(in_type), std::string::npos) << all;
  EXPECT_EQ(all.find(in_type), all.rfind(in_type)) << "once for the type, not per instance\n" << all;
  EXPECT_NE(all.find(to_link), std::string::npos) << all;
  EXPECT_EQ(all.find("cellB/enter' on slot"), std::string::npos) << all;
}

TEST(Hierarchy, LinksReachTheReferencedPlaceOfEachInstance) {
  NetSpec spec;
  PageSpec cell = cellType();
  cell.references = {{"exit", {}}, {"enter", {}}};  // references in another order than the places
  spec.page_types = {cell};
  PageSpec line;
  line.name = "line";
  line.places = {place("parts", 1), place("done")};
  line.instances = {{"a", "cell", {}, {}, {}}, {"b", "cell", {}, {}, {}}};
  line.transitions = {transition("feed"), transition("move"), transition("take")};
  line.arcs = {arc("parts", "feed"), arc("feed", "a/enter"), arc("a/exit", "move"), arc("move", "b/enter"),
               arc("b/exit", "take"), arc("take", "done")};
  spec.pages = {line};
  core::Diagnostics diags;
  auto net = compile(spec, diags);
  ASSERT_TRUE(net) << diags.str();
  Kernel k(net, {1.0, 1});
  k.start();
  for (int i = 0; i < 12; ++i) k.step();
  EXPECT_EQ(marking(k, "line/done"), 1);  // through a's cell and then b's
  EXPECT_EQ(marking(k, "line/a/exit"), 0);
  EXPECT_EQ(marking(k, "line/b/machine"), 1);
}

}  // namespace
}  // namespace gdpn::net
