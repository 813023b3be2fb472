#pragma once
/// \file
/// Arithmetic over named numbers, as a part's fields write derived values
/// (`translation: [=length/2, 0, 0]`): numbers, names, `+ - * /`, parentheses, unary minus,
/// and the functions `min(a, b)`, `max(a, b)`, `abs(x)`, `sqrt(x)`, `floor(x)`, `ceil(x)`, and in
/// degrees `sind(x)`, `cosd(x)`, `atan2d(y, x)`.

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

}  // namespace gdpn::core
