// The headless IDE (EGL surfaceless) on the factory: replayed actions, asserting on what the
// views report and on the picture; replay mistakes located; splitters remembered.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <nlohmann/json.hpp>

#include "gdpn/platform/png.h"
#include "ide/headless_fixture.h"
#include "ide/ide_model.h"
#include "support/cli.h"
#include "support/golden.h"
#include "support/scratch.h"
#include "support/temp_files.h"

namespace gdpn::ide {
namespace {

using gdpn::testing::runShell;

TEST_F(HeadlessIde, OpensTheFactoryInEditModeWithEveryView) {
  const auto r = replay("[]");
  EXPECT_EQ(r["run"]["mode"], "edit");
  EXPECT_EQ(r["run"]["steps"], 0);
  EXPECT_EQ(r["net_view"]["page"], "factory");
  EXPECT_EQ(r["net_view"]["places"], 13);
  EXPECT_EQ(r["net_view"]["transitions"], 12);
  EXPECT_GE(r["net_view"]["drawn"].get<int>(), 13 + 12 + 2);  // and the arcs
  EXPECT_EQ(r["net_view"]["tokens"]["factory/buffer"], 23);  // the initial marking: boxes b01 to b23
  EXPECT_GT(r["world"]["triangles"].get<int>(), 100);
  EXPECT_GT(r["tree"]["nodes_shown"].get<int>(), 10);
  EXPECT_EQ(r["toolbar"]["transitions"].get<int>(), 38);  // 12 on the page, 13 in each station
  EXPECT_TRUE(r["diagnostics"].empty());
}

TEST_F(HeadlessIde, StepAdvancesOneStep) {
  const auto r = replay("- press: step\n");
  EXPECT_EQ(r["run"]["steps"], 1);
  EXPECT_EQ(r["run"]["mode"], "paused");
  EXPECT_EQ(r["status"]["steps"], 1);
}

TEST_F(HeadlessIde, RunForTenSecondsShowsTheArmAtWork) {
  const auto r = replay("- run: 10\n- select: arm/turn\n");
  EXPECT_DOUBLE_EQ(r["run"]["time"].get<double>(), 10.0);
  EXPECT_EQ(r["selection"]["kind"], "node");
  EXPECT_EQ(r["tree"]["selected"], "arm/turn");
  EXPECT_EQ(r["inspector"]["type"], "Joint");
  EXPECT_EQ(r["world"]["highlighted"], true);
  // the joint is a node token: bold in the tree
  const auto& bold = r["tree"]["bold"];
  EXPECT_NE(std::find(bold.begin(), bold.end(), "arm/turn"), bold.end());
}

TEST_F(HeadlessIde, ARunReadsCameraPicturesBesideTheFramesContext) {
  // the vision example's camera is rendered in a context of its own while the IDE draws in
  // the frame's: the boxes are classified, and the frame is drawn on
  const auto r = replayOn("examples/vision", "- run: 7\n", "--screenshot '" + (dir_ / "shot.png").string() + "'");
  EXPECT_EQ(r["run"]["message"], "") << r["run"]["message"];
  EXPECT_DOUBLE_EQ(r["run"]["time"].get<double>(), 7.0);
  EXPECT_NE(last_.out.find("[t=2.65] camera sees boxes/red_1/box as red"), std::string::npos) << last_.out;
  EXPECT_NE(last_.out.find("[t=6.65] camera sees boxes/red_3/box as red"), std::string::npos) << last_.out;
  EXPECT_GT(r["world"]["triangles"].get<int>(), 10);
  EXPECT_GT(std::filesystem::file_size(dir_ / "shot.png"), 10000u);
}

TEST_F(HeadlessIde, TheInspectorShowsWhatASensorReadsAndTheLatestPictureAScriptRead) {
  // before the first picture is read (2.65 s) the camera has none to show, and showing one
  // renders nothing: the run goes as gdpn run's
  auto r = replayOn("examples/vision", "- run: 1\n- select: line/mast/cam\n");
  EXPECT_EQ(r["inspector"]["type"], "ColorCamera");
  EXPECT_TRUE(r["inspector"]["reading"]["picture"].is_null()) << r["inspector"].dump();
  r = replayOn("examples/vision", "- run: 3\n- select: line/mast/cam\n",
               "--screenshot '" + (dir_ / "camera.png").string() + "'");
  EXPECT_EQ(r["inspector"]["reading"]["picture"], nlohmann::json({64, 48})) << r["inspector"].dump();
  EXPECT_NE(last_.out.find("[t=2.65] camera sees boxes/red_1/box as red"), std::string::npos) << last_.out;
  // a region: what is inside it now
  r = replayOn("examples/vision", "- run: 3\n- select: line/diverter/gate\n");
  EXPECT_EQ(r["inspector"]["type"], "Region");
  EXPECT_TRUE(r["inspector"]["reading"]["items"].is_array()) << r["inspector"].dump();
  EXPECT_FALSE(r["inspector"]["reading"]["active"].get<bool>());
}

TEST_F(HeadlessIde, SelectingAPlaceHighlightsEveryNodeTokenItHolds) {
  // P1 holds the arm's three joints as the model starts
  const auto r = replay("- select: factory/P1\n");
  EXPECT_EQ(r["selection"]["kind"], "place");
  EXPECT_EQ(r["inspector"]["tokens"], 3);
  EXPECT_EQ(r["world"]["highlighted_nodes"], 3);
}

TEST_F(HeadlessIde, ContactsAreMarkedOnlyWhileShown) {
  // the boxes lie on the feed belt: a step's contacts are there to mark once they are asked for
  auto r = replay("- run: 2\n- steps: 1\n");
  EXPECT_EQ(r["world"]["contacts"], 0);
  r = replay("- press: contacts\n- run: 2\n- steps: 1\n");
  EXPECT_GT(r["world"]["contacts"].get<int>(), 8);
  r = replay("- press: contacts\n- run: 2\n- press: contacts\n- steps: 1\n");
  EXPECT_EQ(r["world"]["contacts"], 0);
}

TEST_F(HeadlessIde, ASelectedNodeShowsThePlaceOrTheOccurringTransitionHoldingIt) {
  // the arm's joint waits in P1 as the model starts; pickup holds it while it occurs
  auto r = replay("- select: arm/turn\n");
  EXPECT_EQ(r["net_view"]["holding"], nlohmann::json::array({"factory/P1"})) << r["net_view"].dump();
  r = replay("- break: {starts: factory/pickup}\n- run: 30\n- select: arm/turn\n");
  ASSERT_EQ(r["net_view"]["activity"]["factory/pickup"], "occurring");
  EXPECT_EQ(r["net_view"]["holding"], nlohmann::json::array({"factory/pickup"})) << r["net_view"].dump();
  // a node that is no token: nothing
  r = replay("- select: line\n");
  EXPECT_EQ(r["net_view"]["holding"], nlohmann::json::array());
}

/// "- click: [X, Y]" at a point of a report.
std::string clickAt(const nlohmann::json& point) {
  return "- click: [" + std::to_string(point[0].get<int>()) + ", " + std::to_string(point[1].get<int>()) + "]\n";
}

/// "- drag: ..." with the right button at a point of a report, without moving: a right click.
std::string rightClickAt(const nlohmann::json& point) {
  const auto p = "[" + std::to_string(point[0].get<int>()) + ", " + std::to_string(point[1].get<int>()) + "]";
  return "- drag: {from: " + p + ", to: " + p + ", button: right}\n";
}

TEST_F(HeadlessIde, TheNetIsEditedByHandInTheNetView) {
  const std::string model = std::string(GDPN_SOURCE_DIR) + "/examples/basics/figure31";
  auto r = replayOn(model, "[]");
  ASSERT_EQ(r["net_view"]["places"], 4);
  const auto at = r["net_view"]["at"];
  const auto p1 = at["main/P1"], t2 = at["main/T2"];
  // a right click on paper, below P1, offers a place there; choosing it adds P5
  const nlohmann::json paper = {p1[0].get<int>(), p1[1].get<int>() + 80};
  r = replayOn(model, rightClickAt(paper));
  ASSERT_TRUE(r["net_view"]["menu"].contains("Place here")) << r["net_view"].dump();
  const auto place_here = r["net_view"]["menu"]["Place here"];
  r = replayOn(model, rightClickAt(paper) + clickAt(place_here));
  EXPECT_EQ(r["net_view"]["places"], 5);
  EXPECT_EQ(r["undo"]["label"], "add place main/P5") << r["undo"].dump();
  ASSERT_TRUE(r["net_view"]["at"].contains("main/P5"));
  EXPECT_NEAR(r["net_view"]["at"]["main/P5"][1].get<double>(), paper[1].get<double>(), 20);
  // a right click on T2 offers an arc from it; a click on P1 ends it
  const std::string arc_menu = rightClickAt(t2);
  r = replayOn(model, arc_menu);
  ASSERT_TRUE(r["net_view"]["menu"].contains("Arc from here")) << r["net_view"].dump();
  const auto arcs = r["net_view"]["arcs"].get<int>();
  r = replayOn(model, arc_menu + clickAt(r["net_view"]["menu"]["Arc from here"]) + clickAt(p1));
  EXPECT_EQ(r["net_view"]["arcs"], arcs + 1);
  EXPECT_EQ(r["undo"]["label"], "add arc T2 -> P1");
  // a left drag on P1 moves it, one step of undo; Ctrl+Z puts it back
  const nlohmann::json right = {p1[0].get<int>() + 60, p1[1].get<int>()};
  const std::string drag = "- drag: {from: [" + std::to_string(p1[0].get<int>()) + ", " + std::to_string(p1[1].get<int>()) +
                           "], to: [" + std::to_string(right[0].get<int>()) + ", " + std::to_string(right[1].get<int>()) + "]}\n";
  r = replayOn(model, drag);
  EXPECT_NEAR(r["net_view"]["at"]["main/P1"][0].get<double>(), right[0].get<double>(), 12) << r["net_view"].dump();
  EXPECT_EQ(r["undo"]["depth"], 1);
  EXPECT_EQ(r["undo"]["label"], "move main/P1");
  r = replayOn(model, drag + "- press: undo\n");
  EXPECT_EQ(r["net_view"]["at"]["main/P1"], p1);
}

TEST_F(HeadlessIde, TheSceneIsEditedFromTheTreeViewsMenu) {
  // "Group arm" is the tree's 13th row at 1280 x 720 (the parts palette hidden: the tree has
  // the column): a right click there opens its menu
  hidePalette();
  const std::string menu = rightClickAt(nlohmann::json{70, 338});
  auto r = replay(menu);
  ASSERT_TRUE(r["tree"]["menu"].contains("Duplicate")) << r["tree"].dump();
  const auto items = r["tree"]["menu"];
  EXPECT_TRUE(items.contains("Delete, and from the marking"));  // the net holds the arm's joints
  EXPECT_FALSE(items.contains("Delete"));
  r = replay(menu + clickAt(items["Duplicate"]));
  EXPECT_EQ(r["undo"]["label"], "duplicate arm");
  EXPECT_GT(r["tree"]["nodes_shown"].get<int>(), 0);
  r = replay(menu + clickAt(items["Delete, and from the marking"]));
  EXPECT_EQ(r["undo"]["label"], "delete arm");
  r = replay(menu + clickAt(items["Delete, and from the marking"]) + "- press: undo\n");
  EXPECT_EQ(r["undo"]["depth"], 0);
}

TEST_F(HeadlessIde, TheWheelZoomsTheNetViewAboutTheMouse) {
  const auto fitted = replay("[]")["net_view"]["zoom"].get<double>();
  const auto closer = replay("- wheel: {at: [1070, 300], clicks: 3}\n")["net_view"]["zoom"].get<double>();
  const auto farther = replay("- wheel: {at: [1070, 300], clicks: -3}\n")["net_view"]["zoom"].get<double>();
  EXPECT_GT(closer, fitted * 1.5);
  EXPECT_LT(farther, fitted / 1.5);
}

TEST_F(HeadlessIde, TheInspectorSaysWhereAMovingBodyIsInTheRun) {
  const auto r = replay("- run: 1\n- select: arm/turn/column\n");
  EXPECT_EQ(r["inspector"]["type"], "Body");
  ASSERT_EQ(r["inspector"]["live_position"].size(), 3U);
  EXPECT_NEAR(r["inspector"]["live_position"][0].get<double>(), -8.0, 0.5);  // the arm's column stands at x = -8 m
}

TEST_F(HeadlessIde, FiringADisabledTransitionShowsWhyNot) {
  const auto r = replay("- fire: factory/drop\n");
  const auto msg = r["status"]["message"].get<std::string>();
  EXPECT_NE(msg.find("cannot fire factory/drop: "), std::string::npos) << msg;
  EXPECT_NE(msg.find("not enabled"), std::string::npos) << msg;
}

TEST_F(HeadlessIde, RunningInRealTimeTakesOneFramesStepsPerFrame) {
  // a headless frame stands for 1/60 s: 60 frames of real time are 1 s of model time
  const auto r = replay("- press: run\n- frames: 60\n- press: pause\n");
  EXPECT_NEAR(r["run"]["time"].get<double>(), 1.0, 0.05);
  EXPECT_EQ(r["run"]["mode"], "paused");
}

TEST_F(HeadlessIde, ABreakpointStopsTheRunAndTheStatusBarSaysWhich) {
  const auto r = replay("- break: {starts: factory/pickup}\n- run: 30\n");
  EXPECT_LT(r["run"]["time"].get<double>(), 30.0);
  EXPECT_EQ(r["run"]["breakpoints"], nlohmann::json::array({"starts factory/pickup"}));
  EXPECT_EQ(r["status"]["message"], "stopped at breakpoint: starts factory/pickup");
}

TEST_F(HeadlessIde, ResetGoesBackToEditMode) {
  const auto r = replay("- run: 2\n- press: reset\n");
  EXPECT_EQ(r["run"]["mode"], "edit");
  EXPECT_EQ(r["run"]["steps"], 0);
}

TEST_F(HeadlessIde, SelectionIsOneThingAcrossTheViews) {
  // a click on the arm's pedestal in the world view selects it in the tree and the inspector
  auto r = replay("- click: [348, 280]\n");
  const auto picked = r["selection"]["name"].get<std::string>();
  EXPECT_EQ(r["selection"]["kind"], "node");
  EXPECT_TRUE(picked.starts_with("arm/")) << picked;
  EXPECT_EQ(r["tree"]["selected"], picked);
  EXPECT_EQ(r["inspector"]["node"], picked);
  // a place selected by name
  r = replay("- select: factory/P1\n");
  EXPECT_EQ(r["selection"]["kind"], "place");
  EXPECT_EQ(r["inspector"]["tokens"], 3);
}

TEST_F(HeadlessIde, AFieldEditIsUndoneAndRedone) {
  auto r = replay("- set: {node: arm/turn, field: vel1, value: 200}\n");
  EXPECT_EQ(r["undo"]["depth"], 1);
  EXPECT_EQ(r["undo"]["label"], "set arm/turn.vel1");
  r = replay("- set: {node: arm/turn, field: vel1, value: 200}\n- press: undo\n");
  EXPECT_EQ(r["undo"]["depth"], 0);
  EXPECT_EQ(r["undo"]["can_redo"], true);
  r = replay("- set: {node: arm/turn, field: vel1, value: 200}\n- press: undo\n- press: redo\n");
  EXPECT_EQ(r["undo"]["depth"], 1);
}

TEST_F(HeadlessIde, TheInspectorShowsAndSetsATemplatesMarkAndUserData) {
  auto r = replayOn("examples/plant/feeder",
                    "- select: store/box\n"
                    "- set: {node: store/box, field: data.code, value: \"007\"}\n"
                    "- set: {node: store/box, field: data.order, value: 17}\n"
                    "- set: {node: store/box, field: data.sizes, value: [1, 2.5]}\n"
                    "- set: {node: store, field: template, value: false}\n");
  EXPECT_EQ(r["inspector"]["data"], nlohmann::json::parse(R"({"kind": "crate", "code": "007", "order": 17,
                                                              "sizes": [1.0, 2.5]})"));
  EXPECT_EQ(r["inspector"]["template"], false);
  EXPECT_FALSE(r["inspector"].contains("inside_template"));  // the store was unmarked last
  EXPECT_EQ(r["undo"]["depth"], 4);
  EXPECT_EQ(r["undo"]["label"], "unmark template store");
  r = replayOn("examples/plant/feeder", "- select: store/box\n");
  EXPECT_EQ(r["inspector"]["inside_template"], "store");
  replayOn("examples/plant/feeder", "- set: {node: store, field: template, value: maybe}\n", {}, 1);
  EXPECT_NE(last_.out.find("actions.yaml:1:3: error: 'template' expects true or false"), std::string::npos) << last_.out;
}

TEST_F(HeadlessIde, TheInspectorSaysWhichFieldsComeFromAParameterUntilOneIsTypedIn) {
  auto r = replayOn("tests/data/good/params.gdpn.yaml", "- select: belt\n");
  ASSERT_EQ(r["inspector"]["type"], "Conveyor");
  EXPECT_EQ(r["inspector"]["fields"][0]["name"], "speed");
  EXPECT_EQ(r["inspector"]["fields"][0]["param"], "belt_speed");
  EXPECT_EQ(r["inspector"]["fields"][0]["value"], 0.4);
  EXPECT_FALSE(r["inspector"]["fields"][1].contains("param"));
  r = replayOn("tests/data/good/params.gdpn.yaml", "- select: belt\n- set: {node: belt, field: speed, value: 0.7}\n");
  EXPECT_FALSE(r["inspector"]["fields"][0].contains("param"));
  EXPECT_EQ(r["inspector"]["fields"][0]["value"], 0.7);
}

TEST_F(HeadlessIde, ADragOfAnInspectorSliderIsOneUndoStep) {
  // the feed's first Material: its shininess slider is the fifth row of the inspector at 1280 x 720 (below the line of the template mark and the data to add)
  auto r = replay("- select: feed/#0\n- drag: {from: [500, 670], to: [560, 670]}\n");
  EXPECT_EQ(r["inspector"]["type"], "Material");
  EXPECT_EQ(r["undo"]["depth"], 1);
  EXPECT_EQ(r["undo"]["label"], "set feed/#0.shininess");
  r = replay("- select: feed/#0\n- drag: {from: [500, 670], to: [560, 670]}\n- press: undo\n");
  EXPECT_EQ(r["undo"]["depth"], 0);
}

TEST_F(HeadlessIde, AnInvalidFieldValueIsALocatedError) {
  replay("- press: step\n- set: {node: feed/#0, field: bounce, value: 3}\n", {}, 1);
  EXPECT_NE(last_.out.find("actions.yaml:2:3: error: 'bounce' must lie in [0, 1], got 3"), std::string::npos)
      << last_.out;
}

TEST_F(HeadlessIde, MistakesInTheReplayFileAreLocated) {
  replay("- press: step\n- jump: 3\n", {}, 1);
  EXPECT_NE(last_.out.find("actions.yaml:2:3: error: unknown action 'jump'"), std::string::npos) << last_.out;
  replay("- press: fly\n", {}, 1);
  EXPECT_NE(last_.out.find("actions.yaml:1:10: error: unknown action 'fly'"), std::string::npos) << last_.out;
  replay("- select: nowhere\n", {}, 1);
  EXPECT_NE(last_.out.find("actions.yaml:1:3: error: nothing is called 'nowhere'"), std::string::npos) << last_.out;
  replay("- key: f13\n", {}, 1);
  EXPECT_NE(last_.out.find("actions.yaml:1:3: error: unknown key 'f13'"), std::string::npos) << last_.out;
}

TEST_F(HeadlessIde, ADraggedSplitterIsRememberedInTheNextSession) {
  // the tree view's right edge starts at 260 px; drag it 100 px to the right
  auto r = replay("- drag: {from: [263, 400], to: [363, 400]}\n");
  EXPECT_NEAR(r["splitters"]["tree_width"].get<double>(), 360.0, 1.0);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "config" / "gdpn" / "ide.ini"));
  r = replay("[]");
  EXPECT_NEAR(r["splitters"]["tree_width"].get<double>(), 360.0, 1.0);
  EXPECT_NEAR(r["layout"]["world"][0].get<double>(), 366.0, 1.0);
}

TEST_F(HeadlessIde, TheWorldViewFramesTheSelectionTakesStandardViewsAndSceneCameras) {
  auto r = replay("- select: arm/turn\n- view: frame\n");
  EXPECT_NEAR(r["world"]["target"][0].get<double>(), -8.0, 1.0);  // the arm stands at x = -8 m
  r = replay("- view: top\n");
  EXPECT_GT(r["world"]["eye"][2].get<double>(), r["world"]["target"][2].get<double>() + 1.0);
  EXPECT_NEAR(r["world"]["eye"][0].get<double>(), r["world"]["target"][0].get<double>(), 0.5);
  r = replay("- view: armview\n");
  EXPECT_EQ(r["world"]["camera"], "armview");
  EXPECT_NEAR(r["world"]["eye"][0].get<double>(), -4.0, 1e-6);
  replay("- view: sideways\n", {}, 1);
  EXPECT_NE(last_.out.find("actions.yaml:1:3: error: 'sideways' is no standard view"), std::string::npos) << last_.out;
}

TEST_F(HeadlessIde, KeysTypedInTheWorldViewReachTheSensors) {
  const auto r = replay("- key: g\n- key: space\n");
  EXPECT_EQ(r["world"]["keys"], nlohmann::json::array({"g", "space"}));
}

TEST_F(HeadlessIde, AModelThatDoesNotCompileShowsItsErrorsAndAClickSelectsTheConstruct) {
  const auto model = write("bad.gdpn.yaml", R"Y(gdpn: 1
scene:
  - Cube: {name: c, size: [1, 1, 1]}
pages:
  main:
    places:
      a: {tokens: 1}
    transitions:
      t: {}
    arcs:
      - a -> t
      - t -> nowhere
)Y");
  const auto j = replayOn(model, "- click: [900, 502]\n");
  ASSERT_EQ(j["diagnostics"].size(), 1U);
  EXPECT_NE(j["diagnostics"][0].get<std::string>().find("bad.gdpn.yaml:12:9: error: 'nowhere'"), std::string::npos);
  EXPECT_EQ(j["toolbar"]["ready"], false);
  // the arc at line 12 belongs to the transition declared before it
  EXPECT_EQ(j["selection"]["kind"], "transition");
  EXPECT_EQ(j["selection"]["name"], "main/t");
}

TEST_F(HeadlessIde, SaveWritesTheEditedModel) {
  const auto model = write("bin.gdpn.yaml", ide::testing::kBinModel);
  replayOn(model, "- set: {node: drop/paint, field: bounce, value: 0.5}\n- press: save\n");
  std::ifstream in(model);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("bounce: 0.5"), std::string::npos) << text.str();
  EXPECT_EQ(gdpn::testing::runGdpn("check '" + model + "'").code, 0);
}

TEST_F(HeadlessIde, AfterTheIdeIsKilledTheNextStartOffersTheAutosaveAndRestoresEveryEdit) {
  const auto model = write("bin.gdpn.yaml", ide::testing::kBinModel);
  const auto before = gdpn::testing::fileBytes(model);
  // two edits, an autosave one second (60 frames) later, then frames until the IDE is killed
  const auto actions = write("edits.yaml",
                             "- set: {node: drop/paint, field: bounce, value: 0.5}\n"
                             "- set: {node: drop/box, field: mass, value: 2.5}\n"
                             "- frames: 80\n"
                             "- frames: 1000000\n");
  const std::string command = env() + " exec \"" + std::string(GDPN_CLI) + "\" ide '" + model +
                              "' --headless --size 640x360 --autosave 1 --replay '" + actions + "' >/dev/null 2>&1";
  const pid_t ide = fork();
  ASSERT_GE(ide, 0);
  if (ide == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  // wait for the autosave (at most two minutes: a slow machine draws slowly), then kill
  for (int i = 0; i < 1200 && autosaves().empty(); ++i) usleep(100'000);
  usleep(200'000);  // the file is renamed into place complete; give the IDE a moment past it
  kill(ide, SIGKILL);
  int status = 0;
  waitpid(ide, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "the IDE ended before it was killed";
  ASSERT_EQ(autosaves().size(), 1U);
  EXPECT_EQ(gdpn::testing::fileBytes(model), before) << "the autosave went over the model";

  // the next start offers the restore; restoring brings both edits back, one undo step
  auto r = replayOn(model, "- frames: 1\n");
  EXPECT_EQ(r["restore"]["offered"], true);
  r = replayOn(model, "- press: restore\n");
  EXPECT_EQ(r["restore"]["offered"], false);
  EXPECT_EQ(r["undo"]["label"], "restore the autosave");
  EXPECT_EQ(r["document"]["modified"], true);
  r = replayOn(model, "- press: restore\n- press: save\n");
  const auto saved = gdpn::testing::fileBytes(model);
  EXPECT_NE(saved.find("bounce: 0.5"), std::string::npos) << saved;
  EXPECT_NE(saved.find("mass: 2.5"), std::string::npos) << saved;
  // saving removed the autosave: nothing is offered any more
  EXPECT_TRUE(autosaves().empty());
  r = replayOn(model, "- frames: 1\n");
  EXPECT_EQ(r["restore"]["offered"], false);
}

/// "[X, Y]" of a position a report gave.
std::string at(const nlohmann::json& position) {
  return "[" + std::to_string(position[0].get<int>()) + ", " + std::to_string(position[1].get<int>()) + "]";
}

// the inspector made tall (its splitter dragged up) so that the contents view shows whole
constexpr const char* kTallInspector = "- drag: {from: [560, 460], to: [560, 160]}\n";

TEST_F(HeadlessIde, ScriptsAreTypedInTheContentsViewCompiledWhenLeftAndASyntaxErrorIsMarkedOnItsLine) {
  const auto model = write("bin.gdpn.yaml", ide::testing::kBinModel);
  const std::string start = std::string(kTallInspector) + "- select: main/work\n";
  const auto editors = replayOn(model, start)["inspector"]["contents"]["editors"];
  ASSERT_EQ(editors["pre_fire"]["lines"], 0);  // none yet: an Add button
  auto r = replayOn(model, start + "- click: " + at(editors["pre_fire"]["edit"]) +
                               "\n- type: \"box = sim.node('drop/box')\\nbox.mass = 2\\n\"\n- click: [1100, 700]\n"
                               "- click: " + at(editors["guard"]["edit"]) +
                               "\n- type: 'len(bin.items) >'\n- click: [1100, 700]\n- press: save\n");
  const auto contents = r["inspector"]["contents"];
  EXPECT_EQ(r["undo"]["depth"], 2);
  EXPECT_EQ(r["undo"]["label"], "edit transition main/work");
  EXPECT_EQ(contents["editors"]["pre_fire"]["lines"], 2);
  EXPECT_FALSE(contents["editors"]["pre_fire"].contains("error"));
  // the guard is kept as typed, and marked: Python's message on its line
  EXPECT_EQ(contents["editors"]["guard"]["error"]["line"], 1);
  EXPECT_EQ(contents["editors"]["guard"]["error"]["message"], "invalid syntax");
  const auto saved = gdpn::testing::fileBytes(model);
  EXPECT_NE(saved.find("box.mass = 2"), std::string::npos) << saved;
  EXPECT_NE(saved.find("len(bin.items) >"), std::string::npos) << saved;
  // the run refuses the model at the guard's line in the file
  const auto check = gdpn::testing::runGdpn("check '" + model + "'");
  EXPECT_NE(check.code, 0);
  EXPECT_NE(check.out.find("syntax error in guard of transition 'main/work'"), std::string::npos) << check.out;
}

TEST_F(HeadlessIde, ANodeDraggedFromTheTreeOntoASlotBecomesATokenAndTheSlotMenuBindsASensor) {
  const auto model = write("bin.gdpn.yaml", ide::testing::kBinModel);
  const std::string start = std::string(kTallInspector) + "- select: main/landed\n";
  auto r = replayOn(model, start);
  const auto grid = r["inspector"]["contents"]["grid"];
  const auto drop = r["tree"]["rows"]["drop"];
  ASSERT_TRUE(drop.is_array()) << r["tree"].dump();
  // the Transform drop onto b0: a node slot holding it, one step
  const std::string dragged = start + "- drag: {from: " + at(drop) + ", to: " + at(grid["b0"]) + "}\n";
  r = replayOn(model, dragged);
  EXPECT_EQ(r["selection"]["name"], "main/landed") << "a drag from the tree does not select";
  EXPECT_EQ(r["undo"]["label"], "edit place main/landed");
  EXPECT_EQ(r["inspector"]["contents"]["slots"]["b0"]["kind"], "node");
  EXPECT_EQ(r["inspector"]["contents"]["slots"]["b0"]["names"], nlohmann::json::array({"drop"}));
  // c0's menu: a sensor slot reading the region high/bin
  const std::string menu = dragged + "- drag: {from: " + at(grid["c0"]) + ", to: " + at(grid["c0"]) + ", button: right}\n";
  r = replayOn(model, menu);
  const auto items = r["inspector"]["contents"]["menu"];
  ASSERT_TRUE(items.contains("Sensor slot")) << r["inspector"]["contents"].dump();
  r = replayOn(model, menu + "- click: " + at(items["Sensor slot"]) + "\n");
  const auto sensors = r["inspector"]["contents"]["menu"];
  ASSERT_TRUE(sensors.contains("high/bin")) << sensors.dump();
  r = replayOn(model, menu + "- click: " + at(items["Sensor slot"]) + "\n- click: " + at(sensors["high/bin"]) +
                          "\n- press: save\n");
  EXPECT_EQ(r["inspector"]["contents"]["slots"]["c0"]["kind"], "sensor");
  EXPECT_EQ(r["undo"]["depth"], 2);
  const auto saved = gdpn::testing::fileBytes(model);
  EXPECT_NE(saved.find("sensors: {c0: high/bin}"), std::string::npos) << saved;
  EXPECT_EQ(gdpn::testing::runGdpn("check '" + model + "'").code, 0) << saved;
}

TEST_F(HeadlessIde, ATransitionsDurationPriorityAndProbabilityAreSetInTheContentsView) {
  const auto model = write("bin.gdpn.yaml", ide::testing::kBinModel);
  const std::string start = std::string(kTallInspector) + "- select: main/rest\n";
  const auto fields = replayOn(model, start)["inspector"]["contents"]["fields"];
  // a click selects the field's text, which the typing replaces
  const auto set = [&](const char* field, const std::string& text) {
    return "- click: " + at(fields[field]) + "\n- type: '" + text +
           "'\n- key: enter\n";
  };
  auto r = replayOn(model, start + set("duration", "1.25") + set("priority", "3") + set("probability", "0.5"));
  EXPECT_EQ(r["inspector"]["contents"]["duration"], "1.25 s");
  EXPECT_EQ(r["undo"]["depth"], 3);
  r = replayOn(model, start + set("duration", "1.25") + set("priority", "3") + set("probability", "0.5") +
                          "- press: save\n");
  const auto saved = gdpn::testing::fileBytes(model);
  EXPECT_NE(saved.find("rest: {duration: 1.25, priority: 3, probability: 0.5}"), std::string::npos) << saved;
  // a probability outside (0, 1] is refused with the reason
  r = replayOn(model, start + set("probability", "2"));
  EXPECT_EQ(r["undo"]["depth"], 0);
  EXPECT_EQ(r["message"], "a probability lies in (0, 1]");
  // servers: a number, or unlimited by its box; none is refused
  r = replayOn(model, start + set("servers", "3") + "- press: save\n");
  EXPECT_NE(gdpn::testing::fileBytes(model).find("probability: 0.5, servers: 3}"), std::string::npos)
      << gdpn::testing::fileBytes(model);
  // with servers the inspector says how many are busy, a line more above the fields
  const auto with_servers = replayOn(model, start)["inspector"]["contents"]["fields"];
  r = replayOn(model, start + "- click: " + at(with_servers["unlimited"]) + "\n- press: save\n");
  EXPECT_EQ(r["undo"]["depth"], 1);
  EXPECT_NE(gdpn::testing::fileBytes(model).find("probability: 0.5, servers: unlimited}"), std::string::npos)
      << gdpn::testing::fileBytes(model);
  r = replayOn(model, start + "- click: " + at(with_servers["unlimited"]) + "\n- press: save\n");
  EXPECT_EQ(gdpn::testing::fileBytes(model).find("servers:"), std::string::npos) << gdpn::testing::fileBytes(model);
  r = replayOn(model, start + set("servers", "0"));
  EXPECT_EQ(r["undo"]["depth"], 0);
  EXPECT_EQ(r["message"], "servers are a whole number from 1 to 1000000, or unlimited");
}

TEST_F(HeadlessIde, TheTutorialBuildsFromAnEmptyFileAModelWhoseRunPushesTheBoxOff) {
  // examples/tutorial/build.yaml: the scene, the net and its scripts through the IDE alone
  const auto model = (dir_ / "pusher.gdpn.yaml").string();
  const auto built = runShell(env() + " \"$GDPN\" ide '" + model +
                              "' --headless --size 1600x1000 --replay examples/tutorial/build.yaml --report '" +
                              (dir_ / "report.json").string() + "'");
  ASSERT_EQ(built.code, 0) << built.out;
  std::ifstream in(dir_ / "report.json");
  const auto r = nlohmann::json::parse(in, nullptr, false);
  EXPECT_EQ(r["message"], "saved " + model);
  EXPECT_EQ(r["run"]["time"], 6.0);
  // the saved model, run headless: the eye stopped the belt, the slider pushed the box off
  const auto run = gdpn::testing::runGdpn("run '" + model + "' --until 8");
  ASSERT_EQ(run.code, 0) << run.out;
  EXPECT_NE(run.out.find("main/stop                1"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("main/push                1"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("main/pushed          0.202               1              1"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("box: at (0.56, 0.67, 0.16) m, off the belt"), std::string::npos) << run.out;
  EXPECT_EQ(gdpn::testing::runGdpn("check '" + model + "'").code, 0);
}

/// The value of field `name` in the inspector's report.
nlohmann::json fieldValue(const nlohmann::json& report, const std::string& name) {
  for (const auto& f : report["inspector"]["fields"]) {
    if (f["name"] == name) return f["value"];
  }
  return {};
}

TEST_F(HeadlessIde, DraggingAMoveHandleMovesTheTransformAlongItsAxisInSnappedSteps) {
  // the bin model's Transform `high` stands at (0, 0, 0.5), where the view looks; its x handle
  // is 0.16 of the eye's distance long (0.99 m). Dragged from its tip back to the pivot, it
  // moves the node by that length back: -1.00 m in steps of 0.05 m, -0.99 m without them
  const auto model = write("bin.gdpn.yaml", ide::testing::kBinModel);
  auto r = replayOn(model, "- select: high\n");
  ASSERT_EQ(r["world"]["tool"], "move");
  ASSERT_TRUE(r["world"]["handles"].contains("move x")) << r["world"].dump();
  const std::string drag = "- select: high\n- drag: {from: [world, handles, move x], to: [world, pivot]}\n";
  r = replayOn(model, drag);
  EXPECT_EQ(fieldValue(r, "translation"), nlohmann::json::array({-1.0, 0.0, 0.5}));
  EXPECT_EQ(r["undo"]["depth"], 1) << "a drag is one step";
  EXPECT_EQ(r["undo"]["label"], "set high.translation");
  r = replayOn(model, "- press: snap\n" + drag);
  const double x = fieldValue(r, "translation")[0].get<double>();
  EXPECT_NEAR(x, -0.99, 0.02);
  EXPECT_GT(std::abs(x / 0.05 - std::round(x / 0.05)), 1e-6) << "not snapped: " << x;
  // the z handle lifts it; undo puts it back
  r = replayOn(model, "- select: high\n- drag: {from: [world, handles, move z], to: [world, pivot]}\n- press: undo\n");
  EXPECT_EQ(fieldValue(r, "translation"), nlohmann::json::array({0.0, 0.0, 0.5}));
  // a turn ring: dragging its grab point (45 degrees round) to the pivot's side turns the node
  r = replayOn(model, "- press: turn-tool\n- select: high\n- drag: {from: [world, handles, turn z], to: [world, handles, turn x]}\n");
  const auto rotation = fieldValue(r, "rotation");
  EXPECT_NE(rotation, nlohmann::json::array({0.0, 0.0, 1.0, 0.0})) << r["world"].dump();
  const double angle = rotation[3].get<double>();
  EXPECT_NEAR(angle / 5.0, std::round(angle / 5.0), 1e-9) << "turned in 5 degree steps: " << angle;
}

TEST_F(HeadlessIde, AJointLimitDraggedInTheWorldViewAppearsInTheInspector) {
  // a slider along x whose limits stand at -0.5 and +0.5 m about its anchor (0, 0, 0.5)
  const auto model = write("slider.gdpn.yaml", R"Y(gdpn: 1
scene:
  - Camera: {name: view, position: [4, -4, 3], target: [0, 0, 0.5]}
  - Joint:
      name: slide
      kind: slider
      anchor: [0, 0, 0.5]
      axis1: [1, 0, 0]
      lo1: -0.5
      hi1: 0.5
      children: [{Body: {name: cart, mass: 1, children: [{Transform: {translation: [0, 0, 0.5], children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}}]}}]
pages:
  main: {}
)Y");
  auto r = replayOn(model, "- select: slide\n");
  ASSERT_TRUE(r["world"]["handles"].contains("hi1")) << r["world"].dump();
  ASSERT_TRUE(r["world"]["handles"].contains("lo1"));
  EXPECT_EQ(fieldValue(r, "hi1"), 0.5);
  // hi1 dragged to the anchor: 0 m, in the inspector and in the saved model
  r = replayOn(model, "- select: slide\n- drag: {from: [world, handles, hi1], to: [world, pivot]}\n- press: save\n");
  EXPECT_EQ(fieldValue(r, "hi1"), 0.0);
  EXPECT_EQ(fieldValue(r, "lo1"), -0.5);
  EXPECT_EQ(r["undo"]["label"], "set slide.hi1");
  const auto saved = gdpn::testing::fileBytes(model);
  EXPECT_NE(saved.find("hi1: 0\n"), std::string::npos) << saved;
}

TEST_F(HeadlessIde, ANodeDroppedOnAnotherRowMovesUnderItAndDeleteRemovesTheSelection) {
  const auto model = write("bin.gdpn.yaml", ide::testing::kBinModel);
  auto r = replayOn(model, "- drag: {from: [tree, rows, drop], to: [tree, rows, high]}\n");
  EXPECT_EQ(r["undo"]["label"], "move drop under high");
  EXPECT_TRUE(r["tree"]["rows"].contains("high/drop")) << r["tree"]["rows"].dump();
  EXPECT_EQ(r["selection"]["name"], "high/drop");
  // Delete: a place with its arcs; a node; a node the net reads is refused, with where
  r = replayOn(model, "- select: main/never\n- key: delete\n");
  EXPECT_EQ(r["undo"]["label"], "delete main/never");
  EXPECT_EQ(r["selection"]["kind"], "none");
  r = replayOn(model, "- select: drop/paint\n- key: delete\n");
  EXPECT_EQ(r["undo"]["label"], "delete drop/paint");
  r = replayOn(model, "- select: high\n- key: delete\n");
  EXPECT_EQ(r["undo"]["depth"], 0);
  EXPECT_NE(r["message"].get<std::string>().find("'high' is used by the net: main/watching (c0)"), std::string::npos)
      << r["message"];
}

TEST_F(HeadlessIde, ASubtreeIsCopiedAsAModelFileAndPastedUnderTheSelection) {
  const auto model = write("bin.gdpn.yaml", ide::testing::kBinModel);
  auto r = replayOn(model, "- select: drop\n- press: copy\n- select: high\n- press: paste\n");
  EXPECT_EQ(r["undo"]["label"], "paste under high");
  EXPECT_EQ(r["selection"]["name"], "high/drop");
  EXPECT_TRUE(r["tree"]["rows"].contains("high/drop")) << r["tree"]["rows"].dump();
  // the clipboard holds a model file: another model reads it, and its scene is the subtree
  const auto copied = write("copied.gdpn.yaml", r["copied"].get<std::string>());
  EXPECT_EQ(gdpn::testing::runGdpn("check '" + copied + "'").code, 0) << r["copied"];
  EXPECT_NE(r["copied"].get<std::string>().find("name: drop"), std::string::npos) << r["copied"];
  EXPECT_NE(r["copied"].get<std::string>().find("name: box"), std::string::npos) << r["copied"];
  // pasted twice at the top: the second copy gets a number; cut takes the source away
  r = replayOn(model, "- select: drop\n- press: copy\n- select: view\n- press: paste\n");
  EXPECT_EQ(r["selection"]["name"], "drop_1") << "a Camera takes no children: beside it, renamed";
  r = replayOn(model, "- select: drop/paint\n- press: cut\n- select: high\n- press: paste\n");
  EXPECT_TRUE(r["tree"]["rows"].contains("high/paint")) << r["tree"]["rows"].dump();
  EXPECT_EQ(r["undo"]["depth"], 2);
  // nothing on the clipboard: nothing to paste, and nothing said
  r = replayOn(model, "- select: main/idle\n- press: paste\n");
  EXPECT_EQ(r["message"], "");
  EXPECT_EQ(r["undo"]["depth"], 0);
}

TEST_F(HeadlessIde, APlaceOrTransitionIsCopiedAsAModelFileAndPastedIntoTheNetViewsPage) {
  const auto model = write("bin.gdpn.yaml", ide::testing::kBinModel);
  // idle holds 2 tokens; its copy keeps them and gets a free name
  auto r = replayOn(model, "- select: main/idle\n- press: copy\n- press: paste\n- press: save\n");
  EXPECT_EQ(r["undo"]["label"], "paste into main");
  EXPECT_EQ(r["selection"]["name"], "main/idle_1");
  EXPECT_NE(r["copied"].get<std::string>().find("idle: {tokens: 2}"), std::string::npos) << r["copied"];
  const auto saved = gdpn::testing::fileBytes(model);
  EXPECT_NE(saved.find("idle_1: {tokens: 2"), std::string::npos) << saved;
  EXPECT_EQ(gdpn::testing::runGdpn("check '" + model + "'").code, 0) << saved;
  r = replayOn(model, "- select: main/work\n- press: cut\n- press: paste\n");
  EXPECT_EQ(r["selection"]["name"], "main/work") << "cut frees the name";
  EXPECT_EQ(r["undo"]["depth"], 2);
}

TEST_F(HeadlessIde, TheContentsViewShowsEachSlotsNodeTypeAndTheScriptsAlongATokensPath) {
  // the factory's P1: three joints; the path of b0's joint runs through the arm's transitions
  const std::string start = std::string(kTallInspector) + "- select: factory/P1\n";
  auto r = replay(start + "- click: [inspector, contents, grid, b0]\n");
  auto contents = r["inspector"]["contents"];
  EXPECT_EQ(contents["types"]["b0"], nlohmann::json::array({"Joint"}));
  EXPECT_TRUE(contents["conflicts"].empty());
  EXPECT_TRUE(contents["unknown"].empty());
  const auto path = contents["path"];
  ASSERT_GE(path.size(), 3u) << path.dump();
  EXPECT_EQ(path[0], "P1");
  EXPECT_EQ(path[1], "pickup");
  r = replay(start + "- click: [inspector, contents, grid, b0]\n- click: [inspector, contents, path_header]\n");
  contents = r["inspector"]["contents"];
  ASSERT_TRUE(contents["path_scripts"].is_array()) << contents.dump();
  EXPECT_EQ(contents["path_scripts"][0]["what"], "pickup pre_fire");
  // a script reading a field a Joint lacks is flagged before any run
  r = replay(std::string(kTallInspector) + "- select: factory/pickup\n- click: [inspector, contents, editors, pre_fire, edit]\n"
             "- type: \"\\nself.b0.taget1 = 5\"\n- click: [1100, 700]\n");
  contents = r["inspector"]["contents"];
  ASSERT_EQ(contents["unknown"].size(), 1u) << contents.dump();
  EXPECT_EQ(contents["unknown"][0], "pre_fire, line 2: self.b0.taget1: a Joint has no field or method 'taget1'");
}

TEST_F(HeadlessIde, SeveralMeshFilesAreImportedAtOnceThroughTheTreesMenu) {
  // two of tests/data/meshes beside the model, imported by the Scene heading's menu: one step
  const auto model = write("bin.gdpn.yaml", ide::testing::kBinModel);
  for (const char* f : {"tri.obj", "tri.stl"}) {
    std::filesystem::copy_file(std::string(GDPN_SOURCE_DIR) + "/tests/data/meshes/" + f, dir_ / f);
  }
  const std::string menu = "- click: {at: [tree, scene], button: right}\n- click: [tree, menu, Import meshes]\n";
  auto r = replayOn(model, menu + "- click: [tree, menu, files]\n- type: 'tri.obj; tri.stl'\n- click: [tree, menu, Import]\n"
                                  "- press: save\n");
  EXPECT_EQ(r["message"], "saved " + model) << r["message"];
  EXPECT_EQ(r["undo"]["depth"], 1);
  EXPECT_EQ(r["undo"]["label"], "paste under the scene");
  EXPECT_TRUE(r["tree"]["rows"].contains("tri")) << r["tree"]["rows"].dump();
  EXPECT_TRUE(r["tree"]["rows"].contains("tri_1")) << r["tree"]["rows"].dump();
  const auto saved = gdpn::testing::fileBytes(model);
  EXPECT_NE(saved.find("file: tri.obj"), std::string::npos) << saved;
  EXPECT_NE(saved.find("file: tri.stl"), std::string::npos) << saved;
  EXPECT_EQ(gdpn::testing::runGdpn("check '" + model + "'").code, 0) << saved;
  // a file that is not there is named in the message; nothing changes
  r = replayOn(model, menu + "- click: [tree, menu, files]\n- type: 'nothere.obj'\n- click: [tree, menu, Import]\n");
  EXPECT_EQ(r["undo"]["depth"], 0);
  EXPECT_NE(r["message"].get<std::string>().find("nothere.obj"), std::string::npos) << r["message"];
}

TEST_F(HeadlessIde, AKeyboardSensorHearsTheWorldViewsKeysWhileTheViewerIsInside) {
  // tests/data/input/console.gdpn.yaml with a camera inside the booth: 'go' waits for the g key
  std::ifstream source(std::string(GDPN_SOURCE_DIR) + "/tests/data/input/console.gdpn.yaml");
  std::stringstream text;
  text << source.rdbuf();
  auto console = text.str();
  console.replace(console.find("  - Camera: {position: [10, 0, 1]}"), 34,
                  "  - Camera: {position: [10, 0, 1]}\n  - Camera: {name: inside, position: [0, 0, 0.5], target: [0, 5, 0.5]}");
  const auto model = write("console.gdpn.yaml", console);
  // inside the booth, g held for a step: go fires
  auto j = replayOn(model, "- view: inside\n- hold: g\n- steps: 2\n- release: g\n- select: main/done\n");
  EXPECT_EQ(j["inspector"]["tokens"], 1);
  // outside, the same key is not heard
  j = replayOn(model, "- hold: g\n- steps: 2\n- release: g\n- select: main/done\n");
  EXPECT_EQ(j["inspector"]["tokens"], 0);
}

TEST_F(HeadlessIde, AClickOnAButtonInTheWorldViewDuringARunIsFeltByItsMouseSensor) {
  // a Body holding a Cube and a MouseSensor, in the middle of the view; `press` fires on a click
  const auto model = write("button.gdpn.yaml", ide::testing::kButtonModel);
  const std::string click = "- click: [world, center]\n";
  // the run started (a step), a click on the cap: the status line names the sensor that will
  // feel it, and the selection stays
  auto r = replayOn(model, "- press: step\n" + click);
  EXPECT_EQ(r["status"]["message"], "clicked button/cap: button/mouse feels it at the next step") << r["status"].dump();
  EXPECT_EQ(r["world"]["clicked"], nlohmann::json::array({"button/mouse"}));
  EXPECT_EQ(r["selection"]["kind"], "none");
  EXPECT_EQ(r["net_view"]["tokens"]["main/pressed"], 0);
  const auto eye = r["world"]["eye"];
  // at the next step boundary the sensor counts it, and press fires on c0.clicks > 0
  r = replayOn(model, "- press: step\n" + click + "- steps: 2\n- select: button/mouse\n");
  EXPECT_EQ(r["inspector"]["reading"]["clicks"], 1) << r["inspector"].dump();
  EXPECT_EQ(r["net_view"]["tokens"]["main/pressed"], 1) << r["net_view"].dump();
  EXPECT_EQ(r["net_view"]["tokens"]["main/ready"], 0);

  // a click beside the cap, and a drag that starts on it (an orbit), count nothing
  const auto origin = r["world"]["origin"];
  const auto center = r["world"]["center"];
  const auto beside = clickAt(nlohmann::json::array({origin[0].get<int>() + 12, origin[1].get<int>() + 12}));
  const auto orbit = "- drag: {from: [world, center], to: [" + std::to_string(center[0].get<int>() + 80) + ", " +
                     std::to_string(center[1].get<int>()) + "]}\n";
  r = replayOn(model, "- press: step\n" + beside + orbit + "- steps: 2\n- select: button/mouse\n");
  EXPECT_EQ(r["inspector"]["reading"]["clicks"], 0) << r["inspector"].dump();
  EXPECT_EQ(r["net_view"]["tokens"]["main/pressed"], 0);
  EXPECT_EQ(r["world"]["clicked"], nlohmann::json::array());
  EXPECT_NE(r["world"]["eye"], eye);  // the drag orbited

  // in edit mode a click on the cap selects it, as before, and the run made at Step never
  // sees it
  r = replayOn(model, click + "- steps: 2\n");
  EXPECT_EQ(r["selection"]["name"], "button/cap");
  EXPECT_EQ(r["world"]["clicked"], nlohmann::json::array());
  EXPECT_EQ(r["net_view"]["tokens"]["main/pressed"], 0);
}

TEST_F(HeadlessIde, TheNetViewShowsPickupRedWhileItOccursAndTheMarkingOfTheRun) {
  auto r = replay("- break: {starts: factory/pickup}\n- press: fastest\n- frames: 5\n");
  EXPECT_EQ(r["run"]["message"], "stopped at breakpoint: starts factory/pickup");
  EXPECT_EQ(r["net_view"]["activity"]["factory/pickup"], "occurring");
  EXPECT_EQ(r["net_view"]["activity"]["factory/leave"], "idle");
  EXPECT_EQ(r["net_view"]["tokens"]["factory/P1"], 0);  // pickup took the arm's joints
  r = replay("- run: 30\n");
  EXPECT_LT(r["net_view"]["tokens"]["factory/buffer"].get<int>(), 23);  // boxes have been fed
}

TEST_F(HeadlessIde, AClickInTheNetViewSelectsAndADoubleClickGoesIntoAnInstance) {
  const auto at = replay("[]")["net_view"]["at"];
  const auto p3 = at["factory/P3"], station = at["factory/stationA"];
  auto r = replay("- click: [" + std::to_string(p3[0].get<int>()) + ", " + std::to_string(p3[1].get<int>()) + "]\n");
  EXPECT_EQ(r["selection"]["kind"], "place");
  EXPECT_EQ(r["selection"]["name"], "factory/P3");
  EXPECT_EQ(r["inspector"]["kind"], "place");
  const std::string click = "- click: [" + std::to_string(station[0].get<int>()) + ", " +
                            std::to_string(station[1].get<int>()) + "]\n";
  r = replay(click + click);
  EXPECT_EQ(r["net_view"]["path"], "factory/stationA");
  EXPECT_EQ(r["net_view"]["page"], "station");
  EXPECT_GT(r["net_view"]["places"].get<int>(), 0);
}

TEST_F(HeadlessIde, TheContentsOfP1AreItsThreeJointTokensAndDropShowsItsScripts) {
  auto r = replay("- select: factory/P1\n");
  const auto slots = r["inspector"]["contents"]["slots"];
  ASSERT_EQ(slots.size(), 3u) << slots.dump();
  EXPECT_EQ(slots["b0"]["kind"], "node");
  EXPECT_EQ(slots["b0"]["names"], nlohmann::json::array({"arm/turn"}));
  EXPECT_EQ(slots["b2"]["names"], nlohmann::json::array({"arm/turn/column/lift/boom/wrist"}));
  EXPECT_EQ(r["inspector"]["tokens"], 3);
  r = replay("- select: factory/drop\n");
  const auto contents = r["inspector"]["contents"];
  EXPECT_EQ(contents["duration"], "1 s");
  ASSERT_EQ(contents["scripts"].size(), 2u) << contents.dump();
  EXPECT_EQ(contents["scripts"][0]["what"], "pre_fire");
  EXPECT_EQ(contents["scripts"][0]["lines"], 2);
  EXPECT_EQ(contents["scripts"][1]["what"], "post_fire");
}

TEST_F(HeadlessIde, TheMiniViewShowsTheNetOverTheWorldAndAClickThereSelects) {
  EXPECT_EQ(replay("[]")["mini_view"]["shown"], false);  // closed until asked for
  const auto r = replay("- press: mini-view\n");
  ASSERT_EQ(r["mini_view"]["shown"], true);
  EXPECT_GE(r["mini_view"]["drawn"].get<int>(), 13 + 12 + 2);
  const auto p1 = r["mini_view"]["at"]["factory/P1"];
  const auto world = r["layout"]["world"];  // x, y, w, h
  EXPECT_GT(p1[0].get<double>(), world[0].get<double>());
  EXPECT_LT(p1[1].get<double>(), world[1].get<double>() + world[3].get<double>());
  const auto clicked = replay("- press: mini-view\n- click: [" + std::to_string(p1[0].get<int>()) + ", " +
                              std::to_string(p1[1].get<int>()) + "]\n");
  EXPECT_EQ(clicked["selection"]["name"], "factory/P1");
  EXPECT_EQ(clicked["inspector"]["contents"]["slots"].size(), 3u);
}

TEST_F(HeadlessIde, TheBreakpointsAreListedUnderTheDiagnostics) {
  EXPECT_TRUE(replay("[]")["breakpoints"].empty());
  const auto r = replay("- break: {starts: factory/pickup}\n- break: {when: 'sim.time > 20'}\n");
  EXPECT_EQ(r["breakpoints"], nlohmann::json::array({"starts factory/pickup", "sim.time > 20"}));
}

TEST_F(HeadlessIde, AMovieFilmsTheWindowIntoTheCurrentFolder) {
  const auto file = write("movie.yaml", "- press: movie\n- press: run\n- frames: 12\n- press: movie\n");
  const auto report = (dir_ / "report.json").string();
  const auto model = std::string(GDPN_SOURCE_DIR) + "/examples/factory";
  // an odd size: the movie leaves the last row and column out
  const auto r = runShell("cd '" + dir_.string() + "' && XDG_CONFIG_HOME='" + (dir_ / "config").string() +
                          "' \"$GDPN\" ide '" + model + "' --headless --size 641x361 --replay '" + file +
                          "' --report '" + report + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream in(report);
  const auto j = nlohmann::json::parse(in, nullptr, false);
  EXPECT_EQ(j["toolbar"]["filming"], false);
  const std::string message = j["status"]["message"];
  EXPECT_EQ(message.rfind("saved gdpn-ide-1.mp4 (", 0), 0u) << message;
  ASSERT_TRUE(std::filesystem::exists(dir_ / "gdpn-ide-1.mp4"));
  EXPECT_GT(std::filesystem::file_size(dir_ / "gdpn-ide-1.mp4"), 1000u);
  const auto probe = runShell("ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of csv=p=0 '" +
                              (dir_ / "gdpn-ide-1.mp4").string() + "'");
  EXPECT_EQ(probe.out.substr(0, 7), "640,360") << probe.out;
}

TEST_F(HeadlessIde, TheFactoryAfterTwoSecondsLooksLikeItsGolden) {
  // golden: tests/data/golden/ide_factory.png, made by this test with GDPN_UPDATE_GOLDEN=1 (the
  // parts palette hidden: it lists whatever library the machine has)
  const auto shot = (dir_ / "shot.png").string();
  hidePalette();
  replay("- run: 2\n- select: arm/turn\n", "--screenshot '" + shot + "'");
  int w = 0, h = 0;
  std::vector<std::uint8_t> rgb;
  std::string why;
  ASSERT_TRUE(platform::readPng(shot, w, h, rgb, why)) << why;
  EXPECT_EQ(w, 1280);
  EXPECT_EQ(h, 720);
  gdpn::testing::expectLikeGolden(w, h, rgb, std::string(GDPN_SOURCE_DIR) + "/tests/data/golden/ide_factory.png");
}

}  // namespace
}  // namespace gdpn::ide
