// The scale and spot light manipulators in the headless IDE (EGL surfaceless): a box's tabs and
// a spot light's aim and cone handles dragged where the report places them, the resulting
// fields read from the inspector's report, and undo.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/cli.h"
#include "support/temp_files.h"

namespace gdpn::ide {
namespace {

using gdpn::testing::runShell;

// a box 0.8 x 1.2 x 0.4 m centred at (0, 0, 0.5), where the camera looks from 2.8 m away, and a
// spot light 0.8 m above it pointing down with a cone of 30 degrees
constexpr const char* kModel = R"Y(gdpn: 1
scene:
  - Camera: {name: view, position: [1.6, -1.6, 2.1], target: [0, 0, 0.5]}
  - Transform: {name: stand, translation: [0, 0, 0.5], children: [{Cube: {name: box, size: [0.8, 1.2, 0.4]}}]}
  - Light: {name: spot, kind: spot, location: [0.3, 0, 1.3], direction: [0, 0, -1], cutoff: 30}
  - Transform: {name: stretched, translation: [0, 0, 0.5], scale: [2, 1, 1], children: [{Region: {name: zone, size: [1, 1, 0.2]}}]}
pages:
  main: {}
)Y";

class ManipulatorReplay : public gdpn::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    model_ = write("stage.gdpn.yaml", kModel);
  }
  /// Runs the headless IDE (1280 x 720) on the model with `actions`; the report.
  nlohmann::json replay(const std::string& actions) {
    const auto file = write("actions.yaml", actions);
    const auto report = (dir_ / "report.json").string();
    std::filesystem::remove(report);
    const auto env = "XDG_CONFIG_HOME='" + (dir_ / "config").string() + "' XDG_STATE_HOME='" + (dir_ / "state").string() + "'";
    const auto run = runShell(env + " \"$GDPN\" ide '" + model_ + "' --headless --size 1280x720 --replay '" + file +
                              "' --report '" + report + "'");
    EXPECT_EQ(run.code, 0) << run.out;
    if (run.code != 0) return {};
    std::ifstream in(report);
    return nlohmann::json::parse(in, nullptr, false);
  }
  std::string model_;
};

/// The value of field `name` in the inspector's report.
nlohmann::json fieldValue(const nlohmann::json& report, const std::string& name) {
  for (const auto& f : report["inspector"]["fields"]) {
    if (f["name"] == name) return f["value"];
  }
  return {};
}

/// A point of the window as a replay writes it: "[x, y]".
std::string at(double x, double y) {
  return "[" + std::to_string(std::lround(x)) + ", " + std::to_string(std::lround(y)) + "]";
}

/// The pixel `k` times as far from the pivot as `handle`, on the same side.
std::string beyond(const nlohmann::json& world, const std::string& handle, double k) {
  const auto& p = world["pivot"];
  const auto& h = world["handles"][handle];
  const double px = p[0].get<double>(), py = p[1].get<double>();
  return at(px + k * (h[0].get<double>() - px), py + k * (h[1].get<double>() - py));
}

TEST_F(ManipulatorReplay, ABoxSeenFromAboveOffersTheTabsOfARectangle) {
  const auto r = replay("- press: scale-tool\n- select: stand/box\n- view: top\n");
  EXPECT_EQ(r["world"]["tool"], "scale");
  const auto& handles = r["world"]["handles"];
  for (const char* tab : {"scale +x", "scale -x", "scale +y", "scale -y", "scale +x+y", "scale +x-y", "scale -x+y",
                          "scale -x-y"}) {
    EXPECT_TRUE(handles.contains(tab)) << tab << ": " << handles.dump();
  }
  EXPECT_EQ(handles.size(), 8U) << handles.dump();
  // the pivot is the box's centre, between its +x and -x tabs
  const auto& p = r["world"]["pivot"];
  EXPECT_NEAR((handles["scale +x"][0].get<double>() + handles["scale -x"][0].get<double>()) / 2, p[0].get<double>(), 1.0);
  // the move tool offers a box no handles
  EXPECT_TRUE(replay("- select: stand/box\n- view: top\n")["world"]["handles"].empty());
  // a box Region (here under a scale) offers the same; aslant, three faces and nine edges
  EXPECT_EQ(replay("- press: scale-tool\n- select: stretched/zone\n- view: top\n")["world"]["handles"].size(), 8U);
  const auto aslant = replay("- press: scale-tool\n- select: stretched/zone\n- view: iso\n")["world"]["handles"];
  EXPECT_EQ(aslant.size(), 12U) << aslant.dump();
}

TEST_F(ManipulatorReplay, AFaceTabDraggedTwiceAsFarFromTheCentreDoublesItsAxisAndUndoRestoresIt) {
  // seen from above, the plane of the box's middle faces the view: twice as far on the screen
  // is twice as far in the box, so the +x face moves by half the box (0.4 m) and the centred box
  // grows by twice that
  const std::string setup = "- press: scale-tool\n- select: stand/box\n- view: top\n";
  const auto before = replay(setup);
  ASSERT_TRUE(before["world"]["handles"].contains("scale +x")) << before["world"].dump();
  const std::string drag = setup + "- drag: {from: [world, handles, scale +x], to: " +
                           beyond(before["world"], "scale +x", 2.0) + "}\n";
  auto r = replay(drag);
  EXPECT_EQ(fieldValue(r, "size"), nlohmann::json::array({1.6, 1.2, 0.4})) << r["world"].dump();
  EXPECT_EQ(r["undo"]["depth"], 1) << "a drag is one step";
  EXPECT_EQ(r["undo"]["label"], "set stand/box.size");
  r = replay(drag + "- press: undo\n");
  EXPECT_EQ(fieldValue(r, "size"), nlohmann::json::array({0.8, 1.2, 0.4}));
  // the -y tab pulled back to the centre leaves one step of 0.05 m
  r = replay(setup + "- drag: {from: [world, handles, scale -y], to: [world, pivot]}\n");
  EXPECT_EQ(fieldValue(r, "size"), nlohmann::json::array({0.8, 0.05, 0.4}));
}

TEST_F(ManipulatorReplay, ACornerTabScalesTheTwoAxesItJoins) {
  const std::string setup = "- press: scale-tool\n- select: stand/box\n- view: top\n";
  const auto before = replay(setup);
  ASSERT_TRUE(before["world"]["handles"].contains("scale +x+y")) << before["world"].dump();
  const std::string drag = setup + "- drag: {from: [world, handles, scale +x+y], to: " +
                           beyond(before["world"], "scale +x+y", 1.5) + "}\n";
  auto r = replay(drag);
  EXPECT_EQ(fieldValue(r, "size"), nlohmann::json::array({1.2, 1.8, 0.4})) << r["world"].dump();
  EXPECT_EQ(r["undo"]["depth"], 1);
  r = replay(drag + "- press: undo\n");
  EXPECT_EQ(fieldValue(r, "size"), nlohmann::json::array({0.8, 1.2, 0.4}));
  EXPECT_EQ(r["undo"]["depth"], 0);
}

TEST_F(ManipulatorReplay, ABoxRegionUnderAScaleIsSizedInItsOwnMetres) {
  // the zone, 1 m along x under a scale of 2, shows 2 m: its +x face pulled half as far again
  // out moves 0.5 m in the world, 0.25 m of its own, so its size grows by 0.5 m
  const std::string setup = "- press: scale-tool\n- select: stretched/zone\n- view: top\n";
  const auto before = replay(setup);
  ASSERT_TRUE(before["world"]["handles"].contains("scale +x")) << before["world"].dump();
  const auto r = replay(setup + "- drag: {from: [world, handles, scale +x], to: " + beyond(before["world"], "scale +x", 1.5) +
                        "}\n");
  EXPECT_EQ(fieldValue(r, "size"), nlohmann::json::array({1.5, 1.0, 0.2})) << r["world"].dump();
  EXPECT_EQ(r["undo"]["label"], "set stretched/zone.size");
}

TEST_F(ManipulatorReplay, ASpotLightIsAimedAtThePointerAndUndoRestoresItsDirection) {
  // from the front the light's plane y = 0 faces the view: the aim handle hangs below the light;
  // dragged as far to the right and as far down, the light points 45 degrees down toward +x
  const std::string setup = "- press: aim-tool\n- select: spot\n- view: front\n";
  const auto before = replay(setup);
  const auto& world = before["world"];
  ASSERT_TRUE(world["handles"].contains("aim")) << world.dump();
  ASSERT_TRUE(world["handles"].contains("cone"));
  const double px = world["pivot"][0].get<double>(), py = world["pivot"][1].get<double>();
  const double reach = world["handles"]["aim"][1].get<double>() - py;
  EXPECT_GT(reach, 50.0) << "the aim handle hangs below the light";
  EXPECT_NEAR(world["handles"]["aim"][0].get<double>(), px, 1.0);
  const std::string drag = setup + "- drag: {from: [world, handles, aim], to: " + at(px + reach, py + reach) + "}\n";
  auto r = replay(drag);
  const auto d = fieldValue(r, "direction");
  ASSERT_EQ(d.size(), 3U) << r["inspector"].dump();
  EXPECT_NEAR(d[0].get<double>(), std::sqrt(0.5), 1e-9);
  EXPECT_EQ(d[1].get<double>(), 0.0);
  EXPECT_NEAR(d[2].get<double>(), -std::sqrt(0.5), 1e-9);
  EXPECT_EQ(fieldValue(r, "cutoff"), 30.0) << "the cone keeps its size";
  EXPECT_EQ(r["undo"]["depth"], 1);
  EXPECT_EQ(r["undo"]["label"], "set spot.direction");
  r = replay(drag + "- press: undo\n");
  EXPECT_EQ(fieldValue(r, "direction"), nlohmann::json::array({0.0, 0.0, -1.0}));
  // a press on the handle without a move changes nothing
  r = replay(setup + "- click: [world, handles, aim]\n");
  EXPECT_EQ(r["undo"]["depth"], 0);
}

TEST_F(ManipulatorReplay, ASpotLightDraggedOntoAShapeShinesOnIt) {
  // the aim dot dropped on the box's centre as seen from the front: the light at (0.3, 0, 1.3)
  // points at (0, -0.6, 0.5) on the box's front face, heading -116.6 and elevation -50.0
  // degrees, snapped to -115 and -50
  const std::string setup = "- press: aim-tool\n- select: spot\n- view: front\n";
  const auto box = replay("- press: scale-tool\n- select: stand/box\n- view: front\n");
  ASSERT_TRUE(box["world"].contains("pivot")) << box["world"].dump();
  const auto& p = box["world"]["pivot"];
  const auto r = replay(setup + "- drag: {from: [world, handles, aim], to: " + at(p[0].get<double>(), p[1].get<double>()) + "}\n");
  const auto d = fieldValue(r, "direction");
  ASSERT_EQ(d.size(), 3U) << r["inspector"].dump();
  constexpr double kDeg = 3.14159265358979323846 / 180;
  EXPECT_NEAR(d[0].get<double>(), std::cos(-50 * kDeg) * std::cos(-115 * kDeg), 1e-9);
  EXPECT_NEAR(d[1].get<double>(), std::cos(-50 * kDeg) * std::sin(-115 * kDeg), 1e-9);
  EXPECT_NEAR(d[2].get<double>(), std::sin(-50 * kDeg), 1e-9);
}

TEST_F(ManipulatorReplay, ASpotLightsConeIsSizedByItsHandleAndUndoRestoresIt) {
  // the cone's handle dragged to a point 45 degrees off the beam: a cone of 45 degrees
  const std::string setup = "- press: aim-tool\n- select: spot\n- view: front\n";
  const auto before = replay(setup);
  const auto& world = before["world"];
  ASSERT_TRUE(world["handles"].contains("cone")) << world.dump();
  const double px = world["pivot"][0].get<double>(), py = world["pivot"][1].get<double>();
  const std::string drag = setup + "- drag: {from: [world, handles, cone], to: " + at(px + 120, py + 120) + "}\n";
  auto r = replay(drag);
  EXPECT_EQ(fieldValue(r, "cutoff"), 45.0) << r["world"].dump();
  EXPECT_EQ(fieldValue(r, "direction"), nlohmann::json::array({0.0, 0.0, -1.0})) << "the beam keeps its direction";
  EXPECT_EQ(r["undo"]["label"], "set spot.cutoff");
  // wider than a hemisphere is refused: dragged above the light the cone stops at 90 degrees
  r = replay(setup + "- drag: {from: [world, handles, cone], to: " + at(px + 120, py - 30) + "}\n");
  EXPECT_EQ(fieldValue(r, "cutoff"), 90.0);
  r = replay(drag + "- press: undo\n");
  EXPECT_EQ(fieldValue(r, "cutoff"), 30.0);
}

// a slider joined to the world, its anchor left at the world's origin (a slider has no use for
// it), moving a plate placed at (1, 0.5, 0.3) along x between -0.2 and +0.4 m
constexpr const char* kSliderModel = R"Y(gdpn: 1
scene:
  - Camera: {name: view, position: [1, -2, 3], target: [1, 0.5, 0.3]}
  - Joint:
      name: rail
      kind: slider
      axis1: [1, 0, 0]
      lo1: -0.2
      hi1: 0.4
      children:
        - Transform:
            name: carriage
            translation: [1, 0.5, 0.3]
            children: [{Body: {name: plate, children: [{Cube: {size: [0.2, 0.2, 0.05]}}]}}]
pages:
  main: {}
)Y";

/// The unit the inspector shows for field `name`.
nlohmann::json fieldUnit(const nlohmann::json& report, const std::string& name) {
  for (const auto& f : report["inspector"]["fields"]) {
    if (f["name"] == name) return f["unit"];
  }
  return {};
}

TEST_F(ManipulatorReplay, ASlidersLimitsStandOnTheBodyItMovesInMetres) {
  model_ = write("slider.gdpn.yaml", kSliderModel);
  const auto body = replay("- select: rail/carriage\n- view: top\n")["world"]["pivot"];
  const auto r = replay("- select: rail\n- view: top\n");
  const auto& world = r["world"];
  ASSERT_TRUE(world["handles"].contains("lo1") && world["handles"].contains("hi1")) << world.dump();
  // the limits are drawn from the plate, not from the world's origin (the unused anchor)
  EXPECT_NEAR(world["pivot"][0].get<double>(), body[0].get<double>(), 1.0) << world.dump();
  EXPECT_NEAR(world["pivot"][1].get<double>(), body[1].get<double>(), 1.0) << world.dump();
  // along x seen from above: lo1 0.2 m to the left, hi1 0.4 m to the right, level with it
  const double px = world["pivot"][0].get<double>(), py = world["pivot"][1].get<double>();
  const double lo = world["handles"]["lo1"][0].get<double>() - px, hi = world["handles"]["hi1"][0].get<double>() - px;
  EXPECT_LT(lo, -10);
  EXPECT_NEAR(hi, -2 * lo, 2.0);
  EXPECT_NEAR(world["handles"]["hi1"][1].get<double>(), py, 1.0);
  // hi1 dragged halfway back to the plate: 0.2 m
  const auto dragged = replay("- select: rail\n- view: top\n- drag: {from: [world, handles, hi1], to: " +
                              beyond(world, "hi1", 0.5) + "}\n");
  EXPECT_EQ(fieldValue(dragged, "hi1"), 0.2) << dragged["world"].dump();
  // the inspector's units follow the joint's kind: a slider's in m, m/s and N
  EXPECT_EQ(fieldUnit(r, "lo1"), "m");
  EXPECT_EQ(fieldUnit(r, "hi1"), "m");
  EXPECT_EQ(fieldUnit(r, "target1"), "m");
  EXPECT_EQ(fieldUnit(r, "vel1"), "m/s");
  EXPECT_EQ(fieldUnit(r, "fmax1"), "N");
  EXPECT_EQ(fieldUnit(r, "anchor"), "m");
  // a hinge's in deg, deg/s and N m
  const auto hinge = replay("- set: {node: rail, field: kind, value: hinge}\n- select: rail\n");
  EXPECT_EQ(fieldUnit(hinge, "lo1"), "deg");
  EXPECT_EQ(fieldUnit(hinge, "target1"), "deg");
  EXPECT_EQ(fieldUnit(hinge, "vel1"), "deg/s");
  EXPECT_EQ(fieldUnit(hinge, "fmax1"), "N m");
}

}  // namespace
}  // namespace gdpn::ide
