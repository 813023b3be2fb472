#include "graphviz_layout.h"

#include <graphviz/cgraph.h>
#include <graphviz/gvc.h>

#include <cstdio>
#include <memory>
#include <mutex>

namespace gdpn::diagram::detail {
namespace {

// Graphviz keeps global state: one layout at a time
std::mutex g_graphviz;

// one context for the process, made at the first layout and kept (Graphviz 2.43 loses part of
// each context it frees, and loading its plugins each time costs more than a small layout)
GVC_t* context() {
  static GVC_t* gvc = gvContext();
  return gvc;
}

constexpr int kBezierSamples = 8;  // points per cubic piece of an edge's spline

std::string inches(double layout_units) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4f", layout_units / 72.0);
  return text;
}

Point cubic(const pointf& a, const pointf& b, const pointf& c, const pointf& d, double t) {
  const double u = 1.0 - t;
  const double w0 = u * u * u, w1 = 3 * u * u * t, w2 = 3 * u * t * t, w3 = t * t * t;
  return {w0 * a.x + w1 * b.x + w2 * c.x + w3 * d.x, w0 * a.y + w1 * b.y + w2 * c.y + w3 * d.y};
}

struct GraphDeleter {
  void operator()(Agraph_t* g) const { agclose(g); }
};

}  // namespace

std::optional<GvResult> dotLayout(const std::vector<GvNode>& nodes, const std::vector<GvEdge>& edges, double rank_gap,
                                  std::string& why) {
  std::lock_guard lock(g_graphviz);
  GVC_t* gvc = context();
  if (gvc == nullptr) {
    why = "cannot start Graphviz";
    return std::nullopt;
  }
  std::unique_ptr<Agraph_t, GraphDeleter> graph(agopen(const_cast<char*>("net"), Agdirected, nullptr));
  Agraph_t* g = graph.get();
  // the graph's look: left to right, nodes of fixed size with no labels, edges ending on the outline
  agattr(g, AGRAPH, const_cast<char*>("rankdir"), const_cast<char*>("LR"));
  agattr(g, AGRAPH, const_cast<char*>("nodesep"), const_cast<char*>("0.5"));
  std::string ranksep = inches(rank_gap);
  agattr(g, AGRAPH, const_cast<char*>("ranksep"), ranksep.data());
  agattr(g, AGNODE, const_cast<char*>("shape"), const_cast<char*>("box"));
  agattr(g, AGNODE, const_cast<char*>("fixedsize"), const_cast<char*>("true"));
  agattr(g, AGNODE, const_cast<char*>("label"), const_cast<char*>(""));
  agattr(g, AGNODE, const_cast<char*>("width"), const_cast<char*>("0.5"));
  agattr(g, AGNODE, const_cast<char*>("height"), const_cast<char*>("0.5"));
  agattr(g, AGEDGE, const_cast<char*>("arrowhead"), const_cast<char*>("none"));
  std::vector<Agnode_t*> made;
  made.reserve(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    std::string name = "n" + std::to_string(i);
    Agnode_t* n = agnode(g, name.data(), 1);
    std::string w = inches(nodes[i].width), h = inches(nodes[i].height);
    agsafeset(n, const_cast<char*>("width"), w.data(), const_cast<char*>("0.5"));
    agsafeset(n, const_cast<char*>("height"), h.data(), const_cast<char*>("0.5"));
    if (nodes[i].round) agsafeset(n, const_cast<char*>("shape"), const_cast<char*>("circle"), const_cast<char*>("box"));
    made.push_back(n);
  }
  std::vector<Agedge_t*> made_edges;
  made_edges.reserve(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    std::string key = "e" + std::to_string(i);
    made_edges.push_back(agedge(g, made[edges[i].from], made[edges[i].to], key.data(), 1));
  }
  if (gvLayout(gvc, g, "dot") != 0) {
    why = "Graphviz could not lay out the page";
    return std::nullopt;
  }
  // read back: Graphviz has y up, in points; the picture wants y down from the top
  const boxf bb = GD_bb(g);
  auto flip = [&](double x, double y) { return Point{x - bb.LL.x, bb.UR.y - y}; };
  GvResult result;
  for (Agnode_t* n : made) result.centres.push_back(flip(ND_coord(n).x, ND_coord(n).y));
  for (std::size_t i = 0; i < made_edges.size(); ++i) {
    std::vector<Point> line;
    const splines* spl = ED_spl(made_edges[i]);
    if (spl != nullptr && spl->size > 0 && spl->list[0].size >= 4) {
      const bezier& bz = spl->list[0];
      line.push_back(flip(bz.list[0].x, bz.list[0].y));
      for (std::size_t k = 0; k + 3 < static_cast<std::size_t>(bz.size); k += 3) {
        for (int s = 1; s <= kBezierSamples; ++s) {
          const Point p = cubic(bz.list[k], bz.list[k + 1], bz.list[k + 2], bz.list[k + 3],
                                static_cast<double>(s) / kBezierSamples);
          line.push_back(flip(p.x, p.y));
        }
      }
    } else {
      line = {result.centres[edges[i].from], result.centres[edges[i].to]};
    }
    result.edges.push_back(std::move(line));
  }
  gvFreeLayout(gvc, g);
  return result;
}

}  // namespace gdpn::diagram::detail
