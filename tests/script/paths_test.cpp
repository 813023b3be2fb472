// A model in a folder whose name is not valid UTF-8 (a path is bytes): its scripts compile,
// fail and are located as anywhere else, and every message shows the path with the bytes
// that are not UTF-8 written as \xNN, never aborting the process.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gdpn/core/diagnostics.h"
#include "gdpn/core/text.h"
#include "gdpn/model/simulation.h"

namespace gdpn::model {
namespace {

namespace fs = std::filesystem;

/// A model file written into a fresh folder named with a byte that is not UTF-8 (0xff).
class BytesFolderModel {
 public:
  explicit BytesFolderModel(const std::string& text) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("gdpn_" + std::string(info ? info->name() : "x") + "_" + std::to_string(getpid()) + "_\xff\xfe");
    fs::create_directories(dir_);
    path_ = (dir_ / "m.gdpn.yaml").string();
    std::ofstream(path_) << text;
  }
  ~BytesFolderModel() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  void addFile(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }
  /// The path as the user gave it (bytes).
  const std::string& path() const { return path_; }
  /// The path as messages show it.
  std::string shown() const { return core::escapeInvalidUtf8(path_); }
  /// The folder as messages show it, with a slash.
  std::string shownDir() const { return core::escapeInvalidUtf8(dir_.string()) + "/"; }
  /// Loads and compiles the model.
  std::unique_ptr<Simulation> open(core::Diagnostics& diags) const {
    auto m = loadModel(path_, diags);
    return m ? Simulation::create(*m, diags, std::nullopt, script::ScriptLimits{0, 0}) : nullptr;
  }

 private:
  fs::path dir_;
  std::string path_;
};

TEST(BytesPaths, EscapeWritesEveryByteThatIsNotUtf8AsHex) {
  EXPECT_EQ(core::escapeInvalidUtf8("/tmp/a\xff/b\xc3\xa9/\xe2\x82"), "/tmp/a\\xff/b\xc3\xa9/\\xe2\\x82");
  EXPECT_EQ(core::escapeInvalidUtf8("plain"), "plain");
}

TEST(BytesPaths, BadYamlIsLocatedAtTheEscapedPath) {
  BytesFolderModel m("gdpn: 1\npages:\n  main:\n    places: [P1, {\n");
  core::Diagnostics diags;
  EXPECT_FALSE(m.open(diags));
  EXPECT_EQ(diags.str().rfind(m.shown() + ":5:1: error: YAML syntax", 0), 0u) << diags.str();
}

TEST(BytesPaths, SyntaxErrorsInlineQuotedAndInAFileAreLocated) {
  BytesFolderModel m(R"Y(gdpn: 1
pages:
  main:
    places:
      P: {tokens: 1}
    transitions:
      T:
        pre_fire: |
          y = (1 +
        guard: "x >> > 1"
      U: {pre_fire: {file: cell.py, function: start}}
    arcs:
      - P -> T
      - P -> U
)Y");
  m.addFile("cell.py", "def start(self):\n    return 1 +\n");
  core::Diagnostics diags;
  EXPECT_FALSE(m.open(diags));
  const std::string all = diags.str();
  EXPECT_NE(all.find(m.shown() + ":9:"), std::string::npos) << all;
  EXPECT_NE(all.find(m.shown() + ":10:"), std::string::npos) << all;
  EXPECT_NE(all.find(m.shownDir() + "cell.py:2:"), std::string::npos) << all;
  EXPECT_EQ(core::firstInvalidUtf8(all), std::string::npos) << all;
}

TEST(BytesPaths, AGlobalsScriptThatRaisesIsLocated) {
  BytesFolderModel m("gdpn: 1\nscripts:\n  globals: |\n    x = 1\n    raise ValueError('boom')\n"
                     "pages:\n  main:\n    places:\n      P: {tokens: 1}\n");
  core::Diagnostics diags;
  EXPECT_FALSE(m.open(diags));
  const std::string all = diags.str();
  EXPECT_EQ(all.rfind(m.shown() + ":5: error: the globals script raised an exception", 0), 0u) << all;
  EXPECT_NE(all.find("ValueError: boom"), std::string::npos) << all;
  EXPECT_EQ(core::firstInvalidUtf8(all), std::string::npos) << all;
}

TEST(BytesPaths, AScriptFileThatRaisesIsLocated) {
  BytesFolderModel m("gdpn: 1\nscripts:\n  globals: {file: g.py}\npages:\n  main:\n    places:\n      P: {tokens: 1}\n");
  m.addFile("g.py", "a = 1\nraise ValueError('from the file')\n");
  core::Diagnostics diags;
  EXPECT_FALSE(m.open(diags));
  const std::string all = diags.str();
  EXPECT_NE(all.find(m.shownDir() + "g.py\", line 2"), std::string::npos) << all;
  EXPECT_NE(all.find("ValueError: from the file"), std::string::npos) << all;
  EXPECT_EQ(core::firstInvalidUtf8(all), std::string::npos) << all;
}

TEST(BytesPaths, AnExceptionDuringTheRunNamesTheEscapedPathAndLine) {
  BytesFolderModel m(R"Y(gdpn: 1
settings: {dt: 1, until: 10}
pages:
  main:
    places:
      P: {tokens: 1}
    transitions:
      T:
        pre_fire: |
          raise ValueError("in the run")
    arcs:
      - P -> T
)Y");
  core::Diagnostics diags;
  auto sim = m.open(diags);
  ASSERT_TRUE(sim) << diags.str();
  const auto outcome = sim->run({});
  EXPECT_EQ(outcome.reason, StopReason::ScriptError);
  EXPECT_EQ(outcome.message.rfind(m.shown() + ":10: error: pre_fire of transition 'main/T' at t = 0 s raised", 0), 0u)
      << outcome.message;
  EXPECT_NE(outcome.message.find("File \"" + m.shown() + "\", line 10"), std::string::npos) << outcome.message;
  EXPECT_NE(outcome.message.find("ValueError: in the run"), std::string::npos) << outcome.message;
}

#ifdef GDPN_CLI
TEST(BytesPaths, CheckAndRunExitOneWithLocatedMessages) {
  BytesFolderModel m("gdpn: 1\nscripts:\n  globals: |\n    raise ValueError('boom')\n"
                     "pages:\n  main:\n    places:\n      P: {tokens: 1}\n");
  for (const char* command : {"check", "run"}) {
    const std::string out = m.path() + ".out";
    const int status = std::system(
        ("'" + std::string(GDPN_CLI) + "' " + command + " '" + m.path() + "' > '" + out + "' 2>&1").c_str());
    std::stringstream text;
    text << std::ifstream(out).rdbuf();
    ASSERT_TRUE(WIFEXITED(status)) << command;
    EXPECT_EQ(WEXITSTATUS(status), 1) << command << ": " << text.str();
    EXPECT_EQ(text.str().rfind(m.shown() + ":4: error: the globals script raised an exception", 0), 0u)
        << command << ": " << text.str();
  }
}
#endif

}  // namespace
}  // namespace gdpn::model
