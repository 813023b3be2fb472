#pragma once
// Internal: no promises. A saved model keeps the layout of the file it was read from.

#include <optional>
#include <string>

namespace gdpn::model::detail {

/// The text `after` (the canonical text of an edited model) laid over `original` (the file the
/// model was read from, whose own canonical text is `before`). Every map entry and list item
/// whose canonical text the edit did not change keeps its bytes in `original` (its comments,
/// key order, layout and style); a changed one is written canonically where it stood, at its
/// indentation, keeping the comment lines above it (and a trailing comment when it stays on one
/// line); a new one follows its canonical predecessor; a removed one goes with the comment lines
/// just above it. Keys the original writes and the canonical text leaves out (defaults) stay.
/// Nullopt when the trees cannot be matched (a flow collection edited inside is rewritten
/// whole, but an edit the layout cannot take, such as a reordering, gives up). Whether the
/// result reads back as `after` is the caller's to check.
std::optional<std::string> keepLayout(const std::string& original, const std::string& before, const std::string& after);

}  // namespace gdpn::model::detail
