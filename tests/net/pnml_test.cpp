// PNML's pages, reference nodes and gdpn's tool-specific part: a model -> PNML -> model round
// trip keeps everything the net has, pages are read as pages and references as the nodes they
// stand for (the files are in tests/data/pnml/, written for these tests).

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "gdpn/core/file.h"
#include "gdpn/model/model.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/net.h"
#include "gdpn/net/pnml.h"

namespace gdpn::net {
namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(GDPN_SOURCE_DIR) / "tests/data/pnml";

/// The text of tests/data/pnml/`name`.
std::string data(const std::string& name) {
  std::ifstream in(kData / name, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The arcs of `page` as "from -> to".
std::vector<std::string> arcs(const PageSpec& page) {
  std::vector<std::string> out;
  for (const auto& a : page.arcs) out.push_back(a.from + " -> " + a.to);
  return out;
}

TEST(PnmlToolSpecific, ModelToPnmlToModelKeepsEveryConstructOfTheNet) {
  // durations of every law, priorities, probabilities, servers, guards, scripts inline and in
  // files, capacities, slots, node tokens, sensors, predicates, conditions, pages, a page type
  // and its instance, descriptions and the globals: P/T PNML has none of them
  core::Diagnostics diags;
  auto model = model::loadModel((kData / "every_construct.gdpn.yaml").string(), diags);
  ASSERT_TRUE(model) << diags.str();
  ASSERT_TRUE(compile(model->net, diags)) << diags.str();
  std::string why;
  std::vector<PnmlUnseen> unseen;
  const auto text = writePnml(model->net, why, model->description, &unseen);
  ASSERT_TRUE(text) << why;
  std::string name;
  auto back = parsePnml(*text, "every.pnml", diags, &name);
  ASSERT_TRUE(back) << diags.str() << *text;
  EXPECT_EQ(diags.str(), "");
  EXPECT_TRUE(*back == model->net) << *text;
  EXPECT_EQ(name, model->description);
  // and writing it again gives the same bytes
  EXPECT_EQ(writePnml(*back, why, name), *text);

  // what other tools will not see, each kind once with its count
  std::string said;
  for (const auto& u : unseen) said += std::to_string(u.count) + " " + u.what + "\n";
  EXPECT_EQ(said,
            "6 transition durations\n"
            "2 transition priorities\n"
            "1 transition probability\n"
            "2 transitions' servers\n"
            "1 guard\n"
            "1 transition with scripts (pre_fire, in_fire, post_fire)\n"
            "3 places with a capacity\n"
            "1 place declaring slot kinds\n"
            "3 markings and arc weights on slots other than a0\n"
            "1 place holding node tokens\n"
            "1 place reading sensors\n"
            "2 places with scripts\n"
            "1 arc with predicates\n"
            "1 arc with conditions\n"
            "2 page descriptions\n"
            "1 page type instance's settings (position, translation, rotation, params, part, uses)\n"
            "1 globals script\n");
}

TEST(PnmlToolSpecific, OtherToolsReadAPlainNetBesideIt) {
  // the P/T part stands alone: markings, inscriptions, a referencePlace for a link
  core::Diagnostics diags;
  auto model = model::loadModel((kData / "every_construct.gdpn.yaml").string(), diags);
  ASSERT_TRUE(model) << diags.str();
  std::string why;
  const auto text = writePnml(model->net, why, model->description);
  ASSERT_TRUE(text) << why;
  EXPECT_NE(text->find("<place id=\"store\"><name><text>boxes waiting</text></name><graphics><position x=\"1.5\" "
                       "y=\"-2\"/></graphics><initialMarking><text>2</text></initialMarking><toolspecific tool=\"gdpn\" "
                       "version=\"1\">"),
            std::string::npos)
      << *text;
  EXPECT_NE(text->find("<referencePlace id=\"cellA.in\" ref=\"in\"/>"), std::string::npos) << *text;
  EXPECT_NE(text->find("<arc id=\"arc4\" source=\"move\" target=\"cellA.in\"/>"), std::string::npos) << *text;
  EXPECT_NE(text->find("<arc id=\"arc6\" source=\"done\" target=\"check\" type=\"test\"><inscription><text>3</text>"
                       "</inscription></arc>"),
            std::string::npos)
      << *text;
  EXPECT_NE(text->find("<transition id=\"idle\"><name><text>idle</text></name><toolspecific tool=\"gdpn\" version=\"1\">"
                       "<duration law=\"exponential\" a=\"4\"/><priority>-1</priority></toolspecific></transition>"),
            std::string::npos)
      << *text;
}

TEST(PnmlToolSpecific, AMistakeInGdpnsPartIsReportedWhereItIs) {
  core::Diagnostics diags;
  EXPECT_FALSE(parsePnml(R"(<pnml><net id="n" type="ptnet"><page id="g">
<transition id="t"><toolspecific tool="gdpn" version="1">
  <priority>high</priority><duration law="sometimes"/><colour/></toolspecific></transition>
<place id="p"><toolspecific tool="gdpn" version="1"><tokens slot="z9">1</tokens></toolspecific></place>
</page></net></pnml>)",
                         "bad.pnml", diags));
  EXPECT_EQ(diags.str(),
            "bad.pnml:3:3: error: a priority expects a whole number, got \"high\"\n"
            "bad.pnml:3:28: error: <duration> needs law=\"fixed\", \"uniform\", \"normal\", \"exponential\" or "
            "\"immediate\"\n"
            "bad.pnml:3:55: error: <colour> is nothing gdpn's tool-specific part of transition 't' holds\n"
            "bad.pnml:4:53: error: <tokens> needs slot=\"a0\" ... \"d7\", got \"z9\"\n");
}

TEST(PnmlToolSpecific, APartOfAnotherVersionIsLeftWithAWarning) {
  core::Diagnostics diags;
  auto spec = parsePnml(R"(<pnml><net id="n" type="ptnet"><page id="g">
<transition id="t"><toolspecific tool="gdpn" version="9"><priority>3</priority></toolspecific></transition>
</page></net></pnml>)",
                        "v9.pnml", diags);
  ASSERT_TRUE(spec) << diags.str();
  EXPECT_EQ(spec->pages[0].transitions[0].priority, 0);
  EXPECT_EQ(diags.str(), "v9.pnml:2:20: warning: gdpn's tool-specific part of version '9' is not read: this gdpn reads "
                         "version 1\n");
}

TEST(PnmlPages, APageInsideAnotherIsAPageTypeInstantiatedThereAndReferencesAreTheirNodes) {
  core::Diagnostics diags;
  std::string name;
  auto spec = parsePnml(data("two_pages.pnml"), "two_pages.pnml", diags, &name);
  ASSERT_TRUE(spec) << diags.str();
  EXPECT_EQ(diags.str(), "");
  EXPECT_EQ(name, "Two pages");
  ASSERT_EQ(spec->pages.size(), 1u);
  const PageSpec& main = spec->pages[0];
  EXPECT_EQ(main.name, "main");
  ASSERT_EQ(main.instances.size(), 1u);
  EXPECT_EQ(main.instances[0].name, "cell");
  EXPECT_EQ(main.instances[0].type, "cell");
  // the referencePlace in-ref (through in-ref-2) is the place in; finish-ref is finish
  EXPECT_EQ(arcs(main), (std::vector<std::string>{"start -> load", "load -> cell/in", "finish -> done",
                                                  "cell/out -> finish"}));
  ASSERT_EQ(spec->page_types.size(), 1u);
  const PageSpec& cell = spec->page_types[0];
  EXPECT_EQ(cell.name, "cell");
  EXPECT_EQ(arcs(cell), (std::vector<std::string>{"in -> work", "work -> out"}));
  ASSERT_EQ(cell.references.size(), 2u);
  EXPECT_EQ(cell.references[0].place, "in");
  EXPECT_EQ(cell.references[1].place, "out");

  // it compiles to the net the file draws, its constructs named by its pages
  auto net = compile(*spec, diags);
  ASSERT_TRUE(net) << diags.str();
  std::vector<std::string> places;
  for (PlaceId p{}; p < PlaceId(static_cast<std::uint32_t>(net->places().size())); ++p) places.push_back(net->placeName(p));
  EXPECT_EQ(places, (std::vector<std::string>{"main/start", "main/done", "main/cell/in", "main/cell/out"}));

  // and PNML -> model -> PNML -> model keeps the pages
  std::string why;
  const auto text = writePnml(*spec, why, name);
  ASSERT_TRUE(text) << why;
  auto again = parsePnml(*text, "again.pnml", diags);
  ASSERT_TRUE(again) << diags.str() << *text;
  EXPECT_TRUE(*again == *spec) << *text;
}

TEST(PnmlPages, ACycleOfReferencesIsRefusedWhereItCloses) {
  core::Diagnostics diags;
  EXPECT_FALSE(parsePnml(data("reference_cycle.pnml"), "reference_cycle.pnml", diags));
  EXPECT_EQ(diags.str(), "reference_cycle.pnml:11:7: error: the references 'r2' -> 'r3' -> 'r2' form a cycle: none of "
                         "them reaches a place or transition\n");
}

TEST(PnmlPages, AReferenceToNothingOrToTheOtherKindIsLocated) {
  core::Diagnostics diags;
  EXPECT_FALSE(parsePnml(R"(<pnml><net id="n" type="ptnet"><page id="g">
  <place id="p"/><transition id="t"/>
  <referencePlace id="r1" ref="t"/>
  <referenceTransition id="r2" ref="nowhere"/>
  <referencePlace id="r3"/>
  <arc id="a" source="r1" target="r2"/>
</page></net></pnml>)",
                         "refs.pnml", diags));
  EXPECT_EQ(diags.str(),
            "refs.pnml:4:3: error: <referenceTransition> 'r2' refers to 'nowhere', which is no node of the net\n"
            "refs.pnml:5:3: error: <referencePlace> 'r3' has no ref (the id of the node it stands for)\n"
            "refs.pnml:3:3: error: <referencePlace> 'r1' stands for transition 't'; a referencePlace stands for a "
            "place\n");
}

TEST(PnmlPages, TwoPagesThatAnArcJoinsAreReadAsOneWithAWarning) {
  // gdpn's arcs reach places of their transition's page and of pages directly inside it (a
  // referencePlace on the transition's page is a fusion place: pnml_fusion_test.cpp)
  core::Diagnostics diags;
  auto spec = parsePnml(R"(<pnml><net id="n" type="ptnet">
<page id="left"><place id="p"><initialMarking><text>1</text></initialMarking></place></page>
<page id="right"><transition id="t"/>
  <arc id="a" source="p" target="t"/></page>
<page id="alone"><place id="q"/></page>
</net></pnml>)",
                        "siblings.pnml", diags);
  ASSERT_TRUE(spec) << diags.str();
  EXPECT_EQ(diags.str(), "siblings.pnml:4:3: warning: page 'right' is read as part of page 'left': arc 'a' joins "
                         "transition 't' of page 'right' and place 'p' of page 'left', and a transition's arcs reach "
                         "only places of its own page and of pages directly inside it (or a referencePlace on its "
                         "page, a fusion place)\n");
  ASSERT_EQ(spec->pages.size(), 2u);
  EXPECT_EQ(spec->pages[0].name, "left");
  EXPECT_EQ(arcs(spec->pages[0]), (std::vector<std::string>{"p -> t"}));
  EXPECT_EQ(spec->pages[1].name, "alone");
  EXPECT_TRUE(compile(*spec, diags)) << diags.str();
}

TEST(PnmlPages, ANetOfOnePageIsThePageNetAndKeepsItsName) {
  core::Diagnostics diags;
  std::string name;
  auto spec = parsePnml(data("figure31.pnml"), "figure31.pnml", diags, &name);
  ASSERT_TRUE(spec) << diags.str();
  ASSERT_EQ(spec->pages.size(), 1u);
  EXPECT_EQ(spec->pages[0].name, "net");
  EXPECT_EQ(name, "figure31");  // no <name>: the id
}

TEST(PnmlPages, APageTypeUsedTwiceIsRefusedForPnml) {
  core::Diagnostics diags;
  auto model = model::loadModel((fs::path(GDPN_SOURCE_DIR) / "tests/data/good/everything.gdpn.yaml").string(), diags);
  ASSERT_TRUE(model) << diags.str();
  std::string why;
  EXPECT_FALSE(writePnml(model->net, why));
  EXPECT_EQ(why, "page type 'cell' has 2 instances; PNML's pages are not reused, so each page type is written as the "
                 "one page inside its one instance");
}

}  // namespace
}  // namespace gdpn::net
