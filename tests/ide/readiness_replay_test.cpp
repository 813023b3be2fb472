// The headless IDE on a guarded transition: the net view draws it enabled only when the last
// firing phase found it able to start, and the inspector says what held it back.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "ide/headless_fixture.h"

namespace gdpn::ide {
namespace {

// t's marking suffices from the start (a holds its token); its guard is false until 0.5 s
constexpr const char* kGuarded = R"Y(gdpn: 1
scene:
  - Cube: {name: c, size: [1, 1, 1]}
pages:
  main:
    places:
      a: {tokens: 1}
      b: {}
    transitions:
      t: {duration: 10, guard: "sim.time >= 0.5"}
    arcs:
      - a -> t
      - t -> b
)Y";

TEST_F(HeadlessIde, ATransitionWhoseGuardIsFalseIsDrawnHeldBackAndTheInspectorSaysWhy) {
  const auto model = write("guarded.gdpn.yaml", kGuarded);
  // one step: the firing phase found the guard false
  auto r = replayOn(model, "- press: step\n- select: main/t\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["net_view"]["activity"]["main/t"], "held back");
  EXPECT_EQ(r["inspector"]["state"], "held back");
  EXPECT_EQ(r["inspector"]["readiness"], "guard");
  EXPECT_EQ(r["inspector"]["why"], "held back: guard false");
  // Fire refuses it, for the same reason
  r = replayOn(model, "- press: step\n- fire: main/t\n- select: main/t\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_NE(r["status"]["message"].get<std::string>().find("guard is false"), std::string::npos) << r["status"];
  // past 0.5 s a firing phase finds the guard true: it starts
  r = replayOn(model, "- press: step\n- run: 1\n- select: main/t\n");
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["net_view"]["activity"]["main/t"], "occurring");
  EXPECT_EQ(r["inspector"]["state"], "occurring");
  EXPECT_EQ(r["inspector"]["why"], "");
}

}  // namespace
}  // namespace gdpn::ide
