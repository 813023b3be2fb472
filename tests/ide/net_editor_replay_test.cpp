// The net view as an editor (issue 57): arcs are items (selected by a click, edited in the
// inspector, reversed, deleted), a rubber band selects several items that move and go as one
// undo step, tools add places and transitions with a click and arcs with a drag, and a page
// type is made from a selection.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

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

TEST_F(NetEditor, AnArcDraggedByItsPathBendsThereItsBendMovesAndADoubleClickTakesItAway) {
  const auto arcs = start_["net_view"]["arc_at"];
  const auto middle = arcs["main: a -> t"];
  const auto low = off(middle, 0, 50);
  // a drag from the arc's path: selected, and bent where it was let go, one step
  const std::string bend = dragLine(middle, low);
  auto r = run(bend);
  EXPECT_EQ(r["selection"]["name"], "main: a -> t");
  EXPECT_EQ(r["undo"]["depth"], 1);
  EXPECT_EQ(r["undo"]["label"], "edit arc a -> t");
  ASSERT_TRUE(r["net_view"]["handles"].contains("bend 0")) << r["net_view"].dump();
  const auto handle = r["net_view"]["handles"]["bend 0"];
  EXPECT_NEAR(handle[0].get<double>(), low[0].get<double>(), 8);
  EXPECT_NEAR(handle[1].get<double>(), low[1].get<double>(), 8);
  // the bend dragged further: another step; saved, the file keeps the route
  const auto lower = off(handle, 20, 20);
  r = run(bend + dragLine(handle, lower) + "- press: save\n");
  EXPECT_EQ(r["undo"]["depth"], 2);
  EXPECT_NEAR(r["net_view"]["handles"]["bend 0"][1].get<double>(), lower[1].get<double>(), 8);
  auto saved = gdpn::testing::fileBytes(model_);
  EXPECT_NE(saved.find("{from: a, to: t, via: [["), std::string::npos) << saved;
  EXPECT_EQ(gdpn::testing::runGdpn("check '" + model_ + "'").code, 0) << saved;
  // a double-click on the bend takes it away: the arc is straight again (from the file as it was)
  write("edit.gdpn.yaml", kModel);
  r = run(bend + "- click: " + at(handle) + "\n- click: " + at(handle) + "\n- press: save\n");
  EXPECT_FALSE(r["net_view"]["handles"].contains("bend 0")) << r["net_view"]["handles"].dump();
  saved = gdpn::testing::fileBytes(model_);
  EXPECT_NE(saved.find("      - a -> t\n"), std::string::npos) << saved;
  // a weighted arc's label is dragged by its handle
  write("edit.gdpn.yaml", kModel);
  const std::string weighted = "- click: " + at(arcs["main: c -> u"]) + "\n";
  r = run(weighted);
  const std::string weight = "- click: " + at(r["inspector"]["fields"]["weight a0"]) + "\n- type: '2'\n- key: enter\n";
  r = run(weighted + weight);
  ASSERT_TRUE(r["net_view"]["handles"].contains("label")) << r["net_view"].dump();
  r = run(weighted + weight + dragLine(r["net_view"]["handles"]["label"], off(r["net_view"]["handles"]["label"], 0, -30)) +
          "- press: save\n");
  saved = gdpn::testing::fileBytes(model_);
  EXPECT_NE(saved.find("label_at: ["), std::string::npos) << saved;
  EXPECT_EQ(r["undo"]["depth"], 2);
}

TEST_F(NetEditor, ARubberBandOfFiveItemsMovesAndIsDeletedAsOneUndoStep) {
  const auto places = start_["net_view"]["at"];
  // a band from the empty paper around the top row: a, t, b and the arcs a -> t, t -> b
  const auto from = off(places["main/a"], -30, -30), to = off(places["main/b"], 30, 30);
  const std::string band = dragLine(from, to);
  auto r = run(band);
  EXPECT_EQ(r["selection"]["count"], 5) << r["selection"].dump();  // 3 constructs and 2 arcs
  // a drag on one of them moves all three constructs, one step; the rows below stay
  const std::string move = dragLine(places["main/t"], off(places["main/t"], 0, 40));
  r = run(band + move);
  EXPECT_EQ(r["undo"]["depth"], 1);
  EXPECT_EQ(r["undo"]["label"], "move 3 items of main");
  for (const char* name : {"main/a", "main/t", "main/b"}) {
    EXPECT_NEAR(r["net_view"]["at"][name][1].get<double>(), places[name][1].get<double>() + 40, 10) << name;
  }
  EXPECT_EQ(r["net_view"]["at"]["main/c"], places["main/c"]);
  // Shift-click takes one away: the move leaves it
  r = run(band + "- hold: shift\n- click: " + at(places["main/b"]) + "\n- release: shift\n" + move);
  EXPECT_EQ(r["net_view"]["at"]["main/b"], places["main/b"]);
  EXPECT_EQ(r["undo"]["label"], "move 2 items of main");
  // Delete takes the band's five items away as one step; undo gives back the page as it was
  r = run(band + "- key: delete\n");
  EXPECT_EQ(r["net_view"]["places"], 3);
  EXPECT_EQ(r["net_view"]["transitions"], 2);
  EXPECT_EQ(r["net_view"]["arcs"], 3);
  EXPECT_EQ(r["undo"]["depth"], 1);
  EXPECT_EQ(r["undo"]["label"], "delete 5 items of main");
  r = run(band + move + "- key: delete\n- press: undo\n- press: undo\n- press: save\n");
  EXPECT_EQ(r["net_view"]["places"], 5);
  EXPECT_EQ(gdpn::testing::fileBytes(model_), kModel);
}

TEST_F(NetEditor, TheMenusDeleteTakesAPlaceWithItsArcsAndCutTakesOnlyWhatItCopies) {
  const auto places = start_["net_view"]["at"];
  // the right-click menu's Delete on t: its two arcs go with it, one step
  const std::string menu = "- drag: {from: " + at(places["main/t"]) + ", to: " + at(places["main/t"]) + ", button: right}\n";
  auto r = run(menu);
  ASSERT_TRUE(r["net_view"]["menu"].contains("Delete")) << r["net_view"]["menu"].dump();
  r = run(menu + "- click: " + at(r["net_view"]["menu"]["Delete"]) + "\n");
  EXPECT_EQ(r["net_view"]["transitions"], 2);
  EXPECT_EQ(r["net_view"]["arcs"], 3);
  EXPECT_EQ(r["undo"]["label"], "delete main/t");
  // an arc alone is not copied, so Cut leaves it
  r = run("- select: 'main: a -> t'\n- press: cut\n");
  EXPECT_EQ(r["net_view"]["arcs"], 5);
  EXPECT_EQ(r["undo"]["depth"], 0);
  // a click on one of a band's items selects it alone
  const auto band = dragLine(off(places["main/a"], -30, -30), off(places["main/u"], 20, 30));
  r = run(band + "- click: " + at(places["main/c"]) + "\n");
  EXPECT_EQ(r["selection"]["count"], 1);
  EXPECT_EQ(r["selection"]["name"], "main/c");
}

// a and t off the quarter grid, joined by an arc with two bends
constexpr const char* kOffGrid = R"Y(gdpn: 1
pages:
  main:
    places:
      a: {tokens: 1, at: [0.1, 0]}
      b: {at: [4, 0]}
    transitions:
      t: {at: [2, 0]}
    arcs:
      - {from: a, to: t, via: [[0.5, 1], [1.5, 2]]}
      - t -> b
)Y";

TEST_F(HeadlessIde, AReversedArcRunsItsRouteTheOtherWayAndAGroupKeepsItsOwnPositions) {
  const auto model = write("off.gdpn.yaml", kOffGrid);
  size_ = "1600x900";
  auto r = replayOn(model, "- select: 'main: a -> t'\n- press: reverse-arc\n- press: save\n");
  EXPECT_EQ(r["selection"]["name"], "main: t -> a");
  auto saved = gdpn::testing::fileBytes(model);
  EXPECT_NE(saved.find("{from: t, to: a, via: [[1.5, 2], [0.5, 1]]}"), std::string::npos) << saved;
  // a and t dragged together: each keeps its own position plus the step, and the bends go along
  write("off.gdpn.yaml", kOffGrid);  // the file as it was
  r = replayOn(model, "[]");
  const auto pa = r["net_view"]["at"]["main/a"], pt = r["net_view"]["at"]["main/t"];
  const double unit = pt[0].get<double>() - pa[0].get<double>();  // about 1.9 units' pixels
  const auto down = off(pt, 0, static_cast<int>(std::lround(unit / 1.9)));  // one unit down
  r = replayOn(model, "- select: main/a\n- hold: ctrl\n- click: " + at(pt) + "\n- release: ctrl\n" + dragLine(pt, down) +
                          "- press: save\n");
  EXPECT_EQ(r["selection"]["count"], 2);
  saved = gdpn::testing::fileBytes(model);
  EXPECT_NE(saved.find("a: {tokens: 1, at: [0.1, 1]}"), std::string::npos) << saved;
  EXPECT_NE(saved.find("t: {at: [2, 1]}"), std::string::npos) << saved;
  EXPECT_NE(saved.find("via: [[0.5, 2], [1.5, 3]]"), std::string::npos) << saved;
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


TEST_F(HeadlessIde, AnInstanceIsAddedFromThePapersMenuAndAnArcDrawnToItChoosesItsPort) {
  const auto model = write("line.gdpn.yaml", gdpn::testing::fileBytes(std::string(GDPN_SOURCE_DIR) +
                                                                      "/examples/basics/two_cells/two_cells.gdpn.yaml"));
  size_ = "1600x900";
  (void)replayOn(model, "- press: net-full\n");  // the settings keep the net view filling the window
  auto r = replayOn(model, "[]");
  const auto at0 = r["net_view"]["at"];
  // below load_a, on the paper: the menu's Instance here, then the page type
  const nlohmann::json paper = {at0["line/load_a"][0].get<int>(), at0["line/load_a"][1].get<int>() + 150};
  const std::string menu = "- drag: {from: " + at(paper) + ", to: " + at(paper) + ", button: right}\n";
  r = replayOn(model, menu);
  ASSERT_TRUE(r["net_view"]["menu"].contains("Instance here")) << r["net_view"]["menu"].dump();
  const std::string sub = menu + "- click: " + at(r["net_view"]["menu"]["Instance here"]) + "\n";
  r = replayOn(model, sub);
  ASSERT_TRUE(r["net_view"]["menu"].contains("cell")) << r["net_view"]["menu"].dump();
  const std::string add = sub + "- click: " + at(r["net_view"]["menu"]["cell"]) + "\n";
  r = replayOn(model, add);
  EXPECT_EQ(r["selection"]["name"], "line/cell1");
  EXPECT_EQ(r["undo"]["label"], "add instance line/cell1 of cell");

  ASSERT_TRUE(r["net_view"]["at"].contains("line/cell1"));
  // the Arc tool: a drag from load_a to it asks which port; enter
  const std::string arc = add + "- key: a\n" + dragLine(r["net_view"]["at"]["line/load_a"], r["net_view"]["at"]["line/cell1"]);
  r = replayOn(model, arc);
  ASSERT_TRUE(r["net_view"]["menu"].contains("enter")) << r["net_view"]["menu"].dump();
  r = replayOn(model, arc + "- click: " + at(r["net_view"]["menu"]["enter"]) + "\n");
  EXPECT_TRUE(r["net_view"]["arc_at"].contains("line: load_a -> cell1/enter")) << r["net_view"]["arc_at"].dump();
  EXPECT_EQ(r["undo"]["depth"], 2);
  // the inspector (the views as they were: the net view no longer fills the window) says its
  // type and ports
  r = replayOn(model, add + "- press: net-full\n");
  EXPECT_EQ(r["inspector"]["type"], "cell");
  EXPECT_EQ(r["inspector"]["ports"], "enter, exit");
  (void)replayOn(model, "- press: net-full\n");
  // its page, and back
  r = replayOn(model, add + "- press: open-instance\n");
  EXPECT_EQ(r["net_view"]["path"], "line/cell1");
  EXPECT_EQ(r["net_view"]["page"], "cell");
}

TEST_F(HeadlessIde, APageLargerThanTheViewGetsAnOverviewWhoseClickMovesTheView) {
  size_ = "1600x900";
  auto r = replay("[]");  // the factory
  EXPECT_EQ(r["net_view"]["overview"], false);  // fitted: the whole page is in view
  // zoomed in about the middle of the view: an overview in its corner
  const auto& p1 = r["net_view"]["at"]["factory/P1"];
  const std::string zoom = "- wheel: {at: " + at(p1) + ", clicks: 6}\n";
  r = replay(zoom);
  ASSERT_EQ(r["net_view"]["overview"], true) << r["net_view"].dump();
  const auto box = r["net_view"]["overview_box"];
  const auto before = r["net_view"]["at"]["factory/P1"];
  // a click at the overview's left edge brings the page's left end into view: the page moves right
  const nlohmann::json left = {box[0].get<int>() + 2, (box[1].get<int>() + box[3].get<int>()) / 2};
  r = replay(zoom + "- click: " + at(left) + "\n");
  EXPECT_GT(r["net_view"]["at"]["factory/P1"][0].get<int>(), before[0].get<int>()) << r["net_view"].dump();
  EXPECT_EQ(r["selection"]["kind"], "none");  // a click there selects nothing
}

/// The lines of `text` holding "N states, M edges" and the invariants' counts, as `gdpn analyze` prints them.
std::string analysisFigures(const std::string& text) {
  std::string out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const auto states = line.find(" states, ");
    if (states != std::string::npos) out += line.substr(line.rfind(' ', states - 1) + 1) + "\n";
    if (line.find("P-invariants (") != std::string::npos || line.find("T-invariants (") != std::string::npos) out += line + "\n";
  }
  return out;
}

TEST_F(HeadlessIde, APageTypeMadeFromARubberBandKeepsTheStateSpaceAndTheTraceUpToNames) {
  // two_cells with a preparation stage (tests/data/page_from_selection): arcs cross the band both
  // ways, node slots among them, a test arc and an inhibitor
  const auto before = write("before.gdpn.yaml", gdpn::testing::fileBytes(std::string(GDPN_SOURCE_DIR) +
                                                                         "/tests/data/page_from_selection/two_cells.gdpn.yaml"));
  const auto model = write("line.gdpn.yaml", gdpn::testing::fileBytes(before));
  size_ = "1600x900";
  // the net view fills the window (the settings keep it so for the replays that follow)
  auto r = replayOn(model, "- press: net-full\n");
  const auto places = r["net_view"]["at"];
  // a band around staged, prep, done, jam and power (fetch and trays stay outside)
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (const char* name : {"line/staged", "line/prep", "line/done", "line/jam", "line/power"}) {
    x0 = std::min(x0, places[name][0].get<double>());
    y0 = std::min(y0, places[name][1].get<double>());
    x1 = std::max(x1, places[name][0].get<double>());
    y1 = std::max(y1, places[name][1].get<double>());
  }
  const double gap = (places["line/staged"][0].get<double>() - places["line/fetch"][0].get<double>()) * 0.6;
  const nlohmann::json from = {static_cast<int>(x0 - gap), static_cast<int>(y0 - gap)};
  const nlohmann::json to = {static_cast<int>(x1 + gap), static_cast<int>(y1 + gap)};
  r = replayOn(model, dragLine(from, to) + "- press: page-type-from-selection\n- press: save\n");
  EXPECT_EQ(r["selection"]["kind"], "instance") << r["status"].dump();
  EXPECT_EQ(r["selection"]["name"], "line/subnet1");
  EXPECT_EQ(r["undo"]["depth"], 1);
  const auto made = gdpn::testing::fileBytes(model);
  EXPECT_NE(made.find("subnet1: {type: subnet1"), std::string::npos) << made;
  // the same state space and invariants
  const auto a = gdpn::testing::runGdpn("analyze '" + before + "'"), b = gdpn::testing::runGdpn("analyze '" + model + "'");
  ASSERT_EQ(a.code, 0) << a.out;
  ASSERT_EQ(b.code, 0) << b.out;
  EXPECT_FALSE(analysisFigures(a.out).empty()) << a.out;
  EXPECT_EQ(analysisFigures(a.out), analysisFigures(b.out)) << b.out;
  // the same trace, the names that moved renamed
  const auto ta = (dir_ / "a.jsonl").string(), tb = (dir_ / "b.jsonl").string();
  ASSERT_EQ(gdpn::testing::runGdpn("run '" + before + "' -q --trace '" + ta + "'").code, 0);
  ASSERT_EQ(gdpn::testing::runGdpn("run '" + model + "' -q --trace '" + tb + "'").code, 0);
  std::string expected = gdpn::testing::fileBytes(ta);
  for (const char* name : {"staged", "prep", "done", "jam", "power"}) {
    const std::string old = "line/" + std::string(name) + "\"", now = "line/subnet1/" + std::string(name) + "\"";
    for (auto at = expected.find(old); at != std::string::npos; at = expected.find(old, at + now.size())) expected.replace(at, old.size(), now);
  }
  EXPECT_EQ(gdpn::testing::fileBytes(tb), expected);
  // made and undone, saved: the file as it was, byte for byte
  write("line.gdpn.yaml", gdpn::testing::fileBytes(before));
  r = replayOn(model, dragLine(from, to) + "- press: page-type-from-selection\n- press: undo\n- press: save\n");
  EXPECT_EQ(gdpn::testing::fileBytes(model), gdpn::testing::fileBytes(before));
}

}  // namespace
}  // namespace gdpn::ide
