#pragma once
// Test support: a model written to a temporary folder, for the script tests.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "gdpn/model/simulation.h"

namespace gdpn::testing {

/// A model written to a temporary folder (so that script files beside it can be found).
class ScriptModel {
 public:
  explicit ScriptModel(const std::string& text, const std::string& name = "m.gdpn.yaml") {
    // unique across tests and across processes (CTest runs tests side by side)
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() / ("gdpn_" + std::string(info ? info->name() : "x") + "_" +
                                                     std::to_string(getpid()) + "_" + std::to_string(counter()++));
    std::filesystem::create_directories(dir_);
    path_ = (dir_ / name).string();
    std::ofstream(path_) << text;
  }
  ~ScriptModel() { std::filesystem::remove_all(dir_); }
  void addFile(const std::string& name, const std::string& text) const {
    std::filesystem::create_directories((dir_ / name).parent_path());
    std::ofstream(dir_ / name) << text;
  }
  /// Loads and compiles; the diagnostics text on failure.
  std::unique_ptr<model::Simulation> open(core::Diagnostics& diags, double timeout = 0) const {
    auto m = model::loadModel(path_, diags);
    return m ? model::Simulation::create(*m, diags, std::nullopt, script::ScriptLimits{timeout, 0}) : nullptr;
  }
  const std::string& path() const { return path_; }

 private:
  static int& counter() {
    static int n = 0;
    return n;
  }
  std::filesystem::path dir_;
  std::string path_;
};

}  // namespace gdpn::testing
