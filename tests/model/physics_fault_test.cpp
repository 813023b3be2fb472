// Physics fed non-finite or degenerate values: a script's vector that is no number or too
// large is refused where the script wrote it; a joint a script cannot have is refused; a body
// that still runs away stops the run as a physics error naming it and the time, the trace
// kept. Nothing crashes.

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "gdpn/model/simulation.h"

namespace gdpn::model {
namespace {

std::unique_ptr<Simulation> open(const std::string& text, core::Diagnostics& diags) {
  auto m = parseModel(text, "fault.gdpn.yaml", diags);
  return m ? Simulation::create(*m, diags) : nullptr;
}

/// A box on a body whose transition `push` runs `code` (one line of Python, on the
/// body `box`) after logging "before"; the script is on line 13 of the file.
std::string pushed(const std::string& code) {
  return R"Y(gdpn: 1
settings: {dt: 0.01, until: 1}
scene:
  - World: {auto_disable: false}
  - Body: {name: box, mass: 1, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}
pages:
  main:
    places:
      p: {tokens: {d0: [box]}}
      q: {}
    transitions:
      push:
        pre_fire: "sim.log('before'); box = self.d0[0]; )Y" +
         code + R"Y("
    arcs:
      - {from: p, to: push, weight: {d0: 1}}
      - {from: push, to: q, weight: {d0: 1}}
)Y";
}

/// A hinge 'shoulder' (its `axes`, as fields) holding an arm whose cube is 1 m out along x;
/// transition `move` runs `script` (lines of Python on the joint `j`) once.
std::string jointed(const std::string& axes, const std::string& script) {
  std::string text = R"Y(gdpn: 1
settings: {dt: 0.01, until: 0.5}
scene:
  - Joint:
      name: shoulder
      kind: hinge
      )Y" + axes + R"Y(
      children: [{Body: {name: arm, mass: 1, children: [{Transform: {translation: [1, 0, 0], children: [{Cube: {}}]}}]}}]
pages:
  main:
    places:
      p: {tokens: {d0: [shoulder]}}
      q: {}
    transitions:
      move:
        pre_fire: |
          j = self.d0[0]
)Y";
  std::istringstream lines(script);
  for (std::string line; std::getline(lines, line);) text += "          " + line + "\n";
  return text + R"Y(    arcs:
      - {from: p, to: move, weight: {d0: 1}}
      - {from: move, to: q, weight: {d0: 1}}
)Y";
}

/// The run of `text` to its end, with its trace in `trace`.
RunOutcome runOf(const std::string& text, std::string& trace) {
  core::Diagnostics diags;
  auto sim = open(text, diags);
  EXPECT_TRUE(sim) << diags.str();
  if (!sim) return {};
  std::ostringstream out;
  sim->traceTo(out);
  const auto outcome = sim->run({});
  trace = out.str();
  return outcome;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(PhysicsFault, AVectorThatIsNoNumberOrTooLargeIsRefusedWhereTheScriptGaveIt) {
  // NaN, an infinity, and a number that overflows once squared, through each method
  const struct {
    const char* call;
    const char* says;
  } cases[] = {
      {"box.set_velocity((float('nan'), 0, 0))", "set_velocity(nan, 0, 0): each number must be finite and at most 1e+12 m/s"},
      {"box.set_force((0, float('inf'), 0))", "set_force(0, inf, 0): each number must be finite and at most 1e+18 N"},
      {"box.add_force((0, 0, -float('inf')))", "add_force(0, 0, -inf): each number must be finite"},
      {"box.set_torque((1e308, 0, 0))", "set_torque(1e+308, 0, 0): each number must be finite and at most 1e+18 N m"},
      {"box.set_velocity((0, 1e308 * 10, 0))", "set_velocity(0, inf, 0)"},
  };
  for (const auto& c : cases) {
    std::string trace;
    const auto outcome = runOf(pushed(c.call), trace);
    EXPECT_EQ(outcome.reason, StopReason::ScriptError) << c.call;
    EXPECT_TRUE(has(outcome.message, "ValueError: ")) << outcome.message;
    EXPECT_TRUE(has(outcome.message, c.says)) << outcome.message;
    // located at the script's line in the model file
    EXPECT_TRUE(has(outcome.message, "fault.gdpn.yaml:13:")) << outcome.message;
    EXPECT_TRUE(has(trace, "\"text\":\"before\"")) << trace;
  }
}

TEST(PhysicsFault, ASpawnPlaceThatIsNoNumberIsRefused) {
  std::string trace;
  const auto outcome = runOf(pushed("box.parent.spawn(box, (0, float('nan'), 0))"), trace);
  EXPECT_EQ(outcome.reason, StopReason::ScriptError);
  EXPECT_TRUE(has(outcome.message, "spawn(0, nan, 0): each number must be finite")) << outcome.message;
  EXPECT_TRUE(has(outcome.message, "fault.gdpn.yaml:13:")) << outcome.message;
}

TEST(PhysicsFault, AJointKindAScriptCannotHaveIsRefusedAndTheJointStaysAsItWas) {
  // a hinge about z, its axis2 along z too: as a universal joint its axes would be parallel
  std::string trace;
  const auto outcome = runOf(jointed("axis1: [0, 0, 1]\n      axis2: [0, 0, 1]",
                                     "try:\n    j.kind = \"universal\"\nexcept ValueError as e:\n"
                                     "    sim.log(\"refused:\", e, \"kind is\", j.kind)"),
                             trace);
  EXPECT_EQ(outcome.reason, StopReason::Dead) << outcome.message;
  EXPECT_TRUE(has(trace, "refused: 'kind': universal joint 'shoulder' has axis2 parallel to axis1: its two axes need "
                         "different directions kind is hinge"))
      << trace;
}

TEST(PhysicsFault, ABodyThatRunsAwayStopsTheRunNamingItAndTheTimeWithTheTraceKept) {
  // 1e17 N on 1 kg: within what a script may apply, but the box flies beyond 1e12 m in the
  // first step
  std::string trace;
  const auto outcome = runOf(pushed("box.set_force((1e17, 0, 0))"), trace);
  EXPECT_EQ(outcome.reason, StopReason::PhysicsError) << outcome.message;
  EXPECT_STREQ(stopReasonName(outcome.reason), "physics error");
  EXPECT_TRUE(has(outcome.message, "physics error at t = 0.01 s: body 'box' ran away: its position became (1e+13, 0, "))
      << outcome.message;
  EXPECT_NEAR(outcome.time, 0.01, 1e-12);
  // the events before it, then the error
  const auto before = trace.find("\"text\":\"before\"");
  const auto error = trace.find("\"ev\":\"error\"");
  ASSERT_NE(before, std::string::npos) << trace;
  ASSERT_NE(error, std::string::npos) << trace;
  EXPECT_LT(before, error);
  EXPECT_TRUE(has(trace.substr(error), "body 'box' ran away")) << trace;
}

TEST(PhysicsFault, AMotorBeyondTheLargestNumbersAFieldTakesIsRefusedAtTheAssignment) {
  // vel1 and fmax1 of 1e300: refused where the script sets them, naming the field, not a body
  // run away a step later with no location
  std::string trace;
  auto outcome = runOf(jointed("axis1: [0, 0, 1]", "j.vel1 = 1e300\nj.fmax1 = 1e300"), trace);
  EXPECT_EQ(outcome.reason, StopReason::ScriptError) << outcome.message;
  EXPECT_TRUE(has(outcome.message, "'vel1' must be at most 1e+12, got 1e+300")) << outcome.message;
  // at the largest they take the run goes on or ends as a physics error, never with a crash
  // or a flood of ODE's warnings
  outcome = runOf(jointed("axis1: [0, 0, 1]", "j.vel1 = 1e12\nj.fmax1 = 1e12"), trace);
  EXPECT_NE(outcome.reason, StopReason::ScriptError) << outcome.message;
  if (outcome.reason == StopReason::PhysicsError) {
    EXPECT_TRUE(has(outcome.message, "body 'shoulder/arm' ran away")) << outcome.message;
  }
}

}  // namespace
}  // namespace gdpn::model
