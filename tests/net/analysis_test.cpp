// The untimed analysis against the Model Checking Contest's reference answers, and PNML
// reading mistakes with their locations.

#include "gdpn/net/analysis.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "gdpn/net/builder.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/pnml.h"

namespace gdpn::net {
namespace {

namespace fs = std::filesystem;

const fs::path kConformance = fs::path(GDPN_SOURCE_DIR) / ".." / "shared" / "conformance" / "pnml";

struct Reference {
  std::string model;
  std::uint64_t states, edges;
  std::int64_t max_place, max_marking;
  bool rd, os, l, ql, sm;
};

std::vector<Reference> references() {
  std::vector<Reference> out;
  std::ifstream in(kConformance / "reference.tsv");
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

class Conformance : public ::testing::TestWithParam<Reference> {};

TEST_P(Conformance, MatchesTheReferenceExactly) {
  const Reference& ref = GetParam();
  core::Diagnostics diags;
  auto spec = loadPnml((kConformance / (ref.model + ".pnml")).string(), diags);
  ASSERT_TRUE(spec) << diags.str();
  auto net = compile(*spec, diags);
  ASSERT_TRUE(net) << diags.str();
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

INSTANTIATE_TEST_SUITE_P(Mcc, Conformance, ::testing::ValuesIn(references()),
                         [](const ::testing::TestParamInfo<Reference>& param) {
                           std::string n = param.param.model;
                           for (auto& c : n) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return n;
                         });

TEST(Conformance, TheReferenceListIsThere) {
  EXPECT_EQ(references().size(), 12u) << "looked in " << kConformance;
}

TEST(Analysis, ClosedFormsOfThePhilosophersAndReferendum) {
  for (const auto& [model, states] : std::vector<std::pair<std::string, std::uint64_t>>{
           {"Philosophers-PT-000005", 243}, {"Referendum-PT-0010", 59050}}) {
    core::Diagnostics diags;
    auto spec = loadPnml((kConformance / (model + ".pnml")).string(), diags);
    auto net = compile(*spec, diags);
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
  EXPECT_EQ(net->transitions()[s.deadlock_path[0]].name, "net/T1");
  EXPECT_EQ(net->transitions()[s.deadlock_path[1]].name, "net/T2");
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
        BadPnml{"<pnml>\n <net id=\"n\" type=\"http://www.pnml.org/version-2009/grammar/symmetricnet\"/></pnml>",
                "bad.pnml:2:2: error: only place/transition nets (ptnet) are supported"},
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
    auto first = loadPnml((kConformance / (std::string(model) + ".pnml")).string(), diags);
    ASSERT_TRUE(first) << diags.str();
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

TEST(Pnml, WritingRefusesWhatAPTNetCannotHold) {
  NetSpec spec;
  PageSpec page;
  page.name = "main";
  PlaceSpec p;
  p.name = "p";
  p.nodes.push_back({24, {"box"}, {}});
  page.places.push_back(p);
  spec.pages.push_back(page);
  std::string why;
  EXPECT_FALSE(writePnml(spec, why));
  EXPECT_NE(why.find("node slots"), std::string::npos) << why;
}

}  // namespace
}  // namespace gdpn::net

namespace gdpn::net {
namespace {

TEST(Analysis, CountsBeyondWhatTheSearchHoldsGiveAPartialAnswer) {
  // a transition that doubles tokens grows without bound: the search stops, labelled partial
  NetBuilder b;
  const auto p = b.addPlace("P");
  b.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, 2000000000);
  const auto t = b.addTransition("grow");
  b.addInput(p, t, kDefaultSlot, 1);
  b.addOutput(t, p, kDefaultSlot, 1000000000);
  const auto s = explore(*b.freeze());
  EXPECT_FALSE(s.complete);
  EXPECT_FALSE(s.live);
}

}  // namespace
}  // namespace gdpn::net
