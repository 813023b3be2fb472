#pragma once
// Test support for the IDE tests: the headless IDE (EGL surfaceless) run as a program on a
// model with a replay file, its report read back, its settings and state kept in the test's
// own folder.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/cli.h"
#include "support/temp_files.h"

namespace gdpn::ide {

/// A test of the headless IDE: replays run on a model, their reports read back.
class HeadlessIde : public gdpn::testing::TempDirTest {
 protected:
  /// Runs the headless IDE (1280 x 720) on the factory with `actions` (a replay file's text);
  /// the report.
  nlohmann::json replay(const std::string& actions, const std::string& extra = {}, int expect = 0) {
    return replayOn("examples/factory", actions, extra, expect);
  }
  /// The same on the model at `model`.
  nlohmann::json replayOn(const std::string& model, const std::string& actions, const std::string& extra = {},
                          int expect = 0) {
    const auto file = write("actions.yaml", actions);
    const auto report = (dir_ / "report.json").string();
    std::filesystem::remove(report);
    last_ = gdpn::testing::runShell(env() + " \"$GDPN\" ide '" + model + "' --headless --size " + size_ +
                                    " --replay '" + file + "' --report '" + report + "' " + extra);
    EXPECT_EQ(last_.code, expect) << last_.out;
    if (last_.code != 0) return {};
    std::ifstream in(report);
    return nlohmann::json::parse(in, nullptr, false);
  }
  /// The settings and state folders of the IDEs these tests start: inside the test's folder.
  [[nodiscard]] std::string env() const {
    return "XDG_CONFIG_HOME='" + (dir_ / "config").string() + "' XDG_STATE_HOME='" + (dir_ / "state").string() + "'";
  }
  /// Starts the IDEs these tests run with the parts palette hidden (their settings say so): the
  /// tree has the whole left column, as before there was a palette, and no picture shows
  /// whatever parts library the machine holds.
  void hidePalette() {
    std::filesystem::create_directories(dir_ / "config" / "gdpn");
    std::ofstream(dir_ / "config" / "gdpn" / "ide.ini") << "palette=0\n";
  }
  /// The autosaves in the state folder.
  [[nodiscard]] std::vector<std::filesystem::path> autosaves() const {
    std::vector<std::filesystem::path> found;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir_ / "state" / "gdpn" / "autosave", ec)) {
      if (e.path().filename().string().front() != '.') found.push_back(e.path());
    }
    return found;
  }
  gdpn::testing::CliResult last_;
  std::string size_ = "1280x720";  // the window of the IDEs started
};

}  // namespace gdpn::ide
