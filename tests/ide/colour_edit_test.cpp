// Value tokens edited in the IDE's document (issue 59): colour sets and variables declared,
// changed and deleted as undoable steps, each definition checked first; inscriptions checked
// as typed with the column of their mistake; completion in the inscription language; values
// and bindings as text.

#include <gtest/gtest.h>

#include "gdpn/ide/colour_edit.h"
#include "gdpn/ide/document.h"
#include "gdpn/model/colour_text.h"
#include "gdpn/model/model.h"

namespace gdpn::ide {
namespace {

std::unique_ptr<Document> orders() {
  core::Diagnostics diags;
  auto doc = Document::open(GDPN_SOURCE_DIR "/tests/data/colour/orders.gdpn.yaml", diags);
  EXPECT_TRUE(doc) << diags.str();
  return doc;
}

std::vector<std::string> names(const CompletionQuery& q) {
  std::vector<std::string> out;
  for (const auto& c : q.names) out.push_back(c.name);
  return out;
}

TEST(ColourDefinition, ReadsWhatTheModelFileWritesAndLocatesItsMistakeInTheText) {
  core::Diagnostics diags;
  auto c = model::readColourDefinition("Phil", "{cyclic: [ph1, ph2, ph3]}", diags);
  ASSERT_TRUE(c) << diags.str();
  EXPECT_EQ(c->kind, net::ColourKind::Enum);
  EXPECT_TRUE(c->cyclic);
  EXPECT_EQ(model::colourDefinition(*c), "{cyclic: [ph1, ph2, ph3]}");
  c = model::readColourDefinition("Id", "{range: [1, 5]}", diags);
  ASSERT_TRUE(c);
  EXPECT_EQ(model::colourDefinition(*c), "{range: [1, 5]}");
  EXPECT_EQ(model::colourDefinition(*model::readColourDefinition("N", "int", diags)), "int");
  EXPECT_FALSE(diags.hasErrors()) << diags.str();
  // an empty range: said at the range's list, column 9 of the text
  core::Diagnostics bad;
  EXPECT_FALSE(model::readColourDefinition("Id", "{range: [5, 1]}", bad));
  ASSERT_TRUE(bad.hasErrors());
  EXPECT_EQ(bad.all()[0].loc.line, 1);
  EXPECT_EQ(bad.all()[0].loc.column, 9) << bad.str();
  EXPECT_NE(bad.all()[0].message.find("is empty"), std::string::npos) << bad.str();
  core::Diagnostics word;
  EXPECT_FALSE(model::readColourDefinition("X", "intt", word));
  EXPECT_EQ(word.all()[0].loc.column, 1);
  EXPECT_NE(word.all()[0].message.find("unknown colour set kind 'intt'"), std::string::npos) << word.str();
}

TEST(ColourEdit, ANewSetIsDeclaredAsOneStepAndUndoTakesItAway) {
  auto doc = orders();
  const auto& net = doc->model().net;
  TextProblem problem;
  auto colours = editedColours(net, net.colours.size(), "Size", "{enum: [small, large]}", problem);
  ASSERT_TRUE(colours) << problem.message;
  ASSERT_EQ(colours->size(), 4u);
  EXPECT_EQ(doc->execute(std::make_unique<SetDeclarationsCommand>(*colours, net.variables, "declare colour set Size")), "");
  EXPECT_EQ(doc->model().net.colours.back().name, "Size");
  EXPECT_NE(doc->text().find("Size: {enum: [small, large]}"), std::string::npos) << doc->text();
  EXPECT_TRUE(doc->undo());
  EXPECT_EQ(doc->model().net.colours.size(), 3u);
}

TEST(ColourEdit, AMistakeIsRefusedWithWhereItIsAndNothingChanges) {
  auto doc = orders();
  const auto& net = doc->model().net;
  TextProblem problem;
  // the syntax of the definition: its column
  EXPECT_FALSE(editedColours(net, 0, "Id", "{range: [1, x]}", problem));
  EXPECT_EQ(problem.column, 13);
  // a name taken, a component not declared before: the whole row's
  EXPECT_FALSE(editedColours(net, net.colours.size(), "Name", "int", problem));
  EXPECT_NE(problem.message.find("Name"), std::string::npos) << problem.message;
  EXPECT_FALSE(editedColours(net, net.colours.size(), "Pair", "{product: [Id, Missing]}", problem));
  EXPECT_NE(problem.message.find("Missing"), std::string::npos) << problem.message;
  // a rename of a set in use, and a variable's rename or a set that is not there
  EXPECT_FALSE(editedColours(net, 0, "Ident", "{range: [1, 3]}", problem));
  EXPECT_NE(problem.message.find("is used (by colour set Order"), std::string::npos) << problem.message;
  EXPECT_FALSE(editedVariables(net, 0, "m", "Id", problem));
  EXPECT_NE(problem.message.find("variable 'n' is used (by arc main: waiting -> serve"), std::string::npos) << problem.message;
  EXPECT_FALSE(editedVariables(net, net.variables.size(), "k", "Nothing", problem));
  EXPECT_NE(problem.message.find("'Nothing', which is not declared"), std::string::npos) << problem.message;
  EXPECT_FALSE(editedVariables(net, net.variables.size(), "n", "Id", problem));
  EXPECT_NE(problem.message.find("declared twice"), std::string::npos) << problem.message;
  // a change that keeps the name is fine: the range grows
  const auto wider = editedColours(net, 0, "Id", "{range: [1, 9]}", problem);
  ASSERT_TRUE(wider) << problem.message;
  EXPECT_EQ((*wider)[0].hi, 9);
  // what uses a set, a variable
  EXPECT_EQ(usesOfColour(net, "Order"), (std::vector<std::string>{"place main/waiting a0", "place main/done a0"}));
  EXPECT_EQ(usesOfVariable(net, "s"), (std::vector<std::string>{"arc main: waiting -> serve", "arc main: serve -> done"}));
  // the command checks too: a variable of a set that is gone is refused, and nothing changed
  auto without = net.colours;
  without.erase(without.begin());  // Id, which Order and n need
  EXPECT_NE(doc->execute(std::make_unique<SetDeclarationsCommand>(without, net.variables, "x")), "");
  EXPECT_EQ(doc->model().net.colours.size(), 3u);
  EXPECT_FALSE(doc->history().canUndo());
}

TEST(InscriptionCheck, ATypeErrorIsFoundWithItsColumnAndACorrectTextChecks) {
  auto doc = orders();
  const auto scope = colourScopeOf(doc->model().net);
  EXPECT_EQ(scope.error, "");
  EXPECT_FALSE(checkInscriptionText(scope, "(n, s)", "Order", InscriptionRole::Arc));
  // a string where the product wants an Id: at the string's column
  auto p = checkInscriptionText(scope, "(s, s)", "Order", InscriptionRole::Arc);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->line, 1);
  EXPECT_EQ(p->column, 2);
  EXPECT_NE(p->message.find("expected Id"), std::string::npos) << p->message;
  // a syntax error, an unknown name
  p = checkInscriptionText(scope, "(n, s", "Order", InscriptionRole::Arc);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->column, 6) << p->message;
  p = checkInscriptionText(scope, "(n, t)", "Order", InscriptionRole::Arc);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->column, 5);
  // a condition must be a bool; initial values name no variable and must have values
  EXPECT_FALSE(checkInscriptionText(scope, "n < 3 and s <> \"x\"", {}, InscriptionRole::Condition));
  p = checkInscriptionText(scope, "n + 1", {}, InscriptionRole::Condition);
  ASSERT_TRUE(p);
  EXPECT_NE(p->message.find("bool"), std::string::npos) << p->message;
  EXPECT_FALSE(checkInscriptionText(scope, "2'(1, \"a\")", "Order", InscriptionRole::Values));
  p = checkInscriptionText(scope, "(n, \"a\")", "Order", InscriptionRole::Values);
  ASSERT_TRUE(p);
  EXPECT_NE(p->message.find("cannot name variables ('n')"), std::string::npos) << p->message;
  p = checkInscriptionText(scope, "(7, \"a\")", "Order", InscriptionRole::Values);
  ASSERT_TRUE(p);
  EXPECT_NE(p->message.find("no value"), std::string::npos) << p->message;
}

TEST(InscriptionCompletion, OffersVariablesSetsConstantsFieldsAndWordsButNothingInAString) {
  core::Diagnostics diags;
  auto doc = Document::open(GDPN_SOURCE_DIR "/tests/data/colour/philosophers.gdpn.yaml", diags);
  ASSERT_TRUE(doc) << diags.str();
  auto net = doc->model().net;
  net.colours.push_back(*model::readColourDefinition("Job", "{record: {id: Phil, size: int}}", diags));
  net.variables.push_back({"job", "Job", {}});
  const auto scope = colourScopeOf(net);
  ASSERT_EQ(scope.error, "");
  // `p`: the variable; `ph`: the constants and the set; `su`: succ, a function
  EXPECT_EQ(names(completeInscription(scope, "p", 1)), (std::vector<std::string>{"p", "ph1", "ph2", "ph3", "ph4", "ph5", "pred"}));
  const auto ph = completeInscription(scope, "2'Ph", 4);
  EXPECT_EQ(names(ph), (std::vector<std::string>{"Phil"}));
  EXPECT_EQ(ph.start, 2u);
  const auto su = completeInscription(scope, "p ++ su", 7);
  ASSERT_EQ(names(su), (std::vector<std::string>{"succ"}));
  EXPECT_EQ(su.names[0].signature, "(x)");
  // a record variable's fields after its dot
  const auto fields = completeInscription(scope, "job.", 4);
  EXPECT_TRUE(fields.member);
  EXPECT_EQ(names(fields), (std::vector<std::string>{"id", "size"}));
  EXPECT_TRUE(completeInscription(scope, "\"p", 2).names.empty());
}

TEST(ValuesText, WritesAMultisetAsTheLanguageDoesAndShortensALargeOne) {
  auto doc = orders();
  const auto scope = colourScopeOf(doc->model().net);
  const auto order = *scope.colours.find("Order");
  net::Multiset m;
  m[net::Value::tuple({net::Value::integer(1), net::Value::string("a")})] = 2;
  m[net::Value::tuple({net::Value::integer(2), net::Value::string("b")})] = 1;
  EXPECT_EQ(valuesText(scope.colours, order, m, 10), "2'(1, \"a\") ++ 1'(2, \"b\")");
  EXPECT_EQ(valuesText(scope.colours, order, m, 1), "2'(1, \"a\") ... and 1 more value");
  EXPECT_EQ(valuesText(scope.colours, order, {}, 1), "empty");
  net::TransitionInscriptions t;
  t.variables = {"n", "s"};
  t.sets = {*scope.colours.find("Id"), *scope.colours.find("Name")};
  EXPECT_EQ(bindingText(scope.colours, t, {net::Value::integer(2), net::Value::string("b")}), "n = 2, s = \"b\"");
}

}  // namespace
}  // namespace gdpn::ide
