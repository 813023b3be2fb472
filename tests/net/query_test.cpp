// Queries: the text form (read back from its own printing, mistakes located by column), and
// reachability answers checked against the whole state space of the conformance nets, each
// witness replayed from the initial marking.

#include "gdpn/net/query.h"

#include <gtest/gtest.h>

#include "gdpn/net/builder.h"
#include "support/conformance.h"

namespace gdpn::net {
namespace {

using testing::conformanceNet;

// the small conformance nets (a whole state space in milliseconds), bounded
const char* kNets[] = {"ResAllocation-PT-R002C002", "ERK-PT-000001",    "Eratosthenes-PT-010",
                       "Angiogenesis-PT-01",        "TokenRing-PT-005", "Philosophers-PT-000005",
                       "CircularTrains-PT-012",     "RobotManipulation-PT-00002", "FMS-PT-00002",
                       "Dekker-PT-010"};

Formula parsed(const Net& net, const std::string& text) {
  QueryError e;
  auto f = parseQuery(net, text, e);
  EXPECT_TRUE(f) << text << ": column " << e.column << ": " << e.message;
  return f ? *f : Formula{};
}

/// Fires `path` from the initial marking, checking each transition enabled on the way (by
/// the query's own fireable atom); the marking reached, or nullopt.
std::optional<std::vector<std::int64_t>> replay(const Net& net, const std::vector<TransitionId>& path) {
  std::vector<std::int64_t> m;
  for (const PlaceSlot& ps : net.placeSlots()) m.push_back(ps.initial);
  for (TransitionId t : path) {
    Formula fireable;
    fireable.kind = FormulaKind::Fireable;
    fireable.transitions = {t};
    if (!holdsIn(net, fireable, m)) return std::nullopt;
    for (const Term& term : net.termsOf(t)) {
      if (term.kind == TermKind::Input) m[term.place_slot] -= term.weight;
      if (term.kind == TermKind::Output) m[term.place_slot] += term.weight;
    }
  }
  return m;
}

TEST(QueryText, EachFormulaReadsBackFromItsOwnText) {
  const auto net = conformanceNet("Philosophers-PT-000005");
  ASSERT_TRUE(net);
  for (const char* text : {
           "EF deadlock",
           "AG not deadlock",
           "EF (net/Think_1 = 0 and fireable(net/FF1a_1, net/FF1a_2))",
           "AG net/Think_1 + net/Eat_1 + 2 <= 3",
           "E [net/Think_1 = 1 U net/Eat_1 >= 1]",
           "A (G F fireable(net/FF1a_1))",
           "E [net/Think_1 = 1 U X net/Eat_1 != 0]",
           "not (true or false) and EX net/Fork_1 < 1",
           "AF EG (net/Fork_1 > 0 or deadlock)",
       }) {
    const Formula f = parsed(*net, text);
    EXPECT_EQ(formulaText(*net, f), text);
    EXPECT_EQ(formulaText(*net, parsed(*net, formulaText(*net, f))), text);
  }
  // other spellings of the same formulas
  const std::pair<const char*, const char*> same[] = {
      {"EF (Think_1 == 0 && !deadlock || false)", "EF ((net/Think_1 = 0 and not deadlock) or false)"},
      {"A G  F fireable(FF1a_1)", "A (G F fireable(net/FF1a_1))"},
      {"E F (Think_1 = 0)", "EF net/Think_1 = 0"},
      {"E (Think_1 = 1 U deadlock)", "E [net/Think_1 = 1 U deadlock]"},
      {"A (F EG deadlock)", "AF EG deadlock"},
      {"\"net/Think_1\" >= 1", "net/Think_1 >= 1"},
  };
  for (const auto& [text, canonical] : same) EXPECT_EQ(formulaText(*net, parsed(*net, text)), canonical) << text;
  EXPECT_TRUE(isStateFormula(parsed(*net, "Think_1 = 0 and not fireable(FF1a_1)")));
  EXPECT_FALSE(isStateFormula(parsed(*net, "Think_1 = 0 and EF deadlock")));
}

TEST(QueryText, MistakesAreLocatedByColumn) {
  const auto net = conformanceNet("Philosophers-PT-000005");
  ASSERT_TRUE(net);
  const struct {
    const char* text;
    std::size_t column;
    const char* says;
  } cases[] = {
      {"EF (Think_1 = 0", 16, "expected ')'"},
      {"EF Thnk_1 = 0", 4, "no place is called 'Thnk_1'"},
      {"EF FF1a_1 > 0", 4, "a transition is: fireable(FF1a_1)?"},
      {"AG fireable(Think_1)", 13, "no transition is called 'Think_1'"},
      {"EF Think_1", 11, "expected a comparison"},
      {"E [ Think_1 = 1 deadlock ]", 17, "expected 'U'"},
      {"EF Think_1 = 1 $", 16, "'$' is not part of a query"},
      {"EF \"Think_1 = 1", 4, "never closed"},
      {"AG U = 1", 4, "'U' is a keyword"},
      {"Think_1 = 99999999999999999999", 11, "too large"},
      {"EF deadlock deadlock", 13, "expected the end"},
      {"", 1, "expected a place"},
  };
  for (const auto& c : cases) {
    QueryError e;
    EXPECT_FALSE(parseQuery(*net, c.text, e)) << c.text;
    EXPECT_EQ(e.column, c.column) << c.text << ": " << e.message;
    EXPECT_NE(e.message.find(c.says), std::string::npos) << c.text << ": " << e.message;
  }
}

TEST(QueryText, NestingIsBoundedAndLongChainsStayFlat) {
  const auto net = conformanceNet("Philosophers-PT-000005");
  ASSERT_TRUE(net);
  // 150 negations: the 101st is one level too deep
  std::string deep;
  for (int i = 0; i < 150; ++i) deep += "not ";
  QueryError e;
  EXPECT_FALSE(parseQuery(*net, deep + "deadlock", e));
  EXPECT_EQ(e.column, 401u);
  EXPECT_NE(e.message.find("nested more than 100 levels"), std::string::npos) << e.message;
  // 10,000 conjuncts: one node, answered without a deep walk
  std::string chain = "EF (true";
  for (int i = 0; i < 10'000; ++i) chain += " and Think_1 + Eat_1 <= 1";
  const Formula f = parsed(*net, chain + ")");
  ASSERT_EQ(f.operands[0].operands[0].operands.size(), 10'001u);
  EXPECT_EQ(answerQuery(*net, f).verdict, Verdict::True);
  // parentheses keep their group
  EXPECT_EQ(formulaText(*net, parsed(*net, "Think_1 = 0 and (Eat_1 = 0 and deadlock) and true")),
            "net/Think_1 = 0 and (net/Eat_1 = 0 and deadlock) and true");
}

TEST(QueryText, APlaceWithoutItsPathIsFoundOnlyWhenOneEndsSo) {
  NetBuilder b;
  const auto a = b.addPlace("line/a/buffer");
  b.addPlace("line/b/buffer");
  b.addPlace("line/b/idle");
  const auto t = b.addTransition("line/a/take");
  b.addInput(a, t);
  const auto net = b.freeze();
  QueryError e;
  EXPECT_TRUE(parseQuery(*net, "EF idle = 1 and fireable(take)", e)) << e.message;
  EXPECT_FALSE(parseQuery(*net, "EF buffer = 1", e));
  EXPECT_NE(e.message.find("no place is called 'buffer'"), std::string::npos) << e.message;
  EXPECT_TRUE(parseQuery(*net, "EF a/buffer = 1", e)) << e.message;
}

TEST(QueryAnswers, ReachabilityAgreesWithTheWholeStateSpaceAndEveryWitnessReplays) {
  for (const char* model : kNets) {
    SCOPED_TRACE(model);
    const auto net = conformanceNet(model);
    ASSERT_TRUE(net);
    ExploreOptions shortest;
    shortest.shortest_path = true;
    const StateSpace space = explore(*net, shortest);
    ASSERT_TRUE(space.complete && space.bounded);
    auto check = [&](const std::string& text, Verdict want, const Formula* target) {
      SCOPED_TRACE(text);
      const QueryAnswer a = answerQuery(*net, parsed(*net, text));
      EXPECT_EQ(a.verdict, want);
      if (!a.has_marking) return a;
      const auto reached = replay(*net, a.path);
      EXPECT_TRUE(reached);
      if (reached) {
        EXPECT_EQ(*reached, a.marking);
      }
      if (target) {
        EXPECT_TRUE(holdsIn(*net, *target, a.marking));
      }
      return a;
    };
    const Formula dead = parsed(*net, "deadlock");
    const QueryAnswer d = check("EF deadlock", space.deadlock ? Verdict::True : Verdict::False, &dead);
    if (space.deadlock) {
      // breadth first: as short as the analysis's shortest path
      EXPECT_EQ(d.path.size(), space.deadlock_path.size());
    } else {
      EXPECT_EQ(d.states, space.states);  // every marking looked at
    }
    check("AG not deadlock", space.deadlock ? Verdict::False : Verdict::True, &dead);
    // each place's bound: reached, never passed
    for (std::size_t p = 0; p < net->places().size(); p += 1 + net->places().size() / 8) {
      const std::string name = "\"" + net->places()[p].name + "\"";
      const std::string bound = std::to_string(space.place_bound[p]);
      const Formula at = parsed(*net, name + " >= " + bound);
      check("EF " + name + " >= " + bound, Verdict::True, &at);
      check("EF " + name + " > " + bound, Verdict::False, nullptr);
      check("AG " + name + " <= " + bound, Verdict::True, nullptr);
      // below the bound somewhere, unless the place never changes
      const bool constant = std::find(space.constant_places.begin(), space.constant_places.end(), p) !=
                            space.constant_places.end();
      const Formula below = parsed(*net, name + " < " + bound);
      check("AG " + name + " >= " + bound, constant ? Verdict::True : Verdict::False, &below);
    }
    // each transition that can fire: a marking enabling it, and one firing more reaches it
    for (std::size_t t = 0; t < net->transitions().size(); t += 1 + net->transitions().size() / 8) {
      const std::string text = "fireable(\"" + net->transitions()[t].name + "\")";
      const Formula on = parsed(*net, text);
      check("EF " + text, space.fired[t] ? Verdict::True : Verdict::False, &on);
      check("not EF " + text, space.fired[t] ? Verdict::False : Verdict::True, &on);
    }
  }
}

TEST(QueryAnswers, LimitsAndUnansweredKindsAreSaidNeverGuessed) {
  const auto net = conformanceNet("Dekker-PT-010");
  ASSERT_TRUE(net);
  ExploreOptions small;
  small.max_states = 10;
  // no marking of Dekker-PT-010 is dead: only the whole space could say so
  QueryAnswer a = answerQuery(*net, parsed(*net, "EF deadlock"), small);
  EXPECT_EQ(a.verdict, Verdict::Unknown);
  EXPECT_EQ(a.stop, ExploreStop::MaxStates);
  EXPECT_FALSE(a.has_marking);
  a = answerQuery(*net, parsed(*net, "A (G F deadlock)"));
  EXPECT_EQ(a.verdict, Verdict::Unknown);
  EXPECT_NE(a.unsupported.find("only reachability"), std::string::npos);
  // a state formula is answered at the initial marking
  a = answerQuery(*net, parsed(*net, "not deadlock"));
  EXPECT_EQ(a.verdict, Verdict::True);
  EXPECT_EQ(a.states, 1u);
}

TEST(QueryAnswers, AnUnboundedPlaceIsSearchedByItsCounts) {
  // a producer that never stops: p grows without bound; EF p >= 5 is found five firings on
  NetBuilder b;
  const auto p = b.addPlace("p");
  const auto t = b.addTransition("produce");
  b.addOutput(t, p);
  const auto net = b.freeze();
  const QueryAnswer a = answerQuery(*net, parsed(*net, "EF p >= 5"));
  EXPECT_EQ(a.verdict, Verdict::True);
  EXPECT_EQ(a.path.size(), 5u);
  ExploreOptions small;
  small.max_states = 100;
  EXPECT_EQ(answerQuery(*net, parsed(*net, "AG p < 1000"), small).verdict, Verdict::Unknown);
}

}  // namespace
}  // namespace gdpn::net
