// The Session: reset, step, run, fire one transition, step the plant alone, breakpoints, live
// input and taking an edited model.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "gdpn/net/timeline.h"
#include "gdpn/session/session.h"

namespace gdpn::session {
namespace {

std::unique_ptr<Session> open(const std::string& text, core::Diagnostics& diags, SessionOptions options = {}) {
  auto m = model::parseModel(text, "session.gdpn.yaml", diags);
  return m ? Session::create(std::move(*m), diags, options) : nullptr;
}

std::unique_ptr<Session> openFile(const std::string& relative) {
  core::Diagnostics diags;
  auto m = model::loadModel(std::string(GDPN_SOURCE_DIR) + "/" + relative, diags);
  std::unique_ptr<Session> s;
  if (m) s = Session::create(std::move(*m), diags);
  EXPECT_TRUE(s) << diags.str();
  return s;
}

// the producer makes an item each second, the consumer takes 1.5 s per item (dt 0.01)
const char* kProducerConsumer = "examples/basics/producer_consumer/producer_consumer.gdpn.yaml";

std::int64_t tokens(const Session& s, const std::string& place) {
  const auto p = s.simulation().net().findPlace(place);
  if (!p) {
    ADD_FAILURE() << "no place " << place;
    return -1;
  }
  return s.simulation().kernel().placeTokens(*p);
}

// boxes fall into a bin watched by a region; drawn durations make the seed matter
const std::string kBin = R"Y(gdpn: 1
settings: {dt: 0.01, seed: 3}
scene:
  - Transform: {translation: [0, 0, -0.1], children: [{Plane: {}}]}
  - Transform: {name: high, translation: [0, 0, 0.5], children: [{Region: {name: bin, size: [4, 4, 1], scope: world}}]}
  - Transform:
      name: drop
      translation: [0, 0, 3]
      children:
        - Body: {name: box, mass: 1, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}
pages:
  main:
    places:
      idle: {tokens: 2}
      watching: {sensors: {c0: high/bin}}
      landed: {}
      busy: {}
    transitions:
      work: {duration: {exponential: 0.3}}
      rest: {duration: {uniform: [0.1, 0.4]}}
      see: {}
    arcs:
      - idle -> work
      - work -> busy
      - busy -> rest
      - rest -> idle
      - {from: watching, to: see, condition: 'len(c0.items) > 0'}
      - see -> landed
)Y";

TEST(Session, ResetGivesTheTraceOfAFreshModelByteForByte) {
  core::Diagnostics diags;
  auto fresh = open(kBin, diags);
  ASSERT_TRUE(fresh) << diags.str();
  std::ostringstream expected;
  fresh->traceTo(expected);
  fresh->run({3.0, {}});
  ASSERT_NE(expected.str().find("\"main/see\""), std::string::npos) << "the box lands in the bin";

  // a session that ran, fired, stepped the plant and had breakpoints, then reset
  auto s = open(kBin, diags);
  ASSERT_TRUE(s);
  std::ostringstream first;
  s->traceTo(first);
  s->run({1.0, {}});
  s->stepPlant();
  (void)s->fire("main/rest");
  std::string why;
  ASSERT_TRUE(s->addBreakpoint(Breakpoint::predicate("sim.time > 100"), why));
  std::ostringstream again;
  s->traceTo(again);
  ASSERT_TRUE(s->reset(diags));
  EXPECT_EQ(s->simulation().kernel().steps(), 0);
  EXPECT_EQ(tokens(*s, "main/idle"), 2);
  s->run({3.0, {}});
  EXPECT_EQ(again.str(), expected.str());

  // another seed gives another run, and resetting with the first seed gives the first again
  std::ostringstream other;
  s->traceTo(other);
  ASSERT_TRUE(s->reset(diags, 11));
  s->run({3.0, {}});
  EXPECT_NE(other.str(), expected.str());
  std::ostringstream back;
  s->traceTo(back);
  ASSERT_TRUE(s->reset(diags, 3));
  s->run({3.0, {}});
  EXPECT_EQ(back.str(), expected.str());
}

// a transition whose probability almost never lets it start by itself
const std::string kChoice = R"Y(gdpn: 1
settings: {dt: 0.1}
scripts:
  globals: 'allowed = False'
pages:
  main:
    places:
      ready: {tokens: 1}
      empty: {}
      full: {capacity: 1, tokens: 1}
      done: {}
    transitions:
      rare: {duration: 1, probability: 0.000001}
      starved: {}
      blocked: {}
      guarded: {guard: allowed}
    arcs:
      - ready -> rare
      - rare -> done
      - empty -> starved
      - ready -> blocked
      - blocked -> full
      - {from: ready, to: guarded, kind: test}
)Y";

TEST(Session, FireStartsTheChosenTransitionNow) {
  core::Diagnostics diags;
  auto s = open(kChoice, diags);
  ASSERT_TRUE(s) << diags.str();
  s->run({{}, 5});
  ASSERT_EQ(tokens(*s, "main/ready"), 1) << "the net did not start 'rare' by itself";
  EXPECT_EQ(s->fire("main/rare"), "");
  const auto rare = *s->simulation().net().findTransition("main/rare");
  EXPECT_TRUE(s->simulation().kernel().occurring(rare));
  EXPECT_EQ(tokens(*s, "main/ready"), 0);
  // it completes a second (10 steps) later
  s->run({{}, 14});
  EXPECT_EQ(tokens(*s, "main/done"), 0);
  s->run({{}, 15});
  EXPECT_EQ(tokens(*s, "main/done"), 1);
}

TEST(Session, FireOfATransitionThatCannotStartIsRefusedWithTheReason) {
  core::Diagnostics diags;
  auto s = open(kChoice, diags);
  ASSERT_TRUE(s) << diags.str();
  EXPECT_EQ(s->fire("main/nothing"), "no transition 'main/nothing' in the net");
  EXPECT_EQ(s->fire("main/starved"), "'main/starved' is not enabled: 'main/empty' a0 holds 0 of the 1 it needs");
  EXPECT_EQ(s->fire("main/blocked"), "'main/blocked' is not enabled: 'main/full' a0 has no room for 1 more");
  EXPECT_EQ(s->fire("main/guarded"), "'main/guarded''s guard is false");
  EXPECT_EQ(tokens(*s, "main/ready"), 1) << "a refused fire changes nothing";
  ASSERT_EQ(s->fire("main/rare"), "");
  EXPECT_EQ(s->fire("main/rare"), "'main/rare' is occurring");
}

TEST(Session, FireAfterAScriptErrorSaysTheScriptsHaveStopped) {
  core::Diagnostics diags;
  auto s = open(R"Y(gdpn: 1
settings: {dt: 0.1}
pages:
  main:
    places:
      a: {tokens: 2}
      b: {}
    transitions:
      broken: {probability: 0.000001, pre_fire: '1 / 0'}
      fine: {probability: 0.000001}
    arcs:
      - a -> broken
      - broken -> b
      - a -> fine
      - fine -> b
)Y",
                diags);
  ASSERT_TRUE(s) << diags.str();
  EXPECT_EQ(s->fire("main/broken"), "");  // it starts; its pre_fire raises
  ASSERT_TRUE(s->simulation().scriptHalt());
  EXPECT_EQ(s->fire("main/fine"), "'main/fine' cannot start: the model's scripts have stopped");
}

TEST(Session, WhatAFireEnablesStartsAtTheNextStep) {
  core::Diagnostics diags;
  auto s = open(R"Y(gdpn: 1
settings: {dt: 0.1}
pages:
  main:
    places:
      gate: {tokens: 1}
      opened: {}
      waited: {}
    transitions:
      open: {duration: 1, probability: 0.000001}
      wait: {}
    arcs:
      - gate -> open
      - open -> opened
      - {from: gate, to: wait, kind: inhibitor}
      - wait -> waited
)Y",
                diags);
  ASSERT_TRUE(s) << diags.str();
  s->run({{}, 3});
  ASSERT_EQ(s->fire("main/open"), "");
  // the emptied gate enables 'wait' (its inhibitor arc): the next step's firing phase starts it
  std::string why;
  ASSERT_TRUE(s->addBreakpoint(Breakpoint::starts("main/wait"), why));
  const auto outcome = s->run({{}, 20});
  EXPECT_EQ(outcome.reason, model::StopReason::Breakpoint);
  EXPECT_EQ(outcome.steps, 4);
}

TEST(Session, SensorConditionsAreReadAgainWhenTheNetIsBackOn) {
  core::Diagnostics diags;
  auto s = open(kBin, diags);
  ASSERT_TRUE(s) << diags.str();
  const auto see = *s->simulation().net().findTransition("main/see");
  // the box falls into the bin while the net is off: nothing sees it
  for (int i = 0; i < 150; ++i) s->stepPlant();
  ASSERT_LT(s->simulation().plant()->find("drop/box")->world.position.z, 0.5) << "the box lies in the bin";
  ASSERT_GT(s->simulation().plant()->find("drop/box")->world.position.z, -0.05) << "on the floor";
  EXPECT_FALSE(s->simulation().kernel().occurring(see));
  EXPECT_EQ(tokens(*s, "main/landed"), 0);
  // the first step with the net on reads the bin's condition as it is now
  s->step();
  EXPECT_TRUE(s->simulation().kernel().occurring(see));
}

TEST(Session, APredicateOnAModelWithoutScriptsLeavesItsTraceAsItWas) {
  auto plain = openFile(kProducerConsumer);
  ASSERT_TRUE(plain);
  std::ostringstream expected;
  plain->traceTo(expected);
  plain->run({{}, 600});
  auto s = openFile(kProducerConsumer);
  ASSERT_TRUE(s);
  std::ostringstream trace;
  s->traceTo(trace);
  std::string why;
  ASSERT_TRUE(s->addBreakpoint(Breakpoint::predicate("sim.time > 1000"), why));
  EXPECT_EQ(s->run({{}, 600}).reason, model::StopReason::Until);
  EXPECT_EQ(trace.str(), expected.str());
}

const std::string kFall = R"Y(gdpn: 1
settings: {dt: 0.01}
scene:
  - Body: {name: ball, mass: 1, children: [{Sphere: {radius: 0.1}}]}
pages:
  main:
    places:
      a: {tokens: 1}
      b: {}
    transitions:
      t: {duration: 1}
    arcs:
      - a -> t
      - t -> b
)Y";

TEST(Session, StepPlantMovesThePlantWhileTheNetWaits) {
  core::Diagnostics diags;
  auto s = open(kFall, diags);
  ASSERT_TRUE(s) << diags.str();
  s->step();  // t starts at time 0 and would complete at 1 s
  const auto t = *s->simulation().net().findTransition("main/t");
  ASSERT_TRUE(s->simulation().kernel().occurring(t));
  const double z0 = s->simulation().plant()->find("ball")->world.position.z;
  for (int i = 0; i < 50; ++i) s->stepPlant();
  // the ball fell for half a second more: z = z0 - g t^2 / 2 (within a step's integration error)
  const double z = s->simulation().plant()->find("ball")->world.position.z;
  const double t0 = 0.01, t1 = 0.51;
  EXPECT_NEAR(z0 - z, 9.81 / 2 * (t1 * t1 - t0 * t0), 0.06);
  EXPECT_DOUBLE_EQ(s->simulation().kernel().now(), 0.51);
  // the marking stayed, and the occurrence paused: it completes half a second late
  EXPECT_EQ(tokens(*s, "main/a"), 0);
  EXPECT_EQ(tokens(*s, "main/b"), 0);
  EXPECT_TRUE(s->simulation().kernel().occurring(t));
  std::string why;
  ASSERT_TRUE(s->addBreakpoint(Breakpoint::completes("main/t"), why)) << why;
  const auto outcome = s->run({});
  EXPECT_EQ(outcome.reason, model::StopReason::Breakpoint);
  EXPECT_EQ(outcome.steps, 150);
  EXPECT_EQ(tokens(*s, "main/b"), 1);
}


model::RunOutcome runTo(Session& s, Breakpoint bp) {
  std::string why;
  const auto id = s.addBreakpoint(std::move(bp), why);
  EXPECT_TRUE(id) << why;
  auto outcome = s.run({{}, 100000});
  EXPECT_EQ(outcome.reason, model::StopReason::Breakpoint);
  EXPECT_EQ(s.hit(), id);
  return outcome;
}

TEST(Session, ABreakpointOnAContinuousPlaceComparesItsAmount) {
  // the pump fills at 0.3 L/s, dt 0.1: 0.5 L is first reached at the end of step 17 (0.51 L),
  // 1 L at the end of step 34 (1.02 L)
  auto s = openFile("tests/data/hybrid/fill.gdpn.yaml");
  ASSERT_TRUE(s);
  auto outcome = runTo(*s, Breakpoint::level("main/tank", Compare::GreaterEqual, 0.5));
  EXPECT_EQ(outcome.steps, 17);
  ASSERT_TRUE(s->hit());
  EXPECT_TRUE(s->removeBreakpoint(*s->hit()));
  const auto tank = *s->simulation().net().findPlace("main/tank");
  EXPECT_NEAR(s->simulation().kernel().amount(tank), 0.51, 1e-12);
  core::Diagnostics diags;
  ASSERT_TRUE(s->reset(diags)) << diags.str();
  outcome = runTo(*s, Breakpoint::marking("main/tank", Compare::GreaterEqual, 1));
  EXPECT_EQ(outcome.steps, 34);
  EXPECT_NEAR(s->simulation().kernel().amount(tank), 1.02, 1e-12);
}

TEST(Session, ABreakpointOnAStartStopsAtTheStepItStarts) {
  auto s = openFile(kProducerConsumer);
  ASSERT_TRUE(s);
  // the first item is made at 1 s; the consumer starts on it in the same step
  const auto outcome = runTo(*s, Breakpoint::starts("main/consume"));
  EXPECT_EQ(outcome.steps, 100);
  EXPECT_EQ(outcome.message, "breakpoint 1: starts main/consume");
  // running on stops at the next start: the first item is consumed at 2.5 s, the second
  // waits in the buffer since 2 s, so the consumer starts again at 2.5 s
  EXPECT_EQ(s->run({{}, 100000}).steps, 250);
}

TEST(Session, ABreakpointOnACompletionStopsAtTheStepItCompletes) {
  auto s = openFile(kProducerConsumer);
  ASSERT_TRUE(s);
  EXPECT_EQ(runTo(*s, Breakpoint::completes("main/consume")).steps, 250);
  EXPECT_EQ(tokens(*s, "main/consumed"), 1);
}

TEST(Session, AMarkingBreakpointStopsAtTheFirstStepItsConditionHolds) {
  auto s = openFile(kProducerConsumer);
  ASSERT_TRUE(s);
  const auto outcome = runTo(*s, Breakpoint::marking("main/buffer", Compare::GreaterEqual, 3));
  EXPECT_EQ(tokens(*s, "main/buffer"), 3);
  // one step earlier it did not hold
  auto before = openFile(kProducerConsumer);
  before->run({{}, outcome.steps - 1});
  EXPECT_LT(tokens(*before, "main/buffer"), 3);
}

TEST(Session, APredicateBreakpointStopsWhenItsExpressionHolds) {
  auto s = openFile(kProducerConsumer);
  ASSERT_TRUE(s);
  // the model has no scripts: the interpreter starts for the predicate
  const auto outcome =
      runTo(*s, Breakpoint::predicate("len(sim.place('main/consumed').a0) >= 2"));
  ASSERT_EQ(outcome.message, "breakpoint 1: len(sim.place('main/consumed').a0) >= 2");
  EXPECT_EQ(outcome.steps, 400);  // the second item is consumed at 4 s
  // a disabled breakpoint never holds; a removed one is gone
  ASSERT_TRUE(s->enableBreakpoint(1, false));
  const auto on = s->run({{}, 500});
  EXPECT_EQ(on.reason, model::StopReason::Until);
  EXPECT_EQ(on.steps, 500);
  EXPECT_TRUE(s->removeBreakpoint(1));
  EXPECT_FALSE(s->removeBreakpoint(1));
  EXPECT_TRUE(s->breakpoints().empty());
}

TEST(Session, APredicateThatRaisesEndsTheRunAsAScriptErrorNamingIt) {
  auto s = openFile(kProducerConsumer);
  ASSERT_TRUE(s);
  std::string why;
  ASSERT_TRUE(s->addBreakpoint(Breakpoint::predicate("sim.time > undefined_name"), why));
  const auto outcome = s->run({{}, 100});
  EXPECT_EQ(outcome.reason, model::StopReason::ScriptError);
  EXPECT_EQ(outcome.steps, 0);  // checked first after time 0's firing phase
  EXPECT_NE(outcome.message.find("breakpoint 1 (sim.time > undefined_name) failed"), std::string::npos) << outcome.message;
  EXPECT_NE(outcome.message.find("NameError: name 'undefined_name' is not defined"), std::string::npos);
}

TEST(Session, ABreakpointOnSomethingTheNetLacksIsRefused) {
  auto s = openFile(kProducerConsumer);
  ASSERT_TRUE(s);
  std::string why;
  EXPECT_FALSE(s->addBreakpoint(Breakpoint::starts("main/nope"), why));
  EXPECT_EQ(why, "no transition 'main/nope' in the net");
  EXPECT_FALSE(s->addBreakpoint(Breakpoint::marking("buffer", Compare::Equal, 0), why));
  EXPECT_EQ(why, "no place 'buffer' in the net");
  // a near miss offers the name meant
  EXPECT_FALSE(s->addBreakpoint(Breakpoint::marking("main/bufer", Compare::GreaterEqual, 2), why));
  EXPECT_EQ(why, "no place 'main/bufer' in the net (did you mean 'main/buffer'?)");
  EXPECT_FALSE(s->addBreakpoint(Breakpoint::predicate("  "), why));
}

TEST(Session, LiveInputReachesTheSensorsAtItsTime) {
  auto s = openFile("tests/data/input/console.gdpn.yaml");
  ASSERT_TRUE(s);
  std::string why;
  ASSERT_TRUE(s->addBreakpoint(Breakpoint::starts("main/go"), why));
  // without input the net is dead at once
  EXPECT_EQ(s->run({2.0, {}}).reason, model::StopReason::Dead);
  // the viewer steps into the booth, then presses g: 'go' starts at the step the key arrives
  sensors::InputEvent walk;
  walk.kind = sensors::InputEvent::Kind::Viewpoint;
  walk.t = 2.5;
  walk.position = {0, 0, 0};
  sensors::InputEvent key;
  key.kind = sensors::InputEvent::Kind::Key;
  key.t = 3.0;
  key.key = "g";
  s->push(key);
  s->push(walk);  // pushed later, delivered earlier: events go in time order
  const auto outcome = s->run({5.0, {}});
  EXPECT_EQ(outcome.reason, model::StopReason::Breakpoint);
  EXPECT_EQ(outcome.steps, 30);
}

TEST(Session, RebuildTakesAnEditedModelOrKeepsTheOldOne) {
  core::Diagnostics diags;
  auto s = open(kFall, diags);
  ASSERT_TRUE(s) << diags.str();
  s->run({{}, 20});
  // an edit with a mistake: diagnostics at their place, the old run untouched
  auto bad = model::parseModel(kFall, "session.gdpn.yaml", diags);
  ASSERT_TRUE(bad);
  bad->net.pages[0].arcs[0].from = "nowhere";
  core::Diagnostics errors;
  EXPECT_FALSE(s->rebuild(*bad, errors));
  ASSERT_TRUE(errors.hasErrors());
  EXPECT_NE(errors.str().find("session.gdpn.yaml:"), std::string::npos) << errors.str();
  EXPECT_NE(errors.str().find("nowhere"), std::string::npos) << errors.str();
  EXPECT_EQ(s->simulation().kernel().steps(), 20);
  EXPECT_EQ(s->model().net.pages[0].arcs[0].from, "a");
  // a good edit: the run starts again from the new model; a breakpoint on what the edit
  // removed goes with it
  std::string why;
  ASSERT_TRUE(s->addBreakpoint(Breakpoint::marking("main/b", Compare::Greater, 5), why));
  ASSERT_TRUE(s->addBreakpoint(Breakpoint::starts("main/t"), why));
  auto good = model::parseModel(kFall, "session.gdpn.yaml", diags);
  good->net.pages[0].transitions[0].duration.a = 0.5;
  good->net.pages[0].transitions[0].name = "quick";
  good->net.pages[0].arcs[0].to = "quick";
  good->net.pages[0].arcs[1].from = "quick";
  core::Diagnostics fine;
  ASSERT_TRUE(s->rebuild(*good, fine)) << fine.str();
  ASSERT_EQ(s->breakpoints().size(), 1u);
  EXPECT_EQ(s->breakpoints()[0].second.target, "main/b");
  EXPECT_EQ(s->simulation().kernel().steps(), 0);
  s->run({{}, 60});
  EXPECT_EQ(tokens(*s, "main/b"), 1);
}

}  // namespace
}  // namespace gdpn::session

namespace gdpn::session {
namespace {

// the run request: what each run of a session collects from its start, kept over resets

std::size_t circuitCount(const model::Report& report) {
  std::size_t n = 0;
  for (const auto& c : report.cycles) n += c.circuits.size();
  return n;
}

TEST(RunRequest, ByDefaultTheReportShowsEachCircuitOfATokenWithAlternatives) {
  auto s = openFile("tests/data/good/alternatives.gdpn.yaml");
  ASSERT_TRUE(s);
  const auto outcome = s->run({{}, {}});
  // the station token works red parts and skips blue ones: two circuits, each measured
  EXPECT_EQ(circuitCount(s->report(outcome)), 2u);
  EXPECT_EQ(s->timeline(), nullptr);
  // again after a reset: the request holds for every run the session makes
  core::Diagnostics diags;
  ASSERT_TRUE(s->reset(diags));
  EXPECT_EQ(circuitCount(s->report(s->run({{}, {}}))), 2u);
}

TEST(RunRequest, ATimelineWhenAskedAndNoStatisticsWhenNoReportIs) {
  core::Diagnostics diags;
  auto m = model::loadModel(std::string(GDPN_SOURCE_DIR) + "/tests/data/good/alternatives.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  SessionOptions options;
  options.run.timeline = true;
  auto s = Session::create(*m, diags, options);
  ASSERT_TRUE(s) << diags.str();
  s->run({{}, 100});
  ASSERT_NE(s->timeline(), nullptr);
  EXPECT_FALSE(s->timeline()->occurrences().empty());
  options.run = {};
  options.run.report = false;
  auto quiet = Session::create(*m, diags, options);
  ASSERT_TRUE(quiet) << diags.str();
  EXPECT_EQ(quiet->timeline(), nullptr);
  EXPECT_EQ(quiet->run({{}, 100}).steps, 100);
}

TEST(RunRequest, AReplayedWitnessSaysHowFarItGot) {
  auto s = openFile(kProducerConsumer);
  ASSERT_TRUE(s);
  EXPECT_FALSE(s->replayVerdict());
  core::Diagnostics diags;
  EXPECT_FALSE(s->replay("/nonexistent/witness.json", diags));
  EXPECT_TRUE(diags.hasErrors());
  EXPECT_FALSE(s->replayVerdict());
}

}  // namespace
}  // namespace gdpn::session
