// The one syntax of breakpoints written as text (gdpn run --break, the IDE's replay, Python's
// add_breakpoint): every accepted form, and each mistake located at its character.

#include <gtest/gtest.h>

#include "gdpn/session/breakpoint_syntax.h"

namespace gdpn::session {
namespace {

TEST(BreakpointSyntax, StartAndCompleteNameATransition) {
  auto b = parseBreakpoint("start:main/consume");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->kind, BreakKind::Starts);
  EXPECT_EQ(b->target, "main/consume");
  b = parseBreakpoint("complete:factory/pickup");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->kind, BreakKind::Completes);
  EXPECT_EQ(b->target, "factory/pickup");
  EXPECT_EQ(b->describe(), "completes factory/pickup");
}

TEST(BreakpointSyntax, WhenTakesTheRestAsAPythonExpression) {
  const auto b = parseBreakpoint("when:sim.time >= 3 and x<2");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->kind, BreakKind::Predicate);
  EXPECT_EQ(b->expression, "sim.time >= 3 and x<2");
}

TEST(BreakpointSyntax, EveryComparisonOfAPlaceWithANumber) {
  const std::pair<const char*, Compare> forms[] = {{"<", Compare::Less},          {"<=", Compare::LessEqual},
                                                   {"==", Compare::Equal},        {"!=", Compare::NotEqual},
                                                   {">=", Compare::GreaterEqual}, {">", Compare::Greater}};
  for (const auto& [op, how] : forms) {
    const auto b = parseBreakpoint(std::string("main/buffer") + op + "3");
    ASSERT_TRUE(b) << op;
    EXPECT_EQ(b->kind, BreakKind::Marking);
    EXPECT_EQ(b->target, "main/buffer");
    EXPECT_EQ(b->compare, how) << op;
    EXPECT_EQ(b->value, 3);
  }
  const auto negative = parseBreakpoint("p>-2");
  ASSERT_TRUE(negative);
  EXPECT_EQ(negative->value, -2);
}

TEST(BreakpointSyntax, ANumberWithAFractionOrAnExponentComparesAsARealNumber) {
  auto b = parseBreakpoint("main/tank>=2.5");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->kind, BreakKind::Marking);
  EXPECT_EQ(b->target, "main/tank");
  EXPECT_EQ(b->compare, Compare::GreaterEqual);
  EXPECT_EQ(b->real, 2.5);
  EXPECT_EQ(b->describe(), "main/tank >= 2.5");
  b = parseBreakpoint("main/tank<1e-3");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->real, 1e-3);
  // a whole number stays whole (tokens, or an amount compared with it)
  b = parseBreakpoint("main/tank>=5");
  ASSERT_TRUE(b);
  EXPECT_FALSE(b->real);
  EXPECT_EQ(b->value, 5);
}

TEST(BreakpointSyntax, MistakesAreLocatedAtTheirCharacter) {
  struct Case {
    const char* text;
    int column;  // 1-based, in the text
  };
  const Case cases[] = {
      {"main/buffer", 12},     // no operator: at the end
      {"main/buffer=>3", 12},  // no such operator: at it
      {"main/buffer>=", 14},   // no number: at the end
      {"main/buffer>=x", 14},  // not a number: at it
      {"main/buffer>=3x", 15}, // trailing text: at it
      {"p>=99999999999999999999", 4},  // out of range
      {"main/tank>=2.5x", 15},  // trailing text after a real number: at it
      {"main/tank>=1e999", 12},  // no finite number
      {"main/tank>=.", 12},     // a point alone
  };
  for (const auto& c : cases) {
    const auto b = parseBreakpoint(c.text);
    ASSERT_FALSE(b) << c.text;
    EXPECT_EQ(b.error().severity, core::Severity::Error);
    EXPECT_EQ(b.error().loc.column, c.column) << c.text;
    EXPECT_EQ(b.error().message, kBreakpointForms) << c.text;
  }
}

TEST(BreakpointSyntax, AWhereGivenShiftsTheLocation) {
  // the text as it stands in a file: line 4, its first character at column 10
  const auto b = parseBreakpoint("buffer>=x", {"a.yaml", 4, 10});
  ASSERT_FALSE(b);
  EXPECT_EQ(b.error().str(), "a.yaml:4:18: error: " + std::string(kBreakpointForms));
}

}  // namespace
}  // namespace gdpn::session
