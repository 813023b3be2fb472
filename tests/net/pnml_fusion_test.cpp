// PNML's referencePlace and gdpn's fusion places: a reference that an arc on another page
// reaches a place through is a member of a fusion set with the place, and a fusion set is
// written back as its declaring member and referencePlaces to it.

#include <gtest/gtest.h>

#include "gdpn/net/compile.h"
#include "gdpn/net/net.h"
#include "gdpn/net/pnml.h"

namespace gdpn::net {
namespace {

/// A place `name` with `tokens`, a member of `set` ("" for none).
PlaceSpec place(std::string name, std::int64_t tokens = 0, std::string set = {}) {
  PlaceSpec p;
  p.name = std::move(name);
  if (tokens > 0) p.tokens.push_back({kDefaultSlot, tokens});
  p.fusion = std::move(set);
  return p;
}

TransitionSpec transition(std::string name) {
  TransitionSpec t;
  t.name = std::move(name);
  return t;
}

ArcSpec arc(std::string from, std::string to) {
  ArcSpec a;
  a.from = std::move(from);
  a.to = std::move(to);
  return a;
}

TEST(PnmlFusion, AReferencePlaceThatAnArcOfAnotherPageReachesIsAFusionMember) {
  core::Diagnostics diags;
  auto spec = parsePnml(R"(<pnml><net id="n" type="ptnet">
<page id="left"><place id="p"><initialMarking><text>1</text></initialMarking></place></page>
<page id="right"><transition id="t"/><referencePlace id="rp" ref="p"/>
  <arc id="a" source="rp" target="t"/></page>
<page id="alone"><place id="q"/></page>
</net></pnml>)",
                        "siblings.pnml", diags);
  ASSERT_TRUE(spec) << diags.str();
  EXPECT_EQ(diags.str(), "");
  // the pages stay apart: the reference is a place of its page, in one fusion set with p
  ASSERT_EQ(spec->pages.size(), 3u);
  ASSERT_EQ(spec->fusions.size(), 1u);
  EXPECT_EQ(spec->fusions[0].name, "p");
  EXPECT_EQ(spec->fusions[0].scope, FusionScope::Global);
  ASSERT_EQ(spec->pages[0].places.size(), 1u);
  EXPECT_EQ(spec->pages[0].places[0].fusion, "p");
  const PageSpec& right = spec->pages[1];
  EXPECT_EQ(right.name, "right");
  ASSERT_EQ(right.places.size(), 1u);
  EXPECT_EQ(right.places[0].name, "rp");
  EXPECT_EQ(right.places[0].fusion, "p");
  EXPECT_TRUE(right.places[0].tokens.empty());
  ASSERT_EQ(right.arcs.size(), 1u);
  EXPECT_EQ(right.arcs[0].from, "rp");

  auto net = compile(*spec, diags);
  ASSERT_TRUE(net) << diags.str();
  EXPECT_EQ(net->places().size(), 2u);
  EXPECT_EQ(net->findPlace("right/rp"), net->findPlace("left/p"));
  const auto slots = net->placeSlotsOf(*net->findPlace("right/rp"));
  ASSERT_NE(slots.begin(), slots.end());
  EXPECT_EQ(net->placeSlots()[*slots.begin()].initial, 1);
}

/// Two pages sharing the place `stock` (global), and a page type whose two trays are one per
/// instance.
NetSpec withFusion() {
  NetSpec spec;
  spec.fusions = {{"stock", FusionScope::Global, {}}, {"tray", FusionScope::Instance, {}}};
  PageSpec in;
  in.name = "inbound";
  in.places = {place("dock", 3), place("stock", 1, "stock")};
  in.places[1].capacity.push_back({kDefaultSlot, 2});
  in.places[1].position = EditorPos{2, 1};
  in.transitions = {transition("unload")};
  in.arcs = {arc("dock", "unload"), arc("unload", "stock")};
  PageSpec out;
  out.name = "outbound";
  out.places = {place("shelf", 0, "stock"), place("shipped")};
  out.places[0].position = EditorPos{0, 1};
  out.transitions = {transition("ship")};
  out.arcs = {arc("shelf", "ship"), arc("ship", "cell/in")};
  out.instances = {{"cell", "cell", {}, {}, {}}};
  PageSpec cell;
  cell.name = "cell";
  cell.references = {{"in", {}}};
  cell.places = {place("in"), place("tray_a", 0, "tray"), place("tray_b", 2, "tray")};
  cell.transitions = {transition("load"), transition("unload")};
  cell.arcs = {arc("in", "load"), arc("load", "tray_a"), arc("tray_b", "unload")};
  spec.pages = {in, out};
  spec.page_types = {cell};
  return spec;
}

TEST(PnmlFusion, AFusionSetIsWrittenAsReferencePlacesAndReadBackTheSame) {
  const NetSpec spec = withFusion();
  std::string why;
  const auto text = writePnml(spec, why, "fused");
  ASSERT_TRUE(text) << why;
  // other tools see the members as references to the declaring member
  EXPECT_NE(text->find("<referencePlace id=\"shelf\" ref=\"stock\">"), std::string::npos) << *text;
  EXPECT_NE(text->find("<referencePlace id=\"tray_a\" ref=\"tray_b\">"), std::string::npos) << *text;
  EXPECT_NE(text->find("<place id=\"stock\">"), std::string::npos) << *text;
  EXPECT_NE(text->find("<fusion name=\"tray\" scope=\"instance\"/>"), std::string::npos) << *text;

  core::Diagnostics diags;
  auto again = parsePnml(*text, "fused.pnml", diags);
  ASSERT_TRUE(again) << diags.str() << *text;
  EXPECT_EQ(diags.str(), "");
  EXPECT_TRUE(*again == spec) << *text;

  // and both compile to one net: one stock, one tray in the cell's one instance
  auto a = compile(spec, diags), b = compile(*again, diags);
  ASSERT_TRUE(a && b) << diags.str();
  EXPECT_EQ(a->places().size(), 5u);
  EXPECT_EQ(b->places().size(), 5u);
  for (PlaceId p{}; p < PlaceId(static_cast<std::uint32_t>(a->places().size())); ++p) {
    EXPECT_EQ(a->placeName(p), b->placeName(p));
  }
  EXPECT_EQ(b->findPlace("outbound/shelf"), b->findPlace("inbound/stock"));
  EXPECT_EQ(b->findPlace("outbound/cell/tray_a"), b->findPlace("outbound/cell/tray_b"));
  EXPECT_EQ(b->placeName(*b->findPlace("outbound/cell/tray_a")), "outbound/cell/tray_b");
}

}  // namespace
}  // namespace gdpn::net
