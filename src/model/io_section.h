#pragma once
// Internal: no promises. The `io` section of a model file (docs/format.md, "I/O").

#include <functional>
#include <string>

#include "colour_io.h"
#include "gdpn/model/io.h"
#include "yaml_reader.h"

namespace gdpn::model::detail {

/// Reads the `io` section: `lockstep: ADDRESS` and the four tables, each a map of addresses
/// to entries. Every mistake (an unknown key, an address out of range, two entries over one
/// address, a key that does not go with the table, a `value` that is no inscription, a name
/// that is no identifier or that two entries share) is
/// reported through `r` at its place; `source` locates a value's characters.
IoSpec readIo(const YAML::Node& section, YamlReader& r, const SourceMap& source);

/// Whether the entries' names (ioEntryName) are unique; each name two entries share is one
/// `error` at the entry to change (the later in the file, or the one whose name is derived).
bool checkIoNames(const IoSpec& io, const std::function<void(const core::SourceLoc&, std::string)>& error);

/// Writes `io` as the reader reads it (table by table, addresses in order).
void writeIo(YAML::Emitter& out, const IoSpec& io);

}  // namespace gdpn::model::detail
