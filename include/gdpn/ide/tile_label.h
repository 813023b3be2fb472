#pragma once
/// \file
/// The name under a tile of the parts palette: broken into lines that each fit the tile, at
/// spaces where it can, inside a word (with a hyphen) where a word alone is too wide; at most
/// so many lines, the last one ending in ".." when the name goes on.

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace gdpn::ide {

/// `name` as lines no wider than `width` (in the units of `measure`, which gives a text's
/// width; pixels in the palette), `max_lines` of them at most (at least one). Every character
/// of the name is on a line unless the lines ran out, spaces where it breaks aside; a line that
/// would not hold even one character holds one. A UTF-8 character is never split.
std::vector<std::string> tileLabel(std::string_view name, float width,
                                   const std::function<float(std::string_view)>& measure, std::size_t max_lines = 2);

}  // namespace gdpn::ide
