#pragma once
// The benchmarks' large page: a grid of transitions and places (bench/diagram_bench.cpp,
// bench/net_editor_bench.cpp).

#include <string>

#include "gdpn/net/spec.h"

namespace gdpn::bench {

namespace net = gdpn::net;

/// A grid page: `columns` x `rows` transitions, each feeding a place to its right that feeds
/// the next transition; positions given (x: 2 editor units per column, y: 1 per row) or not.
inline net::PageSpec gridPage(int columns, int rows, bool placed) {
  net::PageSpec page;
  page.name = "grid";
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < columns; ++x) {
      const auto id = std::to_string(x) + "_" + std::to_string(y);
      net::TransitionSpec t;
      t.name = "t" + id;
      net::PlaceSpec p;
      p.name = "p" + id;
      if (placed) {
        t.position = net::EditorPos{2.0 * x, 1.0 * y};
        p.position = net::EditorPos{2.0 * x + 1, 1.0 * y};
      }
      if (x % 3 == 0) p.tokens.push_back({net::kDefaultSlot, x % 7, {}});
      page.transitions.push_back(t);
      page.places.push_back(p);
      net::ArcSpec out;
      out.from = t.name;
      out.to = p.name;
      page.arcs.push_back(out);
      if (x > 0) {
        net::ArcSpec in;
        in.from = "p" + std::to_string(x - 1) + "_" + std::to_string(y);
        in.to = t.name;
        page.arcs.push_back(in);
      }
    }
  return page;
}

}  // namespace gdpn::bench
