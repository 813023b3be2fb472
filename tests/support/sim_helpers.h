#pragma once
// Test support: opening models and reading the sim.log lines of a trace.

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "gdpn/model/simulation.h"

namespace gdpn::testing {

/// The model at `relative` (from the source tree), made ready to run; null after a failed
/// expectation that shows the diagnostics.
inline std::unique_ptr<model::Simulation> openModelFile(const std::string& relative,
                                                      std::optional<std::uint64_t> seed = {}) {
  core::Diagnostics diags;
  auto m = model::loadModel(std::string(GDPN_SOURCE_DIR) + "/" + relative, diags);
  std::unique_ptr<model::Simulation> sim;
  if (m) sim = model::Simulation::create(*m, diags, seed);
  EXPECT_TRUE(sim) << diags.str();
  return sim;
}

/// The text of every sim.log line in a JSON Lines trace, in order.
inline std::vector<std::string> logLines(const std::string& trace) {
  std::vector<std::string> out;
  std::istringstream lines(trace);
  std::string line;
  while (std::getline(lines, line)) {
    const auto at = line.find("\"ev\":\"log\",\"text\":\"");
    if (at != std::string::npos) out.push_back(line.substr(at + 19, line.size() - at - 21));
  }
  return out;
}

}  // namespace gdpn::testing
