// The headless IDE on hybrid nets: a continuous place's amount in the inspector, the contents
// view and the net view while a run goes on; the amount set in the contents view while paused
// (and refused past the capacity); a place and a transition made continuous and back, with
// undo, and a rate checked as it is typed.

#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "ide/headless_fixture.h"
#include "support/scratch.h"

namespace gdpn::ide {
namespace {

// tests/data/hybrid/fill.gdpn.yaml, copied: a pump fills a 10 L tank at 0.3 L/s from 0 L; a
// level switch at 1 L stops it (from 3.4 s); dt 0.1 s
class HybridIde : public HeadlessIde {
 protected:
  void SetUp() override {
    HeadlessIde::SetUp();
    hidePalette();
    size_ = "1600x900";
    model_ = write("fill.gdpn.yaml", gdpn::testing::fileBytes(GDPN_SOURCE_DIR "/tests/data/hybrid/fill.gdpn.yaml"));
  }
  nlohmann::json run(const std::string& actions) { return replayOn(model_, actions); }
  std::string model_;
};

TEST_F(HybridIde, AContinuousPlacesAmountShowsInTheInspectorTheContentsAndTheNetView) {
  // 10 steps of 0.1 s at 0.3 L/s: 0.3 L
  auto r = run("- steps: 10\n- select: main/tank\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  const auto& in = r["inspector"];
  ASSERT_TRUE(in.contains("amount")) << in.dump(1);
  EXPECT_NEAR(in["amount"].get<double>(), 0.3, 1e-9);
  EXPECT_EQ(in["unit"], "L");
  EXPECT_NEAR(in["contents"]["amount"].get<double>(), 0.3, 1e-9);
  EXPECT_EQ(in["contents"]["capacity"], 10.0);
  EXPECT_EQ(in["contents"]["level_text"], "0.3 of 10 L");
  EXPECT_NEAR(r["net_view"]["amounts"]["main/tank"].get<double>(), 0.3, 1e-9);
  EXPECT_NEAR(r["net_view"]["flow_rates"]["main/pump"].get<double>(), 0.3, 1e-12);
  EXPECT_EQ(r["net_view"]["activity"]["main/pump"], "enabled");  // it flows
  // the pump: its effective and nominal rates
  r = run("- steps: 10\n- select: main/pump\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["state"], "flowing");
  EXPECT_NEAR(r["inspector"]["flow_rate"].get<double>(), 0.3, 1e-12);
  EXPECT_NEAR(r["inspector"]["nominal_rate"].get<double>(), 0.3, 1e-12);
  EXPECT_EQ(r["inspector"]["rate_unit"], "L/s");
  EXPECT_EQ(r["inspector"]["contents"]["rate"], "0.3");  // as written, no duration
  // the tank crosses 1 L at 3.33 s; `stop` starts at the next step boundary, 3.4 s, taking the
  // mark: the pump is off and drawn idle, the tank holds 0.3 L/s x 3.4 s = 1.02 L
  r = run("- steps: 50\n- select: main/pump\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["state"], "off");
  EXPECT_EQ(r["net_view"]["activity"]["main/pump"], "idle");
  EXPECT_NEAR(r["net_view"]["amounts"]["main/tank"].get<double>(), 1.02, 1e-9);
}

TEST_F(HybridIde, TheContentsViewSetsTheAmountWhilePausedAndSaysWhyItRefuses) {
  const std::string paused = "- steps: 10\n- select: main/tank\n- frames: 2\n";
  const std::string field = "- click: [inspector, contents, fields, set amount]\n- key: ctrl+a\n";
  auto r = run(paused + field + "- type: '0.75'\n- key: enter\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["run"]["mode"], "paused") << r["run"];
  EXPECT_DOUBLE_EQ(r["inspector"]["amount"].get<double>(), 0.75);  // the kernel's amount
  EXPECT_DOUBLE_EQ(r["net_view"]["amounts"]["main/tank"].get<double>(), 0.75);
  EXPECT_EQ(r["inspector"]["contents"]["amount_error"], "");
  // it goes on from there: one step of 0.1 s at 0.3 L/s
  r = run(paused + field + "- type: '0.75'\n- key: enter\n- frames: 2\n- steps: 1\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_NEAR(r["inspector"]["amount"].get<double>(), 0.78, 1e-9);
  // more than its capacity: refused, the amount as it was, the reason under the field
  r = run(paused + field + "- type: '12'\n- key: enter\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_NEAR(r["inspector"]["amount"].get<double>(), 0.3, 1e-9);
  EXPECT_NE(r["inspector"]["contents"]["amount_error"].get<std::string>().find("capacity"), std::string::npos)
      << r["inspector"]["contents"];
}

TEST_F(HybridIde, APlaceMadeContinuousAndBackWithUndo) {
  const std::string pick = "- select: main/stopped\n- frames: 2\n";
  auto r = run(pick);
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["contents"]["continuous"], false);
  const std::string on = pick + "- click: [inspector, contents, fields, continuous]\n- frames: 2\n";
  r = run(on);
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["contents"]["continuous"], true);
  EXPECT_EQ(r["inspector"]["contents"]["amount"], 0.0);
  EXPECT_TRUE(r["inspector"]["contents"]["capacity"].is_null());
  // its unit typed in
  const std::string unit = on + "- click: [inspector, contents, fields, unit]\n- type: kg\n- key: enter\n- frames: 2\n";
  r = run(unit);
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["contents"]["unit"], "kg");
  // undo: no unit; undo again: discrete
  r = run(unit + "- press: undo\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["contents"]["continuous"], true);
  EXPECT_EQ(r["inspector"]["contents"]["unit"], "");
  r = run(unit + "- press: undo\n- press: undo\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["contents"]["continuous"], false);
  // the box again: discrete by an edit of its own
  r = run(on + "- click: [inspector, contents, fields, continuous]\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["contents"]["continuous"], false);
}

TEST_F(HybridIde, ATransitionMadeContinuousHasARateCheckedAsItIsTyped) {
  const std::string on = "- select: main/stop\n- frames: 2\n- click: [inspector, contents, fields, continuous]\n- frames: 2\n";
  auto r = run(on);
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["contents"]["continuous"], true);
  EXPECT_EQ(r["inspector"]["contents"]["rate"], "1");
  // a name the page has no continuous place of: the error at its column, nothing applied
  const std::string field = on + "- click: [inspector, contents, fields, rate]\n- key: ctrl+a\n";
  r = run(field + "- type: '2 * tnak'\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  const auto why = r["inspector"]["contents"]["rate_error"].get<std::string>();
  EXPECT_EQ(why.rfind("rate, column 5: ", 0), 0u) << why;
  EXPECT_NE(why.find("tank"), std::string::npos) << why;  // did you mean
  r = run(field + "- type: '2 * tnak'\n- key: enter\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["contents"]["rate"], "1");
  // `running` is discrete: no rate names it
  r = run(field + "- type: 'running'\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_NE(r["inspector"]["contents"]["rate_error"].get<std::string>().find("column 1"), std::string::npos);
  // the tank's amount: applied at Enter; undo brings back the rate of 1, undo again a transition
  const std::string typed = field + "- type: '0.1 * tank'\n- key: enter\n- frames: 2\n";
  r = run(typed);
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["contents"]["rate_error"], "");
  EXPECT_EQ(r["inspector"]["contents"]["rate"], "0.1 * tank");
  r = run(typed + "- press: undo\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["contents"]["rate"], "1");
  r = run(typed + "- press: undo\n- press: undo\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["contents"]["continuous"], false);
}

TEST_F(HybridIde, AnArcWithAContinuousPlaceHasARealWeight) {
  // the level switch's threshold: 1 L, then 2.5 L; undo gives 1 L back
  const std::string pick = "- select: 'main: tank -> stop (test)'\n- frames: 2\n";
  auto r = run(pick);
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["weight"], 1.0);
  const std::string typed = pick + "- click: [inspector, fields, weight]\n- key: ctrl+a\n- type: '2.5'\n- key: enter\n- frames: 2\n";
  r = run(typed);
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["weight"], 2.5);
  r = run(typed + "- press: undo\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["inspector"]["weight"], 1.0);
  // the run takes it: the pump stops after the tank crosses 2.5 L (8.33 s), from 8.4 s
  r = run(typed + "- steps: 100\n- select: main/tank\n- frames: 2\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_NEAR(r["inspector"]["amount"].get<double>(), 0.3 * 8.4, 1e-9);
}

}  // namespace
}  // namespace gdpn::ide
