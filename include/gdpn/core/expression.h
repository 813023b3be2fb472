#pragma once
/// \file
/// Arithmetic over named numbers, as a part's fields write derived values
/// (`translation: [=length/2, 0, 0]`): numbers, names, `+ - * /`, parentheses, unary minus,
/// and the functions `min(a, b)`, `max(a, b)`, `abs(x)`, `sqrt(x)`, `floor(x)`, `ceil(x)`, and in
/// degrees `sind(x)`, `cosd(x)`, `atan2d(y, x)`, and `exp(x)`. Evaluated at once (`evaluate`), or
/// compiled once into a Program that runs many times over changing names (a flow's rate).

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gdpn::core {

/// Why an expression could not be evaluated, and where.
struct ExpressionError {
  std::size_t column = 0;  ///< 0-based offset into the expression's text
  std::string message;     ///< what is wrong ("no parameter 'lenght' (did you mean 'length'?)")
};

/// Looks up a name: its value, or nullopt when there is none.
using NameLookup = std::function<std::optional<double>(std::string_view)>;

/// The value of `text`, names read through `lookup`; nullopt with `error` when the text is not
/// an expression, names what `lookup` does not know (`names` are offered in a "did you mean"),
/// divides by zero, or gives something not finite.
std::optional<double> evaluate(std::string_view text, const NameLookup& lookup, ExpressionError& error,
                               const std::vector<std::string>& names = {});

/// The names `text` refers to, in order of first use (functions excluded); empty when it does
/// not parse.
std::vector<std::string> expressionNames(std::string_view text);

/// An expression compiled for a stack machine: its names are numbered slots of an array of
/// values given at each run. A division by zero gives an infinity and sqrt() of a negative
/// number 0: what uses the result decides (a flow's rate counts a value not finite as 0).
struct Program {
  /// An operation of the machine.
  enum class Op : std::uint8_t { Const, Load, Add, Sub, Mul, Div, Neg, Call };
  /// One step: push `value` (Const), push values[`arg`] (Load), or apply function `arg` (Call).
  struct Step {
    Op op;
    std::uint32_t arg;
    double value;
  };
  /// The deepest the stack may get.
  static constexpr std::size_t kMostDepth = 64;
  std::vector<Step> ops;            ///< in the order they run
  std::vector<std::uint32_t> reads; ///< the slots it loads, ascending, once each
  std::size_t depth = 0;            ///< the deepest its stack gets
  /// Its value over `values` (indexed by the slots its names resolved to).
  [[nodiscard]] double run(const double* values) const;
};

/// `text` compiled: each name is numbered by `resolve` (nullopt: an error at the name, offering
/// `names` in a "did you mean"). Nullopt with `error` when it does not parse, names what
/// `resolve` does not know, or nests deeper than Program::kMostDepth.
std::optional<Program> compileExpression(std::string_view text,
                                         const std::function<std::optional<std::uint32_t>(std::string_view)>& resolve,
                                         ExpressionError& error, const std::vector<std::string>& names = {});

}  // namespace gdpn::core
