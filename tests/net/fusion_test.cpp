// Fusion places (semantics.md, "Fusion places"): the members of a fusion set are one place of
// the compiled net, one for the net (global) or one per instance of their page (instance).

#include <gtest/gtest.h>

#include "gdpn/net/analysis.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/kernel.h"
#include "support/spec_helpers.h"

namespace gdpn::net {
namespace {

using namespace gdpn::testing;

/// `p` as a member of fusion set `set`.
PlaceSpec member(PlaceSpec p, std::string set) {
  p.fusion = std::move(set);
  return p;
}

/// Two pages sharing the place `stock`: `inbound` fills it (and declares it), `outbound` empties it.
NetSpec twoPages() {
  NetSpec spec;
  spec.fusions = {{"stock", FusionScope::Global, {}}};
  PageSpec in;
  in.name = "inbound";
  in.places = {place("dock", 3), member(place("stock", 1, 2), "stock")};
  in.transitions = {transition("unload", 1.0)};
  in.arcs = {arc("dock", "unload"), arc("unload", "stock")};
  PageSpec out;
  out.name = "outbound";
  out.places = {member(place("shelf"), "stock"), place("shipped")};
  out.transitions = {transition("ship", 2.0)};
  out.arcs = {arc("shelf", "ship"), arc("ship", "shipped")};
  spec.pages = {in, out};
  return spec;
}

/// The same net written with the two members merged by hand, on one page.
NetSpec mergedByHand() {
  NetSpec spec;
  PageSpec main;
  main.name = "main";
  main.places = {place("dock", 3), place("stock", 1, 2), place("shipped")};
  main.transitions = {transition("unload", 1.0), transition("ship", 2.0)};
  main.arcs = {arc("dock", "unload"), arc("unload", "stock"), arc("stock", "ship"), arc("ship", "shipped")};
  spec.pages = {main};
  return spec;
}

TEST(Fusion, AGlobalSetAcrossTwoPagesIsOnePlaceThatEitherNameFinds) {
  core::Diagnostics diags;
  auto net = compile(twoPages(), diags);
  ASSERT_TRUE(net) << diags.str();
  EXPECT_EQ(diags.str(), "");
  EXPECT_EQ(net->places().size(), 3u);
  const auto stock = net->findPlace("inbound/stock");
  ASSERT_TRUE(stock);
  EXPECT_EQ(net->findPlace("outbound/shelf"), stock);
  EXPECT_EQ(net->placeName(*stock), "inbound/stock");  // the declaring member's name
  EXPECT_EQ(net->findPlace("outbound/shipped"), PlaceId{2u});

  // a token put on one page's member is taken by the other page's transition
  Kernel k(net, {1.0, 1});
  k.start();
  std::int64_t shipped = 0;
  for (int i = 0; i < 20; ++i) {
    k.step();
    EXPECT_EQ(k.placeTokens(*net->findPlace("outbound/shelf")), k.placeTokens(*stock));
    EXPECT_LE(k.placeTokens(*stock), 2);
    shipped = k.placeTokens(*net->findPlace("outbound/shipped"));
  }
  EXPECT_EQ(shipped, 4);  // the one on the shelf and the three of the dock
}

TEST(Fusion, TheStateSpaceIsThatOfTheNetWithThePlacesMergedByHand) {
  core::Diagnostics diags;
  auto fused = compile(twoPages(), diags);
  auto merged = compile(mergedByHand(), diags);
  ASSERT_TRUE(fused && merged) << diags.str();
  const auto a = explore(*fused);
  const auto b = explore(*merged);
  EXPECT_EQ(a.states, b.states);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_GT(a.states, 4u);
}

/// A cell whose two tray places are one (`tray`, of scope `scope`); two instances of it on `line`.
NetSpec twoCells(FusionScope scope) {
  NetSpec spec;
  spec.fusions = {{"tray", scope, {}}};
  PageSpec cell;
  cell.name = "cell";
  cell.references = {{"in", {}}, {"out", {}}};
  cell.places = {place("in"), member(place("tray_a"), "tray"), member(place("tray_b"), "tray"), place("out")};
  cell.transitions = {transition("load"), transition("unload")};
  cell.arcs = {arc("in", "load"), arc("load", "tray_a"), arc("tray_b", "unload"), arc("unload", "out")};
  PageSpec line;
  line.name = "line";
  line.places = {place("src", 2)};
  line.instances = {{"A", "cell", {}, {}, {}}, {"B", "cell", {}, {}, {}}};
  line.transitions = {transition("feed")};
  line.arcs = {arc("src", "feed"), arc("feed", "A/in")};
  spec.page_types = {cell};
  spec.pages = {line};
  return spec;
}

TEST(Fusion, AnInstanceSetInAPageTypeInstancedTwiceGivesTwoPlaces) {
  core::Diagnostics diags;
  auto net = compile(twoCells(FusionScope::Instance), diags);
  ASSERT_TRUE(net) << diags.str();
  EXPECT_EQ(net->places().size(), 1u + 2 * 3u);
  const auto a = net->findPlace("line/A/tray_a"), b = net->findPlace("line/B/tray_a");
  ASSERT_TRUE(a && b);
  EXPECT_NE(*a, *b);
  EXPECT_EQ(net->findPlace("line/A/tray_b"), a);
  EXPECT_EQ(net->findPlace("line/B/tray_b"), b);
  EXPECT_EQ(net->placeName(*b), "line/B/tray_a");
  // the other places of each instance keep their own names
  EXPECT_EQ(net->placeName(*net->findPlace("line/B/out")), "line/B/out");

  // tokens fed to A go through A's tray only
  Kernel k(net, {1.0, 1});
  k.start();
  for (int i = 0; i < 10; ++i) k.step();
  EXPECT_EQ(k.placeTokens(*net->findPlace("line/A/out")), 2);
  EXPECT_EQ(k.placeTokens(*net->findPlace("line/B/out")), 0);
}

TEST(Fusion, AGlobalSetInAPageTypeInstancedTwiceIsOnePlace) {
  core::Diagnostics diags;
  auto net = compile(twoCells(FusionScope::Global), diags);
  ASSERT_TRUE(net) << diags.str();
  EXPECT_EQ(net->places().size(), 1u + 2 * 2u + 1u);
  const auto tray = net->findPlace("line/A/tray_a");
  ASSERT_TRUE(tray);
  for (const char* name : {"line/A/tray_b", "line/B/tray_a", "line/B/tray_b"}) EXPECT_EQ(net->findPlace(name), tray) << name;
  // A's load fills the one tray, which A's and B's unload empty (A's first: declared first)
  Kernel k(net, {1.0, 1});
  k.start();
  for (int i = 0; i < 10; ++i) k.step();
  EXPECT_EQ(k.placeTokens(*net->findPlace("line/A/out")) + k.placeTokens(*net->findPlace("line/B/out")), 2);
  EXPECT_EQ(k.placeTokens(*tray), 0);
}

TEST(Fusion, AMemberOfAnUndeclaredSetIsLocated) {
  NetSpec spec = twoPages();
  spec.pages[1].places[0].fusion = "stok";
  spec.pages[1].places[0].fusion_loc = {"m.gdpn.yaml", 9, 16};
  core::Diagnostics diags;
  EXPECT_FALSE(compile(spec, diags));
  EXPECT_EQ(diags.str(), "m.gdpn.yaml:9:16: error: place 'outbound/shelf' is a member of fusion set 'stok', which the "
                         "model does not declare (under 'fusion') (did you mean 'stock'?)\n");
}

TEST(Fusion, TwoMembersThatDeclareDifferentlyAreLocated) {
  NetSpec spec = twoPages();
  spec.pages[0].places[1].loc = {"m.gdpn.yaml", 6, 7};
  spec.pages[1].places[0] = member(place("shelf", 2), "stock");
  spec.pages[1].places[0].loc = {"m.gdpn.yaml", 14, 7};
  core::Diagnostics diags;
  EXPECT_FALSE(compile(spec, diags));
  EXPECT_EQ(diags.str(), "m.gdpn.yaml:14:7: error: place 'outbound/shelf' and place 'inbound/stock' of fusion set "
                         "'stock' declare its tokens, capacity, slot kinds, sensors or scripts differently; one member "
                         "declares them and the others name the set alone\n"
                         "m.gdpn.yaml:6:7: note: 'inbound/stock' declares them here\n");
  // the same declarations twice are one declaration
  spec.pages[1].places[0] = member(place("shelf", 1, 2), "stock");
  core::Diagnostics again;
  EXPECT_TRUE(compile(spec, again)) << again.str();
}

TEST(Fusion, AnInstanceSetWithMembersOnTwoPagesIsLocated) {
  NetSpec spec = twoPages();
  spec.fusions[0].scope = FusionScope::Instance;
  spec.pages[0].places[1].fusion_loc = {"m.gdpn.yaml", 6, 22};
  spec.pages[1].places[0].fusion_loc = {"m.gdpn.yaml", 14, 22};
  core::Diagnostics diags;
  EXPECT_FALSE(compile(spec, diags));
  EXPECT_EQ(diags.str(), "m.gdpn.yaml:14:22: error: fusion set 'stock' is one place per instance, so its members lie on "
                         "one page or page type; 'outbound/shelf' lies on 'outbound' but 'inbound/stock' on 'inbound' "
                         "(make the set global to join places of different pages)\n"
                         "m.gdpn.yaml:6:22: note: the set's first member is here\n");
}

TEST(Fusion, TwoArcsToOneFusedPlaceThroughTwoMembersAreLocated) {
  NetSpec spec = twoPages();
  // unload puts a token on the stock and one on a second member on its own page
  spec.pages[0].places.push_back(member(place("stock2"), "stock"));
  spec.pages[0].arcs.push_back(arc("unload", "stock2"));
  spec.pages[0].arcs[1].loc = {"m.gdpn.yaml", 10, 9};
  spec.pages[0].arcs[2].loc = {"m.gdpn.yaml", 11, 9};
  core::Diagnostics diags;
  EXPECT_FALSE(compile(spec, diags));
  EXPECT_EQ(diags.str(), "m.gdpn.yaml:11:9: error: a second arc between transition 'inbound/unload' and fusion place "
                         "'inbound/stock' on slot a0 (through another member of its set): give one arc the sum of "
                         "their weights\n"
                         "m.gdpn.yaml:10:9: note: the first arc is here\n");
}

TEST(Fusion, ASetWithoutMembersIsWarnedOf) {
  NetSpec spec = mergedByHand();
  spec.fusions = {{"spare", FusionScope::Global, {"m.gdpn.yaml", 3, 3}}};
  core::Diagnostics diags;
  EXPECT_TRUE(compile(spec, diags));
  EXPECT_EQ(diags.str(), "m.gdpn.yaml:3:3: warning: fusion set 'spare' has no members (a place joins it with 'fusion: "
                         "spare')\n");
}

}  // namespace
}  // namespace gdpn::net
