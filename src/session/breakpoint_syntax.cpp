#include "gdpn/session/breakpoint_syntax.h"

#include <charconv>
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
  // the number: whole, and all that is left
  const std::string_view number = text.substr(end);
  std::int64_t value = 0;
  const auto [ptr, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (ec != std::errc()) return at(end);
  if (ptr != number.data() + number.size()) return at(end + static_cast<std::size_t>(ptr - number.data()));
  return Breakpoint::marking(std::string(text.substr(0, op)), *how, value);
}

}  // namespace gdpn::session
