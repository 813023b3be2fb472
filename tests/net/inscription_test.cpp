// The inscription language (net/inscription.h): parsing with located errors, printing back,
// type checking and evaluation, on answers worked out by hand.

#include <gtest/gtest.h>

#include "gdpn/net/inscription.h"

namespace gdpn::net {
namespace {

SourceLoc at(int line = 5, int column = 10) { return {"m.gdpn.yaml", line, column}; }

Expr parse(std::string_view text) {
  core::Diagnostics d;
  auto e = parseInscription(text, at(), d);
  EXPECT_TRUE(e.has_value()) << text << "\n" << d.str();
  return e ? *e : Expr{};
}

/// The one error parsing `text` (at line 5, column 10 of m.gdpn.yaml) reports.
std::string parseError(std::string_view text) {
  core::Diagnostics d;
  const auto e = parseInscription(text, at(), d);
  EXPECT_FALSE(e.has_value()) << text;
  EXPECT_EQ(d.errorCount(), 1U) << d.str();
  return d.all().empty() ? std::string() : d.all().front().str();
}

/// Same tree: operators, values, names, fields and operands (not locations).
bool same(const Expr& a, const Expr& b) {
  if (a.op != b.op || a.value != b.value || a.name != b.name || a.fields != b.fields || a.args.size() != b.args.size()) {
    return false;
  }
  for (std::size_t k = 0; k < a.args.size(); ++k) {
    if (!same(a.args[k], b.args[k])) return false;
  }
  return true;
}

/// `text` parsed and printed back with the built-in sets.
std::string printed(std::string_view text) {
  const Colours c;
  return inscriptionText(parse(text), c);
}

TEST(InscriptionParse, EveryConstructPrintsBack) {
  for (std::string_view text :
       {"x", "42", "\"a \\\"q\\\" b\"", "true", "false", "dot", "empty", "all", "all(Phil)", "succ(x)", "pred(x)",
        "(x, y)", "(x, (1, y))", "{id = 1, name = \"a\"}", "r.id", "r.a.b", "-x", "not b", "a + b", "a - b", "a * b",
        "a / b", "a % b", "a = b", "a <> b", "a < b", "a <= b", "a > b", "a >= b", "a and b", "a or b",
        "if c then x else y", "2'x", "2'x ++ 1'y", "(n + 1)'x", "x'(1, 2)", "1'(x ++ y)", "(x, all)"}) {
    EXPECT_EQ(printed(text), text);
  }
}

TEST(InscriptionParse, AlternativeSpellingsPrintInOneForm) {
  EXPECT_EQ(printed("a == b"), "a = b");
  EXPECT_EQ(printed("a != b"), "a <> b");
  EXPECT_EQ(printed("((x))"), "x");
  EXPECT_EQ(printed("  2 ' x\n ++\n\t1'y  "), "2'x ++ 1'y");
}

TEST(InscriptionParse, TimesBindsTighterThanSum) {
  const Expr e = parse("2'x ++ 1'y");
  ASSERT_EQ(e.op, Expr::Op::Sum);
  ASSERT_EQ(e.args[0].op, Expr::Op::Times);
  EXPECT_EQ(e.args[0].args[0].value, Value::integer(2));
  EXPECT_EQ(e.args[0].args[1].op, Expr::Op::Name);
  EXPECT_EQ(e.args[0].args[1].name, "x");
  EXPECT_EQ(e.args[1].op, Expr::Op::Times);
  EXPECT_EQ(e.args[1].args[1].name, "y");
}

TEST(InscriptionParse, ProductBindsTighterThanSumOfNumbers) {
  const Expr e = parse("a + b * c");
  ASSERT_EQ(e.op, Expr::Op::Add);
  EXPECT_EQ(e.args[0].name, "a");
  ASSERT_EQ(e.args[1].op, Expr::Op::Mul);
  EXPECT_EQ(e.args[1].args[0].name, "b");
  EXPECT_EQ(e.args[1].args[1].name, "c");
  // left-associative: a - b - c is (a - b) - c
  const Expr s = parse("a - b - c");
  ASSERT_EQ(s.op, Expr::Op::Sub);
  EXPECT_EQ(s.args[0].op, Expr::Op::Sub);
  EXPECT_EQ(s.args[1].name, "c");
}

TEST(InscriptionParse, NotBindsTighterThanAnd) {
  const Expr e = parse("not a and b");
  ASSERT_EQ(e.op, Expr::Op::And);
  ASSERT_EQ(e.args[0].op, Expr::Op::Not);
  EXPECT_EQ(e.args[0].args[0].name, "a");
  EXPECT_EQ(e.args[1].name, "b");
  // and binds tighter than or; a comparison tighter than not
  const Expr o = parse("a or b and c");
  ASSERT_EQ(o.op, Expr::Op::Or);
  EXPECT_EQ(o.args[1].op, Expr::Op::And);
  const Expr n = parse("not x = y");
  ASSERT_EQ(n.op, Expr::Op::Not);
  EXPECT_EQ(n.args[0].op, Expr::Op::Eq);
}

TEST(InscriptionParse, UnaryMinusIsLooserThanTimesAndFields) {
  const Expr e = parse("-2'x");
  ASSERT_EQ(e.op, Expr::Op::Neg);
  EXPECT_EQ(e.args[0].op, Expr::Op::Times);
  const Expr f = parse("-r.a");
  ASSERT_EQ(f.op, Expr::Op::Neg);
  EXPECT_EQ(f.args[0].op, Expr::Op::Field);
}

TEST(InscriptionParse, IfTakesTheRestAsItsElseBranch) {
  const Expr e = parse("if c then 1'x else 1'y ++ 1'z");
  ASSERT_EQ(e.op, Expr::Op::If);
  EXPECT_EQ(e.args[2].op, Expr::Op::Sum);
  // as an operand it is written in parentheses
  const Expr s = parse("(if c then x else y) ++ 1'z");
  ASSERT_EQ(s.op, Expr::Op::Sum);
  EXPECT_EQ(s.args[0].op, Expr::Op::If);
  EXPECT_EQ(inscriptionText(s, Colours{}), "(if c then x else y) ++ 1'z");
}

TEST(InscriptionParse, RecordsAndTuplesKeepTheirParts) {
  const Expr r = parse("{b = 1, a = x}");
  ASSERT_EQ(r.op, Expr::Op::Record);
  EXPECT_EQ(r.fields, (std::vector<std::string>{"b", "a"}));
  ASSERT_EQ(r.args.size(), 2U);
  EXPECT_EQ(r.args[1].name, "x");
  const Expr a = parse("all(Phil)");
  EXPECT_EQ(a.op, Expr::Op::All);
  EXPECT_EQ(a.name, "Phil");
  EXPECT_EQ(parse("all").name, "");
}

TEST(InscriptionParse, RoundTripGivesTheSameTree) {
  for (std::string_view text :
       {"a - (b - c)", "(a - b) - c", "a * (b + c)", "-(-x)", "- -x", "not not a", "(a or b) and c",
        "a or (b and c)", "(a = b) = c", "(2'x ++ 1'y) ++ 3'z", "2'x ++ (1'y ++ 3'z)", "(2'x)'y",
        "if a then if b then x else y else z", "succ(pred(x)).f", "((x, y), {a = (1, 2), b = -3})",
        "if (x, y) = (1, 2) then all(P) else empty", "-(2'x)", "(-2)'x", "(a + b).f", "x % 3 + -y * 2",
        "\"tab\\there\\nnewline\""}) {
    const Expr e = parse(text);
    const std::string once = inscriptionText(e, Colours{});
    const Expr again = parse(once);
    EXPECT_TRUE(same(e, again)) << text << " printed as " << once;
    EXPECT_EQ(inscriptionText(again, Colours{}), once);
  }
}

TEST(InscriptionParse, LocationsFollowLinesAndColumns) {
  // the first line counts from the text's column, later lines from 1
  const Expr e = parse("2'x ++\n   1'y");
  EXPECT_EQ(e.loc, at(5, 10));
  EXPECT_EQ(e.args[0].args[1].loc, at(5, 12));
  EXPECT_EQ(e.args[1].loc, at(6, 4));
  EXPECT_EQ(e.args[1].args[1].loc, at(6, 6));
}

TEST(InscriptionParse, ErrorsAreLocated) {
  // column 10 is the text's first character
  EXPECT_EQ(parseError("(x, y"), "m.gdpn.yaml:5:15: error: expected ')' after the tuple's components, found end of "
                                  "the inscription");
  EXPECT_EQ(parseError("(x y)"), "m.gdpn.yaml:5:13: error: expected ')' after the expression in parentheses, found 'y'");
  EXPECT_EQ(parseError("x +"), "m.gdpn.yaml:5:13: error: expected a value, found the end of the inscription");
  EXPECT_EQ(parseError("if x then y"), "m.gdpn.yaml:5:21: error: expected 'else' after the 'then' branch, found end "
                                       "of the inscription");
  EXPECT_EQ(parseError("x y"), "m.gdpn.yaml:5:12: error: unexpected 'y' after the inscription");
  EXPECT_EQ(parseError("a < b < c"), "m.gdpn.yaml:5:16: error: comparisons do not chain: put one of them in "
                                     "parentheses");
  EXPECT_EQ(parseError("2'x'y"), "m.gdpn.yaml:5:13: error: n'v takes one multiplicity: put the inner one in "
                                 "parentheses");
  EXPECT_EQ(parseError("x # y"), "m.gdpn.yaml:5:12: error: '#' is not part of the inscription language");
  EXPECT_EQ(parseError("!x"), "m.gdpn.yaml:5:10: error: '!' is not part of the inscription language (write 'not')");
  EXPECT_EQ(parseError("\"abc"), "m.gdpn.yaml:5:10: error: a string that is never closed");
  EXPECT_EQ(parseError("\"a\\qb\""), "m.gdpn.yaml:5:12: error: unknown escape in a string (write \\\", \\\\, \\n or "
                                     "\\t)");
  EXPECT_EQ(parseError("99999999999999999999"), "m.gdpn.yaml:5:10: error: number 99999999999999999999 is too large "
                                                "(at most 9223372036854775807)");
  EXPECT_EQ(parseError("{a = 1, 2}"), "m.gdpn.yaml:5:18: error: expected a field's name in the record");
  EXPECT_EQ(parseError("{a 1}"), "m.gdpn.yaml:5:13: error: expected '=' after the field's name, found number 1");
  EXPECT_EQ(parseError("all(1)"), "m.gdpn.yaml:5:14: error: expected a colour set's name after 'all('");
  EXPECT_EQ(parseError("succ x"), "m.gdpn.yaml:5:15: error: expected '(' after 'succ', found 'x'");
  EXPECT_EQ(parseError("r.1"), "m.gdpn.yaml:5:12: error: expected a field's name after '.'");
  EXPECT_EQ(parseError("then"), "m.gdpn.yaml:5:10: error: expected a value, found 'then'");
  EXPECT_EQ(parseError(""), "m.gdpn.yaml:5:10: error: expected a value, found the end of the inscription");
}

TEST(InscriptionParse, ErrorsOnALaterLineCountColumnsFromOne) {
  EXPECT_EQ(parseError("1'x ++\n  1'(y,\n   z"), "m.gdpn.yaml:7:5: error: expected ')' after the tuple's components, "
                                                 "found end of the inscription");
  EXPECT_EQ(parseError("1'x ++\n\n  ) "), "m.gdpn.yaml:7:3: error: expected a value, found ')'");
}

TEST(InscriptionParse, DeepNestingIsRefusedCleanly) {
  const std::string parens = std::string(100000, '(') + "x" + std::string(100000, ')');
  EXPECT_NE(parseError(parens).find("error: the inscription nests deeper than 200 levels"), std::string::npos);
  std::string nots;
  for (int k = 0; k < 100000; ++k) nots += "not ";
  EXPECT_NE(parseError(nots + "x").find("nests deeper than"), std::string::npos);
  EXPECT_NE(parseError(std::string(100000, '-') + "x").find("nests deeper than"), std::string::npos);
  // a long chain nests too: it is refused before the tree grows past what a walk of it can take
  std::string chain = "x";
  for (int k = 0; k < 100000; ++k) chain += " ++ x";
  EXPECT_NE(parseError(chain).find("nests deeper than 2000 levels"), std::string::npos);
  // what stays below the limits is read
  std::string fine = "x";
  for (int k = 0; k < 1000; ++k) fine += " ++ x";
  EXPECT_EQ(parse(fine).op, Expr::Op::Sum);
  EXPECT_EQ(parse(std::string(150, '(') + "x" + std::string(150, ')')).op, Expr::Op::Name);
}

TEST(InscriptionParse, AVarIsWrittenByItsName) {
  Expr e = parse("x + 1");
  e.args[0].op = Expr::Op::Var;
  e.args[0].index = 1;
  const std::vector<std::string> names = {"a", "n"};
  EXPECT_EQ(inscriptionText(e, Colours{}, &names), "n + 1");
  EXPECT_EQ(inscriptionText(e, Colours{}), "$1 + 1");
}

}  // namespace
}  // namespace gdpn::net
