// The I/O list in the headless IDE, driven by user input only (clicks on the items its report
// names, typed text, keys): its tab, values and forcing only during a run, a forced input that
// the control pattern answers, Release all, an analogue output forced by typing, two replays
// alike, and Map for PLC saved into the io section.

#include <gtest/gtest.h>

#include <string>

#include "gdpn/model/model.h"
#include "ide/headless_fixture.h"
#include "ide/lamp_model.h"

namespace gdpn::ide {
namespace {

class IoListIde : public HeadlessIde {
 protected:
  void SetUp() override {
    HeadlessIde::SetUp();
    size_ = "1600x900";
    path_ = write("lamp.gdpn.yaml", testing::lampModel());
  }
  /// The report after `actions` on the lamp model.
  nlohmann::json on(const std::string& actions, int expect = 0) { return replayOn(path_, actions, {}, expect); }
  std::string path_;
};

/// The list open and the run one step on: the start of the replays that force.
constexpr const char* kRunning = "- click: [inspector_tabs, I/O]\n- press: step\n";

TEST_F(IoListIde, ItsTabSharesTheInspectorsPanelAndOutsideARunShowsNoValuesAndForcesNothing) {
  auto r = on("- click: [inspector_tabs, I/O]\n- click: [io_list, rows, main/lamp1.seen, force1]\n");
  EXPECT_EQ(r["inspector_tabs"]["active"], "I/O");
  EXPECT_FALSE(r.contains("inspector"));
  const auto& list = r["io_list"];
  EXPECT_EQ(list["running"], false);
  EXPECT_EQ(list["order"].size(), 4U);
  const auto& seen = list["rows"]["main/lamp1.seen"];
  EXPECT_EQ(seen["direction"], "input");
  EXPECT_EQ(seen["signal"], "digital");
  EXPECT_TRUE(seen["value"].is_null());
  EXPECT_EQ(seen["forced"], false);
  EXPECT_EQ(seen["pending"], false);
  EXPECT_EQ(list["rows"]["main/lamp1.height"]["unit"], "m");
  EXPECT_EQ(list["rows"]["main/lamp1.light"]["addresses"], nlohmann::json::array({"coil 0"}));
  EXPECT_EQ(list["rows"]["main/lamp1.light"]["names"], nlohmann::json::array({"lamp1_light"}));
  EXPECT_EQ(list["rows"]["main/lamp1.height"]["uses"], nlohmann::json::array({"main/watch guard"}));
  EXPECT_EQ(r["run"]["mode"], "edit");
  // View > I/O List shows it and hides it again; Release All Forces cannot be done outside a run
  r = on("- press: io-list\n");
  EXPECT_EQ(r["inspector_tabs"]["active"], "I/O");
  r = on("- press: io-list\n- press: io-list\n");
  EXPECT_EQ(r["inspector_tabs"]["active"], "Inspector");
  r = on("- click: [inspector_tabs, I/O]\n- click: [inspector_tabs, Inspector]\n");
  EXPECT_EQ(r["inspector_tabs"]["active"], "Inspector");
  EXPECT_TRUE(r.contains("inspector"));
  on("- press: release-forces\n", 1);
  EXPECT_NE(last_.out.find("'release-forces' cannot be done now"), std::string::npos) << last_.out;
}

TEST_F(IoListIde, ForcingSeenLightsTheLampThroughItsControlPatternAndReleaseAllPutsItBack) {
  const std::string force = std::string(kRunning) + "- click: [io_list, rows, main/lamp1.seen, force1]\n";
  // asked while paused: it waits for the next step
  auto r = on(force);
  auto seen = r["io_list"]["rows"]["main/lamp1.seen"];
  EXPECT_EQ(r["io_list"]["running"], true);
  EXPECT_EQ(seen["pending"], true);
  EXPECT_EQ(seen["asked"], 1.0);
  EXPECT_EQ(seen["forced"], false);
  EXPECT_EQ(r["message"], "main/lamp1.seen forced to 1 at the next step");
  // at the next steps the input reads 1 and the control pattern lights the lamp
  r = on(force + "- steps: 5\n");
  seen = r["io_list"]["rows"]["main/lamp1.seen"];
  EXPECT_EQ(seen["forced"], true);
  EXPECT_EQ(seen["value"], 1.0);
  EXPECT_EQ(r["io_list"]["rows"]["main/lamp1.light"]["value"], 1.0);
  EXPECT_EQ(r["io_list"]["rows"]["main/lamp1.light"]["forced"], false);
  EXPECT_EQ(r["io_list"]["forced"], 1);
  // Release all: the plant's 0 again, and the lamp goes dark
  r = on(force + "- steps: 5\n- click: [io_list, release_all]\n- steps: 5\n");
  seen = r["io_list"]["rows"]["main/lamp1.seen"];
  EXPECT_EQ(seen["forced"], false);
  EXPECT_EQ(seen["value"], 0.0);
  EXPECT_EQ(r["io_list"]["rows"]["main/lamp1.light"]["value"], 0.0);
  EXPECT_EQ(r["io_list"]["forced"], 0);
  // one by one: Release on the row
  r = on(force + "- steps: 2\n- click: [io_list, rows, main/lamp1.seen, release]\n- steps: 2\n");
  EXPECT_EQ(r["io_list"]["rows"]["main/lamp1.seen"]["forced"], false);
}

TEST_F(IoListIde, AnAnalogueOutputIsForcedByTypingItsValue) {
  const std::string type = std::string(kRunning) + "- click: [io_list, rows, main/lamp1.speed, field]\n";
  auto r = on(type + "- type: \"0.25\"\n- key: enter\n- steps: 2\n");
  const auto& speed = r["io_list"]["rows"]["main/lamp1.speed"];
  EXPECT_EQ(speed["forced"], true);
  EXPECT_EQ(speed["value"], 0.25);
  EXPECT_EQ(speed["unit"], "m/s");
  // the Force button takes the typed value too; what is not a number is said so
  r = on(type + "- type: \"1.5\"\n- click: [io_list, rows, main/lamp1.speed, force]\n- steps: 1\n");
  EXPECT_EQ(r["io_list"]["rows"]["main/lamp1.speed"]["value"], 1.5);
  r = on(type + "- type: \"1e\"\n- key: enter\n");
  EXPECT_EQ(r["message"], "'1e' is not a number: type the value to force main/lamp1.speed to");
  EXPECT_EQ(r["io_list"]["rows"]["main/lamp1.speed"]["pending"], false);
}

TEST_F(IoListIde, TwoIdenticalReplaysThatForceGiveIdenticalReports) {
  const std::string actions = std::string(kRunning) +
                              "- click: [io_list, rows, main/lamp1.seen, force1]\n- steps: 7\n"
                              "- click: [io_list, rows, main/lamp1.speed, field]\n- type: \"0.5\"\n- key: enter\n"
                              "- steps: 3\n- click: [io_list, release_all]\n- steps: 4\n";
  const auto a = on(actions);
  const auto b = on(actions);
  EXPECT_EQ(a["io_list"], b["io_list"]);
  EXPECT_EQ(a["run"], b["run"]);
  EXPECT_EQ(a["net_view"], b["net_view"]);
  EXPECT_EQ(a["run"]["steps"], 15);
}

TEST_F(IoListIde, MapForPlcPutsThePartsIoIntoTheSavedIoSectionAsOneStep) {
  auto r = on("- click: [inspector_tabs, I/O]\n- click: [io_list, parts, main/lamp1, map]\n- key: ctrl+s\n");
  EXPECT_EQ(r["io_list"]["parts"]["main/lamp1"]["unmapped"], 0);
  EXPECT_FALSE(r["io_list"]["parts"]["main/lamp1"].contains("map"));  // nothing left to map
  EXPECT_EQ(r["io_list"]["rows"]["main/lamp1.seen"]["addresses"], nlohmann::json::array({"discrete input 0"}));
  EXPECT_EQ(r["undo"]["label"], "map lamp1's I/O for a PLC");
  EXPECT_EQ(r["undo"]["depth"], 1);
  core::Diagnostics diags;
  const auto saved = model::loadModel(path_, diags);
  ASSERT_TRUE(saved) << diags.str();
  ASSERT_EQ(saved->io.entries.size(), 4U);
  const auto find = [&](model::IoTable table) -> const model::IoEntry* {
    for (const auto& e : saved->io.entries) {
      if (e.table == table) return &e;
    }
    return nullptr;
  };
  const auto* seen = find(model::IoTable::DiscreteInputs);
  ASSERT_TRUE(seen);
  EXPECT_EQ(seen->address, 0);
  EXPECT_EQ(seen->target, "main/lamp1");
  EXPECT_EQ(seen->io, "seen");
  const auto* speed = find(model::IoTable::HoldingRegisters);
  ASSERT_TRUE(speed);
  EXPECT_EQ(speed->io, "speed");
  EXPECT_EQ(speed->type, model::IoDataType::Float);
  EXPECT_EQ(find(model::IoTable::InputRegisters)->io, "height");
  // an edit: during a run the button does nothing
  write("lamp.gdpn.yaml", testing::lampModel());
  r = on(std::string(kRunning) + "- click: [io_list, parts, main/lamp1, map]\n");
  EXPECT_EQ(r["io_list"]["parts"]["main/lamp1"]["unmapped"], 3);
  EXPECT_EQ(r["undo"]["depth"], 0);
}

}  // namespace
}  // namespace gdpn::ide
