#pragma once
/// \file
/// Breakpoints written as text, in the one syntax that `gdpn run --break`, the IDE's replay
/// (`- break: 'start:T'`) and the Python module (`Model.add_breakpoint('P>=3')`) read:
/// `start:TRANSITION`, `complete:TRANSITION`, `PLACE OP N` (OP one of < <= == != >= >; N a
/// whole number, or a real one such as 2.5 for a continuous place's amount) or `when:PYTHON`.

#include <string_view>

#include "gdpn/core/diagnostics.h"
#include "gdpn/core/result.h"
#include "gdpn/session/session.h"

namespace gdpn::session {

/// What every mistake in a written breakpoint says (the forms it may take).
inline constexpr std::string_view kBreakpointForms =
    "expected start:TRANSITION, complete:TRANSITION, PLACE>=N (or <, <=, ==, !=, >) or when:EXPRESSION";

/// The breakpoint written `text`, or an error located at the character where it goes wrong:
/// `where` is the text's first character (its file, line and column; column 0 counts `text`
/// alone from 1). Names are not looked up here: Session::addBreakpoint refuses one that the
/// net lacks.
[[nodiscard]] core::Result<Breakpoint> parseBreakpoint(std::string_view text, const core::SourceLoc& where = {});

}  // namespace gdpn::session
