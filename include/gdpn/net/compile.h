#pragma once
/// \file
/// compile(): checks a NetSpec against the rules of semantics.md and freezes it into a Net.

#include <memory>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/net.h"
#include "gdpn/net/spec.h"

namespace gdpn::net {

/// Flattens the hierarchy (instances expanded, links resolved, names qualified), propagates
/// slot kinds along arcs, and checks every rule, reporting each problem with its location
/// into `diags`. Returns the frozen net, or nullptr when there was at least one error.
std::shared_ptr<const Net> compile(const NetSpec& spec, core::Diagnostics& diags);

}  // namespace gdpn::net
