// Arithmetic over named numbers: values, precedence, functions and located errors.

#include "gdpn/core/expression.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace gdpn::core {
namespace {

const std::map<std::string, double, std::less<>> kNames = {{"length", 2.0}, {"width", 0.5}, {"n", 3.0}};

std::optional<double> lookup(std::string_view name) {
  auto it = kNames.find(name);
  return it == kNames.end() ? std::nullopt : std::optional<double>(it->second);
}

double value(std::string_view text) {
  ExpressionError e;
  auto v = evaluate(text, lookup, e, {"length", "width", "n"});
  EXPECT_TRUE(v) << text << ": " << e.message;
  return v.value_or(-999);
}

ExpressionError error(std::string_view text) {
  ExpressionError e;
  EXPECT_FALSE(evaluate(text, lookup, e, {"length", "width", "n"})) << text;
  return e;
}

TEST(Expression, Arithmetic) {
  EXPECT_EQ(value("length/2"), 1.0);
  EXPECT_EQ(value("-length/2 + 0.05"), -0.95);
  EXPECT_EQ(value("1 + 2 * 3"), 7.0);
  EXPECT_EQ(value("(1 + 2) * 3"), 9.0);
  EXPECT_EQ(value("2 - 3 - 4"), -5.0);
  EXPECT_EQ(value("8 / 4 / 2"), 1.0);
  EXPECT_EQ(value("--1"), 1.0);
  EXPECT_EQ(value("1e-3 * 1000"), 1.0);
  EXPECT_EQ(value("2.5E+1"), 25.0);
  EXPECT_EQ(value(" width "), 0.5);
}

TEST(Expression, Functions) {
  EXPECT_EQ(value("max(length, 3)"), 3.0);
  EXPECT_EQ(value("min(length, width*2)"), 1.0);
  EXPECT_EQ(value("abs(-n)"), 3.0);
  EXPECT_EQ(value("sqrt(16)"), 4.0);
  EXPECT_EQ(value("floor(length/0.3)"), 6.0);
  EXPECT_EQ(value("ceil(length/0.3)"), 7.0);
  // in degrees, as rotations are written
  EXPECT_NEAR(value("sind(30)"), 0.5, 1e-15);
  EXPECT_NEAR(value("cosd(60)"), 0.5, 1e-15);
  EXPECT_NEAR(value("atan2d(width, width)"), 45.0, 1e-12);
  EXPECT_NEAR(value("atan2d(-1, 0)"), -90.0, 1e-12);
}

TEST(Expression, ErrorsNameWhatAndWhere) {
  auto e = error("lenght/2");
  EXPECT_EQ(e.column, 0U);
  EXPECT_EQ(e.message, "no parameter 'lenght' (did you mean 'length'?)");
  e = error("length/(n-3)");
  EXPECT_EQ(e.message, "division by zero");
  EXPECT_EQ(e.column, 7U);
  e = error("length +");
  EXPECT_EQ(e.column, 8U);
  EXPECT_EQ(error("(length").message, "expected ')'");
  EXPECT_EQ(error("length 2").message, "unexpected '2'");
  EXPECT_EQ(error("mx(1, 2)").message,
            "no function 'mx' (did you mean 'max'?) (there are: min, max, abs, sqrt, floor, ceil, sind, cosd, atan2d, exp)");
  EXPECT_EQ(error("atan2d(1)").message, "atan2d() takes 2 arguments, got 1");
  EXPECT_EQ(error("min(1)").message, "min() takes 2 arguments, got 1");
  EXPECT_EQ(error("sqrt(-1)").message, "sqrt() of a negative number");
  EXPECT_EQ(error("1.2.3").message, "'1.2.3' is not a number");
  EXPECT_EQ(error("").message, "expected a number, a name or '('");
  EXPECT_EQ(error("$x").message, "unexpected '$'");
}

TEST(Expression, NamesInOrder) {
  EXPECT_EQ(expressionNames("width + length*max(width, n)"), (std::vector<std::string>{"width", "length", "n"}));
  EXPECT_TRUE(expressionNames("1 +").empty());
}

}  // namespace
}  // namespace gdpn::core

TEST(CompiledExpression, RunsAsEvaluateComputes) {
  const std::vector<std::string> names{"tank", "k"};
  const auto resolve = [&](std::string_view n) -> std::optional<std::uint32_t> {
    for (std::uint32_t i = 0; i < names.size(); ++i) {
      if (names[i] == n) return i;
    }
    return std::nullopt;
  };
  const double values[] = {40.0, 0.25};
  const auto lookup = [&](std::string_view n) -> std::optional<double> {
    const auto i = resolve(n);
    return i ? std::optional<double>(values[*i]) : std::nullopt;
  };
  for (const char* text : {"k * tank", "-k*(tank - 4)/2", "max(0, min(tank, 3)) + sqrt(k)", "atan2d(1, 1) + exp(k) - floor(2.5)",
                           "2 - 3 - 4", "8 / 4 / 2", "abs(-tank) * cosd(60) + sind(30) + ceil(k)"}) {
    gdpn::core::ExpressionError error;
    const auto program = gdpn::core::compileExpression(text, resolve, error, names);
    ASSERT_TRUE(program) << text << ": " << error.message;
    const auto expected = gdpn::core::evaluate(text, lookup, error);
    ASSERT_TRUE(expected) << text;
    EXPECT_DOUBLE_EQ(program->run(values), *expected) << text;
  }
  gdpn::core::ExpressionError error;
  const auto program = gdpn::core::compileExpression("k * tank + k", resolve, error);
  ASSERT_TRUE(program);
  EXPECT_EQ(program->reads, (std::vector<std::uint32_t>{0, 1}));
}

TEST(CompiledExpression, NamesWhatItDoesNotKnowWhereItStands) {
  const auto resolve = [](std::string_view n) -> std::optional<std::uint32_t> {
    return n == "tank" ? std::optional<std::uint32_t>(0) : std::nullopt;
  };
  gdpn::core::ExpressionError error;
  EXPECT_FALSE(gdpn::core::compileExpression("0.5 * tnak", resolve, error, {"tank"}));
  EXPECT_EQ(error.column, 6u);
  EXPECT_EQ(error.message, "no name 'tnak' (did you mean 'tank'?)");
  EXPECT_FALSE(gdpn::core::compileExpression("tank / (1", resolve, error));
  const double zero[] = {0.0};
  const auto p = gdpn::core::compileExpression("1 / tank", resolve, error);
  ASSERT_TRUE(p);
  EXPECT_TRUE(std::isinf(p->run(zero)));
}
