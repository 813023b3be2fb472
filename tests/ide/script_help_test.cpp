// The script editor in the headless IDE: completion as one types after `sim.` (the names the
// report lists under the field), Tab taking one; and a script's error in an edited model
// reported, and marked, at the line the model file has once saved.

#include <algorithm>
#include <fstream>
#include <sstream>

#include "ide/headless_fixture.h"
#include "support/scratch.h"

namespace gdpn::ide {
namespace {

// two transitions one after the other, each with a one-line script
const char* const kTwoSteps = R"Y(gdpn: 1
settings: {dt: 0.01, seed: 1}
pages:
  main:
    places:
      p: {tokens: 1}
      q: {}
      r: {}
    transitions:
      t1:
        duration: 1
        pre_fire: |
          x = 1
      t2:
        duration: 1
        pre_fire: |
          y = 2
    arcs:
      - p -> t1
      - t1 -> q
      - q -> t2
      - t2 -> r
)Y";

// the inspector made tall (its splitter dragged up) in a 1600 x 900 window
constexpr const char* kTall = "- drag: {from: [700, 641], to: [700, 200]}\n";

class ScriptHelp : public HeadlessIde {
 protected:
  void SetUp() override {
    HeadlessIde::SetUp();
    size_ = "1600x900";
  }
};

TEST_F(ScriptHelp, TypingSimDotOffersTheSimsNamesUnderTheCursorAndTabTakesOne) {
  const auto model = write("two.gdpn.yaml", kTwoSteps);
  const std::string start = std::string(kTall) + "- select: main/t2\n- click: [inspector, contents, editors, pre_fire, edit]\n";
  auto r = replayOn(model, start + "- type: 'sim.'\n");
  auto editor = r["inspector"]["contents"]["editors"]["pre_fire"];
  ASSERT_TRUE(editor.contains("completion")) << editor.dump();
  auto completion = editor["completion"];
  EXPECT_EQ(completion["open"], true);
  EXPECT_EQ(completion["context"], "sim");
  const std::vector<std::string> names = completion["names"];
  for (const char* n : {"dt", "log", "node", "params", "place", "random", "step", "stop", "time", "transition"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n << " in " << completion.dump();
  }
  EXPECT_EQ(completion["selected"], "dt");
  EXPECT_EQ(completion["detail"], "seconds");
  // narrowed by what follows, and taken by Tab
  r = replayOn(model, start + "- type: 'sim.ti'\n- key: tab\n");
  editor = r["inspector"]["contents"]["editors"]["pre_fire"];
  // typed before the script's own "y = 2"
  EXPECT_EQ(editor["text"], "sim.timey = 2\n") << editor.dump();
  EXPECT_EQ(editor["completion"]["open"], false);
  // self. of a transition: its slot among its names; Down chooses, Enter takes
  r = replayOn(model, start + "- type: 'self.'\n- key: down\n- key: down\n- key: enter\n");
  editor = r["inspector"]["contents"]["editors"]["pre_fire"];
  EXPECT_EQ(editor["text"], "self.elapsedy = 2\n") << editor.dump();  // a0, binding, elapsed
  r = replayOn(model, start + "- type: 'self.'\n");
  const std::vector<std::string> self_names = r["inspector"]["contents"]["editors"]["pre_fire"]["completion"]["names"];
  ASSERT_FALSE(self_names.empty());
  EXPECT_EQ(self_names.front(), "a0");
}

TEST_F(ScriptHelp, AScriptErrorInAnEditedModelIsReportedAtTheLineTheFileHasOnceSaved) {
  const auto model = write("two.gdpn.yaml", kTwoSteps);
  // three lines more in t1's script move t2's down by three; t2's script then raises
  const std::string edits = std::string(kTall) +
                            "- select: main/t1\n- click: [inspector, contents, editors, pre_fire, edit]\n"
                            "- type: \"a = 1\\nb = 2\\nc = 3\\n\"\n- click: [1390, 800]\n"
                            "- select: main/t2\n- click: [inspector, contents, editors, pre_fire, edit]\n"
                            "- type: \"z = undefined_name\\n\"\n- click: [1390, 800]\n- frames: 30\n"
                            "- press: run\n- frames: 150\n";
  auto r = replayOn(model, edits + "- press: save\n");
  // the file as saved: where the raising line stands
  const auto saved = gdpn::testing::fileBytes(model);
  std::istringstream lines(saved);
  int at = 0;
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n) {
    if (line.find("z = undefined_name") != std::string::npos) at = n;
  }
  ASSERT_EQ(at, 20) << saved;
  const std::string message = r["status"]["message"];
  EXPECT_NE(message.find("two.gdpn.yaml:20: error: pre_fire of transition 'main/t2'"), std::string::npos) << message;
  // the traceback quotes the line that raised, not what the file on disk held there
  EXPECT_NE(message.find("line 20, in <module>\n    z = undefined_name"), std::string::npos) << message;
  // marked in the script the run view shows: its first line, the file's 20th
  auto script = r["inspector"]["contents"]["scripts"][0];
  ASSERT_TRUE(script.contains("run_error")) << r["inspector"]["contents"].dump();
  EXPECT_EQ(script["run_error"]["line"], 1);
  EXPECT_EQ(script["run_error"]["file_line"], 20);
  EXPECT_EQ(script["run_error"]["message"], "NameError: name 'undefined_name' is not defined");
  EXPECT_EQ(script["first_line"], 20);
  // and in the editor after Reset, until the script is edited
  write("two.gdpn.yaml", kTwoSteps);
  r = replayOn(model, edits + "- press: reset\n");
  script = r["inspector"]["contents"]["editors"]["pre_fire"];
  EXPECT_EQ(script["run_error"]["file_line"], 20) << script.dump();
}

}  // namespace
}  // namespace gdpn::ide
