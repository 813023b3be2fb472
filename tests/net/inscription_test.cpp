// The inscription language (net/inscription.h): parsing with located errors, printing back,
// type checking and evaluation, on answers worked out by hand.

#include <gtest/gtest.h>

#include <map>

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
  EXPECT_EQ(parseError("x y"), "m.gdpn.yaml:5:12: error: expected the end of the inscription, found 'y'");
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

/// A net's sets and variables: R = 1..3, Phil = p1..p3 (not cyclic), Ring = a, b, c (cyclic),
/// Pair = (R, Phil), Rec = {id: R, name: string}; x, y: Phil; n, m: R; i: int; s: string;
/// r: Rec; q: Pair; b: bool; z: Ring.
class Checked : public ::testing::Test {
 protected:
  void SetUp() override {
    core::Diagnostics d;
    auto spec = [](std::string name, ColourKind kind) {
      ColourSetSpec s;
      s.name = std::move(name);
      s.kind = kind;
      return s;
    };
    ColourSetSpec r = spec("R", ColourKind::Integer);
    r.range = true;
    r.lo = 1;
    r.hi = 3;
    ColourSetSpec phil = spec("Phil", ColourKind::Enum);
    phil.constants = {"p1", "p2", "p3"};
    ColourSetSpec ring = spec("Ring", ColourKind::Enum);
    ring.constants = {"a", "b", "c"};
    ring.cyclic = true;
    ColourSetSpec pair = spec("Pair", ColourKind::Product);
    pair.components = {"R", "Phil"};
    ColourSetSpec rec = spec("Rec", ColourKind::Record);
    rec.components = {"R", "string"};
    rec.fields = {"id", "name"};
    ColourSetSpec pp = spec("PP", ColourKind::Product);
    pp.components = {"Phil", "Phil"};
    ASSERT_TRUE(colours.declare({r, phil, ring, pair, rec, pp}, d)) << d.str();
    scope.colours = &colours;
    scope.variable_names = {"x", "y", "n", "m", "i", "s", "r", "q", "b", "z"};
    scope.variable_sets = {kPhil, kPhil, kR, kR, Colours::kInt, Colours::kString, kRec, kPair, Colours::kBool, kRing};
  }

  /// `text` checked against `set` as `what`; the diagnostics' text in `errors`.
  std::optional<Expr> check(std::string_view text, ColourId set, Expect what = Expect::Tokens) {
    core::Diagnostics d;
    auto e = parseInscription(text, at(), d);
    EXPECT_TRUE(e.has_value()) << d.str();
    if (!e) return std::nullopt;
    used.clear();
    const bool ok = checkInscription(*e, set, what, scope, used, d);
    errors = d.str();
    if (!ok) return std::nullopt;
    return e;
  }
  /// The first error checking `text` gives.
  std::string checkError(std::string_view text, ColourId set, Expect what = Expect::Tokens) {
    EXPECT_FALSE(check(text, set, what).has_value()) << text;
    return errors.substr(0, errors.find('\n'));
  }
  /// The binding of `used` from values by variable name.
  Binding bind(const std::map<std::string, Value>& values) const {
    Binding b;
    for (const std::uint32_t v : used) {
      const auto it = values.find(scope.variable_names[v]);
      b.push_back(it == values.end() ? Value::dot() : it->second);
    }
    return b;
  }
  std::optional<Value> value(std::string_view text, ColourId set, const std::map<std::string, Value>& values = {}) {
    const auto e = check(text, set, Expect::Single);
    EXPECT_TRUE(e.has_value()) << text << ": " << errors;
    if (!e) return std::nullopt;
    return evaluate(*e, bind(values), colours);
  }
  bool holds(std::string_view text, const std::map<std::string, Value>& values = {}) {
    const auto e = check(text, Colours::kBool, Expect::Condition);
    EXPECT_TRUE(e.has_value()) << text << ": " << errors;
    if (!e) return false;
    const auto v = evaluate(*e, bind(values), colours);
    EXPECT_TRUE(v.has_value()) << text;
    return v && *v == Value::boolean(true);
  }
  /// The multiset `text` denotes in a place of `set`, written out; "none" when it has no value.
  std::string tokens(std::string_view text, ColourId set, const std::map<std::string, Value>& values = {}) {
    const auto e = check(text, set);
    EXPECT_TRUE(e.has_value()) << text << ": " << errors;
    if (!e) return "unchecked";
    Multiset m;
    if (!evaluateInto(*e, bind(values), colours, set, m)) return "none";
    return colours.text(set, m);
  }

  static constexpr ColourId kR = 4, kPhil = 5, kRing = 6, kPair = 7, kRec = 8, kPP = 9;
  Colours colours;
  InscriptionScope scope;
  std::vector<std::uint32_t> used;
  std::string errors;
};

Value I(std::int64_t n) { return Value::integer(n); }

TEST_F(Checked, NamesResolveToVariablesAndConstants) {
  const auto e = check("(n, p2) ++ 2'(m, x)", kPair);
  ASSERT_TRUE(e.has_value()) << errors;
  // n, then m, then x as they are met
  EXPECT_EQ(used, (std::vector<std::uint32_t>{2, 3, 0}));
  const Expr& first = e->args[0];
  EXPECT_EQ(first.args[0].op, Expr::Op::Var);
  EXPECT_EQ(first.args[0].index, 0);
  EXPECT_EQ(first.args[1].op, Expr::Op::Const);
  EXPECT_EQ(first.args[1].value, I(1));
  EXPECT_EQ(first.args[1].type, kPhil);
  EXPECT_EQ(e->args[1].args[1].args[1].index, 2);
  EXPECT_TRUE(e->multiset);
  EXPECT_EQ(e->type, kPair);
  // printed back with the names of the transition's variables and the constants' names
  const std::vector<std::string> names = {"n", "m", "x"};
  EXPECT_EQ(inscriptionText(*e, colours, &names), "(n, p2) ++ 2'(m, x)");
}

TEST_F(Checked, MistakesAreNamedAndLocated) {
  EXPECT_EQ(checkError("3", kPhil), "m.gdpn.yaml:5:10: error: expected Phil, found int");
  EXPECT_EQ(checkError("1'x ++ 1'y2", kPhil), "m.gdpn.yaml:5:19: error: unknown name 'y2'");
  EXPECT_EQ(checkError("all", Colours::kString), "m.gdpn.yaml:5:10: error: 'all' needs a finite colour set: string is "
                                                 "not");
  EXPECT_EQ(checkError("all(Nope)", kPhil), "m.gdpn.yaml:5:10: error: unknown colour set 'Nope'");
  EXPECT_EQ(checkError("all(R)", kPhil), "m.gdpn.yaml:5:10: error: expected Phil, found a multiset of R");
  EXPECT_EQ(checkError("x'y", kPhil), "m.gdpn.yaml:5:10: error: the multiplicity of n'v needs a whole number, found "
                                      "Phil");
  EXPECT_EQ(checkError("(n, x, x)", kPair), "m.gdpn.yaml:5:10: error: expected Pair (2 components), found a tuple of 3");
  EXPECT_EQ(checkError("(n, n)", kPair), "m.gdpn.yaml:5:14: error: expected Phil, found R");
  EXPECT_EQ(checkError("{id = 1}", kRec), "m.gdpn.yaml:5:10: error: record Rec needs its field 'name'");
  EXPECT_EQ(checkError("{id = 1, name = \"a\", age = 3}", kRec), "m.gdpn.yaml:5:37: error: record Rec has no field "
                                                                 "'age'");
  EXPECT_EQ(checkError("r.age", Colours::kInt, Expect::Single), "m.gdpn.yaml:5:10: error: record Rec has no field 'age'");
  EXPECT_EQ(checkError("x.id", Colours::kInt, Expect::Single), "m.gdpn.yaml:5:10: error: '.id' needs a record, found "
                                                              "Phil");
  EXPECT_EQ(checkError("x + 1", kR, Expect::Single), "m.gdpn.yaml:5:10: error: arithmetic needs a whole number, found "
                                                    "Phil");
  EXPECT_EQ(checkError("if b then x else n", kPhil), "m.gdpn.yaml:5:27: error: expected Phil, found R");
  EXPECT_EQ(checkError("if n then x else y", kPhil), "m.gdpn.yaml:5:13: error: expected bool, found R");
  EXPECT_EQ(checkError("x = n", Colours::kBool, Expect::Condition), "m.gdpn.yaml:5:14: error: expected Phil, found R");
  EXPECT_EQ(checkError("b < b", Colours::kBool, Expect::Condition), "m.gdpn.yaml:5:10: error: only numbers, "
                                                                    "enumeration constants and strings are ordered, "
                                                                    "not bool");
  EXPECT_EQ(checkError("succ(s)", Colours::kString, Expect::Single), "m.gdpn.yaml:5:10: error: 'succ' needs an "
                                                                    "enumeration or a number, found string");
  EXPECT_EQ(checkError("1'x", kPhil, Expect::Single), "m.gdpn.yaml:5:10: error: expected a single value of Phil, found "
                                                     "a multiset");
  EXPECT_EQ(checkError("x", Colours::kBool, Expect::Condition), "m.gdpn.yaml:5:10: error: expected bool, found Phil");
  EXPECT_EQ(checkError("1'x = 1'y", Colours::kBool, Expect::Condition), "m.gdpn.yaml:5:10: error: expected a single "
                                                                        "value, found a multiset");
  EXPECT_EQ(checkError("(x, s) = (y, s)", Colours::kBool, Expect::Condition), "m.gdpn.yaml:5:10: error: no colour set "
                                                                              "is a product of (Phil, string)");
  EXPECT_EQ(checkError("1'x ++ (x, y)", kPhil), "m.gdpn.yaml:5:17: error: expected Phil, found a tuple");
}

TEST_F(Checked, ErrorOnASecondLineIsLocatedThere) {
  EXPECT_EQ(checkError("1'(n, x) ++\n  1'(n,\n     w)", kPair), "m.gdpn.yaml:7:6: error: unknown name 'w'");
}

TEST_F(Checked, NumbersFitAnyIntegerSet) {
  ASSERT_TRUE(check("1'(n + 1, x) ++ 1'(2, p1)", kPair).has_value()) << errors;
  ASSERT_TRUE(check("i", kR).has_value()) << errors;
  ASSERT_TRUE(check("n < i + 2", Colours::kBool, Expect::Condition).has_value()) << errors;
  ASSERT_TRUE(check("(x, y) = (p1, p2) and x <> y", Colours::kBool, Expect::Condition).has_value()) << errors;
  ASSERT_TRUE(check("(p1, p2) = q2", Colours::kBool, Expect::Condition).has_value() == false);
  ASSERT_TRUE(check("q = (1, p2)", Colours::kBool, Expect::Condition).has_value()) << errors;
  ASSERT_TRUE(check("(1, p2) = q", Colours::kBool, Expect::Condition).has_value()) << errors;
  ASSERT_TRUE(check("s < \"b\" and x < y and z <= succ(z)", Colours::kBool, Expect::Condition).has_value()) << errors;
}

TEST_F(Checked, ArithmeticAndComparisons) {
  EXPECT_EQ(value("i * 2 + 7 / 2 - 10 % 4", Colours::kInt, {{"i", I(5)}}), I(11));
  EXPECT_EQ(value("-i - -3", Colours::kInt, {{"i", I(5)}}), I(-2));
  EXPECT_EQ(value("-7 / 2", Colours::kInt), I(-3));
  EXPECT_EQ(value("-7 % 2", Colours::kInt), I(-1));
  EXPECT_EQ(value("i / 0", Colours::kInt, {{"i", I(5)}}), std::nullopt);
  EXPECT_EQ(value("i % 0", Colours::kInt, {{"i", I(5)}}), std::nullopt);
  EXPECT_EQ(value("i * i", Colours::kInt, {{"i", I(INT64_MAX)}}), std::nullopt);
  // a number outside its range has no value
  EXPECT_EQ(value("n + 1", kR, {{"n", I(2)}}), I(3));
  EXPECT_EQ(value("n + 1", kR, {{"n", I(3)}}), std::nullopt);
  EXPECT_EQ(value("n + 1", Colours::kInt, {{"n", I(3)}}), I(4));
  EXPECT_TRUE(holds("x < y and not (x = y) and x <> y", {{"x", I(0)}, {"y", I(2)}}));
  EXPECT_FALSE(holds("x >= y", {{"x", I(0)}, {"y", I(2)}}));
  EXPECT_TRUE(holds("s < \"b\" and s >= \"a\"", {{"s", Value::string("a")}}));
  EXPECT_TRUE(holds("n <= 2 or i / 0 = 1", {{"n", I(1)}}));  // the right operand is not needed
  EXPECT_TRUE(holds("(x, y) = (p1, p3)", {{"x", I(0)}, {"y", I(2)}}));
  EXPECT_TRUE(holds("b == true", {{"b", Value::boolean(true)}}));
}

TEST_F(Checked, IfChoosesABranch) {
  EXPECT_EQ(value("if n > 1 then x else p3", kPhil, {{"n", I(2)}, {"x", I(0)}}), I(0));
  EXPECT_EQ(value("if n > 1 then x else p3", kPhil, {{"n", I(1)}, {"x", I(0)}}), I(2));
  EXPECT_EQ(tokens("if b then 2'x else empty", kPhil, {{"b", Value::boolean(true)}, {"x", I(1)}}), "2'p2");
  EXPECT_EQ(tokens("if b then 2'x else empty", kPhil, {{"b", Value::boolean(false)}, {"x", I(1)}}), "empty");
}

TEST_F(Checked, SuccessorAndPredecessor) {
  // not cyclic: no successor of the last, no predecessor of the first
  EXPECT_EQ(value("succ(x)", kPhil, {{"x", I(0)}}), I(1));
  EXPECT_EQ(value("succ(x)", kPhil, {{"x", I(2)}}), std::nullopt);
  EXPECT_EQ(value("pred(x)", kPhil, {{"x", I(0)}}), std::nullopt);
  EXPECT_EQ(value("pred(p3)", kPhil), I(1));
  // cyclic: around
  EXPECT_EQ(value("succ(z)", kRing, {{"z", I(2)}}), I(0));
  EXPECT_EQ(value("pred(z)", kRing, {{"z", I(0)}}), I(2));
  EXPECT_EQ(value("succ(succ(a))", kRing), I(2));
  // an integer range wraps around; the built-in int adds one
  EXPECT_EQ(value("succ(n)", kR, {{"n", I(3)}}), I(1));
  EXPECT_EQ(value("pred(n)", kR, {{"n", I(1)}}), I(3));
  EXPECT_EQ(value("succ(n)", kR, {{"n", I(2)}}), I(3));
  EXPECT_EQ(value("succ(i)", Colours::kInt, {{"i", I(-1)}}), I(0));
  EXPECT_EQ(value("pred(i)", Colours::kInt, {{"i", I(INT64_MIN)}}), std::nullopt);
}

TEST_F(Checked, TuplesRecordsAndFields) {
  const Value rec = Value::tuple({I(2), Value::string("ann")});
  EXPECT_EQ(value("{name = s, id = n}", kRec, {{"s", Value::string("ann")}, {"n", I(2)}}), rec);
  EXPECT_EQ(value("r.id + 1", kR, {{"r", rec}}), I(3));
  EXPECT_EQ(value("r.name", Colours::kString, {{"r", rec}}), Value::string("ann"));
  EXPECT_EQ(value("(r.id, p2)", kPair, {{"r", rec}}), Value::tuple({I(2), I(1)}));
  EXPECT_EQ(tokens("1'q ++ 1'(succ(n), y)", kPair, {{"q", Value::tuple({I(1), I(0)})}, {"n", I(1)}, {"y", I(0)}}),
            "1'(1, p1) ++ 1'(2, p1)");
  EXPECT_EQ(tokens("{id = 1, name = \"x\"}", kRec), "1'{id = 1, name = \"x\"}");
}

TEST_F(Checked, AllAndItsProducts) {
  EXPECT_EQ(tokens("all", kPhil), "1'p1 ++ 1'p2 ++ 1'p3");
  EXPECT_EQ(tokens("2'all(Phil)", kPhil), "2'p1 ++ 2'p2 ++ 2'p3");
  EXPECT_EQ(tokens("(n, all)", kPair, {{"n", I(3)}}), "1'(3, p1) ++ 1'(3, p2) ++ 1'(3, p3)");
  // (all, all) over a set of 3 values: 9 values
  const auto e = check("(all, all)", kPP);
  ASSERT_TRUE(e.has_value()) << errors;
  Multiset m;
  ASSERT_TRUE(evaluateInto(*e, {}, colours, kPP, m));
  EXPECT_EQ(m.size(), 9U);
  EXPECT_EQ(multisetSize(m), 9);
  EXPECT_EQ(m.begin()->first, Value::tuple({I(0), I(0)}));
  EXPECT_EQ(m.rbegin()->first, Value::tuple({I(2), I(2)}));
  // a multiset component's multiplicities multiply
  EXPECT_EQ(tokens("2'(1'x ++ 1'p1, 3'y)", kPP, {{"x", I(0)}, {"y", I(2)}}), "12'(p1, p3)");
  EXPECT_EQ(tokens("(1'x ++ 1'p2, y)", kPP, {{"x", I(0)}, {"y", I(2)}}), "1'(p1, p3) ++ 1'(p2, p3)");
}

TEST_F(Checked, Multiplicities) {
  EXPECT_EQ(tokens("2'x ++ 1'y ++ x", kPhil, {{"x", I(0)}, {"y", I(0)}}), "4'p1");
  EXPECT_EQ(tokens("n'x", kPhil, {{"n", I(3)}, {"x", I(1)}}), "3'p2");
  EXPECT_EQ(tokens("(n - 1)'x", kPhil, {{"n", I(1)}, {"x", I(1)}}), "empty");
  EXPECT_EQ(tokens("(i)'x", kPhil, {{"i", I(-1)}, {"x", I(1)}}), "none");  // a negative multiplicity
  EXPECT_EQ(tokens("2'(1'x ++ 1'y)", kPhil, {{"x", I(1)}, {"y", I(2)}}), "2'p2 ++ 2'p3");
  EXPECT_EQ(tokens("1'x", kPhil, {{"x", I(3)}}), "none");  // not a value of Phil
  EXPECT_EQ(tokens("i", kR, {{"i", I(7)}}), "none");       // outside the place's range
  EXPECT_EQ(tokens("i", kR, {{"i", I(2)}}), "1'2");
  EXPECT_EQ(tokens("dot", Colours::kDot), "1'dot");
  EXPECT_EQ(tokens("3'dot", Colours::kDot), "3'dot");
  EXPECT_EQ(tokens("empty", Colours::kDot), "empty");
  // a single value is one of it
  EXPECT_EQ(tokens("x", kPhil, {{"x", I(2)}}), "1'p3");
}

}  // namespace
}  // namespace gdpn::net
