#pragma once
/// \file
/// A whole page as a picture file: SVG or PNG by the file's extension, written atomically.

#include <string>
#include <utility>

#include "gdpn/diagram/layout.h"
#include "gdpn/diagram/net_state.h"

namespace gdpn::diagram {

/// The size in pixels that shows all of `layout` at a comfortable zoom (1.5 pixels per
/// layout unit), kept within 320 x 200 and 2400 x 1600 (the zoom shrinks to fit).
[[nodiscard]] std::pair<int, int> naturalSize(const NetLayout& layout);

/// Draws all of `layout` with `state` (may be null), fitted into `width` x `height` pixels,
/// to `path`: SVG when it ends in ".svg", PNG when it ends in ".png". Written beside the old
/// file, then renamed over it. False with `why` on failure (another extension, a size out of
/// range, no font, a file that cannot be written).
[[nodiscard]] bool writeNetPicture(const NetLayout& layout, const NetState* state, int width, int height,
                                   const std::string& path, std::string& why);

}  // namespace gdpn::diagram
