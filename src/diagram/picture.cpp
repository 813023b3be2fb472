#include "gdpn/diagram/picture.h"

#include <algorithm>
#include <cmath>

#include "gdpn/core/output_file.h"
#include "gdpn/diagram/painter.h"
#include "gdpn/diagram/raster_canvas.h"
#include "gdpn/diagram/svg_canvas.h"

namespace gdpn::diagram {
namespace {

constexpr double kNaturalZoom = 1.5;  // pixels per layout unit
constexpr double kMaxZoom = 3.0;      // a picture larger than the page needs: drawn larger, up to this
constexpr double kMargin = 16.0;      // pixels

}  // namespace

std::pair<int, int> naturalSize(const NetLayout& layout) {
  const Box b = drawnBounds(layout);
  const auto side = [](double extent, int low, int high) {
    return std::clamp(static_cast<int>(std::ceil(extent * kNaturalZoom + 2 * kMargin)), low, high);
  };
  return {side(b.width(), 320, 2400), side(b.height(), 200, 1600)};
}

bool writeNetPicture(const NetLayout& layout, const NetState* state, int width, int height, const std::string& path,
                     std::string& why) {
  const SpatialIndex index(layout);
  const Viewport view = fitViewport(layout, width, height, kMargin, kMaxZoom);
  if (path.ends_with(".svg")) {
    SvgCanvas svg(width, height);
    paintNet(layout, index, state, view, svg);
    return core::writeOutput(path, svg.svg(), why);
  }
  if (path.ends_with(".png")) {
    auto raster = RasterCanvas::create(width, height, kDefaultFont, why);
    if (!raster) return false;
    paintNet(layout, index, state, view, *raster);
    return raster->writePng(path, why);
  }
  why = "a net picture is written as .svg or .png, not '" + path + "'";
  return false;
}

}  // namespace gdpn::diagram
