#pragma once
/// \file
/// PNML place/transition nets (the 2009 `ptnet` grammar) in and out.

#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/spec.h"

namespace gdpn::net {

/// The name a place or transition gets from PNML id `id`: the id itself when it is an
/// identifier, else the id with every other character made '_' (and "n" before a leading
/// digit). Where two ids give one name, the later gets '_' appended.
std::string pnmlName(const std::string& id);

/// Reads the PNML text `text` (named `file` in messages) into a NetSpec: places with their
/// initial markings, transitions, arcs with weights (inhibitor and test arcs as tools write
/// them: `type="inhibitor"` or `<type value="inhibitor"/>`), names and graphics positions,
/// and what gdpn's tool-specific part keeps (durations, priorities, scripts, slots ...; other
/// tools' parts are ignored). Pages are pages: a net of one page is the page `net`, else each
/// top-level page is a page and a page inside another a page type instantiated once there.
/// `referencePlace` and `referenceTransition` stand for the node they refer to (through
/// chains of references); an arc that would join a transition to a place of a page other than
/// its own or one directly inside it makes the two pages one, with a warning. Mistakes
/// (malformed XML, missing ids, arcs to unknown nodes, cycles of references, coloured nets)
/// are located. `net_name`, when given, receives the net's `<name>` (else its id).
std::optional<NetSpec> parsePnml(const std::string& text, const std::string& file, core::Diagnostics& diags,
                                 std::string* net_name = nullptr);

/// Reads the PNML file at `path` (as parsePnml).
std::optional<NetSpec> loadPnml(const std::string& path, core::Diagnostics& diags, std::string* net_name = nullptr);

/// What a PNML file keeps only in gdpn's tool-specific part, which other tools do not read:
/// one kind of construct and how many of it the net has.
struct PnmlUnseen {
  std::string what;        ///< the kind, in the number of `count` ("transition durations", "guard")
  std::size_t count = 0;   ///< how many
};

/// Writes `spec` as a PNML place/transition net named `name` (its `<name>`; none when empty):
/// each page a `<page>`, a page type instantiated once a page inside the page of its
/// instance, a link an arc to a `referencePlace`. What a P/T net lacks (durations,
/// priorities, probabilities, servers, scripts, capacities, slots, node tokens, sensors, page
/// descriptions ...) goes into gdpn's `<toolspecific>` parts, and `unseen`, when given,
/// receives each such kind with its count. Values taken from model parameters are written
/// as their values. A page type instantiated other than once cannot be written: nullopt and
/// `why`, and so can a hybrid net (continuous places or transitions). Names that came from
/// PNML ids go back to those ids.
std::optional<std::string> writePnml(const NetSpec& spec, std::string& why, const std::string& name = {},
                                     std::vector<PnmlUnseen>* unseen = nullptr);

}  // namespace gdpn::net
