#pragma once
/// \file
/// One colour set's definition as a text, as the model file writes it under `colours:`
/// (docs/format.md, *Colour sets*): `int`, `{range: [1, 5]}`, `{cyclic: [ph1, ph2]}`,
/// `{product: [A, B]}`, `{record: {id: Id, name: Name}}`. For an editor of the colour sets
/// (the IDE's) that reads and writes what the file holds.

#include <optional>
#include <string>
#include <string_view>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/colour.h"

namespace gdpn::model {

/// Colour set `name` read from `definition`, the one-line value its key has in the `colours`
/// section. Mistakes go to `diags` located in the definition (file "definition", line 1, the
/// column within the text): a bad name, YAML that does not read, an unknown kind, an empty
/// range or enumeration, a constant twice. Nullopt when there was one. Whether the sets it
/// names exist is the net's question (net::Colours::declare).
std::optional<net::ColourSetSpec> readColourDefinition(const std::string& name, std::string_view definition,
                                                       core::Diagnostics& diags);

/// The definition of `c` as the model file writes it (readColourDefinition reads it back).
std::string colourDefinition(const net::ColourSetSpec& c);

}  // namespace gdpn::model
