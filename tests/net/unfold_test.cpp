// Unfolding a coloured net into a place/transition net (unfold.h), on small nets worked out by
// hand: the places per value with their initial tokens, the transitions per binding with
// their arcs' weights, the names they stand for in queries, and the located refusals.

#include <gtest/gtest.h>

#include <algorithm>

#include "gdpn/net/compile.h"
#include "gdpn/net/query.h"
#include "gdpn/net/unfold.h"

namespace gdpn::net {
namespace {

/// A net of one page `net`: philosophers P = {p1, p2, p3} (cyclic) who think and then eat with
/// their fork and their right neighbour's: Think (all(P)) -> Eat, each fork once, and back.
NetSpec philosophers() {
  NetSpec spec;
  ColourSetSpec p;
  p.name = "P";
  p.kind = ColourKind::Enum;
  p.constants = {"p1", "p2", "p3"};
  p.cyclic = true;
  spec.colours.push_back(p);
  spec.variables.push_back({"x", "P", {}});
  PageSpec page;
  page.name = "net";
  auto place = [&](const std::string& name, const std::string& values) {
    PlaceSpec s;
    s.name = name;
    s.colours.push_back({kDefaultSlot, "P", {}});
    if (!values.empty()) s.values.push_back({kDefaultSlot, values, {}});
    page.places.push_back(s);
  };
  place("Think", "all(P)");
  place("Fork", "all");
  place("Eat", "");
  PlaceSpec count;  // a plain place: how many meals
  count.name = "meals";
  page.places.push_back(count);
  for (const char* t : {"take", "leave"}) {
    TransitionSpec s;
    s.name = t;
    page.transitions.push_back(s);
  }
  auto arc = [&](const std::string& from, const std::string& to, const std::string& text) {
    ArcSpec a;
    a.from = from;
    a.to = to;
    if (!text.empty()) a.inscriptions.push_back({kDefaultSlot, text, {}});
    page.arcs.push_back(a);
  };
  arc("Think", "take", "x");
  arc("Fork", "take", "x ++ succ(x)");
  arc("take", "Eat", "x");
  arc("take", "meals", "");
  arc("Eat", "leave", "x");
  arc("leave", "Think", "1'x");
  arc("leave", "Fork", "x ++ succ(x)");
  spec.pages.push_back(page);
  return spec;
}

/// The arcs of `page` as "from -w-> to".
std::vector<std::string> arcs(const PageSpec& page) {
  std::vector<std::string> out;
  for (const auto& a : page.arcs) {
    std::int64_t w = 1;
    for (const auto& x : a.weights) w = x.value;
    out.push_back(a.from + " -" + std::to_string(w) + "-> " + a.to);
  }
  return out;
}

TEST(Unfold, APlacePerValueATransitionPerBindingAndArcsOfItsMultiplicities) {
  core::Diagnostics diags;
  const auto u = unfold(philosophers(), diags);
  ASSERT_TRUE(u) << diags.str();
  EXPECT_TRUE(coloured(philosophers()));
  EXPECT_FALSE(coloured(u->net));
  const PageSpec& page = u->net.pages.at(0);
  std::vector<std::string> places;
  for (const auto& p : page.places) {
    places.push_back(p.name + ":" + (p.tokens.empty() ? std::string("0") : std::to_string(p.tokens[0].value)));
  }
  EXPECT_EQ(places, (std::vector<std::string>{"Think_p1:1", "Think_p2:1", "Think_p3:1", "Fork_p1:1", "Fork_p2:1",
                                              "Fork_p3:1", "Eat_p1:0", "Eat_p2:0", "Eat_p3:0", "meals:0"}));
  std::vector<std::string> transitions;
  for (const auto& t : page.transitions) transitions.push_back(t.name);
  EXPECT_EQ(transitions, (std::vector<std::string>{"take_p1", "take_p2", "take_p3", "leave_p1", "leave_p2", "leave_p3"}));
  // take_p3 takes fork p3 and its successor p1; the plain arc to meals is copied to each
  const auto all = arcs(page);
  for (const char* a : {"Think_p3 -1-> take_p3", "Fork_p3 -1-> take_p3", "Fork_p1 -1-> take_p3", "take_p3 -1-> Eat_p3",
                        "take_p3 -1-> meals", "leave_p2 -1-> Fork_p3", "leave_p2 -1-> Fork_p2"}) {
    EXPECT_NE(std::find(all.begin(), all.end(), a), all.end()) << a;
  }
  EXPECT_EQ(all.size(), 3u * 5u + 3u * 4u);
  // the names queries read
  EXPECT_EQ(u->names.places.at("net/Think"),
            (std::vector<std::string>{"net/Think_p1", "net/Think_p2", "net/Think_p3"}));
  EXPECT_EQ(u->names.transitions.at("net/take"),
            (std::vector<std::string>{"net/take_p1", "net/take_p2", "net/take_p3"}));
  EXPECT_FALSE(u->names.places.contains("net/meals"));
}

TEST(Unfold, AFortyTwoTokenArcAndAConditionLeaveOnlyTheBindingsThatHold) {
  NetSpec spec = philosophers();
  spec.pages[0].transitions[0].when = {kDefaultSlot, "x <> p2", {}};
  spec.pages[0].arcs[3].inscriptions.clear();
  spec.pages[0].arcs[3].weights.push_back({kDefaultSlot, 42, {}, {}});
  spec.pages[0].arcs[2].inscriptions[0].text = "2'x";
  core::Diagnostics diags;
  const auto u = unfold(spec, diags);
  ASSERT_TRUE(u) << diags.str();
  EXPECT_EQ(u->names.transitions.at("net/take"), (std::vector<std::string>{"net/take_p1", "net/take_p3"}));
  const auto all = arcs(u->net.pages[0]);
  EXPECT_NE(std::find(all.begin(), all.end(), "take_p1 -42-> meals"), all.end());
  EXPECT_NE(std::find(all.begin(), all.end(), "take_p3 -2-> Eat_p3"), all.end());
}

TEST(Unfold, QueriesNameColouredPlacesAndTransitionsAndAreWrittenSo) {
  core::Diagnostics diags;
  const auto u = unfold(philosophers(), diags);
  ASSERT_TRUE(u) << diags.str();
  const auto net = compile(u->net, diags);
  ASSERT_TRUE(net) << diags.str();
  QueryError error;
  // Think is the sum of its three places; take any of its three bindings
  const auto f = parseQuery(*net, "EF (Think + Eat = 2 and fireable(take))", error, &u->names);
  ASSERT_TRUE(f) << error.message;
  const Formula& both = f->operands[0].operands[0];
  EXPECT_EQ(both.operands[0].left.slots.size(), 6u);
  EXPECT_EQ(both.operands[1].transitions.size(), 3u);
  EXPECT_EQ(formulaText(*net, *f, &u->names), "EF (net/Think + net/Eat = 2 and fireable(net/take))");
  // one of them alone keeps its own name
  const auto g = parseQuery(*net, "Think_p2 + Think = 1", error, &u->names);
  ASSERT_TRUE(g) << error.message;
  EXPECT_EQ(formulaText(*net, *g, &u->names), "net/Think_p2 + net/Think = 1");
  // the answer: two philosophers never eat at once (three forks, two each)
  EXPECT_EQ(answerQuery(*net, *parseQuery(*net, "AG Eat <= 1", error, &u->names)).verdict, Verdict::True);
  EXPECT_EQ(answerQuery(*net, *parseQuery(*net, "EF Eat = 1", error, &u->names)).verdict, Verdict::True);
  // without the expansion the coloured name is no place
  EXPECT_FALSE(parseQuery(*net, "Think = 1", error));
  EXPECT_EQ(error.message, "no place is called 'Think'");
}

TEST(Unfold, WhatCannotBeUnfoldedIsRefusedWhereItIsWritten) {
  auto refusal = [](NetSpec spec, std::size_t most = kMostUnfoldedBindings) {
    core::Diagnostics diags;
    EXPECT_FALSE(unfold(spec, diags, most));
    return diags.str();
  };
  const SourceLoc at{"m.gdpn.yaml", 7, 9};
  // a set that is not finite
  NetSpec spec = philosophers();
  spec.pages[0].places[2].colours[0] = {kDefaultSlot, "int", at};
  EXPECT_NE(refusal(spec).find("m.gdpn.yaml:7:9: error: place 'Eat' holds values of 'int', which is not finite"),
            std::string::npos)
      << refusal(spec);
  // too many bindings
  spec = philosophers();
  spec.pages[0].transitions[0].loc = at;
  EXPECT_NE(refusal(spec, 2).find("m.gdpn.yaml:7:9: error: transition 'take' cannot be unfolded: "), std::string::npos)
      << refusal(spec, 2);
  // an arc on value slots without an inscription
  spec = philosophers();
  spec.pages[0].transitions.push_back({});
  spec.pages[0].transitions.back().name = "plain";
  spec.pages[0].arcs.push_back({});
  spec.pages[0].arcs.back().from = "Eat";
  spec.pages[0].arcs.back().to = "plain";
  spec.pages[0].arcs.back().loc = at;
  EXPECT_NE(refusal(spec).find("m.gdpn.yaml:7:9: error: the arc between 'Eat' and 'plain' reaches value slot a0 of "
                               "place 'Eat' and has no inscription"),
            std::string::npos)
      << refusal(spec);
  // an inhibitor arc of two values at once: the coloured arc inhibits only where both are there
  spec = philosophers();
  spec.pages[0].arcs[1].kind = ArcKind::Inhibitor;
  spec.pages[0].arcs[1].loc = at;
  EXPECT_NE(refusal(spec).find("m.gdpn.yaml:7:9: error: the inhibitor arc from 'Fork' inhibits with several values at "
                               "once (1'p1 ++ 1'p2), which place/transition arcs cannot say"),
            std::string::npos)
      << refusal(spec);
  // a mistake in an inscription, where it stands
  spec = philosophers();
  spec.pages[0].arcs[0].inscriptions[0] = {kDefaultSlot, "y", at};
  EXPECT_NE(refusal(spec).find("m.gdpn.yaml:7:9: error:"), std::string::npos) << refusal(spec);
}

}  // namespace
}  // namespace gdpn::net
