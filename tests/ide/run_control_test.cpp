// The IDE's run controls against the Session: step, run N steps, run for a time, fire (and
// why not), plant only, reset back to the document exactly, and a run that never changes the
// document.

#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "gdpn/ide/document.h"
#include "gdpn/ide/run_control.h"
#include "gdpn/ide/set_field.h"
#include "gdpn/opcua/client.h"
#include "ide/ide_model.h"
#include "support/cli.h"
#include "support/temp_files.h"

namespace gdpn::ide {
namespace {

using gdpn::testing::TempDirTest;
using ide::testing::kBinModel;

class RunControlTest : public TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    core::Diagnostics diags;
    doc_ = Document::open(write("bin.gdpn.yaml", kBinModel), diags);
    ASSERT_TRUE(doc_) << diags.str();
    ASSERT_TRUE(run_.open(*doc_, diags)) << diags.str();
  }
  std::int64_t tokens(const std::string& place) const {
    const auto& sim = run_.session()->simulation();
    return sim.kernel().placeTokens(*sim.net().findPlace(place));
  }
  std::unique_ptr<Document> doc_;
  RunControl run_;
};

TEST_F(RunControlTest, StepAdvancesExactlyOneStep) {
  EXPECT_EQ(run_.mode(), RunMode::Edit);
  EXPECT_EQ(run_.steps(), 0);
  run_.step();
  EXPECT_EQ(run_.steps(), 1);
  EXPECT_DOUBLE_EQ(run_.time(), 0.01);
  EXPECT_EQ(run_.mode(), RunMode::Paused);
  run_.runSteps(5);
  EXPECT_EQ(run_.steps(), 6);
}

TEST_F(RunControlTest, RunForAdvancesModelTimeInWholeSteps) {
  run_.runFor(0.5);
  EXPECT_EQ(run_.steps(), 50);
}

TEST_F(RunControlTest, RunTakesTheStepsTheClockOwes) {
  run_.run(RunSpeed::RealTime);
  EXPECT_EQ(run_.mode(), RunMode::Running);
  run_.advance(0.1);
  EXPECT_EQ(run_.steps(), 10);
  run_.run(RunSpeed::Faster);
  run_.advance(0.1);
  EXPECT_EQ(run_.steps(), 10 + static_cast<std::int64_t>(10 * kFasterFactor));
  run_.pause();
  run_.advance(0.1);
  EXPECT_EQ(run_.mode(), RunMode::Paused);
  EXPECT_EQ(run_.steps(), 10 + static_cast<std::int64_t>(10 * kFasterFactor));
}

TEST_F(RunControlTest, FiringADisabledTransitionSaysWhyNot) {
  const auto why = run_.fire("main/stuck");
  EXPECT_NE(why, "");
  EXPECT_NE(run_.message().find("cannot fire main/stuck: "), std::string::npos) << run_.message();
  EXPECT_NE(run_.message().find("never"), std::string::npos) << run_.message();
  EXPECT_NE(run_.fire("main/nothing"), "");
}

TEST_F(RunControlTest, FiringAnEnabledTransitionStartsIt) {
  EXPECT_EQ(run_.fire("main/manual"), "");
  EXPECT_EQ(tokens("main/spare"), 0);
  EXPECT_EQ(run_.message(), "fired main/manual");
}

TEST_F(RunControlTest, TheTransitionsListIsTheNets) {
  const auto names = run_.transitions();
  ASSERT_EQ(names.size(), 5U);
  EXPECT_EQ(names.front(), "main/work");
}

TEST_F(RunControlTest, ABreakpointStopsTheRunAndSaysWhich) {
  ASSERT_EQ(run_.addBreakpoint(session::Breakpoint::starts("main/rest")), "");
  EXPECT_NE(run_.addBreakpoint(session::Breakpoint::starts("main/nothing")), "");
  EXPECT_EQ(run_.breakpoints(), std::vector<std::string>{"starts main/rest"});
  run_.runFor(2.0);
  EXPECT_LT(run_.steps(), 200);
  EXPECT_EQ(run_.mode(), RunMode::Paused);
  EXPECT_EQ(run_.message(), "stopped at breakpoint: starts main/rest");
  // kept across a reset; removed by its description
  core::Diagnostics diags;
  ASSERT_TRUE(run_.reset(diags));
  EXPECT_EQ(run_.breakpoints().size(), 1U);
  EXPECT_TRUE(run_.removeBreakpoint("starts main/rest"));
  run_.runFor(2.0);
  EXPECT_EQ(run_.steps(), 200);
}

TEST_F(RunControlTest, PlantOnlyMovesThePlantAndKeepsTheMarking) {
  run_.step();  // the net starts: both tokens go into work
  const auto idle = tokens("main/idle"), busy = tokens("main/busy");
  run_.setPlantOnly(true);
  run_.runSteps(100);
  EXPECT_EQ(tokens("main/idle"), idle);
  EXPECT_EQ(tokens("main/busy"), busy);
  EXPECT_EQ(run_.steps(), 101);
  const auto* box = run_.session()->simulation().plant()->find("drop/box");
  ASSERT_TRUE(box->dynamic_pose);
  EXPECT_LT(box->dynamic_pose->position.z, 2.5);  // it fell from 3 m
}

TEST_F(RunControlTest, ResetThenRunGivesTheTraceOfAFreshRun) {
  std::ostringstream expected;
  {
    core::Diagnostics diags;
    auto fresh = session::Session::create(doc_->snapshot(), diags);
    ASSERT_TRUE(fresh) << diags.str();
    fresh->traceTo(expected);
    fresh->run({2.0, {}});
  }
  run_.runFor(0.7);
  (void)run_.fire("main/work");
  run_.setPlantOnly(true);
  run_.step();
  run_.setPlantOnly(false);
  std::ostringstream again;
  run_.session()->traceTo(again);
  core::Diagnostics diags;
  ASSERT_TRUE(run_.reset(diags)) << diags.str();
  EXPECT_EQ(run_.mode(), RunMode::Edit);
  EXPECT_EQ(run_.steps(), 0);
  run_.runFor(2.0);
  EXPECT_EQ(again.str(), expected.str());
}

TEST_F(RunControlTest, TheRunNeverChangesTheDocument) {
  const auto before = doc_->text();
  const auto revision = doc_->revision();
  run_.runFor(2.0);
  EXPECT_EQ(doc_->text(), before);
  EXPECT_EQ(doc_->revision(), revision);
}

TEST_F(RunControlTest, ResetTakesTheEditedDocument) {
  run_.runFor(0.5);
  ASSERT_EQ(doc_->execute(std::make_unique<SetFieldCommand>("drop", "translation",
                                                             scene::FieldValue{std::array{0.0, 0.0, 9.0}})),
            "");
  core::Diagnostics diags;
  ASSERT_TRUE(run_.reset(diags)) << diags.str();
  const auto* drop = run_.session()->simulation().plant()->find("drop");
  EXPECT_DOUBLE_EQ(drop->localPose().position.z, 9.0);
}

/// The push button (kButtonModel): clicks of the world view reach its MouseSensor through the run.
class RunControlClick : public TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    core::Diagnostics diags;
    doc_ = Document::open(write("button.gdpn.yaml", ide::testing::kButtonModel), diags);
    ASSERT_TRUE(doc_) << diags.str();
    ASSERT_TRUE(run_.open(*doc_, diags)) << diags.str();
  }
  /// The pick ray from the model's camera toward `to` (world frame, m).
  static core::Ray rayTo(core::Vec3 to) {
    const core::Vec3 eye{3, -3, 2};
    const auto d = to - eye;
    return {eye, d * (1.0 / d.length())};
  }
  std::int64_t tokens(const std::string& place) const {
    const auto& sim = run_.session()->simulation();
    return sim.kernel().placeTokens(*sim.net().findPlace(place));
  }
  /// The `clicks` channel of the run's button/mouse.
  double clicks() const {
    const auto& sim = run_.session()->simulation();
    const auto* sensor = sim.plant()->find("button/mouse");
    return sim.reading(sensor->handle()).number("clicks");
  }
  std::unique_ptr<Document> doc_;
  RunControl run_;
};

TEST_F(RunControlClick, AClickOnTheButtonDuringARunIsFeltAtTheNextStep) {
  run_.step();
  const auto target = run_.click(rayTo({0, 0, 0}));
  ASSERT_NE(target.hit.shape, nullptr);
  EXPECT_EQ(target.hit.shape->path(), "button/cap");
  ASSERT_EQ(target.sensors.size(), 1U);
  EXPECT_EQ(target.sensors[0]->path(), "button/mouse");
  EXPECT_EQ(run_.message(), "clicked button/cap: button/mouse feels it at the next step");
  // nothing happens before the step boundary
  EXPECT_EQ(clicks(), 0);
  EXPECT_EQ(tokens("main/pressed"), 0);
  run_.step();
  EXPECT_EQ(clicks(), 1);
  run_.step();
  EXPECT_EQ(tokens("main/pressed"), 1);
}

TEST_F(RunControlClick, AClickThatMissesTheButtonIsNotCounted) {
  run_.step();
  const auto target = run_.click(rayTo({0, 0, 3}));
  EXPECT_EQ(target.hit.shape, nullptr);
  EXPECT_TRUE(target.sensors.empty());
  EXPECT_EQ(run_.message(), "");
  run_.runSteps(3);
  EXPECT_EQ(clicks(), 0);
  EXPECT_EQ(tokens("main/pressed"), 0);
}

TEST_F(RunControlClick, AClickInEditModeDoesNotReachTheRun) {
  // nothing runs yet: the click selects in the world view, and the run made later never sees it
  EXPECT_EQ(run_.mode(), RunMode::Edit);
  const auto target = run_.click(rayTo({0, 0, 0}));
  EXPECT_EQ(target.hit.shape, nullptr);
  EXPECT_TRUE(target.sensors.empty());
  run_.runSteps(3);
  EXPECT_EQ(clicks(), 0);
  EXPECT_EQ(tokens("main/pressed"), 0);
}

#ifdef GDPN_CLI
TEST_F(RunControlClick, AClickGivesTheTraceOfGdpnRunsInputClickAtTheNextStep) {
  // gdpn run --input with the click at 0.06 s; the IDE's click at 0.05 s is felt at the step
  // that ends at 0.06 s
  const auto model = (dir_ / "button.gdpn.yaml").string();
  const auto input = write("clicks.yaml", "- {t: 0.06, click: {from: [3, -3, 2], to: [0, 0, 0]}}\n");
  const auto trace = (dir_ / "cli.jsonl").string();
  const auto r = gdpn::testing::runGdpn("run '" + model + "' --until 0.5 --input '" + input + "' --trace '" + trace + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream in(trace);
  std::stringstream cli;
  cli << in.rdbuf();
  ASSERT_NE(cli.str().find("press"), std::string::npos) << cli.str();

  run_.step();
  core::Diagnostics diags;
  std::ostringstream ide;
  run_.session()->traceTo(ide);
  ASSERT_TRUE(run_.reset(diags)) << diags.str();
  run_.runSteps(5);
  (void)run_.click(rayTo({0, 0, 0}));
  run_.runSteps(45);
  EXPECT_EQ(ide.str(), cli.str());
}

TEST_F(RunControlTest, ResetThenRunGivesTheSameTraceAsGdpnRun) {
  const auto model = (dir_ / "bin.gdpn.yaml").string();
  const auto trace = (dir_ / "cli.jsonl").string();
  const auto r = gdpn::testing::runGdpn("run '" + model + "' --until 2 --trace '" + trace + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream in(trace);
  std::stringstream cli;
  cli << in.rdbuf();

  run_.runFor(1.0);
  core::Diagnostics diags;
  std::ostringstream ide;
  run_.session()->traceTo(ide);
  ASSERT_TRUE(run_.reset(diags));
  run_.runFor(2.0);
  EXPECT_EQ(ide.str(), cli.str());
}

TEST(RunControlFactory, ResetThenRunGivesTheSameTraceAsGdpnRun) {
  const auto dir = std::filesystem::temp_directory_path() / ("gdpn_ide_factory_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto trace = (dir / "cli.jsonl").string();
  const auto r = gdpn::testing::runGdpn("run examples/factory --until 3 -q --trace '" + trace + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream in(trace);
  std::stringstream cli;
  cli << in.rdbuf();
  ASSERT_GT(cli.str().size(), 100U);

  core::Diagnostics diags;
  auto doc = Document::open(std::string(GDPN_SOURCE_DIR) + "/examples/factory/factory.gdpn.yaml", diags);
  ASSERT_TRUE(doc) << diags.str();
  RunControl run;
  ASSERT_TRUE(run.open(*doc, diags)) << diags.str();
  run.runFor(1.5);
  (void)run.fire("factory/stationA/skip");
  std::ostringstream ide;
  run.session()->traceTo(ide);
  ASSERT_TRUE(run.reset(diags)) << diags.str();
  run.runFor(3.0);
  EXPECT_EQ(ide.str(), cli.str());
  std::filesystem::remove_all(dir);
}
#endif

}  // namespace
}  // namespace gdpn::ide

namespace gdpn::ide {
namespace {

/// `run` kept going (advanced each millisecond, as the IDE's frames do) in a thread while a
/// client talks to it.
class Frames {
 public:
  explicit Frames(RunControl& run) : thread_([this, &run] {
      while (!stop_) {
        run.advance(0.001);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    }) {}
  ~Frames() {
    stop_ = true;
    thread_.join();
  }

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

double readNumber(opcua::Client& c, const std::string& node) {
  std::vector<opcua::DataValue> values;
  std::string why;
  EXPECT_TRUE(c.read({{opcua::NodeId::str(node), 13}}, values, why)) << why;
  return values.empty() || !values[0].value ? -1.0 : values[0].value->number().value_or(-1.0);
}

TEST_F(RunControlTest, ServesTheRunOverOpcUaWhilePausedAndThroughAReset) {
  EXPECT_EQ(run_.serveOpcua("nonsense"), "--opcua: expected [ADDRESS:]PORT with a port from 0 to 65535 (0: any free one), got 'nonsense'");
  EXPECT_EQ(run_.opcuaUrl(), "");
  ASSERT_EQ(run_.serveOpcua("0"), "");
  const std::string url = run_.opcuaUrl();
  ASSERT_TRUE(url.starts_with("opc.tcp://127.0.0.1:")) << url;
  EXPECT_EQ(run_.message(), "serving the run over OPC UA on " + url);
  run_.runSteps(7);  // paused after them
  {
    Frames frames(run_);
    std::string why;
    auto client = opcua::Client::connect(url, {}, why);
    ASSERT_TRUE(client) << why;
    EXPECT_DOUBLE_EQ(readNumber(*client, "time"), 0.07);
    EXPECT_EQ(readNumber(*client, "place/main/spare"), 1.0);
    EXPECT_EQ(readNumber(*client, "place/main/idle"), static_cast<double>(tokens("main/idle")));
    client->close();
  }
  // reset: the run made anew is served at the same address
  core::Diagnostics diags;
  ASSERT_TRUE(run_.reset(diags)) << diags.str();
  EXPECT_EQ(run_.opcuaUrl(), url);
  {
    Frames frames(run_);
    std::string why;
    auto client = opcua::Client::connect(url, {}, why);
    ASSERT_TRUE(client) << why;
    EXPECT_DOUBLE_EQ(readNumber(*client, "time"), 0.0);
    client->close();
  }
  run_.stopServing();
  EXPECT_EQ(run_.opcuaUrl(), "");
  std::string why;
  EXPECT_FALSE(opcua::Client::connect(url, {}, why));
}

}  // namespace
}  // namespace gdpn::ide
