// No lost input: the headless IDE pressing and releasing keys within one frame, through the
// same input queue as the window. Before the queue, each of these was lost (ImGui 1.86 reads
// the keys once a frame): Ctrl+S did not save, Enter did not commit a rename, Ctrl+A did not
// select a script's text and typing appended to it.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "ide/ide_model.h"
#include "support/cli.h"
#include "support/temp_files.h"

namespace gdpn::ide {
namespace {

using gdpn::testing::runShell;

class QuickKeys : public gdpn::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    model_ = write("bin.gdpn.yaml", ide::testing::kBinModel);
  }
  /// Runs the headless IDE (1280 x 720) on the model with `actions` (a replay file's text);
  /// the report (empty when the IDE failed).
  nlohmann::json replay(const std::string& actions) {
    const auto file = write("actions.yaml", actions);
    const auto report = (dir_ / "report.json").string();
    std::filesystem::remove(report);
    std::filesystem::remove_all(dir_ / "config");  // each IDE with the layout it starts with
    const auto env = "XDG_CONFIG_HOME='" + (dir_ / "config").string() + "' XDG_STATE_HOME='" + (dir_ / "state").string() + "'";
    last_ = runShell(env + " \"$GDPN\" ide '" + model_ + "' --headless --size 1280x720 --replay '" + file +
                     "' --report '" + report + "'");
    EXPECT_EQ(last_.code, 0) << last_.out;
    if (last_.code != 0) return {};
    std::ifstream in(report);
    return nlohmann::json::parse(in, nullptr, false);
  }
  /// The model file's text.
  [[nodiscard]] std::string saved() const {
    std::ifstream in(model_, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  std::string model_;
  gdpn::testing::CliResult last_;
};

// the inspector made tall (its splitter dragged up) so that the contents view shows whole
constexpr const char* kTallInspector = "- drag: {from: [560, 460], to: [560, 160]}\n";

TEST_F(QuickKeys, CtrlSPressedAndReleasedWithinOneFrameSavesTheModel) {
  const auto before = saved();
  const auto r = replay("- set: {node: drop/paint, field: bounce, value: 0.5}\n- key: ctrl+s\n");
  EXPECT_EQ(r["message"], "saved " + model_) << r["message"];
  const auto after = saved();
  EXPECT_NE(after, before);
  EXPECT_NE(after.find("bounce: 0.5"), std::string::npos) << after;
  EXPECT_EQ(gdpn::testing::runGdpn("check '" + model_ + "'").code, 0) << after;
}

TEST_F(QuickKeys, AQuickEnterCommitsARenameInTheTree) {
  // the node's menu: its name field has the keyboard with the name selected; Enter, pressed
  // and released within one frame, commits the name typed over it
  const auto r = replay("- click: {at: [tree, rows, drop], button: right}\n- type: bucket\n- key: enter\n");
  EXPECT_EQ(r["undo"]["label"], "rename drop to bucket") << r["undo"].dump();
  EXPECT_TRUE(r["tree"]["rows"].contains("bucket")) << r["tree"].dump();
  EXPECT_FALSE(r["tree"]["rows"].contains("drop")) << r["tree"].dump();
}

TEST_F(QuickKeys, CtrlAThenTypingReplacesTheScriptText) {
  // a pre_fire script written, left (compiled, stored), then opened again
  const std::string written = std::string(kTallInspector) +
                              "- select: main/work\n"
                              "- click: [inspector, contents, editors, pre_fire, edit]\n"
                              "- type: \"old = 1\\n\"\n"
                              "- click: [1100, 700]\n"
                              "- click: [inspector, contents, editors, pre_fire, edit]\n"
                              "- frames: 2\n";
  // Ctrl+A within one frame, then the new text typed
  auto r = replay(written + "- key: ctrl+a\n- type: \"new = 2\\n\"\n- click: [1100, 700]\n- press: save\n");
  auto text = saved();
  EXPECT_NE(text.find("new = 2"), std::string::npos) << text;
  EXPECT_EQ(text.find("old = 1"), std::string::npos) << "the typing was appended, Ctrl+A was lost:\n" << text;
  EXPECT_EQ(r["inspector"]["contents"]["editors"]["pre_fire"]["lines"], 1) << r["inspector"]["contents"].dump();
  // Ctrl+A and the typing queued before one frame: they reach the editor in order, the text
  // after the selection and without Ctrl
  model_ = write("bin.gdpn.yaml", ide::testing::kBinModel);
  r = replay(written + "- key: ctrl+a n e w 2\n- click: [1100, 700]\n- press: save\n");
  text = saved();
  EXPECT_NE(text.find("new2"), std::string::npos) << text;
  EXPECT_EQ(text.find("old = 1"), std::string::npos) << "the typing was appended, Ctrl+A was lost:\n" << text;
  EXPECT_EQ(r["inspector"]["contents"]["editors"]["pre_fire"]["lines"], 1) << r["inspector"]["contents"].dump();
}

TEST_F(QuickKeys, AnUnknownKeyInAChordIsALocatedError) {
  const auto file = write("actions.yaml", "- press: step\n- key: ctrl+f13\n");
  const auto r = runShell("\"$GDPN\" ide '" + model_ + "' --headless --size 640x360 --replay '" + file + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("actions.yaml:2:3: error: unknown key 'f13'"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace gdpn::ide
