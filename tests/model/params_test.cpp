// Model parameters: the params section, fields that refer to a parameter, values set from
// outside (--param, Python's params=), and sim.params in scripts.

#include <gtest/gtest.h>

#include <sstream>

#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"
#include "gdpn/scene/fields.h"
#include "support/sim_helpers.h"

namespace gdpn::model {
namespace {

const std::string kFile = std::string(GDPN_SOURCE_DIR) + "/tests/data/good/params.gdpn.yaml";

const net::PlaceSpec& place(const Model& m, const std::string& name) {
  for (const auto& p : m.net.pages.at(0).places) {
    if (p.name == name) return p;
  }
  throw std::runtime_error("no place " + name);
}

const net::TransitionSpec& transition(const Model& m, const std::string& name) {
  for (const auto& t : m.net.pages.at(0).transitions) {
    if (t.name == name) return t;
  }
  throw std::runtime_error("no transition " + name);
}

const Param& param(const Model& m, const std::string& name) {
  for (const auto& p : m.params) {
    if (p.name == name) return p;
  }
  throw std::runtime_error("no parameter " + name);
}

TEST(Params, TheSectionDeclaresNamesValuesAndUnits) {
  core::Diagnostics diags;
  auto m = loadModel(kFile, diags);
  ASSERT_TRUE(m) << diags.str();
  ASSERT_EQ(m->params.size(), 6u);
  EXPECT_EQ(m->params[0].name, "wait");
  EXPECT_EQ(m->params[0].value, 0.5);
  EXPECT_EQ(m->params[0].unit, "s");
  EXPECT_EQ(m->params[0].description, "how long a part is worked on");
  EXPECT_FALSE(m->params[0].integer);
  EXPECT_TRUE(param(*m, "parts").integer);
  EXPECT_EQ(param(*m, "belt_speed").unit, "m/s");
  // the fields that name a parameter hold its value
  EXPECT_EQ(place(*m, "ready").tokens.at(0).value, 3);
  EXPECT_EQ(place(*m, "ready").tokens.at(0).param, "parts");
  EXPECT_EQ(transition(*m, "work").duration.a, 0.5);
  EXPECT_EQ(transition(*m, "work").priority, 2);
  EXPECT_EQ(transition(*m, "vary").probability, 0.5);
}

TEST(Params, OverridesChangeEveryFieldThatNamesTheParameter) {
  core::Diagnostics diags;
  auto m = loadModel(kFile, diags, {{"parts", "5"}, {"wait", "2"}, {"belt_speed", "0.8"}, {"lane", "3"},
                                    {"spread", "1e-1"}, {"chance", "0.25"}});
  ASSERT_TRUE(m) << diags.str();
  EXPECT_EQ(param(*m, "parts").value, 5);
  EXPECT_EQ(param(*m, "parts").declared, 3);
  EXPECT_EQ(place(*m, "ready").tokens.at(0).value, 5);
  EXPECT_EQ(place(*m, "ready").capacity.at(0).value, 5);
  EXPECT_EQ(place(*m, "side").tokens.at(1).value, 3);
  EXPECT_EQ(transition(*m, "work").duration.a, 2.0);
  EXPECT_EQ(transition(*m, "work").priority, 3);
  EXPECT_EQ(transition(*m, "vary").duration.a, 2.0);
  EXPECT_EQ(transition(*m, "vary").duration.b, 1.5);  // a number written as such stays
  EXPECT_EQ(transition(*m, "vary").probability, 0.25);
  EXPECT_EQ(transition(*m, "fast").duration.b, 0.1);
  EXPECT_EQ(transition(*m, "rare").duration.a, 2.0);
  EXPECT_EQ(m->net.pages.at(0).arcs.at(2).weights.at(0).value, 3);
  // scene fields too
  const scene::Node* belt = m->scene->find("belt");
  ASSERT_NE(belt, nullptr);
  EXPECT_EQ(belt->number(scene::field::Conveyor::Speed), 0.8);
  const auto& world = *m->scene->root().children().back();
  EXPECT_EQ(world.number(scene::field::World::Substeps), 3);
}

TEST(Params, SavingWritesTheReferencesAndTheDeclaredValues) {
  core::Diagnostics diags;
  auto plain = loadModel(kFile, diags);
  auto set = loadModel(kFile, diags, {{"parts", "5"}, {"wait", "2"}, {"belt_speed", "0.8"}});
  ASSERT_TRUE(plain && set) << diags.str();
  const std::string text = writeModel(*set);
  EXPECT_EQ(text, writeModel(*plain));
  for (const char* written : {"tokens: $parts", "capacity: $parts", "duration: $wait", "uniform: [$wait, 1.5]",
                              "speed: $belt_speed", "a1: $lane", "priority: $lane", "probability: $chance",
                              "parts: 3", "spread: 0.25", "{value: 0.5, unit: s, description: \"how long a part is worked on\"}"}) {
    EXPECT_NE(text.find(written), std::string::npos) << written << " in\n" << text;
  }
  auto back = parseModel(text, "back.gdpn.yaml", diags);
  ASSERT_TRUE(back) << diags.str() << text;
  EXPECT_EQ(*back, *plain);
}

TEST(Params, ADecimalParameterStaysDecimalWhenItsValueIsWhole) {
  core::Diagnostics diags;
  auto m = parseModel("gdpn: 1\nparams: {speed: 2.0, count: 2}\npages: {main: {places: {p: {tokens: $count}}}}\n",
                      "m.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  EXPECT_FALSE(param(*m, "speed").integer);
  EXPECT_TRUE(param(*m, "count").integer);
  const std::string text = writeModel(*m);
  EXPECT_NE(text.find("speed: 2.0"), std::string::npos) << text;
  auto back = parseModel(text, "m.gdpn.yaml", diags);
  ASSERT_TRUE(back) << diags.str();
  EXPECT_FALSE(param(*back, "speed").integer);
}

TEST(Params, MistakesInOverridesNameTheArgument) {
  const auto error = [](std::vector<ParamOverride> overrides) {
    core::Diagnostics diags;
    EXPECT_FALSE(loadModel(kFile, diags, overrides));
    return diags.str();
  };
  EXPECT_NE(error({{"wiat", "1"}}).find("--param: error: no parameter 'wiat' in"), std::string::npos);
  EXPECT_NE(error({{"wiat", "1"}}).find("(did you mean 'wait'?)"), std::string::npos);
  EXPECT_NE(error({{"wait", "fast"}}).find("--param: error: parameter 'wait' expects a number, got 'fast'"),
            std::string::npos);
  EXPECT_NE(error({{"wait", "inf"}}).find("expects a number, got 'inf'"), std::string::npos);
  EXPECT_NE(error({{"wait", ""}}).find("expects a number, got ''"), std::string::npos);
  EXPECT_NE(error({{"parts", "2.5"}}).find("parameter 'parts' is a whole number (at most 2^53), got '2.5'"), std::string::npos);
  EXPECT_NE(error({{"parts", "2", "params="}, {"x", "1", "params="}}).find("params=: error: no parameter 'x'"),
            std::string::npos);
  // a value the field refuses is reported where the field names the parameter: the loader
  // takes any number, compile() checks each field's range
  core::Diagnostics diags;
  auto m = loadModel(kFile, diags, {{"wait", "-1"}});
  ASSERT_TRUE(m);
  EXPECT_FALSE(Simulation::create(*m, diags));
  EXPECT_NE(diags.str().find("params.gdpn.yaml:19:24: error: duration of transition 'work' is negative (-1 s)"),
            std::string::npos)
      << diags.str();
}

TEST(Params, ParseParamArgumentSplitsAtTheFirstEquals) {
  auto o = parseParamArgument("belt_speed=0.8");
  ASSERT_TRUE(o);
  EXPECT_EQ(o->name, "belt_speed");
  EXPECT_EQ(o->text, "0.8");
  EXPECT_EQ(parseParamArgument("x==1")->text, "=1");
  EXPECT_FALSE(parseParamArgument("x"));
  EXPECT_FALSE(parseParamArgument("=1"));
}

const char* kScripted = R"(gdpn: 1
settings: {dt: 0.25}
params:
  parts: 2
  wait: {value: 0.5, unit: s}
pages:
  main:
    places:
      ready: {tokens: $parts}
      done: {}
    transitions:
      work:
        duration: $wait
        post_fire: |
          sim.log(sim.params.parts, sim.params["wait"], type(sim.params.parts).__name__, "wait" in sim.params, len(sim.params), sorted(sim.params))
          try:
              sim.params.wait = 3
          except AttributeError:
              sim.log("read-only")
          try:
              sim.params.speed
          except AttributeError as e:
              sim.log(e)
    arcs: [ready -> work, work -> done]
)";

TEST(Params, ScriptsReadThemAndCannotSetThem) {
  core::Diagnostics diags;
  auto m = parseModel(kScripted, "scripted.gdpn.yaml", diags, {{"parts", "3"}, {"wait", "0.75"}});
  ASSERT_TRUE(m) << diags.str();
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  std::ostringstream trace;
  sim->traceTo(trace);
  const auto outcome = sim->run({});
  EXPECT_EQ(outcome.reason, StopReason::Dead);
  EXPECT_EQ(outcome.time, 2.25);  // three parts of 0.75 s each
  const auto lines = testing::logLines(trace.str());
  ASSERT_EQ(lines.size(), 9u) << trace.str();
  EXPECT_EQ(lines[0], "3 0.75 int True 2 ['parts', 'wait']");
  EXPECT_EQ(lines[1], "read-only");
  EXPECT_EQ(lines[2], "no parameter 'speed' (the model declares parts, wait)");
}

TEST(Params, AQuotedDollarIsTextAndAHugeWholeNumberIsRefused) {
  core::Diagnostics diags;
  EXPECT_FALSE(parseModel("gdpn: 1\nparams: {n: 2}\npages: {main: {places: {p: {tokens: \"$n\"}}}}\n", "q.gdpn.yaml", diags));
  EXPECT_NE(diags.str().find("q.gdpn.yaml:3:37: error: 'tokens' expects a whole number, got \"$n\""), std::string::npos)
      << diags.str();
  core::Diagnostics big;
  EXPECT_FALSE(parseModel("gdpn: 1\nparams: {n: 9007199254740993}\n", "b.gdpn.yaml", big));
  EXPECT_NE(big.str().find("b.gdpn.yaml:2:13: error: parameter 'n' is a whole number beyond 2^53"), std::string::npos)
      << big.str();
  core::Diagnostics over;
  EXPECT_FALSE(loadModel(kFile, over, {{"parts", "1e30"}}));
  EXPECT_NE(over.str().find("parameter 'parts' is a whole number (at most 2^53), got '1e30'"), std::string::npos)
      << over.str();
}

TEST(Params, APastedFragmentKeepsOnlyTheParametersItsNewModelDeclares) {
  core::Diagnostics diags;
  auto m = loadModel(kFile, diags);
  ASSERT_TRUE(m) << diags.str();
  keepParamsOf(*m, {Param{"wait", 1.0, 1.0, false, "", "", {}}});
  EXPECT_TRUE(m->params.empty());
  EXPECT_EQ(transition(*m, "work").duration.params[0], "wait");  // declared there: kept
  EXPECT_EQ(transition(*m, "work").priority_param, "");
  EXPECT_EQ(transition(*m, "work").priority, 2);                  // the value stays
  EXPECT_EQ(place(*m, "ready").tokens.at(0).param, "");
  EXPECT_TRUE(m->scene->find("belt")->params.empty());
  EXPECT_EQ(m->scene->find("belt")->number(scene::field::Conveyor::Speed), 0.4);
}

}  // namespace
}  // namespace gdpn::model
