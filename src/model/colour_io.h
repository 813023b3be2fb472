#pragma once
// Internal: no promises. Value tokens in the model file (docs/format.md, "Colour sets"): the
// `colours` and `variables` sections, and the texts of the inscription language that places,
// arcs and transitions hold, each located to the character in the file.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gdpn/net/colour.h"
#include "gdpn/net/spec.h"
#include "yaml_reader.h"

namespace gdpn::model::detail {

/// A file's text with where each of its lines starts: from a byte offset to a line and column
/// and back.
class SourceMap {
 public:
  /// The map of `text`, the file `file` (both must outlive it).
  SourceMap(const std::string& file, std::string_view text);
  /// The file's text.
  [[nodiscard]] std::string_view text() const { return text_; }
  /// The byte offset of 1-based `line` and `column` (clamped to the text).
  [[nodiscard]] std::size_t offset(int line, int column) const;
  /// The location of byte `offset` (the end of the text for one past it).
  [[nodiscard]] core::SourceLoc loc(std::size_t offset) const;

 private:
  const std::string& file_;
  std::string_view text_;
  std::vector<std::size_t> starts_;  // the offset of each line's first byte
};

/// Reads `colours`: a map name -> a word (`bool`, `int`, `string`, `dot`) or a map of one key
/// (`range`, `enum`, `cyclic`, `product`, `record`), in the order written. Mistakes (an unknown
/// kind, an empty or malformed range, an empty enumeration, a constant twice, a name that is no
/// identifier) are reported through `r` where they stand; such a set is left out.
std::vector<net::ColourSetSpec> readColours(const YAML::Node& section, YamlReader& r);

/// Reads `variables`: a map name -> colour set name, in the order written.
std::vector<net::VariableSpec> readVariables(const YAML::Node& section, YamlReader& r);

/// The inscription `node` holds (key `what`, on `slot`), its location the file's place of its
/// first character (`fallback` when the node has none), trailing blanks dropped. Parsed at once:
/// a syntax error is reported through `r` at the character it is about, wherever the text stands
/// (plain, quoted with escapes, in a `|` or `>` block). Nullopt (reported) when it is no text or
/// blank; a text with a syntax error is returned too, so that the loader goes on.
std::optional<net::SlotText> readInscription(const YAML::Node& node, const core::SourceLoc& fallback, net::SlotId slot,
                                             const std::string& what, const SourceMap& source, YamlReader& r);

/// Where the text of scalar `node` begins in the file: past its quote, on the line after its
/// block indicator (`fallback` when the node has no place).
core::SourceLoc textStart(const YAML::Node& node, const core::SourceLoc& fallback, const SourceMap& source,
                          const YamlReader& r);

/// Writes `colours` as readColours reads it (nothing when there are none).
void writeColours(YAML::Emitter& out, const std::vector<net::ColourSetSpec>& colours);
/// Writes `variables` as readVariables reads it (nothing when there are none).
void writeVariables(YAML::Emitter& out, const std::vector<net::VariableSpec>& variables);
/// Writes an inscription's text as a value: a `|` block when it spans lines (and the block gives
/// it back), else double-quoted.
void writeInscription(YAML::Emitter& out, const std::string& text);
/// True when writeInscription writes `text` as a block, which only a block map may hold.
bool inscriptionIsBlock(const std::string& text);

}  // namespace gdpn::model::detail
