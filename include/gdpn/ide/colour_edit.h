#pragma once
/// \file
/// Editing value tokens in the IDE (issue 59): the model's colour sets and variables declared,
/// changed and deleted as undoable commands, each definition checked before it is applied; the
/// texts of the inscription language (a place slot's values, an arc's inscription, a
/// transition's condition) checked as they are typed, against the model's sets and variables,
/// with the column of the first mistake; and completion of what may stand at the cursor. No
/// ImGui: the colour sets view and the contents view show it.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gdpn/ide/command.h"
#include "gdpn/ide/script_completion.h"
#include "gdpn/net/colour.h"
#include "gdpn/net/inscription.h"
#include "gdpn/net/spec.h"

namespace gdpn::ide {

/// A mistake in a text being typed: where in the text (both from 1; 0 when it is about the
/// whole text) and what.
struct TextProblem {
  int line = 0;         ///< the text's line
  int column = 0;       ///< the column on that line, bytes
  std::string message;  ///< what is wrong ("expected Phil, found int")
};

/// The model's colour sets and variables, resolved as the compiler resolves them: what texts
/// are checked against. A declaration that does not resolve is left out and named in `error`.
struct ColourScope {
  net::Colours colours;                  ///< the built-ins and the declared sets
  std::vector<std::string> variables;    ///< the variables that resolve, in declaration order
  std::vector<net::ColourId> sets;       ///< and the set of each
  std::string error;                     ///< the declarations' first mistake ("" when none)
  /// The scope the inscription checker takes.
  [[nodiscard]] net::InscriptionScope scope() const { return {&colours, variables, sets}; }
};

/// The scope of the colour sets and variables of `net`.
ColourScope colourScopeOf(const net::NetSpec& net);

/// The declared colour sets and variables checked together, as the compiler would: the first
/// mistake (a clash of names, an unknown set, a variable of an undeclared set, a name used by
/// a set and a variable or a constant), or "".
std::string checkDeclarations(const std::vector<net::ColourSetSpec>& colours, const std::vector<net::VariableSpec>& variables);

/// What of `net` uses colour set `name` (other sets, variables, place slots), each in words
/// ("variable p", "place main/forks a0", "colour set Pair"); empty when nothing does.
std::vector<std::string> usesOfColour(const net::NetSpec& net, const std::string& name);
/// What of `net` names variable `name` in its inscriptions and conditions, in words.
std::vector<std::string> usesOfVariable(const net::NetSpec& net, const std::string& name);

/// The colour sets of `net` with set `index` (its size: a new one, added last) defined as
/// `name` = `definition` (the model file's text: `{range: [1, 5]}`), or nullopt with the
/// mistake in the definition (its column) or the name (column 0): a definition that does not
/// read, a name taken, a component not declared before it, a rename or a change of kind of a set
/// something uses in a way it no longer fits (a rename of a used set is refused: uses are not
/// followed).
std::optional<std::vector<net::ColourSetSpec>> editedColours(const net::NetSpec& net, std::size_t index,
                                                             const std::string& name, std::string_view definition,
                                                             TextProblem& problem);
/// The variables of `net` with variable `index` (its size: a new one) named `name`, of set
/// `set`; nullopt with why: a name that is no identifier or taken, a set not declared, a rename
/// of a variable the inscriptions use.
std::optional<std::vector<net::VariableSpec>> editedVariables(const net::NetSpec& net, std::size_t index,
                                                              const std::string& name, const std::string& set,
                                                              TextProblem& problem);

/// Puts `colours` and `variables` in place of the model's declarations, as one step (checked:
/// refused with the first mistake, as checkDeclarations says).
class SetDeclarationsCommand final : public Command {
 public:
  /// `label`: what the step does ("declare colour set Id").
  SetDeclarationsCommand(std::vector<net::ColourSetSpec> colours, std::vector<net::VariableSpec> variables,
                         std::string label)
      : colours_(std::move(colours)), variables_(std::move(variables)), label_(std::move(label)) {}
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override { return label_; }
  void absorb(const Command&) override {}
  [[nodiscard]] bool changesScene() const override { return false; }

 private:
  std::vector<net::ColourSetSpec> colours_, old_colours_;
  std::vector<net::VariableSpec> variables_, old_variables_;
  std::string label_;
};

/// Where an inscription stands, which says what it must be.
enum class InscriptionRole : std::uint8_t {
  Values,     ///< a value slot's initial values: a multiset of its set, naming no variable
  Arc,        ///< an arc's inscription on a value slot: a multiset of the slot's set
  Condition,  ///< a transition's condition (`when`): a bool
};

/// Inscription `text` checked where it would stand: parsed and typed against the model's sets
/// and variables (`set`: the slot's colour set by name, ignored for a condition). The first
/// mistake with its line and column in the text, or nullopt when it checks.
std::optional<TextProblem> checkInscriptionText(const ColourScope& scope, std::string_view text, const std::string& set,
                                                InscriptionRole role);

/// The names that may complete the word at `cursor` (bytes) in inscription `text`: variables,
/// colour sets, enumeration constants, functions and keywords at the start of a word; after a
/// record's variable and a dot (`j.`), its fields. None inside a string.
CompletionQuery completeInscription(const ColourScope& scope, std::string_view text, std::size_t cursor);

/// `m`, the values of a slot of set `set`, as the language writes them, but at most `most`
/// distinct values: `2'(1,"a") ++ 1'(2,"b")`, and "... and K more values" after the first
/// `most` when there are more; `empty` when none.
std::string valuesText(const net::Colours& colours, net::ColourId set, const net::Multiset& m, std::size_t most);

/// A binding as `p = ph1, n = 3` (the transition's variables and their sets).
std::string bindingText(const net::Colours& colours, const net::TransitionInscriptions& t, const net::Binding& b);

}  // namespace gdpn::ide
