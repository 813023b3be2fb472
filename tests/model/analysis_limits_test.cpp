// `gdpn analyze` under its limits: every phase (invariants, cycle times, state space) stops
// at --time-limit, --max-states or --max-memory with a labelled partial answer and exit 3.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "support/cli.h"

namespace {

namespace fs = std::filesystem;

using gdpn::testing::runGdpn;

/// A model whose one transition empties k places into k others: its k^2 minimal P-invariants
/// p_i + q_j appear in one elimination step, and sorting out the minimal ones is quadratic in
/// k^2 (for k = 280, minutes without a limit). Its state space has two markings.
/// (Each test process writes its own file: tests run side by side.)
std::string fanModel(int k) {
  const std::string path =
      (fs::temp_directory_path() / ("gdpn_fan_" + std::to_string(k) + "_" + std::to_string(::getpid()) + ".gdpn.yaml"))
          .string();
  std::ofstream f(path);
  f << "gdpn: 1\npages:\n  main:\n    places:\n";
  for (int i = 0; i < k; ++i) f << "      p" << i << ": {tokens: 1}\n      q" << i << ": {}\n";
  f << "    transitions:\n      t: {duration: 1}\n    arcs:\n";
  for (int i = 0; i < k; ++i) f << "      - p" << i << " -> t\n      - t -> q" << i << "\n";
  return path;
}

TEST(AnalyzeLimits, ExplodingInvariantsStopAtTheTimeLimitWithALabelledPartialAnswer) {
  const std::string model = fanModel(280);
  auto r = runGdpn("analyze '" + model + "' --time-limit 1 --progress");
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("stopped early: invariants (partial: --time-limit reached)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("invariants (partial: --time-limit reached):"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("invariants: column "), std::string::npos) << r.out;  // the progress line
  r = runGdpn("analyze '" + model + "' --time-limit 1 --json");
  ASSERT_EQ(r.code, 3) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_FALSE(j["partial"].empty()) << r.out;
  EXPECT_EQ(j["partial"][0]["phase"], "invariants");
  EXPECT_EQ(j["partial"][0]["stop"], "partial: --time-limit reached");
  EXPECT_EQ(j["invariants"]["complete"], false);
  fs::remove(model);
}

TEST(AnalyzeLimits, MaxStatesAndMaxMemoryBoundTheInvariantsToo) {
  const std::string model = fanModel(280);
  auto r = runGdpn("analyze '" + model + "' --max-memory 1");
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("stopped early: invariants (partial: --max-memory reached)"), std::string::npos) << r.out;
  r = runGdpn("analyze '" + model + "' --max-states 50");
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("stopped early: invariants (partial: too many candidates)"), std::string::npos) << r.out;
  fs::remove(model);
}

TEST(AnalyzeLimits, ASmallNetIsCompleteUnderTheLimits) {
  const std::string model = fanModel(4);
  const auto r = runGdpn("analyze '" + model + "' --time-limit 60 --max-memory 64");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find("stopped early"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("P-invariants (16)"), std::string::npos) << r.out;
  fs::remove(model);
}

}  // namespace
