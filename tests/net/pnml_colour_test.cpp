// PNML symmetric nets (the contest's coloured format): declarations read into colour sets and
// variables, terms into the inscription language's text, mistakes located at their element,
// and the net written back and read again unchanged. The contest's files are in
// tests/data/conformance-col/ (README.md there); the small nets are written here.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "gdpn/net/pnml.h"
#include "gdpn/net/unfold.h"

namespace gdpn::net {
namespace {

namespace fs = std::filesystem;

const fs::path kColData = fs::path(GDPN_SOURCE_DIR) / "tests/data/conformance-col";

/// A symmetric net around `decls` (declarations) and `page` (the page's elements).
std::string symmetric(const std::string& decls, const std::string& page) {
  return "<?xml version=\"1.0\"?>\n"
         "<pnml xmlns=\"http://www.pnml.org/version-2009/grammar/pnml\">\n"
         "<net id=\"n\" type=\"http://www.pnml.org/version-2009/grammar/symmetricnet\">\n"
         "<page id=\"pg\">\n" +
         page +
         "</page>\n"
         "<declaration><structure><declarations>\n" +
         decls +
         "</declarations></structure></declaration>\n"
         "</net>\n</pnml>\n";
}

const std::string kDecls =
    "<namedsort id=\"philo\" name=\"Philo\"><cyclicenumeration>"
    "<feconstant id=\"Id1\" name=\"1\"/><feconstant id=\"Id2\" name=\"2\"/><feconstant id=\"c-3\" name=\"three\"/>"
    "</cyclicenumeration></namedsort>\n"
    "<namedsort id=\"r\" name=\"R\"><finiteintrange start=\"1\" end=\"3\"/></namedsort>\n"
    "<namedsort id=\"pr\" name=\"P x R\"><productsort><usersort declaration=\"philo\"/><usersort declaration=\"r\"/>"
    "</productsort></namedsort>\n"
    "<namedsort id=\"d\" name=\"Dot\"><dot/></namedsort>\n"
    "<variabledecl id=\"varx\" name=\"x\"><usersort declaration=\"philo\"/></variabledecl>\n"
    "<variabledecl id=\"V-n\" name=\"all\"><usersort declaration=\"r\"/></variabledecl>\n";

const std::string kPage =
    "<place id=\"Think\"><type><structure><usersort declaration=\"philo\"/></structure></type>\n"
    "<hlinitialMarking><structure><all><usersort declaration=\"philo\"/></all></structure></hlinitialMarking></place>\n"
    "<place id=\"Pair\"><type><structure><usersort declaration=\"pr\"/></structure></type>\n"
    "<hlinitialMarking><structure><add>"
    "<subterm><numberof><subterm><numberconstant value=\"2\"><positive/></numberconstant></subterm>"
    "<subterm><tuple><subterm><useroperator declaration=\"c-3\"/></subterm>"
    "<subterm><numberconstant value=\"1\"><positive/></numberconstant></subterm></tuple></subterm></numberof></subterm>"
    "<subterm><numberof><subterm><numberconstant value=\"1\"><positive/></numberconstant></subterm>"
    "<subterm><tuple><subterm><useroperator declaration=\"Id1\"/></subterm>"
    "<subterm><numberconstant value=\"3\"><positive/></numberconstant></subterm></tuple></subterm></numberof></subterm>"
    "</add></structure></hlinitialMarking></place>\n"
    "<place id=\"Go\"><type><structure><usersort declaration=\"d\"/></structure></type>\n"
    "<hlinitialMarking><structure><numberof><subterm><numberconstant value=\"1\"><positive/></numberconstant></subterm>"
    "<subterm><dotconstant/></subterm></numberof></structure></hlinitialMarking></place>\n"
    "<transition id=\"T\"><condition><structure><and>"
    "<subterm><inequality><subterm><variable refvariable=\"varx\"/></subterm>"
    "<subterm><successor><subterm><useroperator declaration=\"Id2\"/></subterm></successor></subterm></inequality></subterm>"
    "<subterm><not><subterm><lessthan><subterm><variable refvariable=\"V-n\"/></subterm>"
    "<subterm><numberconstant value=\"2\"><positive/></numberconstant></subterm></lessthan></subterm></not></subterm>"
    "</and></structure></condition></transition>\n"
    "<arc id=\"a1\" source=\"Think\" target=\"T\"><hlinscription><structure><numberof>"
    "<subterm><numberconstant value=\"1\"><positive/></numberconstant></subterm>"
    "<subterm><variable refvariable=\"varx\"/></subterm></numberof></structure></hlinscription></arc>\n"
    "<arc id=\"a2\" source=\"T\" target=\"Pair\"><hlinscription><structure><tuple>"
    "<subterm><predecessor><subterm><variable refvariable=\"varx\"/></subterm></predecessor></subterm>"
    "<subterm><variable refvariable=\"V-n\"/></subterm></tuple></structure></hlinscription></arc>\n"
    "<arc id=\"a3\" source=\"Go\" target=\"T\"><hlinscription><structure><numberof>"
    "<subterm><numberconstant value=\"1\"><positive/></numberconstant></subterm>"
    "<subterm><dotconstant/></subterm></numberof></structure></hlinscription></arc>\n";

TEST(PnmlSymmetric, DeclarationsAreColourSetsAndVariablesNamedByTheirNamesOrIds) {
  core::Diagnostics diags;
  const auto spec = parsePnml(symmetric(kDecls, kPage), "s.pnml", diags);
  ASSERT_TRUE(spec) << diags.str();
  ASSERT_EQ(spec->colours.size(), 4u);
  const ColourSetSpec& philo = spec->colours[0];
  EXPECT_EQ(philo.name, "Philo");
  EXPECT_EQ(philo.pnml_id, "philo");
  EXPECT_EQ(philo.kind, ColourKind::Enum);
  EXPECT_TRUE(philo.cyclic);
  // "1" and "2" are no identifiers: named by their ids; "three" is one
  EXPECT_EQ(philo.constants, (std::vector<std::string>{"Id1", "Id2", "three"}));
  EXPECT_EQ(philo.constant_pnml_ids, (std::vector<std::string>{"", "", "c-3"}));
  EXPECT_EQ(spec->colours[1].kind, ColourKind::Integer);
  EXPECT_TRUE(spec->colours[1].range);
  EXPECT_EQ(spec->colours[1].lo, 1);
  EXPECT_EQ(spec->colours[1].hi, 3);
  // "P x R" is no identifier: the id, which is
  EXPECT_EQ(spec->colours[2].name, "pr");
  EXPECT_EQ(spec->colours[2].kind, ColourKind::Product);
  EXPECT_EQ(spec->colours[2].components, (std::vector<std::string>{"Philo", "R"}));
  EXPECT_EQ(spec->colours[3].name, "Dot");
  EXPECT_EQ(spec->colours[3].kind, ColourKind::Dot);
  ASSERT_EQ(spec->variables.size(), 2u);
  EXPECT_EQ(spec->variables[0].name, "x");
  EXPECT_EQ(spec->variables[0].colour, "Philo");
  // "all" is a word of the language: the id, made an identifier
  EXPECT_EQ(spec->variables[1].name, "V_n");
  EXPECT_EQ(spec->variables[1].pnml_id, "V-n");
}

TEST(PnmlSymmetric, TermsAreInscriptionTexts) {
  core::Diagnostics diags;
  const auto spec = parsePnml(symmetric(kDecls, kPage), "s.pnml", diags);
  ASSERT_TRUE(spec) << diags.str();
  EXPECT_EQ(diags.str(), "");
  const PageSpec& page = spec->pages.at(0);
  ASSERT_EQ(page.places.size(), 3u);
  ASSERT_EQ(page.places[0].colours.size(), 1u);
  EXPECT_EQ(page.places[0].colours[0].slot, kDefaultSlot);
  EXPECT_EQ(page.places[0].colours[0].text, "Philo");
  EXPECT_EQ(page.places[0].values.at(0).text, "all(Philo)");
  EXPECT_EQ(page.places[1].colours.at(0).text, "pr");
  EXPECT_EQ(page.places[1].values.at(0).text, "2'(three, 1) ++ 1'(Id1, 3)");
  EXPECT_EQ(page.places[2].values.at(0).text, "1'dot");
  ASSERT_EQ(page.transitions.size(), 1u);
  EXPECT_EQ(page.transitions[0].when.text, "x <> succ(Id2) and not V_n < 2");
  ASSERT_EQ(page.arcs.size(), 3u);
  EXPECT_EQ(page.arcs[0].inscriptions.at(0).text, "1'x");
  EXPECT_EQ(page.arcs[1].inscriptions.at(0).text, "(pred(x), V_n)");
  EXPECT_EQ(page.arcs[2].inscriptions.at(0).text, "1'dot");
  EXPECT_EQ(page.arcs[0].weights.size(), 0u);
  // where the text came from: its element
  EXPECT_EQ(page.arcs[0].inscriptions[0].loc.file, "s.pnml");
  EXPECT_GT(page.arcs[0].inscriptions[0].loc.line, 0);
}

TEST(PnmlSymmetric, EveryContestModelIsRead) {
  for (const auto& entry : fs::directory_iterator(kColData)) {
    if (!entry.is_directory()) continue;
    core::Diagnostics diags;
    const auto spec = loadPnml((entry.path() / "model.pnml").string(), diags);
    ASSERT_TRUE(spec) << entry.path() << "\n" << diags.str();
    EXPECT_EQ(diags.str(), "") << entry.path();
    EXPECT_FALSE(spec->colours.empty()) << entry.path();
    for (const auto& page : spec->pages) {
      for (const auto& p : page.places) EXPECT_EQ(p.colours.size(), 1u) << entry.path() << " " << p.name;
      for (const auto& a : page.arcs) EXPECT_EQ(a.inscriptions.size(), 1u) << entry.path() << " " << a.from;
    }
  }
}

/// The first construct where `a` and `b` differ ("" where they are equal).
std::string firstDifference(const NetSpec& a, const NetSpec& b) {
  if (a.colours != b.colours) return "colour sets";
  if (a.variables != b.variables) return "variables";
  if (a.pages.size() != b.pages.size()) return "pages";
  for (std::size_t k = 0; k < a.pages.size(); ++k) {
    const PageSpec &x = a.pages[k], &y = b.pages[k];
    for (std::size_t i = 0; i < std::min(x.places.size(), y.places.size()); ++i) {
      if (!(x.places[i] == y.places[i])) return "place " + x.places[i].name + " / " + y.places[i].name;
    }
    for (std::size_t i = 0; i < std::min(x.transitions.size(), y.transitions.size()); ++i) {
      if (!(x.transitions[i] == y.transitions[i])) return "transition " + x.transitions[i].name + " / " + y.transitions[i].name;
    }
    for (std::size_t i = 0; i < std::min(x.arcs.size(), y.arcs.size()); ++i) {
      if (!(x.arcs[i] == y.arcs[i])) return "arc " + x.arcs[i].from + " -> " + x.arcs[i].to;
    }
    if (!(x == y)) return "page " + x.name;
  }
  return a == b ? "" : "the net";
}

TEST(PnmlSymmetric, WrittenBackAndReadAgainTheNetIsTheSameWithTheSameIds) {
  for (const auto& entry : fs::directory_iterator(kColData)) {
    if (!entry.is_directory()) continue;
    core::Diagnostics diags;
    std::string name;
    const auto spec = loadPnml((entry.path() / "model.pnml").string(), diags, &name);
    ASSERT_TRUE(spec) << diags.str();
    std::string why;
    const auto text = writePnml(*spec, why, name);
    ASSERT_TRUE(text) << entry.path() << ": " << why;
    EXPECT_NE(text->find("grammar/symmetricnet"), std::string::npos);
    const auto back = parsePnml(*text, "back.pnml", diags);
    ASSERT_TRUE(back) << entry.path() << "\n" << diags.str() << *text;
    EXPECT_EQ(firstDifference(*back, *spec), "") << entry.path();
    // the declarations keep their ids, renamed or not
    for (std::size_t i = 0; i < spec->colours.size(); ++i) {
      EXPECT_EQ(back->colours[i].pnml_id, spec->colours[i].pnml_id);
      EXPECT_EQ(back->colours[i].constant_pnml_ids, spec->colours[i].constant_pnml_ids);
    }
    for (std::size_t i = 0; i < spec->variables.size(); ++i) {
      EXPECT_EQ(back->variables[i].pnml_id, spec->variables[i].pnml_id);
    }
    // and writing it again gives the same bytes
    EXPECT_TRUE(writePnml(*back, why, name) == *text) << entry.path();
  }
  // the contest's own ids, as its property files and other tools know them
  core::Diagnostics diags;
  const auto lamport = loadPnml((kColData / "LamportFastMutEx-COL-2" / "model.pnml").string(), diags);
  ASSERT_TRUE(lamport) << diags.str();
  std::string why;
  const auto text = writePnml(*lamport, why);
  ASSERT_TRUE(text) << why;
  for (const char* id : {"<namedsort id=\"T-pid-bool\"", "<feconstant id=\"C-bool-false\" name=\"C_bool_false\"",
                         "<feconstant id=\"C-pid-0\"", "<variabledecl id=\"V-i-pid\" name=\"i\"",
                         "<usersort declaration=\"T-pid\"/>"}) {
    EXPECT_NE(text->find(id), std::string::npos) << id;
  }
}

TEST(PnmlSymmetric, WhatASymmetricNetCannotHoldIsRefused) {
  NetSpec spec;
  spec.colours.push_back({});
  spec.colours[0].name = "Name";
  spec.colours[0].kind = ColourKind::String;
  std::string why;
  EXPECT_FALSE(writePnml(spec, why));
  EXPECT_EQ(why, "colour set 'Name' is a string set that a PNML symmetric net cannot declare (dot, bool, ranges, "
                 "enumerations and products)");
  spec.colours[0].kind = ColourKind::Integer;
  spec.colours[0].range = true;
  spec.colours[0].hi = 3;
  spec.pages.push_back({});
  spec.pages[0].name = "net";
  spec.pages[0].places.push_back({});
  spec.pages[0].places[0].name = "p";
  spec.pages[0].places[0].colours.push_back({kDefaultSlot, "Name", {}});
  spec.pages[0].places[0].values.push_back({kDefaultSlot, "1 + 2", {}});
  EXPECT_FALSE(writePnml(spec, why));
  EXPECT_EQ(why, "the inscription '1 + 2' of place 'p' is no term of a symmetric net: column 1: an operator a "
                 "symmetric net has no term for");
}

TEST(PnmlSymmetric, ATermOfTheWrongSortIsReportedAtItsLabelWhenUnfolded) {
  // Go holds dots; the arc from it takes a philosopher
  std::string page = kPage;
  const std::string from = "<arc id=\"a3\" source=\"Go\" target=\"T\"><hlinscription><structure><numberof>"
                           "<subterm><numberconstant value=\"1\"><positive/></numberconstant></subterm>"
                           "<subterm><dotconstant/></subterm>";
  ASSERT_NE(page.find(from), std::string::npos);
  page.replace(page.find(from), from.size(),
               "<arc id=\"a3\" source=\"Go\" target=\"T\">\n<hlinscription><structure><numberof>"
               "<subterm><numberconstant value=\"1\"><positive/></numberconstant></subterm>"
               "<subterm><variable refvariable=\"varx\"/></subterm>");
  core::Diagnostics diags;
  const auto spec = parsePnml(symmetric(kDecls, page), "s.pnml", diags);
  ASSERT_TRUE(spec) << diags.str();
  EXPECT_FALSE(unfold(*spec, diags));
  // the arc's label starts line 15 (the page on line 5, the arc on line 14); its text is 1'x
  EXPECT_NE(diags.str().find("s.pnml:15:3: error: expected Dot, found Philo"), std::string::npos) << diags.str();
  EXPECT_NE(diags.str().find("s.pnml:15:1: note: in the inscription '1'x'"), std::string::npos) << diags.str();
}

/// The first line of the diagnostics of reading `text` (which must fail) as "s.pnml".
std::string refusal(const std::string& text) {
  core::Diagnostics diags;
  EXPECT_FALSE(parsePnml(text, "s.pnml", diags));
  const std::string all = diags.str();
  return all.substr(0, all.find('\n'));
}

TEST(PnmlSymmetric, MistakesAreLocatedAtTheirElement) {
  // the page's elements start on line 5
  const std::string place = "<place id=\"P\"><type><structure><usersort declaration=\"philo\"/></structure></type>";
  EXPECT_EQ(refusal(symmetric(kDecls, place + "<hlinitialMarking><structure><subtract/></structure></hlinitialMarking></place>\n")),
            "s.pnml:5:111: error: <subtract> (a multiset's difference) has no counterpart in gdpn's inscription language");
  EXPECT_EQ(refusal(symmetric(kDecls, place + "\n<hlinitialMarking><structure><cardinality/></structure></hlinitialMarking></place>\n")),
            "s.pnml:6:30: error: term <cardinality> is not supported in a symmetric net");
  EXPECT_EQ(refusal(symmetric(kDecls, "<place id=\"P\"><type><structure><usersort declaration=\"nope\"/></structure></type></place>\n")),
            "s.pnml:5:32: error: <usersort> names 'nope', which no namedsort declares");
  EXPECT_EQ(refusal(symmetric(kDecls, "<place id=\"P\"><type/></place>\n")),
            "s.pnml:5:15: error: a place's <type> holds <structure> with a sort");
  const std::string arc =
      place + "</place><transition id=\"T\"/>\n<arc id=\"a\" source=\"P\" target=\"T\"><hlinscription><structure>"
              "<variable refvariable=\"y\"/></structure></hlinscription></arc>\n";
  EXPECT_EQ(refusal(symmetric(kDecls, arc)), "s.pnml:6:61: error: <variable> refers to 'y', which no variabledecl declares");
  const std::string numberof =
      place + "<hlinitialMarking><structure><numberof><subterm><dotconstant/></subterm></numberof>"
              "</structure></hlinitialMarking></place>\n";
  EXPECT_EQ(refusal(symmetric(kDecls, numberof)), "s.pnml:5:111: error: <numberof> takes 2 subterms, not 1");
  // the declarations start on line 7 (after an empty page)
  EXPECT_EQ(refusal(symmetric("<namedsort id=\"s\" name=\"S\"><partition/></namedsort>", "")),
            "s.pnml:7:28: error: sort <partition> is not supported (dot, bool, finiteintrange, cyclicenumeration, "
            "finiteenumeration, productsort)");
  EXPECT_EQ(refusal(symmetric("<namedsort id=\"r\" name=\"R\"><finiteintrange start=\"1\" end=\"x\"/></namedsort>", "")),
            "s.pnml:7:28: error: <finiteintrange> needs whole numbers start and end");
  // a net of another type
  std::string other = symmetric("", "");
  other.replace(other.find("symmetricnet"), 12, "hlcorestructure");
  EXPECT_EQ(refusal(other), "s.pnml:3:1: error: only place/transition nets (ptnet) and symmetric nets (symmetricnet) are "
                            "supported; this net is 'http://www.pnml.org/version-2009/grammar/hlcorestructure'");
}

}  // namespace
}  // namespace gdpn::net
