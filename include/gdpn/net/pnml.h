#pragma once
/// \file
/// PNML place/transition nets (the 2009 `ptnet` grammar) in and out.

#include <optional>
#include <string>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/spec.h"

namespace gdpn::net {

/// The name a place or transition gets from PNML id `id`: the id itself when it is an
/// identifier, else the id with every other character made '_' (and "n" before a leading
/// digit). Where two ids give one name, the later gets '_' appended.
std::string pnmlName(const std::string& id);

/// Reads the PNML text `text` (named `file` in messages) into a NetSpec with one page, "net":
/// places with their initial markings, transitions, arcs with weights (inhibitor and test arcs
/// as tools write them: `type="inhibitor"` or `<type value="inhibitor"/>`), names and
/// graphics positions; nested pages are flattened; `<toolspecific>` is ignored. Mistakes
/// (malformed XML, missing ids, arcs to unknown nodes, coloured nets) are located.
std::optional<NetSpec> parsePnml(const std::string& text, const std::string& file, core::Diagnostics& diags);

/// Reads the PNML file at `path`.
std::optional<NetSpec> loadPnml(const std::string& path, core::Diagnostics& diags);

/// Writes `spec` as a PNML place/transition net. It must be one page without instances whose
/// places and arcs use slot a0 only (a plain P/T net); otherwise nullopt and `why`. Names
/// that came from PNML ids go back to those ids.
std::optional<std::string> writePnml(const NetSpec& spec, std::string& why);

}  // namespace gdpn::net
