// The untimed analysis against the Model Checking Contest's reference answers, and PNML
// reading mistakes with their locations.

#include "gdpn/net/analysis.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <random>
#include <set>
#include <fstream>
#include <sstream>

#include "gdpn/core/sanitizers.h"
#include "gdpn/net/builder.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/pnml.h"
#include "net/detail/marking_store.h"
#include "support/conformance.h"

namespace gdpn::net {
namespace {

namespace fs = std::filesystem;
using testing::conformanceNet;
using testing::conformanceSpec;
using testing::kConformanceDir;

/// The state space of `net` searched by `threads` threads (the other options as they come).
StateSpace exploreWith(const Net& net, unsigned threads) {
  ExploreOptions options;
  options.threads = threads;
  return explore(net, options);
}

struct Reference {
  std::string model;
  std::uint64_t states, edges;
  std::int64_t max_place, max_marking;
  bool rd, os, l, ql, sm;
};

std::vector<Reference> references() {
  std::vector<Reference> out;
  std::ifstream in(kConformanceDir / "reference.tsv");
  std::string line;
  std::getline(in, line);  // header
  auto flag = [](const std::string& s) { return s == "TRUE"; };
  while (std::getline(in, line)) {
    std::istringstream f(line);
    Reference r;
    std::string rd, os, l, ql, sm;
    f >> r.model >> r.states >> r.edges >> r.max_place >> r.max_marking >> rd >> os >> l >> ql >> sm;
    r.rd = flag(rd), r.os = flag(os), r.l = flag(l), r.ql = flag(ql), r.sm = flag(sm);
    // the two largest are for benchmarks
    if (r.model != "Kanban-PT-00005" && r.model != "SwimmingPool-PT-02") out.push_back(r);
  }
  return out;
}

/// True when `path` fires in order from the initial marking (each transition enabled by its
/// arcs, inhibitors and capacities) and ends in a marking where nothing is enabled.
bool endsDead(const Net& net, const std::vector<TransitionId>& path) {
  std::vector<std::int64_t> m;
  for (const auto& ps : net.placeSlots()) m.push_back(ps.initial);
  auto enabled = [&](TransitionId t) {
    for (const Term& term : net.termsOf(t)) {
      const std::int64_t v = m[term.place_slot];
      const std::int64_t cap = net.placeSlots()[term.place_slot].capacity;
      if ((term.kind == TermKind::Input || term.kind == TermKind::Test) && v < term.weight) return false;
      if (term.kind == TermKind::Inhibitor && v >= term.weight) return false;
      if (term.kind == TermKind::Output && cap != kUnbounded && v - term.take + term.weight > cap) return false;
    }
    return true;
  };
  for (TransitionId t : path) {
    if (!enabled(t)) return false;
    for (const Term& term : net.termsOf(t)) {
      if (term.kind == TermKind::Input) m[term.place_slot] -= term.weight;
      if (term.kind == TermKind::Output) m[term.place_slot] += term.weight;
    }
  }
  for (TransitionId t{0}; t < net.transitions().size(); ++t) {
    if (enabled(t)) return false;
  }
  return true;
}

class Conformance : public ::testing::TestWithParam<Reference> {};

TEST_P(Conformance, MatchesTheReferenceExactly) {
  const Reference& ref = GetParam();
  auto net = conformanceNet(ref.model);
  ASSERT_TRUE(net);
  const StateSpace s = explore(*net);
  ASSERT_TRUE(s.complete);
  EXPECT_EQ(s.states, ref.states);
  EXPECT_EQ(s.edges, ref.edges);
  EXPECT_EQ(s.max_place, ref.max_place);
  EXPECT_EQ(s.max_marking, ref.max_marking);
  EXPECT_EQ(s.deadlock, ref.rd);
  EXPECT_EQ(s.one_safe, ref.os);
  EXPECT_EQ(s.live, ref.l);
  EXPECT_EQ(s.quasi_live, ref.ql);
  EXPECT_EQ(!s.constant_places.empty(), ref.sm);
}

TEST_P(Conformance, ThreadsGiveTheSameAnswers) {
  const Reference& ref = GetParam();
  auto net = conformanceNet(ref.model);
  ASSERT_TRUE(net);
  const StateSpace one = explore(*net);
  for (unsigned threads : {2u, 3u}) {
    ExploreOptions o;
    o.threads = threads;
    const StateSpace s = explore(*net, o);
    ASSERT_TRUE(s.complete) << threads;
    EXPECT_EQ(s.states, ref.states) << threads;
    EXPECT_EQ(s.edges, ref.edges) << threads;
    EXPECT_EQ(s.max_place, ref.max_place) << threads;
    EXPECT_EQ(s.max_marking, ref.max_marking) << threads;
    EXPECT_EQ(s.deadlock, ref.rd) << threads;
    EXPECT_EQ(s.one_safe, ref.os) << threads;
    EXPECT_EQ(s.live, ref.l) << threads;
    EXPECT_EQ(s.quasi_live, ref.ql) << threads;
    EXPECT_EQ(s.reversible, one.reversible) << threads;
    EXPECT_EQ(s.dead_markings, one.dead_markings) << threads;
    // each search gives its own path; the threads' is a shortest one (breadth first over the
    // graph they keep)
    if (s.deadlock) {
      EXPECT_TRUE(endsDead(*net, s.deadlock_path)) << threads;
      EXPECT_LE(s.deadlock_path.size(), one.deadlock_path.size()) << threads;
    }
    EXPECT_EQ(s.place_bound, one.place_bound) << threads;
    EXPECT_EQ(s.constant_places, one.constant_places) << threads;
  }
}

INSTANTIATE_TEST_SUITE_P(Mcc, Conformance, ::testing::ValuesIn(references()),
                         [](const ::testing::TestParamInfo<Reference>& param) {
                           std::string n = param.param.model;
                           for (auto& c : n) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return n;
                         });

TEST(Conformance, TheReferenceListIsThere) {
  ASSERT_TRUE(fs::is_regular_file(kConformanceDir / "reference.tsv")) << "missing: " << kConformanceDir / "reference.tsv";
  EXPECT_EQ(references().size(), 12u) << "looked in " << kConformanceDir;
}

TEST(Analysis, ClosedFormsOfThePhilosophersAndReferendum) {
  for (const auto& [model, states] : std::vector<std::pair<std::string, std::uint64_t>>{
           {"Philosophers-PT-000005", 243}, {"Referendum-PT-0010", 59050}}) {
    auto net = conformanceNet(model);
    ASSERT_TRUE(net);
    EXPECT_EQ(explore(*net).states, states) << model;  // 3^N, 3^N + 1
  }
}

TEST(Analysis, TheShortestPathToADeadlockIsGiven) {
  // Figure 3.1 in PNML: T1 then T2 reach the dead marking
  core::Diagnostics diags;
  auto spec = parsePnml(R"(<?xml version="1.0"?>
<pnml><net id="n" type="http://www.pnml.org/version-2009/grammar/ptnet"><page id="pg">
  <place id="P1"><initialMarking><text>1</text></initialMarking></place>
  <place id="P2"><initialMarking><text>1</text></initialMarking></place>
  <place id="P3"/><place id="P4"/>
  <transition id="T1"/><transition id="T2"/>
  <arc id="a1" source="P1" target="T1"/><arc id="a2" source="P2" target="T1"/>
  <arc id="a3" source="T1" target="P3"/><arc id="a4" source="P3" target="T2"/>
  <arc id="a5" source="T2" target="P4"/><arc id="a6" source="T2" target="P2"/>
  <toolspecific tool="x" version="1"><anything/></toolspecific>
</page></net></pnml>)", "fig31.pnml", diags);
  ASSERT_TRUE(spec) << diags.str();
  auto net = compile(*spec, diags);
  ASSERT_TRUE(net) << diags.str();
  const auto s = explore(*net);
  EXPECT_EQ(s.states, 3u);
  EXPECT_TRUE(s.deadlock);
  ASSERT_EQ(s.deadlock_path.size(), 2u);
  EXPECT_EQ(net->transitionName(s.deadlock_path[0]), "net/T1");
  EXPECT_EQ(net->transitionName(s.deadlock_path[1]), "net/T2");
  EXPECT_FALSE(s.reversible);
}

struct BadPnml {
  const char* text;
  const char* expected;
};

class PnmlMistake : public ::testing::TestWithParam<BadPnml> {};

TEST_P(PnmlMistake, IsReportedAtItsLocation) {
  core::Diagnostics diags;
  EXPECT_FALSE(parsePnml(GetParam().text, "bad.pnml", diags));
  EXPECT_NE(diags.str().find(GetParam().expected), std::string::npos) << diags.str();
}

INSTANTIATE_TEST_SUITE_P(
    Pnml, PnmlMistake,
    ::testing::Values(
        BadPnml{"<pnml><net id=\"n\" type=\"ptnet\">\n  <place id=\"p\">\n</net></pnml>",
                "bad.pnml:3:1: error: malformed XML: </net> closes <place>"},
        BadPnml{"<pnml><net id=\"n\" type=\"ptnet\"><page id=\"g\">\n  <place/>\n</page></net></pnml>",
                "bad.pnml:2:3: error: <place> has no id"},
        BadPnml{"<pnml><net id=\"n\" type=\"ptnet\"><page id=\"g\"><place id=\"p\"/><transition id=\"t\"/>\n"
                "  <arc id=\"a\" source=\"p\" target=\"nowhere\"/>\n</page></net></pnml>",
                "bad.pnml:2:3: error: arc target 'nowhere' names no place or transition"},
        BadPnml{"<pnml>\n <net id=\"n\" type=\"http://www.pnml.org/version-2009/grammar/hlcorestructure\"/></pnml>",
                "bad.pnml:2:2: error: only place/transition nets (ptnet) and symmetric nets (symmetricnet) are supported"},
        BadPnml{"<pnml><net id=\"n\" type=\"ptnet\"><page id=\"g\">\n<place id=\"p\"><initialMarking><text>x</text>"
                "</initialMarking></place></page></net></pnml>",
                "bad.pnml:2:15: error: an initial marking expects a whole number of tokens, got \"x\""},
        BadPnml{"<pnml attr=noquote/>", "bad.pnml:1:12: error: malformed XML: attribute 'attr' needs a quoted value"}));

}  // namespace
}  // namespace gdpn::net

namespace gdpn::net {
namespace {

TEST(Pnml, RoundTripKeepsTheNet) {
  // PNML -> spec -> PNML -> spec: the same places, transitions, arcs, weights and marking
  for (const char* model : {"Philosophers-PT-000005", "CircularTrains-PT-012", "RobotManipulation-PT-00002"}) {
    core::Diagnostics diags;
    auto first = conformanceSpec(model);
    ASSERT_TRUE(first);
    std::string why;
    const auto text = writePnml(*first, why);
    ASSERT_TRUE(text) << why;
    auto second = parsePnml(*text, "again.pnml", diags);
    ASSERT_TRUE(second) << diags.str() << *text;
    EXPECT_EQ(*first, *second) << model;
    // and the behaviour with it
    EXPECT_EQ(explore(*compile(*first, diags)).states, explore(*compile(*second, diags)).states);
  }
}

TEST(Pnml, ALabelThatLooksLikeARenamedIdIsNotTakenForOne) {
  // found by the PNML fuzzer: a name label "PNML id X" was kept as the description, which a
  // save reads as the original id of a renamed construct, so the place came back as "X"
  const std::string pnml = R"(<pnml><net id="n"><page id="g">
    <place id="a"><name><text>PNML id b</text></name><initialMarking><text>1</text></initialMarking></place>
    <transition id="t"><name><text>PNML id u</text></name></transition>
    <arc id="e" source="a" target="t"/>
  </page></net></pnml>)";
  core::Diagnostics diags;
  auto first = parsePnml(pnml, "label.pnml", diags);
  ASSERT_TRUE(first) << diags.str();
  EXPECT_EQ(first->pages[0].places[0].name, "a");
  EXPECT_EQ(first->pages[0].places[0].description, "");
  std::string why;
  const auto text = writePnml(*first, why);
  ASSERT_TRUE(text) << why;
  auto second = parsePnml(*text, "again.pnml", diags);
  ASSERT_TRUE(second) << diags.str() << *text;
  EXPECT_EQ(*first, *second);
  EXPECT_EQ(second->pages[0].transitions[0].name, "t");
}

TEST(Pnml, AMissingFileGivesADiagnosticNamingItRatherThanACrash) {
  core::Diagnostics diags;
  const std::string path = (kConformanceDir / "NoSuchNet.pnml").string();
  EXPECT_FALSE(loadPnml(path, diags));
  EXPECT_EQ(diags.str(), path + ": error: cannot read the file\n");
}

TEST(Pnml, AnEmptyFileIsRefusedAtItsFirstLine) {
  const fs::path path = fs::temp_directory_path() / "gdpn_empty_test.pnml";
  std::ofstream(path).close();
  core::Diagnostics diags;
  EXPECT_FALSE(loadPnml(path.string(), diags));
  EXPECT_EQ(diags.str(), path.string() + ":1:1: error: malformed XML: the file holds no XML element\n");
  fs::remove(path);
}

TEST(Pnml, AMissingConformanceNetFailsTheTestInsteadOfCrashingIt) {
  // the helpers once dereferenced the empty result: a bus error took the test binary down
  EXPECT_NONFATAL_FAILURE(EXPECT_EQ(conformanceNet("NoSuchNet"), nullptr), "NoSuchNet.pnml\" could not be read");
}

TEST(Pnml, ASecondArcBetweenTheSameNodesIsRefusedWhereItIs) {
  // two output arcs to a place of capacity 1 each found room for one token, and the
  // transition put two there (two inputs likewise took tokens the place did not hold)
  core::Diagnostics diags;
  auto spec = parsePnml(R"(<pnml><net id="n" type="ptnet"><page id="g">
  <place id="P"><initialMarking><text>1</text></initialMarking></place><place id="Q"/>
  <transition id="T"/>
  <arc id="a1" source="P" target="T"/>
  <arc id="a2" source="T" target="Q"/>
  <arc id="a3" source="T" target="Q"/>
</page></net></pnml>)", "par.pnml", diags);
  ASSERT_TRUE(spec) << diags.str();
  EXPECT_FALSE(compile(*spec, diags));
  EXPECT_EQ(diags.str(), "par.pnml:6:3: error: a second arc from 'net/T' to 'net/Q' on slot a0: give one arc the sum "
                         "of their weights\npar.pnml:5:3: note: the first arc is here\n");
}

TEST(Pnml, WritingKeepsWhatAPTNetCannotHoldInGdpnsPart) {
  // node tokens once made the writer refuse the net; gdpn's tool-specific part keeps them
  NetSpec spec;
  PageSpec page;
  page.name = "main";
  PlaceSpec p;
  p.name = "p";
  p.nodes.push_back({24, {"box"}, {}});
  page.places.push_back(p);
  spec.pages.push_back(page);
  std::string why;
  const auto text = writePnml(spec, why);
  ASSERT_TRUE(text) << why;
  core::Diagnostics diags;
  auto back = parsePnml(*text, "back.pnml", diags);
  ASSERT_TRUE(back) << diags.str();
  EXPECT_EQ(*back, spec);
}

}  // namespace
}  // namespace gdpn::net

namespace gdpn::net {
namespace {

TEST(Analysis, AnUnboundedNetGivesACoverabilityGraphNamingItsPlaces) {
  // a transition that doubles tokens: P is unbounded, Q (fed once) is not
  NetBuilder b;
  const auto p = b.addPlace("P");
  const auto q = b.addPlace("Q");
  const auto r = b.addPlace("R");
  b.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, 2000000000);
  b.setSlot(r, kDefaultSlot, SlotKind::Control, kUnbounded, 1);
  const auto grow = b.addTransition("grow");
  b.addInput(p, grow, kDefaultSlot, 1);
  b.addOutput(grow, p, kDefaultSlot, 1000000000);
  const auto once = b.addTransition("once");
  b.addInput(r, once);
  b.addOutput(once, q);
  const auto s = explore(*b.freeze());
  EXPECT_TRUE(s.complete);
  EXPECT_FALSE(s.bounded);
  EXPECT_FALSE(s.decided);
  ASSERT_EQ(s.unbounded_places.size(), 1u);
  EXPECT_EQ(s.unbounded_places[0], p);
  EXPECT_EQ(s.place_bound[p], kOmega);
  EXPECT_EQ(s.place_bound[q], 1);
  EXPECT_TRUE(s.quasi_live);
  // (P=2e9, R=1), (ω, R=1), (P=2e9, Q=1), (ω, Q=1)
  EXPECT_EQ(s.states, 4u);
}

TEST(Analysis, ARoundThatFillsTwentyBuffersAcceleratesThemAllAtOnce) {
  // a token goes round s0 -> s1 -> ... -> s20 -> s0, step i putting one token into buffer i:
  // back at s0 every buffer holds one more than at the start, so all twenty become ω at
  // once (more slots than the search's sketch has fields: 16). The first round's markings
  // (token at s_k, k buffers holding one) and the same round with every buffer ω: 42 states
  // and 42 edges; the most tokens in one marking, ω not counted, is 21 (s20 and 20 buffers).
  constexpr int kSteps = 20;
  NetBuilder b;
  std::vector<PlaceId> s, buffer;
  for (int i = 0; i <= kSteps; ++i) {
    s.push_back(b.addPlace("s" + std::to_string(i)));
    b.setSlot(s.back(), kDefaultSlot, SlotKind::Control, kUnbounded, i == 0 ? 1 : 0);
  }
  for (int i = 0; i < kSteps; ++i) {
    buffer.push_back(b.addPlace("buffer" + std::to_string(i)));
    const auto step = b.addTransition("step" + std::to_string(i));
    b.addInput(s[static_cast<std::size_t>(i)], step);
    b.addOutput(step, s[static_cast<std::size_t>(i) + 1]);
    b.addOutput(step, buffer.back());
  }
  const auto back = b.addTransition("back");
  b.addInput(s.back(), back);
  b.addOutput(back, s.front());
  const auto space = explore(*b.freeze());
  EXPECT_TRUE(space.complete);
  EXPECT_FALSE(space.bounded);
  EXPECT_EQ(space.states, 42u);
  EXPECT_EQ(space.edges, 42u);
  EXPECT_EQ(space.unbounded_places, buffer);
  for (const PlaceId p : s) EXPECT_EQ(space.place_bound[p], 1) << p;
  EXPECT_EQ(space.max_marking, kSteps + 1);
  EXPECT_FALSE(space.one_safe);
}

TEST(Analysis, EachMarkingBelowAcceleratesTheKeyTheOnesBeforeItMade) {
  // p and q, both without a bound: `make` takes q and gives two p, `use` takes a p and gives a
  // q. From (0, 1): make -> (2, 0), use -> (1, 1). (1, 1) is above the start on p: (ω, 1);
  // that is above (2, 0) on q: (ω, ω). Then both transitions loop on it: 3 states, 4 edges.
  NetBuilder b;
  const auto p = b.addPlace("p");
  const auto q = b.addPlace("q");
  b.setSlot(q, kDefaultSlot, SlotKind::Control, kUnbounded, 1);
  const auto make = b.addTransition("make");
  b.addInput(q, make);
  b.addOutput(make, p, kDefaultSlot, 2);
  const auto use = b.addTransition("use");
  b.addInput(p, use);
  b.addOutput(use, q);
  const auto space = explore(*b.freeze());
  EXPECT_TRUE(space.complete);
  EXPECT_EQ(space.states, 3u);
  EXPECT_EQ(space.edges, 4u);
  EXPECT_EQ(space.unbounded_places, (std::vector<PlaceId>{p, q}));
  EXPECT_FALSE(space.deadlock);
}

TEST(Analysis, TheTokensOfAMarkingLeaveOutItsOmegaPlaces) {
  // `grow` keeps a and adds to p: ω at once; `go` takes a and a p to c0, and each step takes
  // c_i to c_(i+1) and puts five tokens into p (ω already). Every marking holds one token
  // besides p's: the most in one marking is 1. States: (a, 0), (a, ω), (c0..c10, ω).
  constexpr int kSteps = 10;
  NetBuilder b;
  const auto a = b.addPlace("a");
  b.setSlot(a, kDefaultSlot, SlotKind::Control, kUnbounded, 1);
  const auto p = b.addPlace("p");
  std::vector<PlaceId> c;
  for (int i = 0; i <= kSteps; ++i) c.push_back(b.addPlace("c" + std::to_string(i)));
  const auto grow = b.addTransition("grow");
  b.addInput(a, grow);
  b.addOutput(grow, a);
  b.addOutput(grow, p);
  const auto go = b.addTransition("go");
  b.addInput(a, go);
  b.addInput(p, go);
  b.addOutput(go, c.front());
  for (int i = 0; i < kSteps; ++i) {
    const auto step = b.addTransition("step" + std::to_string(i));
    b.addInput(c[static_cast<std::size_t>(i)], step);
    b.addOutput(step, c[static_cast<std::size_t>(i) + 1]);
    b.addOutput(step, p, kDefaultSlot, 5);
  }
  const auto space = explore(*b.freeze());
  EXPECT_TRUE(space.complete);
  EXPECT_EQ(space.states, 2u + kSteps + 1);
  EXPECT_EQ(space.edges, 3u + kSteps);
  EXPECT_EQ(space.max_marking, 1);
  EXPECT_EQ(space.place_bound[p], kOmega);
  for (const PlaceId k : c) EXPECT_EQ(space.place_bound[k], 1) << k;
  EXPECT_TRUE(space.deadlock);  // c10
}

/// The classic unbounded producer added to `b`: p0 (one token) -> produce -> p0 + buffer.
struct Producer {
  PlaceId p0, buffer;
};
Producer addProducer(NetBuilder& b) {
  const auto p0 = b.addPlace("p0");
  const auto buffer = b.addPlace("buffer");
  b.setSlot(p0, kDefaultSlot, SlotKind::Control, kUnbounded, 1);
  const auto produce = b.addTransition("produce");
  b.addInput(p0, produce);
  b.addOutput(produce, p0);
  b.addOutput(produce, buffer);
  return {p0, buffer};
}

TEST(Analysis, AProducerWithoutConsumerIsUnboundedOnlyWhereItProduces) {
  // the classic unbounded producer; consume takes buffer and a free token: the buffer is
  // unbounded, the free place is not
  NetBuilder b;
  const auto [p0, buffer] = addProducer(b);
  const auto done = b.addPlace("done");
  const auto consume = b.addTransition("consume");
  b.addInput(buffer, consume);
  b.addOutput(consume, done);
  const auto s = explore(*b.freeze());
  EXPECT_TRUE(s.complete);
  EXPECT_FALSE(s.bounded);
  EXPECT_EQ(s.unbounded_places, (std::vector<PlaceId>{buffer, done}));
  EXPECT_EQ(s.place_bound[p0], 1);
}

TEST(Analysis, TwoThreadsRaceACoverabilitySearchWithAPlainOneAndGiveTheOneThreadAnswer) {
  // five counters, each raised by a transition that an inhibitor stops at four: no invariant
  // or state equation bounds them (neither sees inhibitors), so one thread searches for
  // coverability; they are bounded, so the plain search of two threads ends with the same
  // graph, walked in the same order: 5^5 states, the last one dead
  NetBuilder b;
  for (int i = 0; i < 5; ++i) {
    const auto c = b.addPlace("c" + std::to_string(i));
    const auto raise = b.addTransition("raise" + std::to_string(i));
    b.addInput(c, raise, kDefaultSlot, 4, ArcKind::Inhibitor);
    b.addOutput(raise, c);
  }
  const auto bounded = b.freeze();
  const StateSpace one = exploreWith(*bounded, 1), two = exploreWith(*bounded, 2);
  ASSERT_TRUE(one.complete);
  ASSERT_TRUE(two.complete);
  EXPECT_EQ(one.states, 3125u);
  EXPECT_EQ(two.states, one.states);
  EXPECT_EQ(two.edges, one.edges);
  EXPECT_TRUE(two.bounded);
  EXPECT_EQ(two.place_bound, one.place_bound);
  EXPECT_EQ(two.deadlock_path, one.deadlock_path);
  EXPECT_EQ(two.more_dead_paths, one.more_dead_paths);
  EXPECT_EQ(two.dead_markings, 1u);
  EXPECT_TRUE(endsDead(*bounded, two.deadlock_path));
  EXPECT_EQ(two.live, one.live);
  EXPECT_EQ(two.reversible, one.reversible);
  EXPECT_EQ(two.max_marking, 20);

  // the classic producer: the plain search never ends; the coverability search does, and
  // the plain one stops
  NetBuilder u;
  const PlaceId buffer = addProducer(u).buffer;
  const auto unbounded = u.freeze();
  const StateSpace cover = exploreWith(*unbounded, 1), raced = exploreWith(*unbounded, 2);
  ASSERT_TRUE(raced.complete);
  EXPECT_FALSE(raced.bounded);
  EXPECT_EQ(raced.states, cover.states);
  EXPECT_EQ(raced.edges, cover.edges);
  EXPECT_EQ(raced.unbounded_places, (std::vector<PlaceId>{buffer}));
}

TEST(Analysis, FiringsThatMoveTokensBetweenFieldsOfOnePackedWordKeepEveryCount) {
  // a and b share 5 tokens (a + b = 5: three bits each), c holds at most 2 (two bits); the
  // three lie in one 64-bit word, and each firing changes its fields by one addition: take
  // moves 2 from a to b, give 1 back, fill adds to c while there is room, and empty takes 2
  NetBuilder b;
  const auto a = b.addPlace("a");
  const auto bb = b.addPlace("b");
  const auto c = b.addPlace("c");
  b.setSlot(a, kDefaultSlot, SlotKind::Control, kUnbounded, 5);
  b.setSlot(bb, kDefaultSlot, SlotKind::Control, kUnbounded, 0);
  b.setSlot(c, kDefaultSlot, SlotKind::Control, 2, 0);
  const auto take = b.addTransition("take");
  b.addInput(a, take, kDefaultSlot, 2);
  b.addOutput(take, bb, kDefaultSlot, 2);
  const auto give = b.addTransition("give");
  b.addInput(bb, give);
  b.addOutput(give, a);
  const auto fill = b.addTransition("fill");
  b.addOutput(fill, c);
  const auto empty = b.addTransition("empty");
  b.addInput(c, empty, kDefaultSlot, 2);
  const auto net = b.freeze();
  for (const unsigned threads : {1u, 2u}) {
    const auto s = exploreWith(*net, threads);
    // (a, 5 - a) for a = 0..5, times c = 0, 1, 2; take is enabled where a >= 2 (4 markings of
    // a and b), give where b >= 1 (5): 9 edges for each c; fill where c < 2 and empty where
    // c = 2: 3 edges for each (a, b)
    EXPECT_EQ(s.states, 18u) << threads;
    EXPECT_EQ(s.edges, 9u * 3 + 3u * 6) << threads;
    EXPECT_EQ(s.place_bound[a], 5);
    EXPECT_EQ(s.place_bound[bb], 5);
    EXPECT_EQ(s.place_bound[c], 2);
    EXPECT_EQ(s.max_marking, 7);
    EXPECT_TRUE(s.live);
    EXPECT_TRUE(s.reversible);
    EXPECT_FALSE(s.deadlock);
  }
}

TEST(Analysis, ThreadsDecideReversibilityOnALongRingWithAndWithoutAWayOut) {
  // a token goes round a ring of 300 places; the way back to the start is 299 firings long,
  // so that the threads' sweeps over their arrays make little headway and they search
  // backwards (predecessors looked up, then over the edges reversed). With a way out of the
  // ring into a cycle of two places (never back), the net is neither reversible nor live:
  // the states past the way out, which cannot reach the start, never enable a ring
  // transition; without it, every marking is on the ring: reversible and live.
  for (const bool way_out : {false, true}) {
    NetBuilder b;
    constexpr int kRing = 300;
    std::vector<PlaceId> ring;
    for (int i = 0; i < kRing; ++i) {
      ring.push_back(b.addPlace("r" + std::to_string(i)));
      b.setSlot(ring.back(), kDefaultSlot, SlotKind::Control, kUnbounded, i == 0 ? 1 : 0);
    }
    for (int i = 0; i < kRing; ++i) {
      const auto t = b.addTransition("t" + std::to_string(i));
      b.addInput(ring[static_cast<std::size_t>(i)], t);
      b.addOutput(t, ring[static_cast<std::size_t>((i + 1) % kRing)]);
    }
    if (way_out) {
      const auto q0 = b.addPlace("q0");
      const auto q1 = b.addPlace("q1");
      const auto out = b.addTransition("out");
      b.addInput(ring[1], out);
      b.addOutput(out, q0);
      const auto there = b.addTransition("there");
      b.addInput(q0, there);
      b.addOutput(there, q1);
      const auto back = b.addTransition("back");
      b.addInput(q1, back);
      b.addOutput(back, q0);
    }
    const auto net = b.freeze();
    const auto one = explore(*net);
    ASSERT_EQ(one.states, way_out ? 302u : 300u);
    EXPECT_EQ(one.reversible, !way_out);
    EXPECT_EQ(one.live, !way_out);
    for (const unsigned threads : {2u, 3u}) {
      const auto s = exploreWith(*net, threads);
      EXPECT_EQ(s.states, one.states) << threads;
      EXPECT_EQ(s.edges, one.edges) << threads;
      EXPECT_EQ(s.reversible, !way_out) << threads;
      EXPECT_EQ(s.live, !way_out) << threads;
      EXPECT_FALSE(s.deadlock) << threads;
      EXPECT_EQ(s.dead_markings, 0u) << threads;
    }
  }
}

/// Rings of `sizes` places, a token on each ring's first place: the product of the sizes in
/// markings, every one on the way back to the start, each with a successor per ring, reached
/// by `copies` transitions each (as many edges). With `tokens` on each first place, a ring of
/// n places has C(n + tokens - 1, tokens) markings.
std::shared_ptr<const Net> tokenRings(const std::vector<int>& sizes, int copies = 1, int tokens = 1) {
  NetBuilder b;
  for (int r = 0; r < static_cast<int>(sizes.size()); ++r) {
    const int places = sizes[static_cast<std::size_t>(r)];
    std::vector<PlaceId> ring;
    for (int i = 0; i < places; ++i) {
      ring.push_back(b.addPlace("r" + std::to_string(r) + "_" + std::to_string(i)));
      b.setSlot(ring.back(), kDefaultSlot, SlotKind::Control, kUnbounded, i == 0 ? tokens : 0);
    }
    for (int i = 0; i < places; ++i) {
      for (int c = 0; c < copies; ++c) {
        const auto t = b.addTransition("t" + std::to_string(r) + "_" + std::to_string(i) + "_" + std::to_string(c));
        b.addInput(ring[static_cast<std::size_t>(i)], t);
        b.addOutput(t, ring[static_cast<std::size_t>((i + 1) % places)]);
      }
    }
  }
  return b.freeze();
}
std::shared_ptr<const Net> tokenRings(int rings, int places, int copies = 1) {
  return tokenRings(std::vector<int>(static_cast<std::size_t>(rings), places), copies);
}

/// Three tokens on one ring of 120 places, each step made by `copies` transitions: 295,240
/// markings. A marking's way back is as long as its tokens are from the first place, and the
/// search mostly writes a marking before those further on, so that a sweep over the graph in
/// that order marks about one level of the way back: the sweeps stop after a few (usually the
/// first), having marked far fewer than a sixteenth of the markings.
std::shared_ptr<const Net> threeTokensOnARing(int copies) { return tokenRings(std::vector<int>{120}, copies, 3); }

TEST(Analysis, ThreadsShareTheWayBackOverLevelsOfThousandsOfStates) {
  // three tokens on a ring of 120 places: C(122, 3) = 295,240 markings, every one on the way
  // back to the start (reversible and live), as many edges as the tokens stand on distinct
  // places. The sweeps make little headway, so the threads go breadth first backward, looking
  // predecessors up and past a sixteenth of the states over the edges reversed; the levels
  // far from the start hold up to 1,830 markings each, which they share.
  const auto net = threeTokensOnARing(1);
  for (const unsigned threads : {1u, 2u, 3u}) {
    const auto s = exploreWith(*net, threads);
    EXPECT_EQ(s.states, 295'240u) << threads;
    // markings with the tokens on 3, 2 and 1 places: C(120, 3), 120 * 119 and 120
    EXPECT_EQ(s.edges, 3u * 280'840u + 2u * 14'280u + 120u) << threads;
    EXPECT_TRUE(s.reversible) << threads;
    EXPECT_TRUE(s.live) << threads;
  }
}

TEST(Analysis, UnderAMemoryLimitThreadsFindTheWayBackWithoutReversingTheEdges) {
  // three tokens on a ring of 120 places, each step made by four transitions: 295,240
  // markings, four times as many edges as above, the ways back too long for the sweeps.
  // Reversed, the edges take about 14 MiB more than the search held. Under a limit 2 MiB
  // below the reversing peak, which the search fits in, the way back is searched by looking
  // predecessors up, with the same answers, within the limit (reversing would pass it)
  const auto net = threeTokensOnARing(4);
  ExploreOptions options;
  options.threads = 2;
  std::uint64_t searching = 0;  // the most the search held, as its progress reports say
  options.progress = [&](const ExploreProgress& p) { searching = std::max(searching, p.bytes); };
  const StateSpace reversing = explore(*net, options);
  ASSERT_TRUE(reversing.complete);
  EXPECT_EQ(reversing.states, 295'240u);
  EXPECT_EQ(reversing.edges, 4u * (3u * 280'840u + 2u * 14'280u + 120u));
  EXPECT_TRUE(reversing.reversible);
  options.max_bytes = reversing.peak_bytes - (std::uint64_t{2} << 20);
  ASSERT_GT(options.max_bytes, searching + (std::uint64_t{1} << 20));
  options.progress = nullptr;
  const StateSpace looking = explore(*net, options);
  ASSERT_TRUE(looking.complete);
  EXPECT_EQ(looking.states, reversing.states);
  EXPECT_EQ(looking.edges, reversing.edges);
  EXPECT_TRUE(looking.reversible);
  EXPECT_TRUE(looking.live);
  EXPECT_LE(looking.peak_bytes, options.max_bytes);
}

TEST(Analysis, UnderAMemoryLimitASearchStopsWhereItHoldsMoreWithoutNewStates) {
  // a token on each of four rings: the threads' net has rings of 16 places, each step made by
  // eight transitions (16^4 markings, 32 edges each), so that they store every marking long
  // before they have expanded them all while their graph still grows; one thread's has rings
  // of 24 places (24^4 markings), and its walk, once it has found every marking, still fills
  // the stack of states whose component is not finished as it walks back. Under any limit
  // below the whole search's peak, the search either stops (a partial answer, past the limit
  // by a chunk at most) or holds no more than the limit: the memory is looked at as the
  // search expands and walks back, not only as it stores new markings
  for (unsigned threads : {1u, 2u}) {
    const auto net = threads == 1 ? tokenRings(4, 24) : tokenRings(4, 16, 8);
    ExploreOptions options;
    options.threads = threads;
    const StateSpace whole = explore(*net, options);
    ASSERT_TRUE(whole.complete);
    EXPECT_EQ(whole.states, threads == 1 ? 331'776u : 65'536u);
    // (limits in 32nds of the peak: the walk back passes the last ones, the threads' graph
    // the first)
    for (int part : {16, 24, 28, 29, 30, 31}) {
      options.max_bytes = whole.peak_bytes * static_cast<std::uint64_t>(part) / 32;
      const StateSpace cut = explore(*net, options);
      if (cut.complete) {
        EXPECT_LE(cut.peak_bytes, options.max_bytes) << threads << " threads, " << part << "/32";
      } else {
        EXPECT_EQ(cut.stop, ExploreStop::MaxMemory) << threads << " threads, " << part << "/32";
        // stopped, it passes the limit by no more than a chunk allocated between two looks
        // (2 MiB of one-word markings; 4 MiB of a thread's graph), never by a grown table
        const std::uint64_t chunk = threads == 1 ? std::uint64_t{2} << 20 : threads * (std::uint64_t{4} << 20);
        EXPECT_LE(cut.peak_bytes, options.max_bytes + chunk) << threads << " threads, " << part << "/32";
      }
    }
  }
}

/// AddressSanitizer keeps freed memory a while (its quarantine): the resident set tells
/// nothing of what a search held.
constexpr bool kResidentTells = !core::kSanitized;

/// The most memory the process has held since `from` began, bytes: its resident set's
/// peak, set back to what it holds now before `from` runs (Linux: /proc/self/clear_refs).
std::uint64_t peakResidentDuring(const std::function<void()>& from) {
  auto status = [](const std::string& key) {
    std::ifstream in("/proc/self/status");
    for (std::string line; std::getline(in, line);) {
      if (line.starts_with(key + ":")) return std::stoull(line.substr(key.size() + 1)) * 1024;
    }
    ADD_FAILURE() << "no " << key << " in /proc/self/status";
    return 0ull;
  };
  {
    std::ofstream reset("/proc/self/clear_refs");
    reset << "5";
    EXPECT_TRUE(reset.flush()) << "cannot set the peak back";
  }
  const std::uint64_t before = status("VmRSS");
  EXPECT_LE(status("VmHWM"), before + (std::uint64_t{1} << 20)) << "the peak was not set back";
  from();
  return status("VmHWM") - before;
}

TEST(Analysis, UnderAMemoryLimitASearchOfManyPartsStopsBeforeItMakesTheSuccessors) {
  // 20,000 rings of two places, a token on each: a marking of 40,000 one-bit fields (5 KiB),
  // and 20,000 successors of the first, 100 MB of markings (a model of 10^5 instances has
  // markings of tens of KiB).
  // - Under 16 MiB the search stops before it makes them: a partial answer, and the process
  //   never holds much more than the net (the successors' room was once sized by the
  //   transitions, 200 MB, whatever the limit).
  // - Under 400 MiB one thread stores those 20,000 and stops as it goes on, within the limit;
  //   the threads count what they send each other, and stop near 10,000 states, past the
  //   limit by no more than a chunk of their graph each (4 MiB).
  const auto net = tokenRings(20'000, 2);
  for (const std::uint64_t mib : {16u, 400u}) {
    for (const unsigned threads : {1u, 2u}) {
      ExploreOptions options;
      options.threads = threads;
      options.max_bytes = mib << 20;
      StateSpace cut;
      const std::uint64_t held = peakResidentDuring([&] { cut = explore(*net, options); });
      const std::uint64_t chunks = threads == 1 ? 0 : threads * (std::uint64_t{4} << 20);
      EXPECT_EQ(cut.stop, ExploreStop::MaxMemory) << threads << " threads, " << mib << " MiB";
      if (mib == 16) {
        EXPECT_EQ(cut.states, 1u) << threads;
        EXPECT_LE(cut.peak_bytes, options.max_bytes) << threads;
      } else {
        // two threads: about 10,000 (9,923 to a few more, as their turns fall)
        EXPECT_GT(cut.states, threads == 1 ? 20'000u : 9'500u) << threads;
        EXPECT_LE(cut.peak_bytes, options.max_bytes + chunks) << threads;
      }
      if (kResidentTells) {
        EXPECT_LT(held, (mib == 16 ? 0 : options.max_bytes) + (std::uint64_t{64} << 20)) << threads << " threads, " << mib << " MiB";
      }
    }
  }
}

TEST(Analysis, UnderALimitJustAboveItsPeakASearchEndsThoughItsTableIsNearlyFull) {
  // 9 x 19 x 29 x 37 = 183,483 markings, 17 short of the 183,500 at which a table of 2^18
  // slots grows, each with 32 successors: near its end the walk expands states whose
  // successors would pass the growth point if all were new, though all are stored. Under a
  // limit 64 KiB above the whole search's peak it ends, complete: only the successors not
  // stored yet count towards the table's growth
  const auto net = tokenRings({9, 19, 29, 37}, 8);
  ExploreOptions options;
  const StateSpace whole = explore(*net, options);
  ASSERT_TRUE(whole.complete);
  EXPECT_EQ(whole.states, 183'483u);
  options.max_bytes = whole.peak_bytes + (std::uint64_t{64} << 10);
  const StateSpace limited = explore(*net, options);
  EXPECT_TRUE(limited.complete);
  EXPECT_EQ(limited.states, whole.states);
  EXPECT_EQ(limited.peak_bytes, whole.peak_bytes);
}

TEST(MarkingStore, GrowthWithinSaysHowMuchTheTableGrowsAsMarkingsAreAdded) {
  // what --max-memory is checked against before a table grows: for runs of new markings of
  // every size, from one to past two doublings at once, the table grows by what was said.
  // A marking already stored adds nothing, and the table does not grow for it, even where
  // it holds as many as it takes before growing (716 in 1,024 slots, after the fifth run)
  detail::Store store(detail::Layout({32}, {false}, {true}));
  std::uint64_t next = 0;
  for (std::size_t n : {1u, 2u, 7u, 100u, 606u, 1000u, 5000u, 20'000u, 1u, 90'000u, 3u}) {
    const std::size_t said = store.growthWithin(n), before = store.tableBytes();
    for (std::size_t i = 0; i < n; ++i, ++next) {
      const std::uint64_t m = next;
      bool added = false;
      store.insert(&m, store.hash(&m), added);
      ASSERT_TRUE(added);
    }
    EXPECT_EQ(store.tableBytes() - before, said) << n;
    const std::size_t after = store.tableBytes();
    const std::uint64_t again = 0;
    bool added = true;
    store.insert(&again, store.hash(&again), added);
    EXPECT_FALSE(added);
    EXPECT_EQ(store.tableBytes(), after) << n;
  }
  EXPECT_EQ(store.size(), next);
  EXPECT_GT(store.tableBytes(), std::size_t{1024} * sizeof(std::uint64_t));
}

TEST(MarkingStore, TheWalksArraysTakeAHugePageOfChunksAtATimeOnceTheyHoldOne) {
  // chunks of 256 KiB (the walk's pending edges): the first eight one at a time, as a small
  // search needs, then eight at once, carved from one block that starts on a huge page
  detail::Chunked<std::uint32_t> a;
  constexpr std::size_t kChunk = std::size_t{1} << 16;
  for (std::uint32_t i = 0; i < 8 * kChunk; ++i) a.push(i);
  EXPECT_EQ(a.bytes(), std::size_t{2} << 20);
  a.push(8 * kChunk);
  EXPECT_EQ(a.bytes(), std::size_t{4} << 20);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.at(8 * kChunk)) % core::kHugePageBytes, 0u);
  for (std::uint32_t i = 8 * kChunk + 1; i < 16 * kChunk; ++i) a.push(i);
  EXPECT_EQ(a.bytes(), std::size_t{4} << 20);  // the block's chunks in use
  // runs never cross a chunk, carved or not
  const std::size_t run = a.appendRun(kChunk, 0xffffffffu);
  EXPECT_EQ(run, 16 * kChunk);
  EXPECT_EQ(a.bytes(), std::size_t{6} << 20);
  for (std::uint32_t i = 0; i < 16 * kChunk; i += 4099) ASSERT_EQ(a[i], i);
  a.shrink(3);
  EXPECT_EQ(a.size(), 3u);
  EXPECT_EQ(a.bytes(), std::size_t{6} << 20);  // the chunks stay for reuse
  a.clear();
  EXPECT_EQ(a.bytes(), 0u);
  a.push(5);
  EXPECT_EQ(a[0], 5u);
  // chunks of 1.5 MiB (six words an element): one to a block of 2 MiB after the first
  detail::Chunked<std::uint32_t> b(6);
  for (std::uint32_t i = 0; i < 2 * kChunk; ++i) *b.append() = i;
  EXPECT_EQ(b.bytes(), (std::size_t{3} << 19) + (std::size_t{2} << 20));
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(b.at(kChunk)) % core::kHugePageBytes, 0u);
  EXPECT_EQ(b[2 * kChunk - 1], 2 * kChunk - 1);
}

TEST(MarkingStore, ALookupGivenAPeekedStateTrustsItOnlyWhereItIsTheMarking) {
  // the search passes what Store::peek gave (the first state whose hash tag matches): the
  // right state, another one, or none. Each gives the marking's own id, and a marking not
  // stored is added once, whatever was passed. Two-word markings, as the search packs them
  using detail::StateId;
  detail::Store store(detail::Layout({40, 40}, {false, false}, {true, true}));
  std::vector<std::vector<std::uint64_t>> kept;
  for (std::uint64_t i = 0; i < 1000; ++i) kept.push_back({i, 1000 - i});
  for (const auto& m : kept) {
    bool added = false;
    store.insert(m.data(), store.hash(m.data()), added);
    ASSERT_TRUE(added);
  }
  for (StateId s = 0; s < kept.size(); ++s) {
    const std::uint64_t* m = kept[s].data();
    const std::uint64_t h = store.hash(m);
    EXPECT_EQ(store.peek(h), s);
    const StateId other = (s + 1) % static_cast<StateId>(kept.size());
    for (const StateId peeked : {s, other, detail::kNone}) {
      bool added = true;
      EXPECT_EQ(store.insert(m, h, peeked, added), s) << s << " " << peeked;
      EXPECT_FALSE(added);
      EXPECT_EQ(store.find(m, h, peeked), s) << s << " " << peeked;
    }
  }
  const std::vector<std::uint64_t> fresh{5000, 7};
  const std::uint64_t h = store.hash(fresh.data());
  EXPECT_EQ(store.find(fresh.data(), h, StateId{3}), detail::kNone);
  bool added = false;
  EXPECT_EQ(store.insert(fresh.data(), h, StateId{3}, added), StateId{1000});
  EXPECT_TRUE(added);
  EXPECT_EQ(store.insert(fresh.data(), h, StateId{3}, added), StateId{1000});
  EXPECT_FALSE(added);
  EXPECT_EQ(store.size(), 1001u);
}

TEST(MarkingStore, CandidatesFoundFromMarkedSlotsMissNoEnabledTransition) {
  // Candidates::find tests each watcher of a marked slot first against the one-bit fields it
  // needs in one word: that filter may only drop transitions not enabled. Arcs of every kind,
  // test arcs, a weight no one-bit field holds, fields in both words of a 70-place marking,
  // and a layout where some fields are wider (not in any filter) or may be ω; random markings
  NetBuilder b;
  std::vector<PlaceId> p;
  for (int i = 0; i < 70; ++i) p.push_back(b.addPlace("p" + std::to_string(i)));
  auto at = [&](int i) { return p[static_cast<std::size_t>(i)]; };
  const auto t0 = b.addTransition("t0");
  b.addInput(at(0), t0);
  b.addInput(at(1), t0, kDefaultSlot, 1, ArcKind::Test);
  b.addInput(at(65), t0);
  const auto t1 = b.addTransition("t1");
  b.addInput(at(2), t1, kDefaultSlot, 2);
  b.addInput(at(3), t1, kDefaultSlot, 1, ArcKind::Test);
  const auto t2 = b.addTransition("t2");
  b.addInput(at(66), t2, kDefaultSlot, 1, ArcKind::Test);
  b.addInput(at(5), t2);
  b.addInput(at(6), t2, kDefaultSlot, 1, ArcKind::Inhibitor);
  b.addOutput(t2, at(7));
  const auto t3 = b.addTransition("t3");
  for (int i : {67, 68, 69, 7, 8}) b.addInput(at(i), t3);
  const auto t4 = b.addTransition("t4");
  b.addOutput(t4, at(9));
  for (int i = 10; i < 60; ++i) {
    const auto t = b.addTransition("u" + std::to_string(i));
    b.addInput(at(i), t);
    b.addInput(at(i + 1), t, kDefaultSlot, 1, ArcKind::Test);
    b.addInput(at(64 + i % 6), t);
    b.addOutput(t, at(i - 1));
  }
  const auto net = b.freeze();
  const std::size_t width = net->placeSlots().size();
  std::vector<std::uint32_t> ones(width, 1), mixed(width, 1);
  std::vector<bool> none(width, false), omega(width, false);
  for (std::size_t k = 0; k < width; k += 7) mixed[k] = 4, omega[k] = k % 14 == 0;
  std::mt19937_64 random(7);
  for (const auto& [bits, may_be_omega] : {std::pair{ones, none}, std::pair{mixed, omega}}) {
    const detail::Layout layout(bits, may_be_omega, std::vector<bool>(width, true));
    detail::Candidates candidates(*net);
    detail::Firing firing(*net);
    candidates.use(layout);
    firing.use(layout);
    std::vector<std::int64_t> counts(width);
    std::vector<std::uint64_t> m(layout.words());
    std::vector<TransitionId> found;
    std::size_t enabled = 0;
    for (int round = 0; round < 4000; ++round) {
      for (std::size_t k = 0; k < width; ++k) {
        const auto most = static_cast<std::int64_t>(layout.maxCount(k));
        counts[k] = static_cast<std::int64_t>(random() % 4) == 0 ? 0 : std::min<std::int64_t>(most, static_cast<std::int64_t>(random() % 3));
        if (layout.field(k).omega && random() % 5 == 0) counts[k] = detail::kW;
      }
      std::size_t bad = 0;
      ASSERT_TRUE(layout.pack(counts.data(), m.data(), bad));
      candidates.find(m.data(), firing, found);
      for (TransitionId t{0}; t < net->transitions().size(); ++t) {
        const bool is = firing.enabled(t, m.data());
        enabled += is ? 1 : 0;
        const bool listed = std::find(found.begin(), found.end(), t) != found.end();
        EXPECT_TRUE(listed || !is) << net->transitionName(t) << " is enabled, not found, in round " << round;
        EXPECT_TRUE(!listed || firing.ready(t, m.data())) << net->transitionName(t) << " is found, not ready";
      }
    }
    EXPECT_GT(enabled, 4000u);  // the markings enable many transitions, not a few
  }
  (void)t1, (void)t3, (void)t4;
}

TEST(Analysis, ThreadsFindANetLiveThatIsNotReversible) {
  // two tokens in a; `move` takes one to b, `back` two from b and gives one to a: (2, 0) ->
  // (1, 1) <-> (0, 2). The start is never reached again, but the last two markings enable
  // both transitions in turn: live. The states that cannot reach the start miss no
  // transition, so the threads' strongly connected components decide.
  NetBuilder b;
  const auto a = b.addPlace("a");
  b.setSlot(a, kDefaultSlot, SlotKind::Control, kUnbounded, 2);
  const auto bb = b.addPlace("b");
  const auto move = b.addTransition("move");
  b.addInput(a, move);
  b.addOutput(move, bb);
  const auto back = b.addTransition("back");
  b.addInput(bb, back, kDefaultSlot, 2);
  b.addOutput(back, a);
  b.addOutput(back, bb);
  const auto net = b.freeze();
  for (const unsigned threads : {1u, 2u, 3u}) {
    const auto s = exploreWith(*net, threads);
    EXPECT_EQ(s.states, 3u) << threads;
    EXPECT_EQ(s.edges, 3u) << threads;
    EXPECT_TRUE(s.live) << threads;
    EXPECT_FALSE(s.reversible) << threads;
    EXPECT_FALSE(s.deadlock) << threads;
  }
}

TEST(Analysis, AComponentOfEveryStateIsLiveOnlyWhereEveryTransitionFires) {
  // a token goes round a -> b -> c; `stuck` needs a token in d, which never has one. Every
  // state lies in one component (reversible), but `stuck` never fires: not live; without it,
  // live
  for (const bool stuck : {true, false}) {
    NetBuilder b;
    std::vector<PlaceId> ring;
    for (const char* name : {"a", "b", "c"}) ring.push_back(b.addPlace(name));
    b.setSlot(ring[0], kDefaultSlot, SlotKind::Control, kUnbounded, 1);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const auto t = b.addTransition("t" + std::to_string(i));
      b.addInput(ring[i], t);
      b.addOutput(t, ring[(i + 1) % ring.size()]);
    }
    if (stuck) {
      const auto d = b.addPlace("d");
      const auto t = b.addTransition("stuck");
      b.addInput(d, t);
      b.addOutput(t, ring[0]);
    }
    const auto net = b.freeze();
    for (const unsigned threads : {1u, 2u}) {
      const auto s = exploreWith(*net, threads);
      EXPECT_EQ(s.states, 3u) << threads;
      EXPECT_TRUE(s.reversible) << threads;
      EXPECT_EQ(s.live, !stuck) << threads;
      EXPECT_EQ(s.quasi_live, !stuck) << threads;
    }
  }
}

TEST(Analysis, CountsBeyondWhatTheSearchHoldsGiveAPartialAnswer) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  b.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, 5'000'000'000);
  const auto t = b.addTransition("t");
  b.addInput(p, t);
  const auto s = explore(*b.freeze());
  EXPECT_FALSE(s.complete);
  EXPECT_EQ(s.stop, ExploreStop::Overflow);
  EXPECT_FALSE(s.decided);
}

TEST(Analysis, ThePathToADeadlockFiresFromTheStartToADeadMarking) {
  // five philosophers each take a fork: the shortest way to the dead end is 5 firings; the
  // one-thread search gives the path it walked, cut short wherever one firing reaches further
  // along it, the threads a shortest one
  auto net = conformanceNet("Philosophers-PT-000005");
  ASSERT_TRUE(net);
  const auto one = explore(*net);
  ExploreOptions o;
  o.threads = 2;
  const auto two = explore(*net, o);
  ASSERT_TRUE(one.deadlock);
  EXPECT_TRUE(endsDead(*net, one.deadlock_path));
  EXPECT_TRUE(endsDead(*net, two.deadlock_path));
  EXPECT_EQ(two.deadlock_path.size(), 5u);
  EXPECT_GE(one.deadlock_path.size(), 5u);
  // asked for, one thread finds a shortest one too
  ExploreOptions shortest;
  shortest.shortest_path = true;
  const auto bfs = explore(*net, shortest);
  EXPECT_TRUE(endsDead(*net, bfs.deadlock_path));
  EXPECT_EQ(bfs.deadlock_path.size(), 5u);
  EXPECT_EQ(bfs.states, one.states);
  o.max_states = 50;
  const auto cut = explore(*net, o);
  EXPECT_EQ(cut.stop, ExploreStop::MaxStates);
  EXPECT_FALSE(cut.decided);
  // a dead marking met before the limit is a deadlock, though the threads give no path
  EXPECT_EQ(cut.deadlock, cut.dead_markings > 0);
}

TEST(Analysis, LimitsStopCleanlyWithAPartialAnswer) {
  auto net = conformanceNet("Referendum-PT-0010");
  ASSERT_TRUE(net);
  ExploreOptions few;
  few.max_states = 1000;
  const auto s = explore(*net, few);
  EXPECT_FALSE(s.complete);
  EXPECT_EQ(s.stop, ExploreStop::MaxStates);
  EXPECT_FALSE(s.decided);
  EXPECT_GE(s.states, 1000u);
  ExploreOptions small;
  small.max_bytes = 1;
  std::uint64_t calls = 0;
  small.progress = [&](const ExploreProgress& p) {
    ++calls;
    EXPECT_GT(p.bytes, 0u);
  };
  // the search holds more than a byte from the start, so it stops before it makes the first
  // marking's successors, before any progress report
  const auto m = explore(*net, small);
  EXPECT_EQ(m.stop, ExploreStop::MaxMemory);
  EXPECT_FALSE(m.decided);
  EXPECT_EQ(calls, 0u);
  EXPECT_EQ(m.states, 1u);
}

TEST(MarkingStore, AStoreThatLeavesOutTheSlotsTheInvariantsGiveReadsEveryMarkingBackWhole) {
  // three processes share a lock and three credits that a round of theirs spends and a
  // refill gives back three at a time: each process's two places, the lock with the critical
  // sections, and the credits with what is spent and the critical sections are invariants, so
  // five of the nine slots are worked out from the others (the idle places and the lock from
  // the critical sections, the credits from those and the two-bit count of what is spent). Every marking a breadth-first walk meets is
  // read back whole, and the walk meets the same markings as one over the plain layout
  NetBuilder b;
  auto place = [&](const std::string& name, std::int64_t tokens) {
    const PlaceId at = b.addPlace(name);
    b.setSlot(at, kDefaultSlot, SlotKind::Control, kUnbounded, tokens);
    return at;
  };
  const auto lock = place("lock", 1), credit = place("credit", 3), spent = place("spent", 0);
  for (int i = 0; i < 3; ++i) {
    const auto idle = place("idle" + std::to_string(i), 1), cs = place("cs" + std::to_string(i), 0);
    const auto enter = b.addTransition("enter" + std::to_string(i)), leave = b.addTransition("leave" + std::to_string(i));
    b.addInput(idle, enter);
    b.addInput(lock, enter);
    b.addInput(credit, enter);
    b.addOutput(enter, cs);
    b.addInput(cs, leave);
    b.addOutput(leave, idle);
    b.addOutput(leave, lock);
    b.addOutput(leave, spent);
  }
  const auto refill = b.addTransition("refill");
  b.addInput(spent, refill, kDefaultSlot, 3);
  b.addOutput(refill, credit, kDefaultSlot, 3);
  const auto net = b.freeze();
  const detail::Plan p = detail::plan(*net, {});
  ASSERT_EQ(p.derived.size(), 5u);
  auto walk = [&](const detail::Layout& layout, const std::vector<detail::Derived>& derived) {
    detail::Store store(layout, true, derived);
    detail::Candidates candidates(*net);
    detail::Firing firing(*net);
    candidates.use(layout);
    firing.use(layout);
    std::vector<std::vector<std::uint64_t>> packed(1, std::vector<std::uint64_t>(layout.words()));
    std::size_t bad = 0;
    layout.pack(p.m0.data(), packed[0].data(), bad);
    bool added = false;
    store.insert(packed[0].data(), store.hash(packed[0].data()), added);
    std::set<std::vector<std::int64_t>> met;
    std::vector<std::uint64_t> m, next(layout.words());
    std::vector<TransitionId> found;
    for (detail::StateId s = 0; s < store.size(); ++s) {
      store.load(s, m);
      EXPECT_EQ(m, packed[s]) << s;
      EXPECT_EQ(store.index(s), 0u);
      store.setIndex(s, s + 7);
      std::vector<std::int64_t> counts(layout.width());
      layout.unpack(m.data(), counts.data());
      met.insert(counts);
      candidates.find(m.data(), firing, found);
      for (const TransitionId t : found) {
        std::size_t field = 0;
        if (firing.fire(t, m.data(), next.data(), field) != detail::Fired::Ok) continue;
        if (store.insert(next.data(), store.hash(next.data()), added) == store.size() - 1 && added) packed.push_back(next);
      }
    }
    for (detail::StateId s = 0; s < store.size(); ++s) EXPECT_EQ(store.index(s), s + 7);
    return std::pair{met, layout.keyBytes()};
  };
  const auto [whole, whole_bytes] = walk(detail::Layout::omegaOrBounded(p.bits, p.omega), {});
  const auto [left_out, left_out_bytes] = walk(p.layout(), p.derived);
  EXPECT_EQ(left_out, whole);
  EXPECT_EQ(whole.size(), explore(*net).states);
  EXPECT_EQ(whole.size(), 13u);  // credits and spent of 3, 2, 1 and 0 tokens, none or one of the three inside
  // 5 bits of 11 stored: a byte, against two (and the index: eight bytes a state either way,
  // the least the arena gives one)
  EXPECT_EQ(left_out_bytes, 1u);
  EXPECT_EQ(whole_bytes, 2u);
  EXPECT_EQ(detail::Store(p.layout(), true, p.derived).stateBytes(), 8u);
}

}  // namespace
}  // namespace gdpn::net
