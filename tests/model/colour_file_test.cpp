// Value tokens in the model file: colour sets, variables, place colours and values, arc
// inscriptions and transition conditions read in each of their forms, every mistake located to
// its line and column (inside an inscription too, wherever its text stands), and written back.

#include <gtest/gtest.h>

#include <filesystem>

#include "gdpn/core/file.h"
#include "gdpn/model/model.h"

namespace gdpn::model {
namespace {

/// The model `text` as m.gdpn.yaml, asserted to load.
Model load(const std::string& text) {
  core::Diagnostics diags;
  auto m = parseModel(text, "m.gdpn.yaml", diags);
  EXPECT_TRUE(m) << diags.str();
  EXPECT_FALSE(diags.hasErrors()) << diags.str();
  return m ? std::move(*m) : Model{};
}

/// The diagnostics of loading `text` as m.gdpn.yaml, which must fail.
std::string refuse(const std::string& text) {
  core::Diagnostics diags;
  const auto m = parseModel(text, "m.gdpn.yaml", diags);
  EXPECT_FALSE(m) << text;
  return diags.str();
}

/// True when `all` holds an error at `line`:`col` whose message starts with `message`.
::testing::AssertionResult errorAt(const std::string& all, int line, int col, const std::string& message = {}) {
  const std::string want = "m.gdpn.yaml:" + std::to_string(line) + ":" + std::to_string(col) + ": error: " + message;
  if (all.find(want) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "no '" << want << "' in\n" << all;
}

net::SlotId slot(const char* name) { return net::parseSlot(name).value(); }

TEST(ColourFile, ReadsEveryFormOfColourSetInOrder) {
  const Model m = load(R"(gdpn: 1
colours:
  B: bool
  N: int
  S: string
  D: dot
  Id: {range: [1, 5]}
  P: {enum: [p1, p2, p3]}
  Phil: {cyclic: [ph1, ph2]}
  Pair: {product: [Id, P]}
  Rec: {record: {name: S, id: Id}}
variables:
  x: Id
  p: P
)");
  const auto& c = m.net.colours;
  ASSERT_EQ(c.size(), 9u);
  const std::vector<std::string> names = {"B", "N", "S", "D", "Id", "P", "Phil", "Pair", "Rec"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(c[i].name, names[i]);
    EXPECT_EQ(c[i].loc.line, static_cast<int>(i) + 3) << names[i];
    EXPECT_EQ(c[i].loc.column, 3) << names[i];
  }
  EXPECT_EQ(c[0].kind, net::ColourKind::Bool);
  EXPECT_EQ(c[1].kind, net::ColourKind::Integer);
  EXPECT_FALSE(c[1].range);
  EXPECT_EQ(c[2].kind, net::ColourKind::String);
  EXPECT_EQ(c[3].kind, net::ColourKind::Dot);
  EXPECT_EQ(c[4].kind, net::ColourKind::Integer);
  EXPECT_TRUE(c[4].range);
  EXPECT_EQ(c[4].lo, 1);
  EXPECT_EQ(c[4].hi, 5);
  EXPECT_EQ(c[5].kind, net::ColourKind::Enum);
  EXPECT_FALSE(c[5].cyclic);
  EXPECT_EQ(c[5].constants, (std::vector<std::string>{"p1", "p2", "p3"}));
  EXPECT_EQ(c[6].kind, net::ColourKind::Enum);
  EXPECT_TRUE(c[6].cyclic);
  EXPECT_EQ(c[6].constants, (std::vector<std::string>{"ph1", "ph2"}));
  EXPECT_EQ(c[7].kind, net::ColourKind::Product);
  EXPECT_EQ(c[7].components, (std::vector<std::string>{"Id", "P"}));
  // a record's fields in the order written, not sorted
  EXPECT_EQ(c[8].kind, net::ColourKind::Record);
  EXPECT_EQ(c[8].fields, (std::vector<std::string>{"name", "id"}));
  EXPECT_EQ(c[8].components, (std::vector<std::string>{"S", "Id"}));
  ASSERT_EQ(m.net.variables.size(), 2u);
  EXPECT_EQ(m.net.variables[0].name, "x");
  EXPECT_EQ(m.net.variables[0].colour, "Id");
  EXPECT_EQ(m.net.variables[0].loc.line, 13);
  EXPECT_EQ(m.net.variables[1].name, "p");
  EXPECT_EQ(m.net.variables[1].colour, "P");
}

TEST(ColourFile, ReadsColoursValuesInscriptionsAndConditionsWithTheirPlaces) {
  const Model m = load(R"(gdpn: 1
colours:
  P: {enum: [p1, p2, p3]}
variables:
  x: P
pages:
  main:
    places:
      a: {colour: P, values: all}
      b: {slots: {b0: value}, colour: {b0: "P", b1: int}, values: {b0: "1'p1 ++ 2'p3", b1: '3'}}
    transitions:
      t: {when: "x <> p2"}
    arcs:
      - {from: a, to: t, inscription: x}
      - {from: t, to: b, inscription: {b0: "2'x", b1: "1"}}
)");
  const auto& page = m.net.pages.at(0);
  const auto& a = page.places.at(0);
  ASSERT_EQ(a.colours.size(), 1u);
  EXPECT_EQ(a.colours[0].slot, net::kDefaultSlot);
  EXPECT_EQ(a.colours[0].text, "P");
  EXPECT_EQ(a.colours[0].loc.line, 9);
  EXPECT_EQ(a.colours[0].loc.column, 19);
  ASSERT_EQ(a.values.size(), 1u);
  EXPECT_EQ(a.values[0].slot, net::kDefaultSlot);
  EXPECT_EQ(a.values[0].text, "all");
  EXPECT_EQ(a.values[0].loc.column, 30);
  // a slot with a colour is a value slot: nothing else needs saying
  EXPECT_TRUE(a.kinds.empty());
  const auto& b = page.places.at(1);
  ASSERT_EQ(b.colours.size(), 2u);
  EXPECT_EQ(b.colours[0].loc.column, 45);
  EXPECT_EQ(b.colours[1].slot, slot("b1"));
  EXPECT_EQ(b.colours[1].text, "int");
  ASSERT_EQ(b.values.size(), 2u);
  EXPECT_EQ(b.values[0].slot, slot("b0"));
  EXPECT_EQ(b.values[0].text, "1'p1 ++ 2'p3");
  // the text's first character, inside its quotes
  EXPECT_EQ(b.values[0].loc.line, 10);
  EXPECT_EQ(b.values[0].loc.column, 73);
  EXPECT_EQ(b.values[1].text, "3");
  EXPECT_EQ(b.values[1].loc.column, 93);
  const auto& t = page.transitions.at(0);
  EXPECT_TRUE(t.conditioned());
  EXPECT_EQ(t.when.text, "x <> p2");
  EXPECT_EQ(t.when.loc.line, 12);
  EXPECT_EQ(t.when.loc.column, 18);
  EXPECT_FALSE(t.scripted());  // not a Python guard
  ASSERT_EQ(page.arcs.size(), 2u);
  ASSERT_EQ(page.arcs[0].inscriptions.size(), 1u);
  EXPECT_EQ(page.arcs[0].inscriptions[0].slot, net::kDefaultSlot);
  EXPECT_EQ(page.arcs[0].inscriptions[0].text, "x");
  EXPECT_EQ(page.arcs[0].inscriptions[0].loc.column, 39);
  EXPECT_TRUE(page.arcs[0].weights.empty());
  ASSERT_EQ(page.arcs[1].inscriptions.size(), 2u);
  EXPECT_EQ(page.arcs[1].inscriptions[0].slot, slot("b0"));
  EXPECT_EQ(page.arcs[1].inscriptions[0].text, "2'x");
  EXPECT_EQ(page.arcs[1].inscriptions[1].slot, slot("b1"));
}

TEST(ColourFile, ATextInABlockStartsOnItsFirstLineAndLosesItsLastNewline) {
  const Model m = load(R"(gdpn: 1
colours:
  P: {enum: [p1, p2]}
variables:
  x: P
  y: P
pages:
  main:
    transitions:
      t:
        when: |
          x <> y
            and x = p1
      u:
        when: >
          x = y
)");
  const auto& t = m.net.pages.at(0).transitions.at(0);
  EXPECT_EQ(t.when.text, "x <> y\n  and x = p1");
  EXPECT_EQ(t.when.loc.line, 12);
  EXPECT_EQ(t.when.loc.column, 11);
  const auto& u = m.net.pages.at(0).transitions.at(1);
  EXPECT_EQ(u.when.text, "x = y");
  EXPECT_EQ(u.when.loc.line, 16);
  EXPECT_EQ(u.when.loc.column, 11);
}

/// Bad colour sets, each with where it is reported and how the message starts.
struct BadColour {
  std::string set;  // the set as written after `C: `
  int column;
  std::string message;
};

TEST(ColourFile, EachBadColourSetIsLocated) {
  const BadColour bad[] = {
      {"strng", 6, "unknown colour set kind 'strng' (did you mean 'string'?); a colour set is bool, int, string, dot, or"},
      {"{ranges: [1, 5]}", 7, "unknown key 'ranges' in colour set 'C' (did you mean 'range'?)"},
      {"{range: [5, 1]}", 14, "range [5, 1] is empty"},
      {"{range: [1, x]}", 18, "'range' expects a whole number, got \"x\""},
      {"{range: [1.5, 2]}", 15, "'range' expects a whole number, got \"1.5\""},
      {"{range: [1]}", 14, "'range' expects two whole numbers [lo, hi]"},
      {"{range: 3}", 14, "'range' expects two whole numbers [lo, hi]"},
      {"{enum: []}", 13, "'enum' is empty"},
      {"{cyclic: [a, b, a]}", 22, "constant 'a' stands twice in the enumeration (first at line 3)"},
      {"{enum: [a, 2b]}", 17, "a constant of colour set 'C' is a name of letters, digits and _"},
      {"{product: []}", 16, "'product' is empty"},
      {"{record: {}}", 15, "'record' expects a map of fields"},
      {"{record: {id: [1]}}", 20, "the colour set of field 'id' is a name, got a list"},
      {"{range: [1, 2], enum: [a]}", 6, "colour set 'C' is one of: bool, int"},
      {"[1, 2]", 6, "colour set 'C' is bool, int"},
  };
  for (const auto& b : bad) {
    const std::string all = refuse("gdpn: 1\ncolours:\n  C: " + b.set + "\n");
    EXPECT_TRUE(errorAt(all, 3, b.column, b.message)) << b.set;
  }
  EXPECT_TRUE(errorAt(refuse("gdpn: 1\ncolours: {2C: bool}\n"), 2, 11, "a colour set's name is a word"));
  EXPECT_TRUE(errorAt(refuse("gdpn: 1\nvariables: {x: [P]}\n"), 2, 16, "the colour set of variable 'x' is a name, got a list"));
  EXPECT_TRUE(errorAt(refuse("gdpn: 1\nvariables: {x-1: P}\n"), 2, 13, "a variable's name is a word"));
}

TEST(ColourFile, ValueSlotsAreCheckedAgainstTheirColours) {
  const auto place = [](const std::string& keys) {
    return refuse("gdpn: 1\npages: {main: {places: {p: {" + keys + "}}}}\n");
  };
  // the place's keys start at column 29
  EXPECT_TRUE(errorAt(place("slots: {a0: control}, colour: P"), 2, 59,
                      "slot a0 of place 'p' is a control slot: only a value slot has a colour"));
  EXPECT_TRUE(errorAt(place("slots: {b0: value}"), 2, 37,
                      "value slot b0 of place 'p' has no colour: name its colour set in 'colour'"));
  EXPECT_TRUE(errorAt(place("values: all"), 2, 37, "'values' on slot a0 of place 'p', which has no colour"));
  EXPECT_TRUE(errorAt(place("colour: {b0: P}, values: {b1: all}"), 2, 59, "'values' on slot b1 of place 'p'"));
  EXPECT_TRUE(errorAt(place("colour: P, tokens: 2"), 2, 37, "value slot a0 of place 'p' has 'tokens'"));
  EXPECT_TRUE(errorAt(place("colour: {d0: P}, tokens: {d0: [box]}"), 2, 42,
                      "slot d0 of place 'p' holds node tokens"));
  EXPECT_TRUE(errorAt(place("colour: {c0: P}, sensors: {c0: eye}"), 2, 42, "slot c0 of place 'p' is bound to a sensor"));
  EXPECT_TRUE(errorAt(place("colour: [P]"), 2, 37, "'colour' expects the name of a colour set, got a list"));
  EXPECT_TRUE(errorAt(place("colour: \"P Q\""), 2, 38, "'colour' expects the name of a colour set, got 'P Q'"));
  EXPECT_TRUE(errorAt(place("colour: P, values: \"\""), 2, 48, "'values' is empty"));
  EXPECT_TRUE(errorAt(place("colour: P, values: [1]"), 2, 48, "'values' expects text, got a list"));
}

TEST(ColourFile, AnInscriptionAndAWeightOnOneSlotAreRefused) {
  const std::string all = refuse("gdpn: 1\npages: {main: {arcs: [{from: p, to: t, weight: 2, inscription: x}]}}\n");
  EXPECT_TRUE(errorAt(all, 2, 64, "slot a0 has both 'weight' and 'inscription'"));
  // on different slots they go together
  const Model m = load("gdpn: 1\npages: {main: {arcs: [{from: p, to: t, weight: 2, inscription: {b0: x}}]}}\n");
  EXPECT_EQ(m.net.pages.at(0).arcs.at(0).weights.size(), 1u);
  EXPECT_EQ(m.net.pages.at(0).arcs.at(0).inscriptions.size(), 1u);
}

/// The model of one transition whose `when` is written as `text` (from line 6, column 15).
std::string withWhen(const std::string& text) {
  return "gdpn: 1\npages:\n  main:\n    transitions:\n      t:\n        when: " + text + "\n";
}

TEST(ColourFile, ASyntaxErrorInAnInscriptionIsAtItsCharacterWhereverTheTextStands) {
  // `$` is no character of the language: the error is where it stands in the file
  EXPECT_TRUE(errorAt(refuse(withWhen("x < $")), 6, 19));
  EXPECT_TRUE(errorAt(refuse(withWhen("\"x < $\"")), 6, 20));
  EXPECT_TRUE(errorAt(refuse(withWhen("'x < $'")), 6, 20));
  // escapes take more characters in the file than in the text
  EXPECT_TRUE(errorAt(refuse(withWhen(R"("x = \"a\" or $")")), 6, 29));
  EXPECT_TRUE(errorAt(refuse(withWhen("'x = ''a'' or $'")), 6, 29));
  // on the second line of a block: its line, and its column past the indentation
  EXPECT_TRUE(errorAt(refuse(withWhen("|\n          x > 1 and\n            y $ 2")), 8, 15));
  EXPECT_TRUE(errorAt(refuse(withWhen(">\n          x > 1 and\n            y $ 2")), 8, 15));
  // a plain text over two lines
  EXPECT_TRUE(errorAt(refuse(withWhen("x > 1 and\n          y $ 2")), 7, 13));
  // a double-quoted one over two lines
  EXPECT_TRUE(errorAt(refuse(withWhen("\"x > 1 and\n          y $ 2\"")), 7, 13));
}

TEST(ColourFile, SyntaxErrorsInValuesAndInscriptionsAreLocatedToo) {
  EXPECT_TRUE(errorAt(refuse("gdpn: 1\npages: {main: {places: {p: {colour: P, values: \"1'p1 ++ $\"}}}}\n"), 2, 57));
  EXPECT_TRUE(errorAt(refuse("gdpn: 1\npages: {main: {places: {p: {colour: {b0: P}, values: {b0: '$'}}}}}\n"), 2, 60));
  EXPECT_TRUE(errorAt(refuse("gdpn: 1\npages: {main: {arcs: [{from: p, to: t, inscription: \"(x, $)\"}]}}\n"), 2, 58, "'$' is not part of the inscription language"));
}

/// A model with every form, for the round trip.
const char* const kColoured = R"yaml(gdpn: 1
colours:
  B: bool
  N: int
  S: string
  D: dot
  Id: {range: [-2, 5]}
  P: {enum: [p1, p2, p3]}
  Phil: {cyclic: [ph1, ph2]}
  Pair: {product: [Id, P]}
  Rec: {record: {name: S, id: Id}}
variables:
  x: P
  n: Id
  r: Rec
pages:
  main:
    places:
      a: {colour: P, values: all}
      b: {slots: {b0: value}, colour: {b0: Pair, b1: S}, values: {b0: "(1, p1) ++ 2'(2, p3)", b1: "\"a\" ++ \"b c\""}}
      c: {colour: Rec, values: "{name = \"z\", id = 1}"}
    transitions:
      t:
        when: |
          x <> p2
            and n < 3
      u: {when: "r.id = n"}
    arcs:
      - {from: a, to: t, inscription: x}
      - {from: t, to: b, inscription: {b0: "(n, x)", b1: "\"a\""}, weight: {a0: 1}}
      - from: c
        to: u
        inscription: |
          {name = "z",
           id = n}
)yaml";

TEST(ColourFile, SaveThenLoadGivesTheSameModelAndTheSameBytes) {
  const Model first = load(kColoured);
  const std::string text = writeModel(first);
  core::Diagnostics diags;
  const auto second = parseModel(text, "saved.gdpn.yaml", diags);
  ASSERT_TRUE(second) << diags.str() << "\n" << text;
  EXPECT_EQ(first, *second) << text;
  EXPECT_EQ(writeModel(*second), text);
  // the forms a person writes
  for (const char* form : {"  B: bool\n", "  N: int\n", "  S: string\n", "  D: dot\n", "  Id: {range: [-2, 5]}\n",
                           "  P: {enum: [p1, p2, p3]}\n", "  Phil: {cyclic: [ph1, ph2]}\n", "  Pair: {product: [Id, P]}\n",
                           "  Rec: {record: {name: S, id: Id}}\n", "variables:\n  x: P\n  n: Id\n  r: Rec\n",
                           "a: {colour: P, values: \"all\"}", "colour: {b0: Pair, b1: S}", "inscription: \"x\"",
                           "when: |\n          x <> p2\n            and n < 3\n"}) {
    EXPECT_NE(text.find(form), std::string::npos) << form << "\n" << text;
  }
  // colours and variables before the pages that use them
  EXPECT_LT(text.find("colours:"), text.find("variables:"));
  EXPECT_LT(text.find("variables:"), text.find("pages:"));
  // the block keeps its lines
  const auto& c = second->net.pages.at(0).arcs.at(2).inscriptions.at(0);
  EXPECT_EQ(c.text, "{name = \"z\",\n id = n}");
}

TEST(ColourFile, TheSeedModelLoadsAndSavesBack) {
  core::Diagnostics diags;
  const auto m = loadModel(std::string(GDPN_SOURCE_DIR) + "/tests/data/colour/philosophers.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  EXPECT_EQ(m->net.colours.size(), 1u);
  const auto again = parseModel(writeModel(*m), "saved.gdpn.yaml", diags);
  ASSERT_TRUE(again) << diags.str();
  EXPECT_EQ(*m, *again);
}

TEST(ColourFile, BadInputNeverCrashesAndEveryRefusalSaysWhy) {
  // every prefix of the model, and each byte of it replaced by a character that YAML or the
  // language treat specially: loading either gives a model or says why not
  const std::string text = kColoured;
  const auto check = [](const std::string& input) {
    core::Diagnostics diags;
    const auto m = parseModel(input, "m.gdpn.yaml", diags);
    if (!m) {
      EXPECT_TRUE(diags.hasErrors()) << input;
    }
  };
  for (std::size_t n = 0; n <= text.size(); ++n) check(text.substr(0, n));
  for (const char c : {'"', '\'', '\\', '{', '|', '\n', '$', '('}) {
    for (std::size_t i = 0; i < text.size(); i += 3) {
      std::string changed = text;
      changed[i] = c;
      check(changed);
    }
  }
  // odd values where texts and sets are due
  for (const char* odd : {"~", "[]", "{}", "!tag x", "&a x", "*a", "\"\\x41$\"", "\"\\U0001F600 $\"", "|\n", ">-\n"}) {
    check(std::string("gdpn: 1\ncolours: {C: ") + odd + "}\nvariables: {x: " + odd + "}\n");
    check(withWhen(odd));
    check(std::string("gdpn: 1\npages: {main: {places: {p: {colour: ") + odd + ", values: " + odd + "}}}}\n");
  }
}

}  // namespace
}  // namespace gdpn::model
