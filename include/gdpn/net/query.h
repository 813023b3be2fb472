#pragma once
// Questions about a net's reachable markings: CTL and LTL formulas in a text form for people,
// parsed against the net's own place and transition names, and the answers to them.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/analysis.h"
#include "gdpn/net/name_expansion.h"
#include "gdpn/net/net.h"

namespace gdpn::net {

/// The largest magnitude a sum's constant may have (2^60), so that a sum, and the difference
/// of two, never overflows 64 bits. The parsers refuse larger constants.
constexpr std::int64_t kMostConstant = std::int64_t{1} << 60;

/// The integer side of a comparison: the tokens on some place slots, summed, plus a constant.
struct TokenSum {
  std::vector<PlaceSlotId> slots;  ///< their tokens are added (a slot named twice counts twice)
  std::int64_t constant = 0;       ///< added to them; at most kMostConstant in magnitude
};

/// What a formula node is. State formulas: the atoms and the boolean operators. Path
/// formulas: Next, Future, Globally and Until, each under a path quantifier (All, Exists):
/// `EF p` is Exists(Future(p)), and an LTL formula `A (G F p)` is All(Globally(Future(p))).
enum class FormulaKind : std::uint8_t {
  True,
  False,
  Deadlock,  ///< no transition is enabled
  Fireable,  ///< one of `transitions` is enabled
  Compare,   ///< left `compare` right
  Not,
  And,
  Or,
  All,       ///< on every path from here
  Exists,    ///< on some path from here
  Next,
  Future,
  Globally,
  Until,     ///< operands: what holds until, and what then holds
  Bound,     ///< a number, a query of its own: the most tokens `left` ever counts
};

/// How a comparison compares.
enum class Comparison : std::uint8_t { Less, LessEqual, Equal, NotEqual, GreaterEqual, Greater };

/// The comparison that holds exactly where `c` fails (`<` for `>=`, `!=` for `=`).
inline Comparison negated(Comparison c) {
  constexpr Comparison opposite[] = {Comparison::GreaterEqual, Comparison::Greater, Comparison::NotEqual,
                                     Comparison::Equal,        Comparison::Less,    Comparison::LessEqual};
  return opposite[static_cast<int>(c)];
}

/// A formula: a tree of nodes.
struct Formula {
  FormulaKind kind = FormulaKind::True;
  Comparison compare = Comparison::Equal;  ///< Compare
  TokenSum left, right;                    ///< Compare; Bound: left
  std::vector<TransitionId> transitions;   ///< Fireable
  std::vector<Formula> operands;           ///< And, Or: two or more; Until: two; the others with operands: one
  std::size_t column = 1;                  ///< where the node starts in the text, counted from 1
};

/// A mistake in a query's text, and where it lies.
struct QueryError {
  std::size_t column = 1;  ///< counted from 1
  std::string message;
};

/// Reads a formula in the text form (docs/queries.md):
/// `EF (buffer >= 3 and fireable(consume))`, `AG not deadlock`, `A (G F fireable(t1))`,
/// `E [ idle = 1 U busy + done > 2 ]`, `bound(buffer + done)`. Places and transitions are named as in the net
/// (quoted with "..." where a name is a keyword or holds other characters); a place stands for
/// the tokens on all its slots. Formulas nest at most 100 levels deep. Nullopt on a mistake,
/// described in `error`. Names that `names` (when given) expands stand for what it lists.
std::optional<Formula> parseQuery(const Net& net, std::string_view text, QueryError& error,
                                  const NameExpansion* names = nullptr);

/// The place called `name`, or else the one place whose name ends in "/" + `name` (a name
/// given without its page's path, or a PNML id); none when none or several.
std::optional<PlaceId> findPlaceNamed(const Net& net, std::string_view name);
/// The same for transitions.
std::optional<TransitionId> findTransitionNamed(const Net& net, std::string_view name);

/// The places `name` stands for: where `names` (when given) expands it (its key called `name`,
/// or else the one key ending in "/" + `name`), those of the listed places the net has (none
/// may be all of them); else the one place findPlaceNamed finds. Nullopt when neither.
std::optional<std::vector<PlaceId>> findPlacesNamed(const Net& net, std::string_view name, const NameExpansion* names);
/// The same for transitions.
std::optional<std::vector<TransitionId>> findTransitionsNamed(const Net& net, std::string_view name,
                                                              const NameExpansion* names);

/// One property of a Model Checking Contest property file.
struct Property {
  std::string id;   ///< the contest's id of the formula
  Formula formula;
};

/// Reads a property file of the Model Checking Contest (its XML property language: CTL, LTL,
/// reachability formulas and place bounds over the PNML ids of the net's places and
/// transitions). Mistakes go to `diags` located at their element (file:line:col); nullopt
/// when there was one. Ids that `names` (when given) expands (a coloured net's, unfolded) stand
/// for what it lists.
std::optional<std::vector<Property>> readMccProperties(const Net& net, const std::string& text,
                                                       const std::string& file, core::Diagnostics& diags,
                                                       const NameExpansion* names = nullptr);

/// The formula in the text form, names as in the net; where `names` is given, the places (or
/// transitions) that one of its names stands for, all of them together in a sum (a fireable),
/// are written as that name.
std::string formulaText(const Net& net, const Formula& f, const NameExpansion* names = nullptr);

/// True when no path quantifier or path operator lies inside `f`.
bool isStateFormula(const Formula& f);

/// How a question was answered.
enum class Verdict : std::uint8_t { True, False, Unknown, Value /* a number: QueryAnswer::value */ };

/// The answer to one formula.
struct QueryAnswer {
  Verdict verdict = Verdict::Unknown;
  /// Why Unknown: a limit cut the search short (stop), or the formula is of a kind not
  /// answered yet (`unsupported` says which).
  ExploreStop stop = ExploreStop::Done;
  std::string unsupported;
  /// A shortest firing sequence from the initial marking to a marking that shows the answer
  /// (EF p: one where p holds; AG p: one where p fails), and that marking, per place slot
  /// (has_marking). None where the answer rests on every reachable marking.
  std::vector<TransitionId> path;
  std::vector<std::int64_t> marking;
  bool has_marking = false;
  /// An LTL answer shown by an infinite path (for A, one breaking the formula; for E, one
  /// keeping it): `path` leads to `marking`, from which `cycle` fires forever (empty: the
  /// marking is dead and the path stays in it).
  bool lasso = false;
  std::vector<TransitionId> cycle;
  std::int64_t value = 0;    ///< Value: the bound asked for
  std::uint64_t states = 0;  ///< markings explored to answer
  std::string technique;     ///< in the contest's words: EXPLICIT, INITIAL_STATE, ...
};

/// Answers `f` on the reachable markings of `net`, under `limits` (max_states, max_bytes,
/// deadline, reduction): answerQueries of `f` alone.
QueryAnswer answerQuery(const Net& net, const Formula& f, const ExploreOptions& limits = {});

/// Answers several formulas (docs/queries.md, "What is answered" and "Beyond the state
/// space"). A state formula: at the initial marking. With limits.reduction, each formula is
/// first simplified (the state equation's bounds and refutations, CTL identities) and then
/// answered without the whole graph under a share of the limits (at most 2^20 markings and,
/// under a deadline, half its share of the time left): EF or AG of a state formula by the
/// state equation or a search over stubborn sets that stops at the first marking deciding it
/// (breadth first, then guided), with its path; a bound by the state equation met by a guided
/// search; other CTL by local searches (paths are maximal: a dead marking ends them); LTL by a
/// Büchi automaton's product made on the fly (with ample sets where there is no X). Those
/// left, and all of them without the reduction, are answered on the reachability graph,
/// stored once (12 bytes per edge) where it fits; those left again on the fly with what
/// remains of the limits. Each answer names its technique; one left open says why.
std::vector<QueryAnswer> answerQueries(const Net& net, const std::vector<Formula>& formulas,
                                       const ExploreOptions& limits = {});

/// True when `f` (a state formula) holds in `marking` (per place slot).
bool holdsIn(const Net& net, const Formula& f, const std::vector<std::int64_t>& marking);

}  // namespace gdpn::net
