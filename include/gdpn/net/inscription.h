#pragma once
/// \file
/// The inscription language (semantics: *Value tokens*; docs/format.md, *Inscriptions*): arc
/// expressions, initial markings and transition conditions over typed variables. Parsed and
/// type-checked at load with located errors, evaluated by the kernel and the unfolder. Not
/// Python, so that the analysis can read it.
///
/// Grammar, loosest first (`'` binds tighter than every binary operator):
///
///     expr    := 'if' expr 'then' expr 'else' expr | sum
///     sum     := or ('++' or)*                     multiset sum
///     or      := and ('or' and)*
///     and     := not ('and' not)*
///     not     := 'not' not | cmp
///     cmp     := add (('=' | '==' | '<>' | '!=' | '<' | '<=' | '>' | '>=') add)?
///     add     := mul (('+' | '-') mul)*
///     mul     := unary (('*' | '/' | '%') unary)*
///     unary   := '-' unary | times
///     times   := postfix ("'" postfix)?            n'v: n copies of v (n a whole number >= 0)
///     postfix := primary ('.' field)*
///     primary := NUMBER | STRING | 'true' | 'false' | 'dot' | 'empty' | 'all' | 'all' '(' SET ')'
///              | NAME | ('succ' | 'pred') '(' expr ')' | '(' expr (',' expr)* ')'
///              | '{' field '=' expr (',' field '=' expr)* '}'
///
/// A NAME is a variable or an enumeration's constant. A tuple one of whose components is a
/// multiset (`(x, all)`) is the multiset of every combination.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/colour.h"
#include "gdpn/net/spec.h"

namespace gdpn::net {

/// The most values `all` may stand for, and the most bindings of the variables no input arc
/// binds that the search enumerates per transition: beyond it, a net is refused at load.
inline constexpr std::int64_t kMostValues = 1'000'000;

/// One node of an inscription.
struct Expr {
  /// What the node is.
  enum class Op : std::uint8_t {
    Const,   ///< `value` (numbers, strings, true/false, dot, an enum constant once resolved)
    Name,    ///< `name`, not yet resolved (a variable or an enum constant): parse's output
    Var,     ///< variable `index` (of the transition's variables, after check())
    Tuple,   ///< (args...)
    Record,  ///< {fields[i] = args[i]}
    Field,   ///< args[0].name
    Neg, Not,
    Add, Sub, Mul, Div, Mod,
    Eq, Ne, Lt, Le, Gt, Ge,
    And, Or,
    If,      ///< if args[0] then args[1] else args[2]
    Succ, Pred,
    Times,   ///< args[0]'args[1]
    Sum,     ///< args[0] ++ args[1]
    All,     ///< every value of a finite set once (`name`: the set written, "" when taken from context)
    Empty,   ///< the empty multiset
  };
  Op op = Op::Const;
  Value value;                       ///< Const
  std::string name;                  ///< Name, Field (the field), All (the set, or "")
  std::vector<std::string> fields;   ///< Record: field names, in the order written
  std::vector<Expr> args;            ///< operands
  SourceLoc loc;                     ///< where the node starts in the file
  std::int32_t index = -1;           ///< Var: the variable; Field: the field's index (after check())
  ColourId type = Colours::kDot;     ///< after check(): the set of the value (of each element, for a multiset)
  bool multiset = false;             ///< after check(): a multiset rather than one value
};

/// Parses inscription `text`, whose first character stands at `at` in its file (lines of the
/// text advance `at.line`; the first line's columns count from `at.col`). Syntax errors go to
/// `diags` at their line and column; nullopt when there was one.
std::optional<Expr> parseInscription(std::string_view text, const SourceLoc& at, core::Diagnostics& diags);

/// Parses the text of `text` with every location (a syntax error's, each node's) where it
/// stands in its file (SlotText::where).
std::optional<Expr> parseInscription(const SlotText& text, core::Diagnostics& diags);

/// `e` written back in the language (fully parenthesised only where needed); a Var is written
/// as `names[index]` when `names` is given.
std::string inscriptionText(const Expr& e, const Colours& colours, const std::vector<std::string>* names = nullptr);

/// What the checker resolves names against: the colour sets and the variables in scope.
struct InscriptionScope {
  const Colours* colours = nullptr;        ///< the sets, with their enum constants
  std::vector<std::string> variable_names; ///< every declared variable
  std::vector<ColourId> variable_sets;     ///< and its set
};

/// What an expression must be.
enum class Expect : std::uint8_t {
  Tokens,    ///< an arc inscription or initial marking: a multiset (a single value is one of it)
  Single,    ///< a single value of the set
  Condition, ///< a transition's condition: a bool (the set is ignored)
};

/// Resolves names and types `e` in place: a Name becomes a Var (its `index` the position in
/// `used`, appended when new; `used` holds indices into scope.variable_names) or a Const; every
/// node gets its type. `set` is what the whole must hold (a place slot's set; ignored for a
/// Condition). Mistakes go to `diags` at the node: an unknown name, a type mismatch (`expected
/// P, found int`), `all` of a set that is not finite, a field a record lacks. False when there
/// was one.
bool checkInscription(Expr& e, ColourId set, Expect what, const InscriptionScope& scope, std::vector<std::uint32_t>& used,
                      core::Diagnostics& diags);

/// A binding: the value of each of a transition's variables (by the index a Var holds).
using Binding = std::vector<Value>;

/// Evaluates single-valued `e` under `b`: nullopt where it has no value (a division by zero,
/// the successor of the last constant of an enumeration that is not cyclic, a number outside
/// the range its set allows).
std::optional<Value> evaluate(const Expr& e, const Binding& b, const Colours& colours);
/// Adds `times` x the multiset `e` denotes under `b` to `out` (a single value counts once).
/// False where it has no value (as evaluate; also a negative multiplicity, or a value outside
/// `set`, the set its place holds).
bool evaluateInto(const Expr& e, const Binding& b, const Colours& colours, ColourId set, Multiset& out,
                  std::int64_t times = 1);

/// How an arc of a coloured transition acts on its place slot.
enum class ArcRole : std::uint8_t {
  Take,     ///< a normal input arc: needs the multiset and takes it
  Test,     ///< a test arc: needs it, takes nothing
  Inhibit,  ///< an inhibitor arc: allows only while the place does not hold all of it (semantics)
  Put,      ///< an output arc: deposits it
};

/// One arc of a coloured transition, as the binding search reads it.
struct ArcInscription {
  ArcRole role = ArcRole::Take;  ///< how it acts
  ColourId set = Colours::kDot;  ///< what its place slot holds
  Expr expr;                     ///< checked, a multiset of `set`
};

/// What the binding search needs of one transition: its variables and their sets, its
/// condition, and its arcs.
struct TransitionInscriptions {
  std::vector<std::string> variables;   ///< names, in the binding's order
  std::vector<ColourId> sets;           ///< the set of each variable
  std::optional<Expr> when;             ///< the condition, checked
  std::vector<ArcInscription> arcs;     ///< in the transition's term order
};

/// One enabled binding and what it does: per arc (same index), the multiset it takes, needs,
/// inhibits with or puts.
struct BoundOccurrence {
  Binding binding;             ///< the variables' values
  std::vector<Multiset> arcs;  ///< per arc of the transition
};

/// The multiset place slot of arc `arc` holds now.
using ArcMarking = std::function<const Multiset&(std::size_t arc)>;
/// Whether arc `arc` (a Put) finds room for `tokens` more tokens.
using ArcRoom = std::function<bool(std::size_t arc, std::int64_t tokens)>;

/// Whether an enabled binding found by the search is also acceptable to its caller (the
/// kernel's room on outputs that other arcs share): false drops it as if it were not enabled.
using BindingFilter = std::function<bool(const BoundOccurrence&)>;

/// The binding search of one transition, planned once (semantics: *Value tokens*): the order in
/// which normal and test input arcs' patterns are matched against their places, the variables a
/// conjunct `x = e` of the condition fixes once e's variables are bound (x is then not
/// enumerated, whatever its set), what finite sets leave free, and the conjuncts checked as soon
/// as their variables are bound. When the plan binds the variables in their order it finds the
/// bindings in the canonical order and stops at the `most`-th; otherwise it finds them all and
/// sorts them. Holds references to `t` and `colours`, which must outlive it.
class BindingSearch {
 public:
  /// Plans the search for `t` over `colours`.
  BindingSearch(const TransitionInscriptions& t, const Colours& colours);
  ~BindingSearch();
  BindingSearch(BindingSearch&&) noexcept;
  BindingSearch& operator=(BindingSearch&&) = delete;
  BindingSearch(const BindingSearch&) = delete;
  BindingSearch& operator=(const BindingSearch&) = delete;

  /// As enabledBindings(), keeping only those `accept` (when given) accepts: the first `most`
  /// in the canonical order.
  [[nodiscard]] std::vector<BoundOccurrence> enabled(const ArcMarking& marking, const ArcRoom& room = {},
                                                     std::size_t most = SIZE_MAX, const BindingFilter& accept = {}) const;
  /// True when the plan finds the bindings in the canonical order (it can stop at the first).
  [[nodiscard]] bool ordered() const;
  /// Why the plan cannot search (as unboundVariable()); empty when it can.
  [[nodiscard]] const std::string& refusal() const;

 private:
  struct Plan;
  std::unique_ptr<Plan> plan_;
};

/// The enabled bindings of `t` under `marking`, in the canonical order (variables in their
/// order, values in their set's order), at most `most` of them: found by matching the patterns
/// of normal and test input arcs (a variable, a constant or a tuple of them, with a constant
/// multiplicity) against the values their places hold, by fixing a variable that a conjunct
/// `x = e` of the condition gives once e's variables are bound, then by enumerating what finite
/// sets leave free; each kept when the condition holds, every Take and Test arc's multiset is in
/// its place (each arc's on its own: a place has one normal arc to a transition at most), no
/// Inhibit arc's multiset is (an empty one never inhibits), every value is of its set, and
/// `room` (when given) allows every Put.
std::vector<BoundOccurrence> enabledBindings(const TransitionInscriptions& t, const Colours& colours,
                                             const ArcMarking& marking, const ArcRoom& room = {},
                                             std::size_t most = SIZE_MAX);

/// Every binding of `t` whatever the marking (its variables over their finite sets) whose
/// condition holds and whose arcs all have values: what unfolding needs. Nullopt when a
/// variable's set is not finite or there would be more than `most`, with `why`.
std::optional<std::vector<BoundOccurrence>> allBindings(const TransitionInscriptions& t, const Colours& colours,
                                                        std::size_t most, std::string& why);

/// Why the variables of `t` that matching and the condition's equations leave free cannot be
/// enumerated: one is not of a finite set ("variable 'x' (string) is bound by no input arc
/// ..."), or their combinations number more than kMostValues. Empty when every variable is
/// matched by a normal or test input arc's pattern, fixed by a conjunct `x = e` of the
/// condition, or free and enumerable.
std::string unboundVariable(const TransitionInscriptions& t, const Colours& colours);

}  // namespace gdpn::net
