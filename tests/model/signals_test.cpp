// Signals: what a run records over time, at each signal's period, against analytic answers
// (a falling ball under ODE's semi-implicit Euler steps), and their mistakes.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"
#include "support/sim_helpers.h"

namespace gdpn::model {
namespace {

std::size_t column(const SignalTable& t, const std::string& name) {
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    if (t.columns[c] == name) return c;
  }
  ADD_FAILURE() << "no column " << name;
  return 0;
}

TEST(Signals, AFallingBallsHeightIsHalfGTSquaredAndHalfAStepMore) {
  auto sim = testing::openModelFile("tests/data/good/falling_ball.gdpn.yaml");
  ASSERT_TRUE(sim);
  core::Diagnostics diags;
  ASSERT_TRUE(sim->recordSignals({}, diags)) << diags.str();
  const auto outcome = sim->run({});
  ASSERT_EQ(outcome.reason, StopReason::Until) << outcome.message;
  const SignalTable& t = *sim->signals();
  EXPECT_EQ(t.columns, (std::vector<std::string>{"ball.x", "ball.y", "ball.z", "speed.x", "speed.y", "speed.z",
                                                 "ticks", "clock"}));
  ASSERT_EQ(t.rows.size(), 101u);  // time 0 and every step of 0.01 s to 1 s
  const double g = 9.81, h = 0.01;
  const std::size_t z = column(t, "ball.z"), vz = column(t, "speed.z");
  for (std::size_t n = 0; n <= 100; ++n) {
    const double time = t.time[n];
    EXPECT_NEAR(time, static_cast<double>(n) * h, 1e-12);
    ASSERT_TRUE(t.rows[n][z]);
    // ODE's step: the velocity first, then the position with it: after n steps the ball is
    // g h^2 n (n + 1) / 2 below its start, which is g t^2 / 2 and g h t / 2 more
    const double nn = static_cast<double>(n);
    EXPECT_NEAR(*t.rows[n][z], 20 - g * h * h * nn * (nn + 1) / 2, 1e-9) << n;
    EXPECT_LE(std::abs(*t.rows[n][z] - (20 - g * time * time / 2)), g * h * time / 2 + 1e-9) << n;
    // the speed every 0.25 s, v = -g t exactly
    if (n % 25 == 0) {
      ASSERT_TRUE(t.rows[n][vz]) << n;
      EXPECT_NEAR(*t.rows[n][vz], -g * time, 1e-9) << n;
    } else {
      EXPECT_FALSE(t.rows[n][vz]) << n;
    }
  }
  // the net's ticks every 0.1 s: one more each time; the expression every 0.5 s
  for (std::size_t k = 0; k <= 10; ++k) EXPECT_EQ(t.rows[k * 10][column(t, "ticks")], static_cast<double>(k));
  EXPECT_EQ(t.rows[50][column(t, "clock")], 1.0);
  EXPECT_FALSE(t.rows[49][column(t, "clock")]);
  // as CSV: a header, the shortest exact numbers, an empty cell where nothing was sampled
  std::ostringstream csv;
  t.writeCsv(csv);
  EXPECT_EQ(csv.str().substr(0, csv.str().find('\n', csv.str().find('\n', csv.str().find('\n') + 1) + 1) + 1),
            "time,ball.x,ball.y,ball.z,speed.x,speed.y,speed.z,ticks,clock\n"
            "0,0,0,20,0,0,0,0,0\n"
            "0.01,0,0,19.999019,,,,,\n");
}

TEST(Signals, NothingIsRecordedUnlessAsked) {
  auto sim = testing::openModelFile("tests/data/good/falling_ball.gdpn.yaml");
  ASSERT_TRUE(sim);
  sim->run({});
  EXPECT_EQ(sim->signals(), nullptr);
}

TEST(Signals, CommandLineSignalsAreParsedAndNamedByTheirText) {
  std::string why;
  auto s = parseSignalArgument("node:arm/joint.angle", why);
  ASSERT_TRUE(s) << why;
  EXPECT_EQ(s->kind, SignalSpec::Kind::Node);
  EXPECT_EQ(s->target, "arm/joint");
  EXPECT_EQ(s->quantity, "angle");
  EXPECT_EQ(s->name, "arm/joint.angle");
  s = parseSignalArgument("python:len(sim.place('main/p').d0)", why);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->kind, SignalSpec::Kind::Expression);
  EXPECT_EQ(s->target, "len(sim.place('main/p').d0)");
  EXPECT_EQ(parseSignalArgument("place:main/p", why)->target, "main/p");
  // an axis of a vector: the quantity is the two last words
  s = parseSignalArgument("node:drop/ball.position.z", why);
  ASSERT_TRUE(s) << why;
  EXPECT_EQ(s->target, "drop/ball");
  EXPECT_EQ(s->quantity, "position.z");
  s = parseSignalArgument("node:rig/imu.acceleration.x", why);
  ASSERT_TRUE(s) << why;
  EXPECT_EQ(s->target, "rig/imu");
  EXPECT_EQ(s->quantity, "acceleration.x");
  for (const char* bad : {"main/p", "place:", "node:ball", "node:.x", "python:", "pos:ball"}) {
    EXPECT_FALSE(parseSignalArgument(bad, why)) << bad;
  }
  EXPECT_EQ(why, "expects place:NAME, node:PATH.QUANTITY or python:EXPRESSION, got 'pos:ball'");
}

TEST(Signals, AnExpressionThatFailsStopsTheRunNamingTheSignalAndTheTime) {
  core::Diagnostics diags;
  auto m = parseModel(R"yaml(gdpn: 1
settings: {dt: 0.25, until: 5}
signals:
  left: {expression: "1 / (1 - sim.time)", every: 0.5}
pages:
  main:
    places: {p: {tokens: 1}}
    transitions: {t: {duration: 1}}
    arcs: [p -> t, t -> p]
)yaml",
                      "fails.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim && sim->recordSignals({}, diags)) << diags.str();
  const auto outcome = sim->run({});
  EXPECT_EQ(outcome.reason, StopReason::ScriptError);
  EXPECT_EQ(outcome.time, 1.0);
  EXPECT_EQ(outcome.message.rfind("fails.gdpn.yaml:4:22: error: signal 'left' at t = 1 s: ", 0), 0u) << outcome.message;
  EXPECT_NE(outcome.message.find("ZeroDivisionError"), std::string::npos) << outcome.message;
  // what was sampled before stays
  EXPECT_EQ(sim->signals()->time, (std::vector<double>{0.0, 0.5}));
}

TEST(Signals, APeriodShorterThanAStepSamplesEveryStepAndNamesAreOneColumnEach) {
  auto sim = testing::openModelFile("tests/data/good/falling_ball.gdpn.yaml");
  ASSERT_TRUE(sim);
  core::Diagnostics diags;
  std::string why;
  auto tiny = parseSignalArgument("place:main/ticks", why);
  ASSERT_TRUE(tiny);
  tiny->name = "often";
  tiny->every = 1e-300;
  ASSERT_TRUE(sim->recordSignals({*tiny}, diags)) << diags.str();
  sim->run({0.05, {}});
  EXPECT_EQ(sim->signals()->rows.size(), 6u);
  // a name twice is refused
  auto again = testing::openModelFile("tests/data/good/falling_ball.gdpn.yaml");
  auto twice = *parseSignalArgument("python:1", why);
  twice.name = "ticks";
  EXPECT_FALSE(again->recordSignals({twice}, diags));
  EXPECT_NE(diags.str().find("signal 'ticks': another signal has this name"), std::string::npos) << diags.str();
}

TEST(Signals, ASensorsChannelsAreReadByNameAndOneAxisOfAVector) {
  // a box at rest on the ground carries an Imu (it feels -gravity: 9.81 m/s^2 up); a range
  // finder at the origin looks along +x at a wall whose face is at x = 2.5
  core::Diagnostics diags;
  auto m = parseModel(R"yaml(gdpn: 1
settings: {dt: 0.01, until: 1}
signals:
  eye: {node: post/eye, of: distance}
  main: {node: post/eye, of: reading}
  up: {node: spot/box/imu, of: acceleration.z}
  felt: {node: spot/box/imu, of: acceleration, every: 0.5}
pages:
  main: {places: {p: {tokens: 1}}, transitions: {t: {duration: 0.5}}, arcs: [p -> t, t -> p]}
scene:
  - Plane: {}
  - Transform: {name: post, translation: [0, 3, 0.5], children: [{RangeFinder: {name: eye, length: 10}}]}
  - Transform: {translation: [3, 3, 0.5], children: [{Cube: {size: [1, 1, 1]}}]}
  - Transform:
      name: spot
      translation: [0, -3, 0.1]
      children: [{Body: {name: box, children: [{Cube: {size: [0.2, 0.2, 0.2]}}, {Imu: {name: imu}}]}}]
)yaml",
                      "channels.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim && sim->recordSignals({}, diags)) << diags.str();
  const auto outcome = sim->run({});
  ASSERT_EQ(outcome.reason, StopReason::Until) << outcome.message;
  const SignalTable& t = *sim->signals();
  EXPECT_EQ(t.columns, (std::vector<std::string>{"eye", "main", "up", "felt.x", "felt.y", "felt.z"}));
  const auto& last = t.rows.back();
  EXPECT_NEAR(*last[column(t, "eye")], 2.5, 1e-6);
  EXPECT_EQ(*last[column(t, "main")], *last[column(t, "eye")]);  // a RangeFinder's main number is its distance
  EXPECT_NEAR(*last[column(t, "up")], 9.81, 0.05);
  EXPECT_NEAR(*last[column(t, "felt.z")], 9.81, 0.05);
  EXPECT_NEAR(*last[column(t, "felt.x")], 0.0, 0.05);
}

TEST(Signals, AChannelThatIsNoNumberIsRefusedNamingWhatTheSensorHas) {
  core::Diagnostics diags;
  auto m = parseModel(R"yaml(gdpn: 1
signals:
  rays: {node: lidar, of: ranges}
pages:
  main: {places: {p: {}}}
scene:
  - LaserScan: {name: lidar, count: 8, min_angle: -90, max_angle: 90}
)yaml",
                      "rays.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  EXPECT_FALSE(sim->recordSignals({}, diags));
  EXPECT_NE(diags.str().find("rays.gdpn.yaml:3:"), std::string::npos) << diags.str();
  EXPECT_NE(diags.str().find("a LaserScan has no number 'ranges'"), std::string::npos) << diags.str();
  EXPECT_NE(diags.str().find("reading, active, nearest"), std::string::npos) << diags.str();
}

TEST(Signals, AValueOfAColouredPlaceCountsItsTokensAsTransitionsTakeThem) {
  // p holds 2'a ++ 1'b; wait (1 s) lets take move one a at a time to q (1 s each); b stays
  auto sim = testing::openModelFile("tests/data/good/value_counts.gdpn.yaml");
  ASSERT_TRUE(sim);
  core::Diagnostics diags;
  ASSERT_TRUE(sim->recordSignals({}, diags)) << diags.str();
  const auto outcome = sim->run({});
  ASSERT_EQ(outcome.reason, StopReason::Until) << outcome.message;
  const SignalTable& t = *sim->signals();
  EXPECT_EQ(t.columns, (std::vector<std::string>{"as", "bs", "all", "qa", "ab", "job"}));
  ASSERT_EQ(t.time, (std::vector<double>{0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4}));
  const auto series = [&](const char* name) {
    std::vector<double> out;
    for (const auto& row : t.rows) out.push_back(row[column(t, name)].value_or(-1));
    return out;
  };
  // take starts at 1 s and again at 2 s as it ends (each time with an a), and ends at 3 s
  EXPECT_EQ(series("as"), (std::vector<double>{2, 2, 1, 1, 0, 0, 0, 0, 0}));
  EXPECT_EQ(series("bs"), (std::vector<double>(9, 1)));
  EXPECT_EQ(series("all"), (std::vector<double>{3, 3, 2, 2, 1, 1, 1, 1, 1}));
  EXPECT_EQ(series("qa"), (std::vector<double>{0, 0, 0, 0, 1, 1, 2, 2, 2}));
  // a tuple and a record: 3'(a, b) ++ 1'(b, a); 2'{id = b, kind = a} ++ 1'{id = a, kind = a}
  EXPECT_EQ(series("ab"), (std::vector<double>(9, 3)));
  EXPECT_EQ(series("job"), (std::vector<double>(9, 2)));
}

TEST(Signals, AValueOnTheCommandLineFollowsThePlacesNameAfterAnEqualsSign) {
  std::string why;
  auto s = parseSignalArgument("place:main/pairs=(b, a)", why);
  ASSERT_TRUE(s) << why;
  EXPECT_EQ(s->kind, SignalSpec::Kind::Place);
  EXPECT_EQ(s->target, "main/pairs");
  EXPECT_EQ(s->value, "(b, a)");
  EXPECT_EQ(s->name, "main/pairs=(b, a)");
  EXPECT_TRUE(parseSignalArgument("place:main/p", why)->value.empty());
  // read against the run: (b, a) once on pairs; a wrongly typed value is refused
  auto sim = testing::openModelFile("tests/data/good/value_counts.gdpn.yaml");
  ASSERT_TRUE(sim);
  core::Diagnostics diags;
  auto b = *parseSignalArgument("place:main/p=b", why);
  ASSERT_TRUE(sim->recordSignals({*s, b}, diags)) << diags.str();
  sim->run({0.5, {}});
  const SignalTable& t = *sim->signals();
  EXPECT_EQ(t.rows.front()[column(t, "main/pairs=(b, a)")], 1.0);
  EXPECT_EQ(t.rows.front()[column(t, "main/p=b")], 1.0);
  auto again = testing::openModelFile("tests/data/good/value_counts.gdpn.yaml");
  ASSERT_TRUE(again);
  EXPECT_FALSE(again->recordSignals({*parseSignalArgument("place:main/p=(a, b)", why)}, diags));
  EXPECT_NE(diags.str().find("--signal place:main/p=(a, b): error: signal 'main/p=(a, b)': "), std::string::npos)
      << diags.str();
  // a syntax error, an empty value or name
  EXPECT_FALSE(parseSignalArgument("place:main/p=(a,", why));
  EXPECT_EQ(why.rfind("value '(a,': ", 0), 0u) << why;
  for (const char* bad : {"place:main/p=", "place:=a"}) {
    EXPECT_FALSE(parseSignalArgument(bad, why)) << bad;
    EXPECT_EQ(why, std::string("expects place:NAME=VALUE (main/idle=lathe), got '") + bad + "'");
  }
}

/// The diagnostics of making ready a run of the value_counts model's net with `signal` (a
/// line of the `signals` section, at line 8 of the file), or of reading it.
std::string valueSignalMistake(const std::string& signal) {
  core::Diagnostics diags;
  auto m = parseModel(R"yaml(gdpn: 1
colours:
  Ab: {enum: [a, b]}
  Id: {range: [1, 4]}
  Pair: {product: [Ab, Id]}
variables: {x: Ab}
signals:
)yaml" + signal + R"yaml(
pages:
  main:
    places:
      p: {colour: Ab, values: "2'a ++ 1'b"}
      n: {colour: Id}
      pairs: {colour: Pair}
      two: {colour: {a0: Ab, b0: Id}}
      plain: {tokens: 1}
)yaml",
                      "values.gdpn.yaml", diags);
  if (m) {
    auto sim = Simulation::create(*m, diags);
    EXPECT_TRUE(sim) << diags.str();
    if (sim) {
      EXPECT_FALSE(sim->recordSignals({}, diags)) << signal;
    }
  }
  EXPECT_TRUE(diags.hasErrors()) << signal;
  return diags.str();
}

TEST(Signals, AValueThatIsNoneOfThePlacesSetIsRefusedAtItsCharacter) {
  // a place without value slots, or with two
  EXPECT_NE(valueSignalMistake("  s: {place: main/plain, value: a}")
                .find("values.gdpn.yaml:8:33: error: signal 's': place 'main/plain' holds no values (it has no slot "
                      "with a colour)"),
            std::string::npos)
      << valueSignalMistake("  s: {place: main/plain, value: a}");
  EXPECT_NE(valueSignalMistake("  s: {place: main/two, value: a}")
                .find("values.gdpn.yaml:8:31: error: signal 's': place 'main/two' has value slots a0, b0: 'value' "
                      "counts on a place with one"),
            std::string::npos)
      << valueSignalMistake("  s: {place: main/two, value: a}");
  // of another set: a number for an enumeration, a component of the wrong set in a tuple
  std::string d = valueSignalMistake("  s: {place: main/p, value: 3}");
  EXPECT_NE(d.find("values.gdpn.yaml:8:29: error: signal 's': "), std::string::npos) << d;
  d = valueSignalMistake("  s: {place: main/pairs, value: \"(a, b)\"}");
  EXPECT_NE(d.find("values.gdpn.yaml:8:38: error: signal 's': "), std::string::npos) << d;
  // a multiset, a variable, an unknown name: not one value
  d = valueSignalMistake("  s: {place: main/p, value: \"2'a\"}");
  EXPECT_NE(d.find("values.gdpn.yaml:8:30: error: signal 's': "), std::string::npos) << d;
  d = valueSignalMistake("  s: {place: main/p, value: x}");
  EXPECT_NE(d.find("values.gdpn.yaml:8:29: error: signal 's': "), std::string::npos) << d;
  d = valueSignalMistake("  s: {place: main/p, value: c}");
  EXPECT_NE(d.find("values.gdpn.yaml:8:29: error: signal 's': "), std::string::npos) << d;
  // a number outside the range
  d = valueSignalMistake("  s: {place: main/n, value: 7}");
  EXPECT_NE(d.find("values.gdpn.yaml:8:29: error: signal 's': '7' is no value of Id (1..4)"), std::string::npos) << d;
  // a syntax error, found when the file is read
  d = valueSignalMistake("  s: {place: main/pairs, value: \"(a, 1\"}");
  EXPECT_NE(d.find("values.gdpn.yaml:8:"), std::string::npos) << d;
  // 'value' with a node or an expression
  d = valueSignalMistake("  s: {expression: \"1\", value: a}");
  EXPECT_NE(d.find("values.gdpn.yaml:8:3: error: 'value' goes with 'place' only (signal 's')"), std::string::npos) << d;
}

}  // namespace
}  // namespace gdpn::model
