// Type propagation on the factory and on small nets: the node types each slot can hold, a
// conflict where two meet, scripts that read a field their slot's nodes lack, and the path of a
// slot's tokens.

#include <gtest/gtest.h>

#include "gdpn/ide/document.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/ide/token_types.h"
#include "ide/edit_support.h"
#include "support/spec_helpers.h"

namespace gdpn::ide {
namespace {

using gdpn::ide::testing::openFactory;

NodeTypeOf typesOf(const Document& doc) {
  return [&doc](const std::string& page, const std::string& path) -> const scene::NodeType* {
    const auto& scenes = doc.model().type_scenes;
    const auto it = scenes.find(page);
    const scene::Scene* s = it != scenes.end() ? it->second.get() : doc.scene();
    const auto* node = s != nullptr ? s->find(path) : nullptr;
    return node != nullptr ? &node->type() : nullptr;
  };
}

net::SlotId slot(const char* name) { return *net::parseSlot(name); }

TEST(TokenTypes, TheFactorysSlotsHoldOneTypeEachAndItsScriptsReadOnlyFieldsTheyHave) {
  auto doc = openFactory();
  ASSERT_TRUE(doc);
  const auto t = propagateTokenTypes(doc->model().net, typesOf(*doc));
  EXPECT_EQ(t.types.at({"factory/P1", slot("b0")}), (std::set<std::string>{"Joint"}));
  EXPECT_EQ(t.types.at({"factory/buffer", slot("d0")}), (std::set<std::string>{"Body"}));
  // the arm's joints travel P1 -> pickup -> P2 -> deliver -> ...: the transitions see them too
  EXPECT_EQ(t.types.at({"factory/pickup", slot("b0")}), (std::set<std::string>{"Joint"}));
  EXPECT_TRUE(t.conflicts.empty());
  for (const auto& u : t.unknown) ADD_FAILURE() << u.construct << " " << u.script << ": " << u.use << ": " << u.message;
}

TEST(TokenTypes, AFieldNoNodeOfTheSlotHasIsFlaggedOnItsLine) {
  auto doc = openFactory();
  ASSERT_TRUE(doc);
  auto& page = *findPage(doc->editableNet(), "factory");
  for (auto& t : page.transitions) {
    if (t.name == "pickup") t.pre_fire.code = "self.b0.target1 = -90\nself.b0.taget1 = 5\n";
  }
  const auto t = propagateTokenTypes(doc->model().net, typesOf(*doc));
  ASSERT_EQ(t.unknown.size(), 1u);
  EXPECT_EQ(t.unknown[0].construct, "factory/pickup");
  EXPECT_EQ(t.unknown[0].script, "pre_fire");
  EXPECT_EQ(t.unknown[0].line, 2);
  EXPECT_EQ(t.unknown[0].use, "self.b0.taget1");
  EXPECT_EQ(t.unknown[0].message, "a Joint has no field or method 'taget1'");
}

TEST(TokenTypes, TwoTypesMeetingInASlotAreAConflictNamingTheTransitionsThatBringThem) {
  // a box (a Body) and a joint both reach `mixed`'s b0
  auto doc = openFactory();
  ASSERT_TRUE(doc);
  net::PageSpec page;
  page.name = "mix";
  auto box = gdpn::testing::place("boxes");
  box.nodes.push_back({slot("b0"), {"boxes/b01/box"}, {}});
  auto joints = gdpn::testing::place("joints");
  joints.nodes.push_back({slot("b0"), {"arm/turn"}, {}});
  page.places = {box, joints, gdpn::testing::place("mixed")};
  page.transitions = {gdpn::testing::transition("take_box"), gdpn::testing::transition("take_joint")};
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"boxes", "take_box"}, {"take_box", "mixed"}, {"joints", "take_joint"}, {"take_joint", "mixed"}}) {
    net::ArcSpec a;
    a.from = from;
    a.to = to;
    a.weights = {{slot("b0"), 1, {}}};
    page.arcs.push_back(a);
  }
  doc->editableNet().pages.push_back(page);
  const auto t = propagateTokenTypes(doc->model().net, typesOf(*doc));
  ASSERT_EQ(t.conflicts.size(), 1u);
  EXPECT_EQ(t.conflicts[0].slot, (SlotKey{"mix/mixed", slot("b0")}));
  EXPECT_EQ(t.conflicts[0].types, (std::set<std::string>{"Body", "Joint"}));
  EXPECT_EQ(t.conflicts[0].from, (std::vector<std::string>{"mix/take_box", "mix/take_joint"}));
  // the path of `boxes`' b0 tokens
  EXPECT_EQ(tokenPath(page, "boxes", slot("b0")), (std::vector<std::string>{"boxes", "take_box", "mixed"}));
}

}  // namespace
}  // namespace gdpn::ide
