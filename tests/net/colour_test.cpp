// Colour sets, values and multisets (net/colour.h): built-ins, declarations and their mistakes,
// the canonical order, the values of finite sets, and values written as text.

#include <gtest/gtest.h>

#include "gdpn/net/colour.h"

namespace gdpn::net {
namespace {

SourceLoc line(int n) { return {"m.gdpn.yaml", n, 3}; }

ColourSetSpec range(std::string name, std::int64_t lo, std::int64_t hi, int at = 1) {
  ColourSetSpec s;
  s.name = std::move(name);
  s.kind = ColourKind::Integer;
  s.range = true;
  s.lo = lo;
  s.hi = hi;
  s.loc = line(at);
  return s;
}

ColourSetSpec enumeration(std::string name, std::vector<std::string> constants, bool cyclic = false, int at = 1) {
  ColourSetSpec s;
  s.name = std::move(name);
  s.kind = ColourKind::Enum;
  s.constants = std::move(constants);
  s.cyclic = cyclic;
  s.loc = line(at);
  return s;
}

ColourSetSpec product(std::string name, std::vector<std::string> components, int at = 1) {
  ColourSetSpec s;
  s.name = std::move(name);
  s.kind = ColourKind::Product;
  s.components = std::move(components);
  s.loc = line(at);
  return s;
}

ColourSetSpec record(std::string name, std::vector<std::string> fields, std::vector<std::string> components,
                     int at = 1) {
  ColourSetSpec s = product(std::move(name), std::move(components), at);
  s.kind = ColourKind::Record;
  s.fields = std::move(fields);
  return s;
}

TEST(Colours, BuiltinsStandAtFixedIds) {
  const Colours c;
  ASSERT_EQ(c.sets().size(), 4U);
  EXPECT_EQ(c.at(Colours::kDot).name, "dot");
  EXPECT_EQ(c.at(Colours::kBool).name, "bool");
  EXPECT_EQ(c.at(Colours::kInt).name, "int");
  EXPECT_EQ(c.at(Colours::kString).name, "string");
  EXPECT_EQ(c.find("int"), Colours::kInt);
  EXPECT_EQ(c.at(Colours::kDot).size, 1);
  EXPECT_EQ(c.at(Colours::kBool).size, 2);
  EXPECT_FALSE(c.at(Colours::kInt).size.has_value());
  EXPECT_FALSE(c.at(Colours::kString).size.has_value());
  EXPECT_FALSE(c.find("Phil").has_value());
  EXPECT_STREQ(colourKindName(ColourKind::Record), "record");
  EXPECT_STREQ(colourKindName(ColourKind::Integer), "integer");
}

TEST(Colours, DeclaredSetsFollowInOrderWithSizes) {
  Colours c;
  core::Diagnostics d;
  ASSERT_TRUE(c.declare({range("R", 1, 3), enumeration("Phil", {"p1", "p2"}, true), product("P", {"R", "Phil"}),
                         record("Rec", {"id", "ok"}, {"R", "bool"}), product("S", {"string", "R"})},
                        d))
      << d.str();
  EXPECT_EQ(c.find("R"), 4U);
  EXPECT_EQ(c.find("Phil"), 5U);
  EXPECT_EQ(c.find("P"), 6U);
  EXPECT_EQ(c.at(4).size, 3);
  EXPECT_EQ(c.at(5).size, 2);
  EXPECT_TRUE(c.at(5).cyclic);
  EXPECT_EQ(c.at(6).size, 6);
  EXPECT_EQ(c.at(6).components, (std::vector<ColourId>{4, 5}));
  EXPECT_EQ(c.at(7).size, 6);
  EXPECT_FALSE(c.at(8).size.has_value());
  EXPECT_EQ(c.constant("p2"), (std::pair<ColourId, std::int64_t>{5, 1}));
  EXPECT_FALSE(c.constant("p3").has_value());
}

TEST(Colours, HugeProductsAndRangesCountAsNotFinite) {
  Colours c;
  core::Diagnostics d;
  ASSERT_TRUE(c.declare({range("Big", 0, std::int64_t{1} << 40), product("B2", {"Big", "Big"}),
                         range("All", INT64_MIN, INT64_MAX)},
                        d));
  EXPECT_EQ(c.at(4).size, (std::int64_t{1} << 40) + 1);
  EXPECT_FALSE(c.at(5).size.has_value());
  EXPECT_FALSE(c.at(6).size.has_value());
  EXPECT_TRUE(c.values(5).empty());
}

TEST(Colours, DeclarationMistakesAreLocated) {
  Colours c;
  core::Diagnostics d;
  EXPECT_FALSE(c.declare({range("R", 3, 1, 2), enumeration("E", {}, false, 3), enumeration("F", {"a", "b", "a"}, false, 4),
                          enumeration("G", {"b"}, false, 5), product("P", {"R", "Q"}, 6), range("int", 0, 1, 7),
                          range("R", 0, 1, 8), record("Rec", {"a", "a"}, {"R", "R"}, 9), record("S", {"a"}, {"R", "R"}, 10),
                          product("N", {}, 11)},
                         d));
  const std::string expected =
      "m.gdpn.yaml:2:3: error: colour set 'R' is an empty range 3..1\n"
      "m.gdpn.yaml:3:3: error: colour set 'E' has no constants\n"
      "m.gdpn.yaml:4:3: error: constant 'a' of colour set 'F' is declared twice\n"
      "m.gdpn.yaml:5:3: error: constant 'b' of colour set 'G' is also a constant of 'F' (constants are unique over "
      "colour sets)\n"
      "m.gdpn.yaml:6:3: error: colour set 'P' names an unknown colour set 'Q' (a set may name only sets before it)\n"
      "m.gdpn.yaml:7:3: error: 'int' is a built-in colour set\n"
      "m.gdpn.yaml:8:3: error: colour set 'R' is declared twice\n"
      "m.gdpn.yaml:2:3: note: first declared here\n"
      "m.gdpn.yaml:9:3: error: field 'a' of colour set 'Rec' is declared twice\n"
      "m.gdpn.yaml:10:3: error: colour set 'S' has 1 field names for 2 components\n"
      "m.gdpn.yaml:11:3: error: colour set 'N' has no components\n";
  EXPECT_EQ(d.str(), expected);
  // every declaration still has its id, in order
  EXPECT_EQ(c.sets().size(), 14U);
  EXPECT_EQ(c.find("R"), 4U);
}

TEST(Colours, ASetNamesOnlySetsBeforeIt) {
  Colours c;
  core::Diagnostics d;
  EXPECT_FALSE(c.declare({product("P", {"R"}, 2), range("R", 0, 1, 3)}, d));
  EXPECT_EQ(d.str(), "m.gdpn.yaml:2:3: error: colour set 'P' names an unknown colour set 'R' (a set may name only "
                     "sets before it)\n");
}

TEST(Value, OrderIsByKindThenContents) {
  EXPECT_LT(Value::dot(), Value::boolean(false));
  EXPECT_LT(Value::boolean(false), Value::boolean(true));
  EXPECT_LT(Value::boolean(true), Value::integer(-5));
  EXPECT_LT(Value::integer(-5), Value::integer(3));
  EXPECT_LT(Value::integer(3), Value::string(""));
  EXPECT_LT(Value::string("B"), Value::string("a"));
  EXPECT_LT(Value::string("a"), Value::string("ab"));
  EXPECT_LT(Value::string("z"), Value::string("\xc3\xa9"));  // bytewise: 0xc3 above 'z'
  EXPECT_LT(Value::string("zzz"), Value::tuple({}));
  EXPECT_LT(Value::tuple({Value::integer(1), Value::integer(9)}), Value::tuple({Value::integer(2), Value::integer(0)}));
  EXPECT_LT(Value::tuple({Value::integer(1)}), Value::tuple({Value::integer(1), Value::integer(0)}));
  EXPECT_EQ(Value::tuple({Value::integer(1)}) <=> Value::tuple({Value::integer(1)}), std::strong_ordering::equal);
}

TEST(Multiset, SizeAndContainment) {
  const Multiset big = {{Value::integer(1), 2}, {Value::integer(2), 1}};
  EXPECT_EQ(multisetSize(big), 3);
  EXPECT_EQ(multisetSize({}), 0);
  EXPECT_TRUE(containedIn({{Value::integer(1), 2}}, big));
  EXPECT_FALSE(containedIn({{Value::integer(1), 3}}, big));
  EXPECT_FALSE(containedIn({{Value::integer(3), 1}}, big));
  EXPECT_TRUE(containedIn({}, big));
  EXPECT_TRUE(containedIn({}, {}));
  EXPECT_FALSE(containedIn(big, {}));
}

class DeclaredColours : public ::testing::Test {
 protected:
  void SetUp() override {
    core::Diagnostics d;
    ASSERT_TRUE(c.declare({range("R", -1, 1), enumeration("Phil", {"p1", "p2", "p3"}), product("P", {"R", "Phil"}),
                           record("Rec", {"id", "name"}, {"R", "string"}), product("B", {"bool", "dot"})},
                          d));
  }
  Colours c;
  static constexpr ColourId kR = 4, kPhil = 5, kP = 6, kRec = 7, kB = 8;
};

TEST_F(DeclaredColours, ContainsChecksShapeAndRange) {
  EXPECT_TRUE(c.contains(kR, Value::integer(-1)));
  EXPECT_FALSE(c.contains(kR, Value::integer(2)));
  EXPECT_FALSE(c.contains(kR, Value::boolean(true)));
  EXPECT_TRUE(c.contains(Colours::kInt, Value::integer(INT64_MIN)));
  EXPECT_TRUE(c.contains(kPhil, Value::integer(2)));
  EXPECT_FALSE(c.contains(kPhil, Value::integer(3)));
  EXPECT_FALSE(c.contains(kPhil, Value::integer(-1)));
  EXPECT_TRUE(c.contains(kP, Value::tuple({Value::integer(0), Value::integer(2)})));
  EXPECT_FALSE(c.contains(kP, Value::tuple({Value::integer(0), Value::integer(3)})));
  EXPECT_FALSE(c.contains(kP, Value::tuple({Value::integer(0)})));
  EXPECT_FALSE(c.contains(kP, Value::integer(0)));
  EXPECT_TRUE(c.contains(kRec, Value::tuple({Value::integer(1), Value::string("x")})));
  EXPECT_TRUE(c.contains(Colours::kDot, Value::dot()));
  EXPECT_FALSE(c.contains(Colours::kDot, Value::integer(0)));
  EXPECT_TRUE(c.contains(Colours::kBool, Value::boolean(false)));
  EXPECT_TRUE(c.contains(Colours::kString, Value::string("")));
  EXPECT_FALSE(c.contains(99, Value::dot()));
}

TEST_F(DeclaredColours, ValuesOfFiniteSetsInCanonicalOrder) {
  EXPECT_EQ(c.values(kR), (std::vector<Value>{Value::integer(-1), Value::integer(0), Value::integer(1)}));
  EXPECT_EQ(c.values(Colours::kBool), (std::vector<Value>{Value::boolean(false), Value::boolean(true)}));
  EXPECT_EQ(c.values(Colours::kDot), std::vector<Value>{Value::dot()});
  EXPECT_TRUE(c.values(Colours::kInt).empty());
  EXPECT_TRUE(c.values(Colours::kString).empty());
  EXPECT_TRUE(c.values(kRec).empty());
  const std::vector<Value> p = c.values(kP);
  ASSERT_EQ(p.size(), 9U);
  EXPECT_EQ(p[0], Value::tuple({Value::integer(-1), Value::integer(0)}));
  EXPECT_EQ(p[1], Value::tuple({Value::integer(-1), Value::integer(1)}));
  EXPECT_EQ(p[3], Value::tuple({Value::integer(0), Value::integer(0)}));
  EXPECT_EQ(p[8], Value::tuple({Value::integer(1), Value::integer(2)}));
  EXPECT_TRUE(std::is_sorted(p.begin(), p.end()));
  EXPECT_EQ(c.values(kB).size(), 2U);
}

TEST_F(DeclaredColours, ValuesAsTheLanguageWritesThem) {
  EXPECT_EQ(c.text(kR, Value::integer(-1)), "-1");
  EXPECT_EQ(c.text(kPhil, Value::integer(1)), "p2");
  EXPECT_EQ(c.text(Colours::kBool, Value::boolean(true)), "true");
  EXPECT_EQ(c.text(Colours::kDot, Value::dot()), "dot");
  EXPECT_EQ(c.text(Colours::kString, Value::string("a \"b\"\\")), "\"a \\\"b\\\"\\\\\"");
  EXPECT_EQ(c.text(kP, Value::tuple({Value::integer(1), Value::integer(2)})), "(1, p3)");
  EXPECT_EQ(c.text(kRec, Value::tuple({Value::integer(1), Value::string("a")})), "{id = 1, name = \"a\"}");
  EXPECT_EQ(c.text(kB, Value::tuple({Value::boolean(false), Value::dot()})), "(false, dot)");
}

TEST_F(DeclaredColours, MultisetsAsTheLanguageWritesThem) {
  EXPECT_EQ(c.text(kPhil, Multiset{}), "empty");
  EXPECT_EQ(c.text(kPhil, Multiset{{Value::integer(2), 1}, {Value::integer(0), 2}}), "2'p1 ++ 1'p3");
  EXPECT_EQ(c.text(kR, Multiset{{Value::integer(-1), 1}, {Value::integer(1), 3}}), "1'(-1) ++ 3'1");
}

}  // namespace
}  // namespace gdpn::net
