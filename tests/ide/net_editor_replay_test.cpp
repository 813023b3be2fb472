// The net view as an editor (issue 57): arcs are items (selected by a click, edited in the
// inspector, reversed, deleted), a rubber band selects several items that move and go as one
// undo step, tools add places and transitions with a click and arcs with a drag, and a page
// type is made from a selection.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "ide/headless_fixture.h"
#include "support/cli.h"
#include "support/scratch.h"

namespace gdpn::ide {
namespace {

// a small page with positions, a sensor place and its conditional arc
constexpr const char* kModel = R"Y(gdpn: 1
settings: {dt: 0.01, seed: 3}
scene:
  - Transform: {name: high, translation: [0, 0, 0.5], children: [{Region: {name: bin, size: [4, 4, 1], scope: world}}]}
pages:
  main:
    places:
      a: {tokens: 2, at: [0, 0]}
      b: {at: [4, 0]}
      c: {tokens: 1, at: [0, 3]}
      d: {at: [4, 3]}
      watching: {sensors: {c0: high/bin}, at: [0, 6]}
    transitions:
      t: {at: [2, 0]}
      u: {at: [2, 3]}
      see: {at: [2, 6]}
    arcs:
      - a -> t
      - t -> b
      - c -> u
      - u -> d
      - {from: watching, to: see, condition: 'len(c0.items) > 0'}
)Y";

/// "[X, Y]" of a report's point.
std::string at(const nlohmann::json& p) {
  return "[" + std::to_string(p[0].get<int>()) + ", " + std::to_string(p[1].get<int>()) + "]";
}

/// A point `dx`, `dy` pixels from a report's point.
nlohmann::json off(const nlohmann::json& p, int dx, int dy) { return {p[0].get<int>() + dx, p[1].get<int>() + dy}; }

/// The replay line of a left drag from `a` to `b`.
std::string dragLine(const nlohmann::json& a, const nlohmann::json& b) { return "- drag: {from: " + at(a) + ", to: " + at(b) + "}\n"; }


class NetEditor : public HeadlessIde {
 protected:
  void SetUp() override {
    HeadlessIde::SetUp();
    hidePalette();
    size_ = "1600x900";
    model_ = write("edit.gdpn.yaml", kModel);
    start_ = replayOn(model_, "[]");  // the IDE as it opens: the page and the inspector in view
    ASSERT_TRUE(start_.is_object());
  }
  nlohmann::json run(const std::string& actions) { return replayOn(model_, actions); }
  std::string model_;
  nlohmann::json start_;
};

TEST_F(NetEditor, AClickOnAnArcSelectsItAndTheInspectorSetsItsWeightKindAndCondition) {
  const auto arcs = start_["net_view"]["arc_at"];
  ASSERT_TRUE(arcs.contains("main: a -> t")) << arcs.dump();
  const std::string pick = "- click: " + at(arcs["main: a -> t"]) + "\n";
  auto r = run(pick);
  EXPECT_EQ(r["selection"]["kind"], "arc");
  EXPECT_EQ(r["selection"]["name"], "main: a -> t");
  EXPECT_EQ(r["inspector"]["kind"], "arc");
  EXPECT_EQ(r["inspector"]["arc_kind"], "normal");
  EXPECT_EQ(r["inspector"]["weight a0"], 1);
  const auto fields = r["inspector"]["fields"];
  // the weight: a click on its field, 3, Enter
  const std::string weight = "- click: " + at(fields["weight a0"]) + "\n- type: '3'\n- key: enter\n";
  r = run(pick + weight);
  EXPECT_EQ(r["inspector"]["weight a0"], 3) << r["inspector"].dump();
  EXPECT_EQ(r["undo"]["label"], "edit arc a -> t");
  // the kind: a test arc (the selection follows the arc's new name)
  const std::string kind = "- click: " + at(fields["kind"]) + "\n";
  r = run(pick + weight + kind);
  ASSERT_TRUE(r["inspector"]["fields"].contains("kind test")) << r["inspector"].dump();
  r = run(pick + weight + kind + "- click: " + at(r["inspector"]["fields"]["kind test"]) + "\n- press: save\n");
  EXPECT_EQ(r["selection"]["name"], "main: a -> t (test)");
  EXPECT_EQ(r["inspector"]["arc_kind"], "test");
  EXPECT_EQ(r["undo"]["depth"], 2);
  auto saved = gdpn::testing::fileBytes(model_);
  EXPECT_NE(saved.find("{from: a, to: t, kind: test, weight: 3}"), std::string::npos) << saved;
  // the condition of the sensor slot's arc
  const std::string see = "- click: " + at(arcs["main: watching -> see"]) + "\n";
  r = run(see);
  EXPECT_EQ(r["inspector"]["condition c0"], "len(c0.items) > 0");
  r = run(see + "- click: " + at(r["inspector"]["fields"]["condition c0"]) + "\n- key: ctrl+a\n- type: 'len(c0.items) > 1'\n- key: enter\n- press: save\n");
  EXPECT_EQ(r["inspector"]["condition c0"], "len(c0.items) > 1") << r["inspector"].dump();
  saved = gdpn::testing::fileBytes(model_);
  EXPECT_NE(saved.find("len(c0.items) > 1"), std::string::npos) << saved;
  EXPECT_EQ(gdpn::testing::runGdpn("check '" + model_ + "'").code, 0) << saved;
}

TEST_F(NetEditor, AnArcIsReversedAndDeletedEachAsOneUndoStep) {
  const auto arcs = start_["net_view"]["arc_at"];
  const std::string pick = "- click: " + at(arcs["main: t -> b"]) + "\n";
  auto r = run(pick + "- press: reverse-arc\n");
  EXPECT_EQ(r["selection"]["name"], "main: b -> t");
  EXPECT_TRUE(r["net_view"]["arc_at"].contains("main: b -> t")) << r["net_view"]["arc_at"].dump();
  EXPECT_FALSE(r["net_view"]["arc_at"].contains("main: t -> b"));
  EXPECT_EQ(r["undo"]["depth"], 1);
  // reversed twice, an arc is as it was (two steps)
  r = run("- select: 'main: c -> u'\n- press: reverse-arc\n- press: reverse-arc\n");
  EXPECT_EQ(r["selection"]["name"], "main: c -> u");
  EXPECT_EQ(r["undo"]["depth"], 2);
  // Delete takes the selected arc away; undo gives it back
  r = run(pick + "- key: delete\n");
  EXPECT_EQ(r["net_view"]["arcs"], 4);
  EXPECT_EQ(r["selection"]["kind"], "none");
  r = run(pick + "- key: delete\n- press: undo\n");
  EXPECT_EQ(r["net_view"]["arcs"], 5);
  EXPECT_EQ(r["selection"]["name"], "main: t -> b");
  // the right-click menu on an arc offers the same
  r = run("- drag: {from: " + at(arcs["main: t -> b"]) + ", to: " + at(arcs["main: t -> b"]) + ", button: right}\n");
  EXPECT_TRUE(r["net_view"]["menu"].contains("Reverse Arc")) << r["net_view"]["menu"].dump();
  EXPECT_TRUE(r["net_view"]["menu"].contains("Delete"));
}

TEST_F(NetEditor, ARubberBandOfFiveItemsMovesAndIsDeletedAsOneUndoStep) {
  const auto places = start_["net_view"]["at"];
  // a band around a, t, c, u and their arcs a -> t, c -> u (whole inside), from the empty paper
  const auto from = off(places["main/a"], -30, -30), to = off(places["main/u"], 20, 30);
  const std::string band = dragLine(from, to);
  auto r = run(band);
  EXPECT_EQ(r["selection"]["count"], 6) << r["selection"].dump();  // 4 constructs and 2 arcs
  // a drag on one of them moves all four constructs, one step
  const std::string move = dragLine(places["main/t"], off(places["main/t"], 0, 40));
  r = run(band + move);
  EXPECT_EQ(r["undo"]["depth"], 1);
  EXPECT_EQ(r["undo"]["label"], "move 4 items of main");
  for (const char* name : {"main/a", "main/t", "main/c", "main/u"}) {
    EXPECT_NEAR(r["net_view"]["at"][name][1].get<double>(), places[name][1].get<double>() + 40, 10) << name;
  }
  EXPECT_EQ(r["net_view"]["at"]["main/b"], places["main/b"]);
  // Shift-click takes one away: the move leaves it
  r = run(band + "- hold: shift\n- click: " + at(places["main/c"]) + "\n- release: shift\n" + move);
  EXPECT_EQ(r["net_view"]["at"]["main/c"], places["main/c"]);
  EXPECT_EQ(r["undo"]["label"], "move 3 items of main");
  // Delete takes the band's items away as one step; undo gives back the page as it was
  r = run(band + "- key: delete\n");
  EXPECT_EQ(r["net_view"]["places"], 3);
  EXPECT_EQ(r["net_view"]["transitions"], 1);
  EXPECT_EQ(r["undo"]["depth"], 1);
  r = run(band + move + "- key: delete\n- press: undo\n- press: undo\n- press: save\n");
  EXPECT_EQ(r["net_view"]["places"], 5);
  EXPECT_EQ(gdpn::testing::fileBytes(model_), kModel);
}

TEST_F(NetEditor, ToolsAddPlacesAndTransitionsWithAClickAndArcsWithADrag) {
  const auto places = start_["net_view"]["at"];
  const auto tools = start_["net_view"]["tools"];
  ASSERT_TRUE(tools.contains("Place")) << start_["net_view"].dump();
  const auto paper = off(places["main/b"], 0, 60);
  // P, a click: a place there; T, a click: a transition; A, a drag from the new transition to b
  const auto paper2 = off(places["main/b"], 60, 60);
  auto r = run("- key: p\n- click: " + at(paper) + "\n- key: t\n- click: " + at(paper2) + "\n");
  EXPECT_EQ(r["net_view"]["tool"], "transition");
  ASSERT_TRUE(r["net_view"]["at"].contains("main/P1")) << r["net_view"]["at"].dump();
  ASSERT_TRUE(r["net_view"]["at"].contains("main/T1"));
  EXPECT_NEAR(r["net_view"]["at"]["main/P1"][1].get<double>(), paper[1].get<double>(), 12);
  const std::string adds = "- key: p\n- click: " + at(paper) + "\n- key: t\n- click: " + at(paper2) + "\n";
  r = run(adds + "- key: a\n" + dragLine(r["net_view"]["at"]["main/T1"], r["net_view"]["at"]["main/b"]) + "- key: escape\n");
  EXPECT_TRUE(r["net_view"]["arc_at"].contains("main: T1 -> b")) << r["net_view"]["arc_at"].dump();
  EXPECT_EQ(r["net_view"]["tool"], "select");
  EXPECT_EQ(r["undo"]["depth"], 3);
  // the strip's button does what the key does
  r = run("- click: " + at(tools["Arc"]) + "\n");
  EXPECT_EQ(r["net_view"]["tool"], "arc");
}

TEST_F(NetEditor, SelectAllCopyAndPasteKeepTheArcsAndSelectWhatCame) {
  auto r = run("- press: select-all\n");
  EXPECT_EQ(r["selection"]["count"], 13);  // 5 places, 3 transitions, 5 arcs
  r = run("- press: select-all\n- press: copy\n- press: paste\n");
  EXPECT_EQ(r["net_view"]["places"], 10);
  EXPECT_EQ(r["net_view"]["arcs"], 10);
  EXPECT_EQ(r["selection"]["count"], 13);
  EXPECT_EQ(r["undo"]["depth"], 1);
}

TEST_F(NetEditor, AlignAndDistributePlaceTheSelectionInOneStep) {
  auto r = run("- select: main/b\n- hold: ctrl\n- click: " + at(start_["net_view"]["at"]["main/d"]) +
               "\n- click: " + at(start_["net_view"]["at"]["main/see"]) + "\n- release: ctrl\n- press: align-left\n");
  EXPECT_EQ(r["selection"]["count"], 3) << r["selection"].dump();
  const auto now = r["net_view"]["at"];
  EXPECT_EQ(now["main/b"][0], now["main/see"][0]);
  EXPECT_EQ(now["main/d"][0], now["main/see"][0]);
  EXPECT_EQ(r["undo"]["depth"], 1);
}

}  // namespace
}  // namespace gdpn::ide
