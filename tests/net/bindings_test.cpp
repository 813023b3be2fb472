// The bindings of a coloured transition (net/inscription.h): pattern matching on input arcs,
// free variables over finite sets, conditions, test and inhibitor arcs, room for output, the
// canonical order and `most`, on answers worked out by hand.

#include <gtest/gtest.h>

#include "gdpn/net/inscription.h"

namespace gdpn::net {
namespace {

Value I(std::int64_t n) { return Value::integer(n); }

/// Sets R = 1..3, Phil = p1..p3, Pair = (R, Phil); variables x, y: Phil; n: R; s: string; i: int.
class Bindings : public ::testing::Test {
 protected:
  void SetUp() override {
    ColourSetSpec r;
    r.name = "R";
    r.kind = ColourKind::Integer;
    r.range = true;
    r.lo = 1;
    r.hi = 3;
    ColourSetSpec phil;
    phil.name = "Phil";
    phil.kind = ColourKind::Enum;
    phil.constants = {"p1", "p2", "p3"};
    ColourSetSpec pair;
    pair.name = "Pair";
    pair.kind = ColourKind::Product;
    pair.components = {"R", "Phil"};
    core::Diagnostics d;
    ASSERT_TRUE(colours.declare({r, phil, pair}, d)) << d.str();
    scope.colours = &colours;
    scope.variable_names = {"x", "y", "n", "s", "i"};
    scope.variable_sets = {kPhil, kPhil, kR, Colours::kString, Colours::kInt};
  }

  /// Adds an arc of `role` on a place of `set` with inscription `text`; its marking `held`.
  void arc(ArcRole role, ColourId set, std::string_view text, Multiset held = {}) {
    core::Diagnostics d;
    auto e = parseInscription(text, {"m", 1, 1}, d);
    ASSERT_TRUE(e.has_value()) << d.str();
    ASSERT_TRUE(checkInscription(*e, set, Expect::Tokens, scope, used, d)) << d.str();
    t.arcs.push_back({role, set, std::move(*e)});
    marking.push_back(std::move(held));
  }
  void when(std::string_view text) {
    core::Diagnostics d;
    auto e = parseInscription(text, {"m", 1, 1}, d);
    ASSERT_TRUE(e.has_value()) << d.str();
    ASSERT_TRUE(checkInscription(*e, Colours::kBool, Expect::Condition, scope, used, d)) << d.str();
    t.when = std::move(*e);
  }
  /// The transition's variables: those the inscriptions used, in their order.
  void finish() {
    t.variables.clear();
    t.sets.clear();
    for (const std::uint32_t v : used) {
      t.variables.push_back(scope.variable_names[v]);
      t.sets.push_back(scope.variable_sets[v]);
    }
  }
  std::vector<BoundOccurrence> enabled(std::size_t most = SIZE_MAX, const ArcRoom& room = {}) {
    finish();
    return enabledBindings(t, colours, [this](std::size_t a) -> const Multiset& { return marking[a]; }, room, most);
  }
  /// The bindings as text: "x=p1 n=2; ..." in the order given.
  std::string text(const std::vector<BoundOccurrence>& found) const {
    std::string out;
    for (const BoundOccurrence& o : found) {
      if (!out.empty()) out += "; ";
      for (std::size_t k = 0; k < o.binding.size(); ++k) {
        if (k > 0) out += " ";
        out += t.variables[k] + "=" + colours.text(t.sets[k], o.binding[k]);
      }
    }
    return out;
  }

  static constexpr ColourId kR = 4, kPhil = 5, kPair = 6;
  Colours colours;
  InscriptionScope scope;
  std::vector<std::uint32_t> used;
  TransitionInscriptions t;
  std::vector<Multiset> marking;
};

TEST_F(Bindings, AMultiplicityNeedsThatManyEqualTokens) {
  arc(ArcRole::Take, kPhil, "2'x", {{I(0), 1}, {I(1), 2}, {I(2), 3}});
  const auto found = enabled();
  EXPECT_EQ(text(found), "x=p2; x=p3");
  ASSERT_EQ(found.size(), 2U);
  EXPECT_EQ(found[0].arcs[0], (Multiset{{I(1), 2}}));
}

TEST_F(Bindings, TwoTermsOfOneArcAreCountedTogether) {
  // x = y needs two of one value: only p2 has them
  arc(ArcRole::Take, kPhil, "1'x ++ 1'y", {{I(0), 1}, {I(1), 2}});
  EXPECT_EQ(text(enabled()), "x=p1 y=p2; x=p2 y=p1; x=p2 y=p2");
}

TEST_F(Bindings, TheConditionFilters) {
  arc(ArcRole::Take, kPhil, "x", {{I(0), 1}, {I(2), 1}});
  arc(ArcRole::Take, kPhil, "y", {{I(1), 1}, {I(2), 1}});
  when("x < y");
  EXPECT_EQ(text(enabled()), "x=p1 y=p2; x=p1 y=p3");
}

TEST_F(Bindings, PatternsOfTuplesAndConstants) {
  arc(ArcRole::Take, kPair, "(n, p1)", {{Value::tuple({I(1), I(0)}), 1}, {Value::tuple({I(2), I(1)}), 1},
                                        {Value::tuple({I(3), I(0)}), 1}});
  EXPECT_EQ(text(enabled()), "n=1; n=3");
}

TEST_F(Bindings, AVariableOnTwoArcsAgrees) {
  arc(ArcRole::Take, kPair, "(n, x)", {{Value::tuple({I(1), I(0)}), 1}, {Value::tuple({I(2), I(1)}), 1}});
  arc(ArcRole::Take, kPhil, "x", {{I(1), 1}, {I(2), 1}});
  EXPECT_EQ(text(enabled()), "n=2 x=p2");
}

TEST_F(Bindings, FreeVariablesAreEnumeratedOverTheirFiniteSets) {
  arc(ArcRole::Take, kPhil, "x", {{I(1), 1}});
  arc(ArcRole::Put, kPair, "(n, x)");
  EXPECT_EQ(text(enabled()), "x=p2 n=1; x=p2 n=2; x=p2 n=3");
  when("n <> 2");
  const auto found = enabled();
  EXPECT_EQ(text(found), "x=p2 n=1; x=p2 n=3");
  ASSERT_EQ(found.size(), 2U);
  EXPECT_EQ(found[1].arcs[1], (Multiset{{Value::tuple({I(3), I(1)}), 1}}));
}

TEST_F(Bindings, ATransitionWithNoInputArcEnumeratesEverything) {
  arc(ArcRole::Put, kPhil, "x");
  EXPECT_EQ(text(enabled()), "x=p1; x=p2; x=p3");
}

TEST_F(Bindings, TestArcsBindWithoutTaking) {
  arc(ArcRole::Test, kPhil, "x", {{I(0), 1}, {I(2), 5}});
  arc(ArcRole::Put, kR, "n");
  when("n = 1");
  const auto found = enabled();
  EXPECT_EQ(text(found), "x=p1 n=1; x=p3 n=1");
  ASSERT_EQ(found.size(), 2U);
  EXPECT_EQ(found[1].arcs[0], (Multiset{{I(2), 1}}));
  // a test arc needs its multiset too
  t = {};
  marking.clear();
  used.clear();
  arc(ArcRole::Test, kPhil, "2'x", {{I(0), 1}, {I(2), 2}});
  EXPECT_EQ(text(enabled()), "x=p3");
}

TEST_F(Bindings, InhibitorArcsWithExpressions) {
  // x is refused while the busy place holds it
  arc(ArcRole::Take, kPhil, "x", {{I(0), 1}, {I(1), 1}});
  arc(ArcRole::Inhibit, kPhil, "x", {{I(0), 1}});
  EXPECT_EQ(text(enabled()), "x=p2");
  // two of it: one is not enough to inhibit
  t.arcs.pop_back();
  marking.pop_back();
  arc(ArcRole::Inhibit, kPhil, "2'x", {{I(0), 1}, {I(1), 2}});
  EXPECT_EQ(text(enabled()), "x=p1");
}

TEST_F(Bindings, AnEmptyInhibitorNeverInhibits) {
  arc(ArcRole::Take, kPhil, "x", {{I(0), 1}, {I(1), 1}});
  arc(ArcRole::Inhibit, kPhil, "if x = p1 then empty else 1'p3", {{I(2), 1}});
  EXPECT_EQ(text(enabled()), "x=p1");
}

TEST_F(Bindings, APutOutsideItsRangeExcludesTheBinding) {
  arc(ArcRole::Take, kR, "n", {{I(1), 1}, {I(3), 1}});
  arc(ArcRole::Put, kR, "n + 1");
  EXPECT_EQ(text(enabled()), "n=1");
}

TEST_F(Bindings, RoomIsAskedOfEveryPut) {
  arc(ArcRole::Take, kPhil, "x", {{I(0), 1}, {I(1), 1}});
  arc(ArcRole::Put, kPhil, "if x = p1 then 3'x else 1'x");
  // room for at most two tokens
  const ArcRoom room = [](std::size_t a, std::int64_t tokens) { return a == 1 && tokens <= 2; };
  EXPECT_EQ(text(enabled(SIZE_MAX, room)), "x=p2");
}

TEST_F(Bindings, StringVariablesAreMatched) {
  arc(ArcRole::Take, Colours::kString, "s", {{Value::string("b"), 1}, {Value::string("a"), 1}});
  arc(ArcRole::Put, Colours::kString, "s");
  EXPECT_EQ(text(enabled()), "s=\"a\"; s=\"b\"");
  EXPECT_EQ(unboundVariable(t, colours), "");
}

TEST_F(Bindings, CanonicalOrderAndMost) {
  // the condition names x first, so x is variable 0; y's arc is matched first, yet the order is
  // by x, then y
  when("x <> p3 or y <> p3");
  arc(ArcRole::Take, kPhil, "y", {{I(0), 1}, {I(1), 1}});
  arc(ArcRole::Take, kPhil, "x", {{I(0), 1}, {I(1), 1}});
  const auto found = enabled();
  EXPECT_EQ(text(found), "x=p1 y=p1; x=p1 y=p2; x=p2 y=p1; x=p2 y=p2");
  // at most `most`: the search stops there, and what it found comes in the canonical order
  const auto two = enabled(2);
  ASSERT_EQ(two.size(), 2U);
  EXPECT_LT(two[0].binding, two[1].binding);
  EXPECT_EQ(text(enabled(1)), "x=p1 y=p1");
  EXPECT_TRUE(enabled(0).empty());
}

TEST_F(Bindings, NoTokensNoBinding) {
  arc(ArcRole::Take, kPhil, "x");
  arc(ArcRole::Put, kR, "n");
  EXPECT_TRUE(enabled().empty());
}

TEST_F(Bindings, UnboundVariableNamesAnInfiniteFreeOne) {
  arc(ArcRole::Take, kPhil, "x", {{I(0), 1}});
  arc(ArcRole::Put, Colours::kString, "s");
  finish();
  EXPECT_EQ(unboundVariable(t, colours), "variable 's' (string) is bound by no input arc and its colour set is not "
                                         "finite");
  // it finds no binding rather than enumerating text
  EXPECT_TRUE(enabled().empty());
}

TEST_F(Bindings, UnboundVariableAcceptsFiniteOrMatchedVariables) {
  arc(ArcRole::Test, Colours::kInt, "2'i", {{I(7), 2}});
  arc(ArcRole::Put, kR, "n");
  finish();
  EXPECT_EQ(unboundVariable(t, colours), "");
  // an expression is no pattern: i + 1 does not bind i
  t.arcs.clear();
  marking.clear();
  used.clear();
  arc(ArcRole::Take, Colours::kInt, "i + 1", {{I(7), 1}});
  finish();
  EXPECT_EQ(unboundVariable(t, colours), "variable 'i' (int) is bound by no input arc and its colour set is not "
                                         "finite");
}

TEST_F(Bindings, AConditionsEquationFixesAVariableNoSetCouldEnumerate) {
  // i (int, not finite) is on no input arc: the conjunct i = n * 1000 fixes it once n is matched
  arc(ArcRole::Take, kR, "n", {{I(1), 1}, {I(3), 2}});
  arc(ArcRole::Put, Colours::kInt, "i");
  when("n > 1 and i = n * 1000");
  finish();
  EXPECT_EQ(unboundVariable(t, colours), "");
  const auto found = enabled();
  EXPECT_EQ(text(found), "n=3 i=3000");
  ASSERT_EQ(found.size(), 1U);
  EXPECT_EQ(found[0].arcs[1], (Multiset{{I(3000), 1}}));
}

TEST_F(Bindings, AnEquationFixesAVariableWrittenOnEitherSide) {
  // s = "a" needs no other variable; the string then goes out; e = x as well as x = e
  arc(ArcRole::Take, kR, "n", {{I(2), 1}});
  arc(ArcRole::Put, Colours::kString, "s");
  arc(ArcRole::Put, Colours::kInt, "i");
  when("\"a\" = s and 6 / (n - 3) = i");
  EXPECT_EQ(text(enabled()), "n=2 s=\"a\" i=-6");
  // 6 / (n - 3) has no value for n = 3: no binding, rather than any i
  marking[0] = {{I(3), 1}};
  EXPECT_TRUE(enabled().empty());
}

TEST_F(Bindings, AnEquationsValueOutsideTheVariablesSetBindsNothing) {
  // n in 1..3: 7 is none of its values
  arc(ArcRole::Take, kPhil, "x", {{I(0), 1}});
  arc(ArcRole::Put, kR, "n");
  when("n = 7");
  EXPECT_TRUE(enabled().empty());
  // an equation between two free variables fixes neither: both are enumerated
  t = {};
  marking.clear();
  used.clear();
  arc(ArcRole::Take, kPhil, "x", {{I(0), 1}});
  arc(ArcRole::Put, kR, "n");
  arc(ArcRole::Put, Colours::kInt, "i");
  when("i = i");
  finish();
  EXPECT_EQ(unboundVariable(t, colours), "variable 'i' (int) is bound by no input arc and its colour set is not "
                                         "finite");
}

TEST_F(Bindings, ARangeOfAMillionIsNotEnumeratedWhereTheConditionFixesIt) {
  ColourSetSpec big;
  big.name = "Big";
  big.kind = ColourKind::Integer;
  big.range = true;
  big.lo = 0;
  big.hi = 999'999;
  core::Diagnostics d;
  ASSERT_TRUE(colours.declare({big}, d)) << d.str();
  const ColourId kBig = 7;
  scope.variable_names.push_back("k");
  scope.variable_sets.push_back(kBig);
  arc(ArcRole::Take, kBig, "k", {{I(5), 1}, {I(999'999), 1}});
  scope.variable_names.push_back("m");
  scope.variable_sets.push_back(kBig);
  arc(ArcRole::Put, kBig, "m");
  when("m = k + 1");
  finish();
  BindingSearch search(t, colours);
  EXPECT_EQ(search.refusal(), "");
  EXPECT_TRUE(search.ordered());
  // k = 999999 has no successor in Big
  EXPECT_EQ(text(enabled()), "k=5 m=6");
}

TEST_F(Bindings, APlanMatchingAgainstTheVariablesOrderStillGivesTheCanonicalOrder) {
  // x is the first variable, but only the pair (n, x) binds it, n first: the search must see
  // every binding and sort them, and stop at none before
  arc(ArcRole::Put, kPhil, "x");
  arc(ArcRole::Take, kPair, "(n, x)", {{Value::tuple({I(1), I(2)}), 1}, {Value::tuple({I(2), I(0)}), 1}});
  finish();
  EXPECT_FALSE(BindingSearch(t, colours).ordered());
  EXPECT_EQ(text(enabled()), "x=p1 n=2; x=p3 n=1");
  EXPECT_EQ(text(enabled(1)), "x=p1 n=2");
}

TEST_F(Bindings, AFreeVariableBeforeTheMatchedOnesIsEnumeratedFirst) {
  // b (a range) is free and first; x is matched: the order is b's, then x's
  arc(ArcRole::Put, kR, "n");
  arc(ArcRole::Take, kPhil, "x", {{I(2), 1}, {I(0), 1}});
  when("n < 3");
  finish();
  EXPECT_TRUE(BindingSearch(t, colours).ordered());
  EXPECT_EQ(text(enabled()), "n=1 x=p1; n=1 x=p3; n=2 x=p1; n=2 x=p3");
  EXPECT_EQ(text(enabled(3)), "n=1 x=p1; n=1 x=p3; n=2 x=p1");
}

TEST_F(Bindings, AllBindingsWhateverTheMarking) {
  arc(ArcRole::Take, kPhil, "x");
  arc(ArcRole::Put, kR, "n + 1");
  when("x <> p2");
  finish();
  std::string why;
  const auto all = allBindings(t, colours, 100, why);
  ASSERT_TRUE(all.has_value()) << why;
  // n = 3 has no n + 1 in R
  std::string shown;
  for (const BoundOccurrence& o : *all) shown += colours.text(kPhil, o.binding[0]) + std::to_string(o.binding[1].i) + " ";
  EXPECT_EQ(shown, "p11 p12 p31 p32 ");
  EXPECT_EQ((*all)[3].arcs[1], (Multiset{{I(3), 1}}));
  EXPECT_FALSE(allBindings(t, colours, 8, why).has_value());
  EXPECT_EQ(why, "its variables take more than 8 bindings");
  EXPECT_TRUE(allBindings(t, colours, 9, why).has_value());
}

TEST_F(Bindings, AllBindingsRefusesAnInfiniteVariable) {
  arc(ArcRole::Take, Colours::kString, "s");
  finish();
  std::string why;
  EXPECT_FALSE(allBindings(t, colours, 100, why).has_value());
  EXPECT_EQ(why, "variable 's' (string) is not of a finite colour set");
}

TEST_F(Bindings, AllBindingsOfNoVariables) {
  arc(ArcRole::Put, kPhil, "all");
  finish();
  std::string why;
  const auto all = allBindings(t, colours, 1, why);
  ASSERT_TRUE(all.has_value()) << why;
  ASSERT_EQ(all->size(), 1U);
  EXPECT_EQ(multisetSize((*all)[0].arcs[0]), 3);
}

}  // namespace
}  // namespace gdpn::net
