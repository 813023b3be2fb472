#pragma once
// Internal: no promises. What gdpn's PNML reader and writer agree on: the name and version of
// gdpn's tool-specific part (`<toolspecific tool="gdpn" version="1">`, where a P/T net keeps
// what gdpn's net has beyond places, transitions and weighted arcs) and the note that keeps a
// renamed construct's PNML id.

#include <string>
#include <string_view>

namespace gdpn::net::detail {

/// The `tool` attribute of gdpn's tool-specific parts.
inline constexpr std::string_view kPnmlTool = "gdpn";
/// The `version` attribute gdpn writes and reads.
inline constexpr std::string_view kPnmlToolVersion = "1";

/// How the description of a construct renamed on reading keeps its PNML id: "PNML id X".
inline constexpr std::string_view kIdNote = "PNML id ";

/// True when `description` is such a note rather than a label.
inline bool isIdNote(std::string_view description) { return description.starts_with(kIdNote); }

/// The durations' laws by name, as the tool-specific part writes them (indexed by
/// DurationLaw::Law).
inline constexpr std::string_view kLawNames[] = {"fixed", "uniform", "normal", "exponential", "immediate"};

}  // namespace gdpn::net::detail
