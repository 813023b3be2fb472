#include "gdpn/session/breakpoint_syntax.h"

#include <charconv>
#include <cmath>
#include <string>

namespace gdpn::session {

core::Result<Breakpoint> parseBreakpoint(std::string_view text, const core::SourceLoc& where) {
  // an error at `offset` characters into the text
  const auto at = [&](std::size_t offset) {
    core::SourceLoc loc = where;
    loc.column = (where.column > 0 ? where.column : 1) + static_cast<int>(offset);
    return core::Result<Breakpoint>::failure(std::move(loc), std::string(kBreakpointForms));
  };
  // the named forms: the rest of the text is the transition or the expression
  if (text.starts_with("start:")) return Breakpoint::starts(std::string(text.substr(6)));
  if (text.starts_with("complete:")) return Breakpoint::completes(std::string(text.substr(9)));
  if (text.starts_with("when:")) return Breakpoint::predicate(std::string(text.substr(5)));
  // PLACE OP N: the operator is the first run of <, =, !, >
  const auto op = text.find_first_of("<=!>");
  if (op == std::string_view::npos) return at(text.size());
  const auto end = text.find_first_not_of("<=!>", op);
  const auto how = parseCompare(text.substr(op, end == std::string_view::npos ? std::string_view::npos : end - op));
  if (!how) return at(op);
  if (end == std::string_view::npos) return at(text.size());
  // the number, all that is left: whole (tokens, or an amount), else real (an amount: 2.5, 1e-3)
  const std::string_view number = text.substr(end);
  const char* last = number.data() + number.size();
  std::int64_t value = 0;
  const auto [whole_end, whole_ec] = std::from_chars(number.data(), last, value);
  if (whole_ec == std::errc() && whole_end == last) {
    return Breakpoint::marking(std::string(text.substr(0, op)), *how, value);
  }
  // a real number is written with a fraction or an exponent (digits alone stay whole: a count
  // out of range is a mistake, not a real number)
  if (number.find_first_of(".eE") == std::string_view::npos) {
    if (whole_ec != std::errc()) return at(end);
    return at(end + static_cast<std::size_t>(whole_end - number.data()));
  }
  double real = 0.0;
  const auto [ptr, ec] = std::from_chars(number.data(), last, real, std::chars_format::general);
  if (ec != std::errc() || !std::isfinite(real)) return at(end);
  if (ptr != last) return at(end + static_cast<std::size_t>(ptr - number.data()));
  return Breakpoint::level(std::string(text.substr(0, op)), *how, real);
}

}  // namespace gdpn::session
