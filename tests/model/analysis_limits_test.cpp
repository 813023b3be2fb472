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

/// A model of fans: each transition t<k>_<c> empties k places into k others (c tokens into
/// each), for k from `from` to `to` and c from 1 to `copies`: fan k has k^2 minimal
/// P-invariants, all made in one elimination step, and no two fans are alike (so each is
/// worked out). Fan 280 alone has two markings and more invariants than the candidate limit;
/// fans 40 to 70 twice over, each under that limit, take a good part of a second together and
/// hold many megabytes. (Each test process writes its own file: tests run side by side.)
std::string fanModel(int from, int to, int copies = 1) {
  const std::string path = (fs::temp_directory_path() / ("gdpn_fan_" + std::to_string(from) + "_" + std::to_string(to) +
                                                         "_" + std::to_string(::getpid()) + ".gdpn.yaml"))
                               .string();
  std::ofstream f(path);
  f << "gdpn: 1\npages:\n  main:\n    places:\n";
  for (int c = 1; c <= copies; ++c) {
    for (int k = from; k <= to; ++k) {
      for (int i = 0; i < k; ++i) f << "      p" << k << "_" << c << "_" << i << ": {tokens: 1}\n      q" << k << "_" << c << "_" << i << ": {}\n";
    }
  }
  f << "    transitions:\n";
  for (int c = 1; c <= copies; ++c) {
    for (int k = from; k <= to; ++k) f << "      t" << k << "_" << c << ": {duration: 1}\n";
  }
  f << "    arcs:\n";
  for (int c = 1; c <= copies; ++c) {
    for (int k = from; k <= to; ++k) {
      const std::string t = "t" + std::to_string(k) + "_" + std::to_string(c);
      for (int i = 0; i < k; ++i) {
        f << "      - p" << k << "_" << c << "_" << i << " -> " << t << "\n      - {from: " << t << ", to: q" << k << "_" << c << "_"
          << i << ", weight: " << c << "}\n";
      }
    }
  }
  return path;
}

TEST(AnalyzeLimits, ExplodingInvariantsStopAtTheTimeLimitWithALabelledPartialAnswer) {
  const std::string model = fanModel(40, 70, 2);
  auto r = runGdpn("analyze '" + model + "' --time-limit 0.02 --progress");
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("stopped early: invariants (partial: --time-limit reached)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("invariants (partial: --time-limit reached):"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("invariants: column "), std::string::npos) << r.out;  // the progress line
  r = runGdpn("analyze '" + model + "' --time-limit 0.02 --json");
  ASSERT_EQ(r.code, 3) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_FALSE(j["partial"].empty()) << r.out;
  EXPECT_EQ(j["partial"][0]["phase"], "invariants");
  EXPECT_EQ(j["partial"][0]["stop"], "partial: --time-limit reached");
  EXPECT_EQ(j["invariants"]["complete"], false);
  fs::remove(model);
}

TEST(AnalyzeLimits, MaxStatesAndMaxMemoryBoundTheInvariantsToo) {
  std::string model = fanModel(40, 70, 2);
  auto r = runGdpn("analyze '" + model + "' --max-memory 1 --time-limit 60");
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("stopped early: invariants (partial: --max-memory reached)"), std::string::npos) << r.out;
  fs::remove(model);
  model = fanModel(280, 280);
  r = runGdpn("analyze '" + model + "' --max-states 50");
  // the list cut is named: fan 280's P-invariants (its T-invariants, none, are whole). Too
  // many to list within the candidates' budget, they leave no answer open (a linear program
  // says whether the net is conservative): nothing stopped early, and the exit status is 0
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find("stopped early"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("invariants (P-invariants listed in part: too many to list):"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("P-invariants (0 found; the list was cut short):"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("T-invariants (0): none"), std::string::npos) << r.out;
  fs::remove(model);
}

TEST(AnalyzeLimits, ASmallNetIsCompleteUnderTheLimits) {
  const std::string model = fanModel(4, 4);
  const auto r = runGdpn("analyze '" + model + "' --time-limit 60 --max-memory 64");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find("stopped early"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("P-invariants (16)"), std::string::npos) << r.out;
  fs::remove(model);
}

TEST(AnalyzeLimits, AContestNetWhoseInvariantsUsedToBeCutIsAnsweredWholeWithExitZero) {
  // DoubleExponent-PT-003: bounded, not structurally bounded; the semiflows of y·C <= 0
  // explode, and the invariants phase stopped there (exit 3) though the state space is whole
  const std::string net = std::string(GDPN_SOURCE_DIR) + "/tests/data/bench-nets/DoubleExponent-PT-003.pnml";
  auto r = runGdpn("analyze '" + net + "' --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["states"], 2385072) << "the contest's count";
  EXPECT_TRUE(j["partial"].empty());
  EXPECT_TRUE(j["invariants"]["complete"]);
  EXPECT_TRUE(j["invariants"]["p_complete"]);
  EXPECT_TRUE(j["invariants"]["t_complete"]);
  EXPECT_EQ(j["invariants"]["p"].size(), 17u);
  EXPECT_FALSE(j["invariants"]["structurally_bounded"]);
  r = runGdpn("analyze '" + net + "'");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("invariants:\n  conservative: no; structurally bounded: no; covered by T-invariants: no"),
            std::string::npos) << r.out;
}

TEST(AnalyzeLimits, MinimalTInvariantsTooManyToListLeaveNoAnswerOpen) {
  // BridgeAndVehicles-PT-V10P10N10 has 83,616,500 minimal T-invariants (tests/data/bench-nets):
  // the list is cut at the candidates' budget and says so, while the yes-or-no answers come
  // from linear programs and the state space is whole: exit 0, nothing "stopped early"
  const std::string net = std::string(GDPN_SOURCE_DIR) + "/tests/data/bench-nets/BridgeAndVehicles-PT-V10P10N10.pnml";
  auto r = runGdpn("analyze '" + net + "' --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["states"], 259556) << "the contest's count";
  EXPECT_EQ(j["edges"], 821282);
  EXPECT_TRUE(j["partial"].empty());
  const auto& inv = j["invariants"];
  EXPECT_FALSE(inv["complete"]);
  EXPECT_TRUE(inv["answered"]);
  EXPECT_TRUE(inv["p_complete"]);
  EXPECT_FALSE(inv["t_complete"]);
  EXPECT_EQ(inv["p"].size(), 7u) << "4ti2's count";
  EXPECT_TRUE(inv["conservative"]);
  EXPECT_FALSE(inv["consistent"]);
  r = runGdpn("analyze '" + net + "'");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find("stopped early"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("invariants (T-invariants listed in part: too many to list):"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("T-invariants (0 found; the list was cut short)"), std::string::npos) << r.out;
}

}  // namespace
