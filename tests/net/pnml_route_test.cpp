// An arc's route in PNML: its bend points are the `<position>`s of its `<graphics>` (the
// standard's), its label's offset the `<offset>` of its inscription's; a model -> PNML -> model
// round trip keeps both, and other tools' bend points are read.

#include <filesystem>

#include <gtest/gtest.h>

#include "gdpn/model/model.h"
#include "gdpn/net/pnml.h"

namespace gdpn::net {
namespace {

TEST(PnmlRoute, BendPointsAndTheLabelOffsetMakeTheRoundTrip) {
  core::Diagnostics diags;
  auto model = model::loadModel(
      (std::filesystem::path(GDPN_SOURCE_DIR) / "tests/data/good/bent_arcs.gdpn.yaml").string(), diags);
  ASSERT_TRUE(model) << diags.str();
  std::string why;
  const auto text = writePnml(model->net, why, "bent");
  ASSERT_TRUE(text) << why;
  // busy -> stop: weight 2, one bend; stop -> idle: weight 1, a bend and a label (an inscription of 1 holds it)
  EXPECT_NE(text->find("<arc id=\"arc2\" source=\"busy\" target=\"stop\"><graphics><position x=\"2\" y=\"1.5\"/>"
                       "</graphics><inscription><text>2</text></inscription></arc>"),
            std::string::npos)
      << *text;
  EXPECT_NE(text->find("<arc id=\"arc3\" source=\"stop\" target=\"idle\"><graphics><position x=\"0\" y=\"1.5\"/>"
                       "</graphics><inscription><text>1</text><graphics><offset x=\"0.25\" y=\"0.25\"/></graphics>"
                       "</inscription></arc>"),
            std::string::npos)
      << *text;
  auto back = parsePnml(*text, "bent.pnml", diags);
  ASSERT_TRUE(back) << diags.str();
  EXPECT_EQ(diags.str(), "");
  ASSERT_EQ(back->pages.size(), 1u);
  const auto& arcs = back->pages[0].arcs;
  ASSERT_EQ(arcs.size(), 4u);
  EXPECT_EQ(arcs[2].via, (std::vector<EditorPos>{{2, 1.5}}));
  EXPECT_EQ(arcs[1].label_at, (EditorPos{0, -0.25}));
  EXPECT_EQ(arcs[3].label_at, (EditorPos{0.25, 0.25}));
  EXPECT_TRUE(arcs[3].weights.empty());
  EXPECT_TRUE(*back == model->net) << *text;
  EXPECT_EQ(writePnml(*back, why, "bent"), *text);
}

TEST(PnmlRoute, OtherToolsBendPointsAreReadInOrderAndABadOneIsLeftOut) {
  core::Diagnostics diags;
  auto spec = parsePnml(R"(<pnml><net id="n" type="ptnet"><page id="g">
<place id="p"><graphics><position x="0" y="0"/></graphics></place>
<transition id="t"><graphics><position x="4" y="0"/></graphics></transition>
<arc id="a" source="p" target="t"><graphics><position x="1" y="2"/><position x="x" y="2"/>
  <position x="3" y="2.5"/></graphics><inscription><text>2</text><graphics><offset x="-1" y="0.5"/></graphics></inscription></arc>
</page></net></pnml>)",
                        "other.pnml", diags);
  ASSERT_TRUE(spec) << diags.str();
  EXPECT_EQ(diags.str(), "other.pnml:4:68: warning: a bend point needs finite numbers x and y; this one is left out\n");
  const auto& a = spec->pages.at(0).arcs.at(0);
  EXPECT_EQ(a.via, (std::vector<EditorPos>{{1, 2}, {3, 2.5}}));
  EXPECT_EQ(a.label_at, (EditorPos{-1, 0.5}));
  EXPECT_EQ(a.weights.size(), 1u);
}

}  // namespace
}  // namespace gdpn::net
