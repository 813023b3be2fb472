// Value tokens in the kernel (semantics.md, Value tokens): which bindings are enabled, which
// one occurs, what an occurrence takes and puts, what the trace says; and the compiler's
// located mistakes. Nets are written as specs here; the model file's keys are tested in
// tests/model.

#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "gdpn/net/compile.h"
#include "gdpn/net/kernel.h"
#include "gdpn/net/trace.h"
#include "support/coloured_spec.h"

namespace gdpn::net {
namespace {

using testing::Coloured;
using testing::cyclic;
using testing::range;
using testing::at;

/// The values on place `name` (slot a0), as the language writes them.
std::string values(const Kernel& k, const std::string& name) {
  const Net& net = k.net();
  const auto p = net.findPlace("main/" + name);
  if (!p) return "no place " + name;
  const auto ps = net.findPlaceSlot(*p, kDefaultSlot);
  if (!ps) return "no slot";
  const auto* c = net.colouring();
  return c->colours.text(static_cast<ColourId>(c->slot_set[*ps]), k.values(*ps));
}

std::int64_t count(const Kernel& k, const std::string& name) {
  const auto p = k.net().findPlace("main/" + name);
  return p ? k.placeTokens(*p) : -1;
}

/// Dining philosophers: each takes the fork on its left and on its right (`succ p`); any
/// number may take or release at once.
Coloured philosophers() {
  Coloured n;
  n.set(cyclic("Phil", {"p1", "p2", "p3", "p4", "p5"})).variable("p", "Phil");
  n.place("think", "Phil", "all").place("fork", "Phil", "all").place("eat", "Phil");
  n.transition("take", {}, 1.0, 5).transition("release", {}, 1.0, 5);
  n.arc("think", "take", "p").arc("fork", "take", "p ++ succ(p)").arc("take", "eat", "p");
  n.arc("eat", "release", "p").arc("release", "think", "p").arc("release", "fork", "p ++ succ(p)");
  return n;
}

TEST(ValueTokens, PhilosophersInDeclarationOrderEatAsTheFirstBindingsAllow) {
  auto n = philosophers();
  Kernel k(n.compiled(), {1.0, 1});
  EXPECT_EQ(values(k, "think"), "1'p1 ++ 1'p2 ++ 1'p3 ++ 1'p4 ++ 1'p5");
  k.start();
  // p1 takes forks p1 and p2; p2 then lacks p2; p3 takes p3 and p4; p4 and p5 lack theirs
  const auto take = *k.net().findTransition("main/take");
  EXPECT_EQ(k.occurrences(take), 2u);
  EXPECT_EQ(values(k, "fork"), "1'p5");
  EXPECT_EQ(values(k, "think"), "1'p2 ++ 1'p4 ++ 1'p5");
  // the binding of the oldest running occurrence: p1, the enumeration's first constant
  ASSERT_NE(k.binding(take), nullptr);
  EXPECT_EQ(k.binding(take)->binding, (Binding{Value::integer(0)}));
  k.beginStep();
  k.completeOccurrences();  // and before the firing phase starts release
  EXPECT_EQ(values(k, "eat"), "1'p1 ++ 1'p3");
}

TEST(ValueTokens, PhilosophersKeepTheirInvariantsOverAThousandSteps) {
  auto n = philosophers();
  KernelSettings settings{1.0, 7};
  settings.random_ties = true;
  Kernel k(n.compiled(), settings);
  k.start();
  const auto take = *k.net().findTransition("main/take"), release = *k.net().findTransition("main/release");
  std::set<std::string> seen;
  for (int s = 0; s < 1000; ++s) {
    k.step();
    // every philosopher thinks, eats, or is taking or releasing its forks; every fork is free,
    // or with one of the philosophers beside it who takes, eats or releases
    seen.insert(values(k, "think"));
    const auto busy = static_cast<std::int64_t>(k.occurrences(take) + k.occurrences(release));
    EXPECT_EQ(count(k, "think") + count(k, "eat") + busy, 5);
    EXPECT_EQ(count(k, "fork") + 2 * (count(k, "eat") + busy), 5);
  }
  // drawn bindings: who thinks changes; in declaration order p1 and p3 would always eat
  // together and p2, p4, p5 think
  EXPECT_GT(seen.size(), 3u);
}

TEST(ValueTokens, AMultiplicityNeedsThatManyEqualValues) {
  Coloured n;
  n.set(range("N", 1, 3)).variable("x", "N");
  n.place("P", "N", "2'1 ++ 1'2").place("Q", "N");
  n.transition("T").arc("P", "T", "2'x").arc("T", "Q", "x");
  Kernel k(n.compiled(), {1.0, 1});
  const auto t = *k.net().findTransition("main/T");
  ASSERT_EQ(k.bindings(t).size(), 1u);
  EXPECT_EQ(k.bindings(t)[0].binding, (Binding{Value::integer(1)}));
  k.start();
  k.step();
  EXPECT_EQ(values(k, "P"), "1'2");
  EXPECT_EQ(values(k, "Q"), "1'1");
  EXPECT_EQ(k.readiness(t), Readiness::Tokens);  // one token left of the two it needs
}

TEST(ValueTokens, AConditionChoosesAmongBindingsAndTheFirstInCanonicalOrderOccurs) {
  Coloured n;
  n.set(range("N", 1, 5)).variable("x", "N");
  n.place("P", "N", "1'1 ++ 1'2 ++ 1'3").place("Q", "N");
  n.transition("T", "x > 1", 1.0, 3).arc("P", "T", "x").arc("T", "Q", "x + 10 - 10");
  Kernel k(n.compiled(), {1.0, 1});
  const auto t = *k.net().findTransition("main/T");
  const auto found = k.bindings(t);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].binding[0].i, 2);
  EXPECT_EQ(found[1].binding[0].i, 3);
  k.start();
  EXPECT_EQ(k.occurrences(t), 2u);  // servers 3: x = 2 and x = 3, and no binding is left
  EXPECT_EQ(values(k, "P"), "1'1");
  EXPECT_EQ(k.readiness(t), Readiness::NoBinding);
  k.step();
  EXPECT_EQ(values(k, "Q"), "1'2 ++ 1'3");
}

TEST(ValueTokens, TheUserFiresTheBindingChosenAndABindingNotEnabledIsRefusedWithItsValues) {
  Coloured n;
  n.set(range("N", 1, 5)).variable("x", "N");
  n.place("P", "N", "1'1 ++ 1'2 ++ 1'3").place("Q", "N");
  n.transition("T", "x > 1", 1.0, 3).arc("P", "T", "x").arc("T", "Q", "x");
  n.control("go", 1).transition("U").arc("go", "U", "");
  Kernel k(n.compiled(), {1.0, 1});
  const auto t = *k.net().findTransition("main/T");
  // x = 1 fails the condition, x = 4 is on no token, a binding of two values has one too many
  EXPECT_EQ(k.fire(t, Binding{Value::integer(1)}), "binding (x = 1) of 'main/T' is not enabled (2 enabled now)");
  EXPECT_EQ(k.fire(t, Binding{Value::integer(4)}), "binding (x = 4) of 'main/T' is not enabled (2 enabled now)");
  EXPECT_EQ(k.fire(t, Binding{Value::integer(2), Value::integer(3)}), "a binding of 'main/T' gives 1 values, got 2");
  EXPECT_EQ(k.fire(*k.net().findTransition("main/U"), Binding{}), "'main/U' has no variables to bind");
  EXPECT_EQ(values(k, "P"), "1'1 ++ 1'2 ++ 1'3");  // nothing refused took anything
  // the second in canonical order, x = 3, where fire(t) would take x = 2
  EXPECT_EQ(k.fire(t, Binding{Value::integer(3)}), "");
  EXPECT_EQ(values(k, "P"), "1'1 ++ 1'2");
  ASSERT_NE(k.binding(t), nullptr);
  EXPECT_EQ(k.binding(t)->binding, (Binding{Value::integer(3)}));
  // x = 3 is gone now: its binding is no longer enabled, and none is after x = 2
  EXPECT_EQ(k.fire(t, Binding{Value::integer(3)}), "binding (x = 3) of 'main/T' is not enabled (1 enabled now)");
  EXPECT_EQ(k.fire(t, Binding{Value::integer(2)}), "");
  EXPECT_EQ(k.fire(t, Binding{Value::integer(2)}), "binding (x = 2) of 'main/T' is not enabled (none is now)");
  k.beginStep();
  k.completeOccurrences();
  EXPECT_EQ(values(k, "Q"), "1'2 ++ 1'3");
}

TEST(ValueTokens, AVariableNoArcBindsIsEnumeratedOverItsFiniteSet) {
  Coloured n;
  ColourSetSpec flag;
  flag.name = "Flag";
  flag.kind = ColourKind::Bool;
  n.set(flag).variable("b", "Flag");
  n.control("go", 2).place("Q", "Flag");
  n.transition("T", {}, 1.0).arc("T", "Q", "b");
  ArcSpec in;
  in.from = "go";
  in.to = "T";
  in.loc = at(99);
  n.page().arcs.push_back(in);
  Kernel k(n.compiled(), {1.0, 1});
  const auto t = *k.net().findTransition("main/T");
  ASSERT_EQ(k.bindings(t).size(), 2u);  // false, true
  k.start();
  k.step();
  EXPECT_EQ(values(k, "Q"), "1'false");
  k.step();
  EXPECT_EQ(values(k, "Q"), "2'false");  // declaration order: always the first
}

TEST(ValueTokens, ATestArcBindsWithoutTakingAndAnInhibitorArcRefusesWhatItsPlaceHolds) {
  Coloured n;
  n.set(range("N", 1, 3)).variable("x", "N");
  n.place("A", "N", "1'1 ++ 1'2 ++ 1'3").place("Seen", "N", "1'2").place("Done", "N", "1'1").place("Q", "N");
  n.transition("T", {}, 1.0, 5);
  n.arc("A", "T", "x").arc("Seen", "T", "x", ArcKind::Test).arc("T", "Q", "x");
  n.transition("U", {}, 1.0, 5);
  n.arc("Q", "U", "x").arc("Done", "U", "x", ArcKind::Inhibitor).arc("U", "Done", "x");
  Kernel k(n.compiled(), {1.0, 1});
  k.start();
  EXPECT_EQ(values(k, "A"), "1'1 ++ 1'3");  // only x = 2 is seen
  EXPECT_EQ(values(k, "Seen"), "1'2");       // and a test arc takes nothing
  k.step();
  EXPECT_EQ(values(k, "Q"), "empty");  // U: x = 2 is not done yet
  k.step();
  EXPECT_EQ(values(k, "Done"), "1'1 ++ 1'2");
  const auto u = *k.net().findTransition("main/U");
  // a second 2 in Q would now be inhibited by the 2 in Done
  EXPECT_TRUE(k.bindings(u).empty());
}

TEST(ValueTokens, ABindingWhoseOutputLeavesItsRangeIsNotEnabled) {
  Coloured n;
  n.set(range("N", 1, 3)).variable("x", "N");
  n.place("P", "N", "1'1");
  n.transition("inc").arc("P", "inc", "x").arc("inc", "P", "x + 1");
  Kernel k(n.compiled(), {1.0, 1});
  k.start();
  for (int s = 0; s < 5; ++s) k.step();
  EXPECT_EQ(values(k, "P"), "1'3");
  EXPECT_EQ(k.readiness(*k.net().findTransition("main/inc")), Readiness::NoBinding);
}

TEST(ValueTokens, CapacityCountsEveryValueAndTheBindingsCountsDecideRoom) {
  Coloured n;
  n.set(range("N", 1, 3)).variable("x", "N");
  n.place("P", "N", "1'1 ++ 1'2").place("Q", "N", "1'3", 2);
  n.transition("T", {}, 1.0, 5).arc("P", "T", "x").arc("T", "Q", "x");
  Kernel k(n.compiled(), {1.0, 1});
  k.start();
  const auto t = *k.net().findTransition("main/T");
  EXPECT_EQ(k.occurrences(t), 1u);  // Q (capacity 2) holds one: room for one more
  k.step();
  EXPECT_EQ(values(k, "Q"), "1'1 ++ 1'3");
  EXPECT_EQ(k.readiness(t), Readiness::Room);
}

std::string trace(std::uint64_t seed, bool random) {
  auto n = philosophers();
  KernelSettings settings{0.5, seed};
  settings.random_ties = random;
  Kernel k(n.compiled(), settings);
  std::ostringstream out;
  TraceWriter w(out, k.net(), 0.5, [](NodeRef r) { return std::to_string(r); });
  k.addObserver(&w);
  k.start();
  for (int s = 0; s < 200; ++s) k.step();
  return out.str();
}

TEST(ValueTokens, TheTraceWritesBindingsAndValuesAndTheSameSeedGivesTheSameBytes) {
  const auto first = trace(3, true);
  EXPECT_EQ(first, trace(3, true));
  EXPECT_NE(first, trace(4, true));
  const auto ordered = trace(3, false);
  EXPECT_NE(ordered.find(R"({"step":0,"t":0,"ev":"start","transition":"main/take","binding":{"p":"p1"}})"),
            std::string::npos)
      << ordered.substr(0, 400);
  EXPECT_NE(ordered.find(R"("ev":"remove","place":"main/fork","slot":"a0","count":2,"values":"1'p1 ++ 1'p2"})"),
            std::string::npos)
      << ordered.substr(0, 600);
}

TEST(ValueTokens, MistakesAreLocatedInTheirInscription) {
  {
    auto n = philosophers();
    n.page().arcs[1].inscriptions[0].text = "p ++ succ(p";
    EXPECT_NE(n.refusal().find("value.gdpn.yaml:"), std::string::npos);
  }
  {
    auto n = philosophers();
    n.page().arcs[2].inscriptions[0].text = "3";  // an int into a place of Phil
    const auto why = n.refusal();
    EXPECT_NE(why.find("value.gdpn.yaml:" + std::to_string(n.page().arcs[2].loc.line) + ":40:"), std::string::npos) << why;
    EXPECT_NE(why.find("Phil"), std::string::npos) << why;
  }
  {
    auto n = philosophers();
    n.page().arcs[1].inscriptions.clear();  // fork holds values: the arc must say which
    EXPECT_NE(n.refusal().find("needs an 'inscription'"), std::string::npos);
  }
  {
    Coloured n;
    ColourSetSpec text;
    text.name = "Text";
    text.kind = ColourKind::String;
    n.set(text).variable("s", "Text");
    n.control("go", 1).place("Q", "Text");
    n.transition("T").arc("T", "Q", "s");
    ArcSpec in;
    in.from = "go";
    in.to = "T";
    in.loc = at(99);
    n.page().arcs.push_back(in);
    const auto why = n.refusal();
    EXPECT_NE(why.find("'s'"), std::string::npos) << why;  // a string no input arc binds
  }
  {
    auto n = philosophers();
    n.page().places[0].colours[0].text = "Philosopher";
    EXPECT_NE(n.refusal().find("colour set 'Philosopher' is not declared"), std::string::npos);
  }
}

}  // namespace
}  // namespace gdpn::net
