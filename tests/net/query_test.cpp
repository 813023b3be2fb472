// Queries: the text form (read back from its own printing, mistakes located by column), and
// reachability answers checked against the whole state space of the conformance nets, each
// witness replayed from the initial marking.

#include "gdpn/net/query.h"
#include "gdpn/net/state_equation.h"

#include <gtest/gtest.h>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/builder.h"
#include "support/conformance.h"
#include "support/firing.h"

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

/// Fires `path` from the initial marking, checking each transition enabled on the way; the
/// marking reached, or nullopt.
std::optional<std::vector<std::int64_t>> replay(const Net& net, const std::vector<TransitionId>& path) {
  auto m = testing::initialMarking(net);
  for (TransitionId t : path) {
    if (!testing::fire(net, t, m)) return std::nullopt;
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
      {"Think_1 = 1152921504606846977", 11, "too large (the most is 2^60)"},
      // found by the fuzzer: each below 2^63, their sum beyond it
      {"8006600002080066040 + 8000000002080066040 = Think_1", 1, "too large"},
      {"1152921504606846976 + 1 = Think_1", 23, "add up to more than 2^60"},
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

TEST(QueryText, ContestPropertyFilesAreReadAndTheirMistakesLocated) {
  const auto net = conformanceNet("Eratosthenes-PT-010");
  ASSERT_TRUE(net);
  // PNML ids as the contest writes them ("t8.2"), though gdpn names the transition net/t8_2
  const std::string good = R"(<?xml version="1.0"?>
<property-set xmlns="http://mcc.lip6.fr/">
  <property><id>p-00</id><description>x</description>
    <formula><exists-path><finally><conjunction>
      <is-fireable><transition>t8.2</transition></is-fireable>
      <integer-le><integer-constant>1</integer-constant><tokens-count><place>p2</place><place>p3</place></tokens-count></integer-le>
    </conjunction></finally></exists-path></formula></property>
  <property><id>p-01</id><description>x</description>
    <formula><place-bound><place>p2</place></place-bound></formula></property>
  <property><id>p-02</id><description>x</description>
    <formula><all-paths><until><before><true/></before><reach><deadlock/></reach></until></all-paths></formula></property>
</property-set>
)";
  core::Diagnostics diags;
  const auto properties = readMccProperties(*net, good, "good.xml", diags);
  ASSERT_TRUE(properties) << diags.str();
  ASSERT_EQ(properties->size(), 3u);
  EXPECT_EQ((*properties)[0].id, "p-00");
  EXPECT_EQ(formulaText(*net, (*properties)[0].formula), "EF (fireable(net/t8_2) and 1 <= net/p2 + net/p3)");
  EXPECT_EQ(formulaText(*net, (*properties)[1].formula), "bound(net/p2)");
  EXPECT_EQ(formulaText(*net, (*properties)[2].formula), "A [true U deadlock]");
  const std::string bad = R"(<property-set>
  <property><id>a</id><formula><exists-path><finally><is-fireable><transition>t99</transition></is-fireable></finally></exists-path></formula></property>
  <property><id>b</id><formula><exists-path><somewhere/></exists-path></formula></property>
  <property><id>c</id><formula><negation><place-bound><place>p2</place></place-bound></negation></formula></property>
  <property><id>d</id><formula><integer-le><integer-constant>x1</integer-constant><integer-constant>2</integer-constant></integer-le></formula></property>
  <property><id>e</id><formula><integer-le><integer-constant>-1152921504606846977</integer-constant><integer-constant>2</integer-constant></integer-le></formula></property>
</property-set>
)";
  core::Diagnostics errors;
  EXPECT_FALSE(readMccProperties(*net, bad, "bad.xml", errors));
  const std::string text = errors.str();
  EXPECT_NE(text.find("bad.xml:2:67: error: no transition is called 't99'"), std::string::npos) << text;
  EXPECT_NE(text.find("bad.xml:3:45: error: <somewhere> is not part of the contest's property language"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("bad.xml:4:42: error: <place-bound> is a number"), std::string::npos) << text;
  EXPECT_NE(text.find("bad.xml:5:44: error: 'x1' is not a whole number"), std::string::npos) << text;
  EXPECT_NE(text.find("bad.xml:6:44: error: '-1152921504606846977' is not a whole number of at most 2^60"),
            std::string::npos)
      << text;
  EXPECT_FALSE(readMccProperties(*net, "<property-set><property>", "cut.xml", errors));
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
    ExploreOptions unreduced;  // every enabled transition fired, every marking searched
    unreduced.reduction = false;
    unreduced.state_equation = false;
    const QueryAnswer full = answerQuery(*net, parsed(*net, "EF deadlock"), unreduced);
    EXPECT_EQ(full.verdict, d.verdict);
    if (space.deadlock) {
      // breadth first over every transition: as short as the analysis's shortest path
      EXPECT_EQ(full.path.size(), space.deadlock_path.size());
    } else {
      EXPECT_EQ(full.states, space.states);  // every marking looked at
      EXPECT_LE(d.states, full.states);      // the stubborn sets' markings are some of them
    }
    check("AG not deadlock", space.deadlock ? Verdict::False : Verdict::True, &dead);
    // each place's bound: reached, never passed
    for (PlaceId p{0}; p < net->places().size(); p = PlaceId{p + 1 + net->places().size() / 8}) {
      const std::string name = "\"" + net->placeName(p) + "\"";
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
    for (TransitionId t{0}; t < net->transitions().size(); t = TransitionId{t + 1 + net->transitions().size() / 8}) {
      const std::string text = "fireable(\"" + net->transitionName(t) + "\")";
      const Formula on = parsed(*net, text);
      check("EF " + text, space.fired[t] ? Verdict::True : Verdict::False, &on);
      check("not EF " + text, space.fired[t] ? Verdict::False : Verdict::True, &on);
    }
  }
}

TEST(QueryAnswers, CtlAgreesWithLivenessAndReversibilityOfTheWholeStateSpace) {
  // live: AG EF fireable(t) for every t; reversible: AG EF (the initial marking)
  for (const char* model : kNets) {
    SCOPED_TRACE(model);
    const auto net = conformanceNet(model);
    ASSERT_TRUE(net);
    const StateSpace space = explore(*net);
    ASSERT_TRUE(space.complete && space.decided);
    std::string live = "true", initial = "true";
    for (TransitionId t{0}; t < net->transitions().size(); ++t) live += " and AG EF fireable(\"" + net->transitionName(t) + "\")";
    for (PlaceId pid{0}; pid < net->places().size(); ++pid) {
      const Place& p = net->places()[pid];
      std::int64_t tokens = 0;
      for (auto k = p.slots_begin; k < p.slots_end; ++k) tokens += net->placeSlots()[k].initial;
      initial += " and \"" + net->placeName(pid) + "\" = " + std::to_string(tokens);
    }
    auto answer = [&](const std::string& text) { return answerQuery(*net, parsed(*net, text)); };
    const QueryAnswer l = answer(live);
    EXPECT_EQ(l.verdict, space.live ? Verdict::True : Verdict::False);
    // true, every marking was seen; false, the search may have stopped at the first that shows it
    if (space.live) {
      EXPECT_EQ(l.states, space.states);
    }
    EXPECT_LE(l.states, space.states);
    EXPECT_EQ(answer("AG EF (" + initial + ")").verdict, space.reversible ? Verdict::True : Verdict::False);
    // the fixed points against the breadth-first search: E[true U p] is EF p, A[true U p] is AF p
    const Verdict dead = space.deadlock ? Verdict::True : Verdict::False;
    EXPECT_EQ(answer("E [true U deadlock]").verdict, dead);
    EXPECT_EQ(answer("not EG not deadlock").verdict, answer("A [true U deadlock]").verdict);
    // a dead marking ends its paths: one is reachable exactly when EX true fails somewhere
    EXPECT_EQ(answer("EF not EX true").verdict, dead);
    EXPECT_EQ(answer("AG AX true").verdict, Verdict::True);
  }
}

TEST(QueryAnswers, CtlOnSmallNetsWithKnownAnswers) {
  // a chain into a dead end: a -> b -> c
  NetBuilder chain;
  const auto a = chain.addPlace("a"), b = chain.addPlace("b"), c = chain.addPlace("c");
  chain.setSlot(a, kDefaultSlot, SlotKind::Control, kUnbounded, 1);
  const auto ab = chain.addTransition("ab"), bc = chain.addTransition("bc");
  chain.addInput(a, ab);
  chain.addOutput(ab, b);
  chain.addInput(b, bc);
  chain.addOutput(bc, c);
  const auto line = chain.freeze();
  // a choice: from p, `stop` ends in a dead end, `go` and `back` cycle through q
  NetBuilder choice;
  const auto p = choice.addPlace("p"), q = choice.addPlace("q"), end = choice.addPlace("end");
  choice.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, 1);
  const auto stop = choice.addTransition("stop"), go = choice.addTransition("go"), back = choice.addTransition("back");
  choice.addInput(p, stop);
  choice.addOutput(stop, end);
  choice.addInput(p, go);
  choice.addOutput(go, q);
  choice.addInput(q, back);
  choice.addOutput(back, p);
  const auto loop = choice.freeze();
  const struct {
    const Net& net;
    const char* text;
    Verdict want;
  } cases[] = {
      {*line, "EG a + b + c = 1", Verdict::True},  // the one maximal path, ending dead at c
      {*line, "AF c = 1", Verdict::True},
      {*line, "AX b = 1", Verdict::True},
      {*line, "EX EX EX true", Verdict::False},  // two firings, then nothing
      {*line, "AG (c = 0 or not EX true)", Verdict::True},
      {*line, "A [a + b = 1 U c = 1]", Verdict::True},
      {*line, "A [a = 1 U c = 1]", Verdict::False},  // at b neither holds
      {*line, "E [a = 1 U b = 1]", Verdict::True},
      {*loop, "AF end = 1", Verdict::False},  // go, back, go, ... never ends
      {*loop, "EF end = 1", Verdict::True},
      {*loop, "EG end = 0", Verdict::True},
      {*loop, "AG EF end = 1", Verdict::True},  // the dead end holds it itself
      {*loop, "AG EF p = 1", Verdict::False},   // but cannot leave
      {*loop, "E [p + q = 1 U end = 1]", Verdict::True},
      {*loop, "A [p + q = 1 U end = 1]", Verdict::False},
  };
  for (const auto& x : cases) {
    SCOPED_TRACE(x.text);
    EXPECT_EQ(answerQuery(x.net, parsed(x.net, x.text)).verdict, x.want);
  }
  // LTL: a dead marking's path stutters there forever
  const struct {
    const Net& net;
    const char* text;
    Verdict want;
  } ltl[] = {
      {*line, "A (F G c = 1)", Verdict::True},
      {*line, "A (G F a = 1)", Verdict::False},
      {*line, "A (X X X c = 1)", Verdict::True},  // two firings, then c for ever
      {*line, "A (a = 1 U b = 1)", Verdict::True},
      {*line, "E (X a = 1)", Verdict::False},
      {*loop, "A (G F p = 1)", Verdict::False},  // stop, and p never again
      {*loop, "E (G F p = 1)", Verdict::True},   // go, back, go, ...
      {*loop, "A (F end = 1)", Verdict::False},
      {*loop, "A ((G F p = 1) or (F G end = 1))", Verdict::True},
      {*loop, "A (G (not p = 1 or X (q = 1 or end = 1)))", Verdict::True},
      {*loop, "A (G (not q = 1 or X p = 1))", Verdict::True},
      {*loop, "E (p = 1 U G end = 1)", Verdict::True},
  };
  for (const auto& x : ltl) {
    SCOPED_TRACE(x.text);
    const QueryAnswer answer = answerQuery(x.net, parsed(x.net, x.text));
    EXPECT_EQ(answer.verdict, x.want);
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
  // LTL (the graph, then its product) is bounded by the same limit: all of it is needed to
  // say that no dead marking is ever reached on any path, and 1,000 states are not enough
  ExploreOptions product;
  product.max_states = 1'000;
  a = answerQuery(*net, parsed(*net, "A (G F not deadlock)"), product);
  EXPECT_EQ(a.verdict, Verdict::Unknown);
  EXPECT_EQ(a.stop, ExploreStop::MaxStates);
  a = answerQuery(*net, parsed(*net, "A (G F not deadlock)"));
  EXPECT_EQ(a.verdict, Verdict::True);
  EXPECT_EQ(a.technique, "EXPLICIT LTL_TABLEAU ON_THE_FLY STUBBORN_SETS");  // no X: ample sets serve
  // CTL needs the whole graph: the limit stops it too
  a = answerQuery(*net, parsed(*net, "AG EF deadlock"), small);
  EXPECT_EQ(a.verdict, Verdict::Unknown);
  EXPECT_EQ(a.stop, ExploreStop::MaxStates);
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

TEST(QueryAnswers, ACountBeyondItsFieldStopsTheSearchRatherThanSpillingIntoTheNext) {
  // p and q have no bound: 32 bits each, side by side in one 64-bit word. A billion tokens a
  // firing overflow p's field at the fifth: the search stops there, rather than going on
  // with the carry in q's field and p's count wrapped around
  NetBuilder b;
  const auto p = b.addPlace("p");
  b.addPlace("q");
  const auto t = b.addTransition("produce");
  b.addOutput(t, p, kDefaultSlot, 1'000'000'000);
  const auto net = b.freeze();
  ExploreOptions limits;
  limits.max_states = 1000;
  const QueryAnswer a = answerQuery(*net, parsed(*net, "EF p >= 5000000000"), limits);
  EXPECT_EQ(a.verdict, Verdict::Unknown);
  EXPECT_EQ(a.stop, ExploreStop::Overflow);
  EXPECT_EQ(a.states, 5u);
  EXPECT_EQ(answerQuery(*net, parsed(*net, "EF p >= 4000000000"), limits).verdict, Verdict::True);
}

}  // namespace
}  // namespace gdpn::net

namespace gdpn::net {
namespace {

/// `rings` independent rings of `length` places, one token each at its place 0: length^rings
/// reachable markings, every transition independent of the other rings'.
std::shared_ptr<const Net> rings(int count, int length) {
  NetBuilder b;
  for (int r = 0; r < count; ++r) {
    std::vector<PlaceId> ps;
    for (int i = 0; i < length; ++i) ps.push_back(b.addPlace("r" + std::to_string(r) + "/p" + std::to_string(i)));
    b.setSlot(ps[0], kDefaultSlot, SlotKind::Control, kUnbounded, 1);
    for (int i = 0; i < length; ++i) {
      const auto t = b.addTransition("r" + std::to_string(r) + "/t" + std::to_string(i));
      b.addInput(ps[static_cast<std::size_t>(i)], t);
      b.addOutput(t, ps[static_cast<std::size_t>((i + 1) % length)]);
    }
  }
  return b.freeze();
}

TEST(QueryAnswers, StubbornSetsFindAWitnessNineStepsDeepAmongTenMillionMarkingsFromAFewStates) {
  const auto net = rings(7, 10);  // 10^7 markings
  ExploreOptions searched;  // the searches themselves, not the state equation's refutations
  searched.state_equation = false;
  // the token of ring 0 at its last place: nine firings of ring 0, the other rings left alone
  QueryAnswer a = answerQuery(*net, parsed(*net, "EF r0/p9 = 1"), searched);
  EXPECT_EQ(a.verdict, Verdict::True);
  EXPECT_EQ(a.path.size(), 9u);
  EXPECT_LE(a.states, 10u);
  EXPECT_NE(a.technique.find("STUBBORN_SETS"), std::string::npos);
  const auto reached = replay(*net, a.path);
  ASSERT_TRUE(reached);
  EXPECT_EQ((*reached)[9], 1);
  // never two tokens in one ring: refuted after ring 0's ten markings, not 10^7
  a = answerQuery(*net, parsed(*net, "EF (r0/p0 = 1 and r0/p5 = 1)"), searched);
  EXPECT_EQ(a.verdict, Verdict::False);
  EXPECT_LE(a.states, 10u);
  a = answerQuery(*net, parsed(*net, "AG r3/p0 + r3/p1 + r3/p2 + r3/p3 + r3/p4 + r3/p5 + r3/p6 + r3/p7 + r3/p8 + r3/p9 = 1"),
                  searched);
  EXPECT_EQ(a.verdict, Verdict::True);
  EXPECT_LE(a.states, 10u);
  // a deadlock: none, and said after few markings (each ring cycles by itself)
  a = answerQuery(*net, parsed(*net, "EF deadlock"), searched);
  EXPECT_EQ(a.verdict, Verdict::False);
  EXPECT_LE(a.states, 10u);
  // without the reduction, the same answers from many more markings (a smaller net: 10^4)
  const auto small = rings(4, 10);
  ExploreOptions full = searched;
  full.reduction = false;
  for (const char* text : {"EF (r0/p0 = 1 and r0/p5 = 1)", "EF deadlock", "EF (r0/p9 = 1 and r3/p9 = 1)"}) {
    SCOPED_TRACE(text);
    const QueryAnswer reduced = answerQuery(*small, parsed(*small, text), searched);
    const QueryAnswer all = answerQuery(*small, parsed(*small, text), full);
    EXPECT_EQ(reduced.verdict, all.verdict);
    EXPECT_LT(reduced.states * 10, all.states) << reduced.states << " against " << all.states;
  }
}

TEST(QueryAnswers, BeyondTheStateSpaceEachKindIsAnsweredFromAFewMarkings) {
  // 10^7 markings and a limit of 10^5: no answer may rest on the whole graph
  const auto net = rings(7, 10);
  ExploreOptions limits;
  limits.max_states = 100'000;
  auto answer = [&](const std::string& text, const ExploreOptions& l) { return answerQuery(*net, parsed(*net, text), l); };
  // a bound: the state equation's (one token a ring), held by the initial marking, or reached
  // by a search guided towards it (5 + 7 firings)
  QueryAnswer a = answer("bound(r0/p0 + r1/p0)", limits);
  EXPECT_EQ(a.verdict, Verdict::Value);
  EXPECT_EQ(a.value, 2);
  EXPECT_EQ(a.technique, "STATE_EQUATION INITIAL_STATE");
  a = answer("bound(r0/p5 + r1/p7)", limits);
  ASSERT_EQ(a.verdict, Verdict::Value);
  EXPECT_EQ(a.value, 2);
  EXPECT_EQ(a.technique, "STATE_EQUATION EXPLICIT BEST_FIRST_SEARCH");
  EXPECT_EQ(a.path.size(), 12u);
  const auto reached = replay(*net, a.path);
  ASSERT_TRUE(reached);
  EXPECT_EQ((*reached)[5] + (*reached)[17], 2);  // r0/p5, r1/p7
  // CTL by local searches that stop at what shows the answer
  a = answer("E [r1/p0 = 1 U r0/p9 = 1]", limits);
  EXPECT_EQ(a.verdict, Verdict::True);
  EXPECT_EQ(a.technique, "EXPLICIT CTL_LOCAL");
  EXPECT_LE(a.states, 1'000u);
  a = answer("A [r1/p0 = 1 U r0/p9 = 1]", limits);
  EXPECT_EQ(a.verdict, Verdict::False);
  EXPECT_LE(a.states, 1'000u);
  // simplified by the bounds: a ring never holds two tokens, so AG EF of that is true at once
  a = answer("AG EF r0/p0 + r0/p1 <= 1 and not EG r0/p0 + r1/p0 > 2", limits);
  EXPECT_EQ(a.verdict, Verdict::True);
  EXPECT_EQ(a.technique, "QUERY_SIMPLIFICATION STATE_EQUATION INITIAL_STATE");
  EXPECT_LE(a.states, 1u);
  // LTL: ring 0's token stays at p0 until it moves to p1 (or for ever). True on every path:
  // beside six lines of ten places (a token each, run down once: 10^6 markings of theirs)
  // the product without the reduction needs every marking; with ample sets (one line's move
  // at a time, ring 0's moves being visible), a few
  {
    NetBuilder b;
    for (int r = 0; r < 7; ++r) {
      const std::string name = r == 0 ? "r0" : "l" + std::to_string(r);
      std::vector<PlaceId> ps;
      for (int i = 0; i < 10; ++i) ps.push_back(b.addPlace(name + "/p" + std::to_string(i)));
      b.setSlot(ps[0], kDefaultSlot, SlotKind::Control, kUnbounded, 1);
      for (int i = 0; i < (r == 0 ? 10 : 9); ++i) {
        const auto t = b.addTransition(name + "/t" + std::to_string(i));
        b.addInput(ps[static_cast<std::size_t>(i)], t);
        b.addOutput(t, ps[static_cast<std::size_t>((i + 1) % 10)]);
      }
    }
    const auto lines = b.freeze();
    const std::string weak = "A ((r0/p0 = 1 U r0/p1 = 1) or G r0/p0 = 1)";
    a = answerQuery(*lines, parsed(*lines, weak), limits);
    EXPECT_EQ(a.verdict, Verdict::True);
    EXPECT_EQ(a.technique, "EXPLICIT LTL_TABLEAU ON_THE_FLY STUBBORN_SETS");
    EXPECT_LE(a.states, 1'000u);
    ExploreOptions plain = limits;
    plain.reduction = false;
    a = answerQuery(*lines, parsed(*lines, weak), plain);
    EXPECT_EQ(a.verdict, Verdict::Unknown);
    EXPECT_EQ(a.stop, ExploreStop::MaxStates);
  }
  // a counterexample with the reduction: ring 0 moves on, then stops for ever at p1 while
  // the others go round; the lasso fires from the initial marking and comes back
  a = answer("A (G F r0/p0 = 1)", limits);
  EXPECT_EQ(a.verdict, Verdict::False);
  ASSERT_TRUE(a.lasso);
  const auto start = replay(*net, a.path);
  ASSERT_TRUE(start);
  EXPECT_EQ(*start, a.marking);
  std::vector<TransitionId> around = a.path;
  around.insert(around.end(), a.cycle.begin(), a.cycle.end());
  const auto again = replay(*net, around);
  ASSERT_TRUE(again);
  EXPECT_EQ(*again, a.marking);
  EXPECT_EQ(a.marking[0], 0);  // r0/p0: empty round the cycle
}

TEST(QueryAnswers, TheStateEquationRefutesWhatItsInvariantsForbidAndNothingReachable) {
  const auto net = rings(3, 4);
  ExploreOptions limits;
  // one token per ring for ever: two in a ring, or none anywhere, has no solution
  for (const char* text : {"EF r0/p0 + r0/p2 = 2", "EF deadlock", "AG r1/p0 + r1/p1 + r1/p2 + r1/p3 = 1",
                           "EF (fireable(r0/t0) and fireable(r0/t1))"}) {
    SCOPED_TRACE(text);
    const QueryAnswer a = answerQuery(*net, parsed(*net, text), limits);
    EXPECT_EQ(a.technique, "STATE_EQUATION");
    EXPECT_EQ(a.verdict, std::string(text).starts_with("AG") ? Verdict::True : Verdict::False);
    EXPECT_EQ(a.states, 0u);
  }
  // what is reachable is never refuted: searched, and found
  for (const char* text : {"EF (r0/p3 = 1 and r2/p2 = 1)", "EF fireable(r0/t3)", "AG r1/p0 = 1"}) {
    SCOPED_TRACE(text);
    const Formula f = parsed(*net, text);
    EXPECT_FALSE(stateEquationExcludes(*net, f.operands[0].operands[0]));
    const QueryAnswer a = answerQuery(*net, f, limits);
    EXPECT_NE(a.technique, "STATE_EQUATION");
    EXPECT_TRUE(a.has_marking);
  }
}

}  // namespace
}  // namespace gdpn::net
