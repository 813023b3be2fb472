// The stored reachability graph written as Graphviz DOT or Aldebaran (.aut) text.

#include "gdpn/net/graph_export.h"

#include "detail/query_graph.h"

namespace gdpn::net {
namespace {

using detail::StateId;

/// `text` quoted for DOT and Aldebaran labels: backslashes and quotes escaped.
std::string quoted(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

ExploreStop writeStateGraph(const Net& net, GraphFormat format, std::ostream& out, const ExploreOptions& limits) {
  const detail::StateGraph g = detail::buildGraph(net, limits);
  if (g.stop != ExploreStop::Done) return g.stop;
  const auto& layout = g.store->layout();
  std::vector<std::int64_t> m(layout.width());
  if (format == GraphFormat::Aldebaran) {
    out << "des (0, " << g.succ.size() << ", " << g.size() << ")\n";
    for (StateId s = 0; s < g.size(); ++s) {
      for (auto e = g.first[s]; e < g.first[s + 1]; ++e) {
        out << '(' << s << ", " << quoted(net.transitionName(g.via[e])) << ", " << g.succ[e] << ")\n";
      }
    }
    return ExploreStop::Done;
  }
  out << "digraph reachability {\n  node [shape=box, fontname=\"Helvetica\", fontsize=10];\n"
         "  edge [fontname=\"Helvetica\", fontsize=9];\n";
  std::vector<std::uint64_t> packed;
  for (StateId s = 0; s < g.size(); ++s) {
    layout.unpack(g.store->load(s, packed), m.data());
    std::string label;
    for (PlaceId pid{0}; pid < net.places().size(); ++pid) {
      const Place& p = net.places()[pid];
      std::int64_t n = 0;
      for (auto k = p.slots_begin; k < p.slots_end; ++k) n += m[k];
      if (n != 0) label += (label.empty() ? "" : "\x01") + net.placeName(pid) + (n == 1 ? "" : " = " + std::to_string(n));
    }
    // one place per line: DOT's \n between them, put in after quoting
    std::string text = quoted(label.empty() ? "(no tokens)" : label);
    for (auto at = text.find('\x01'); at != std::string::npos; at = text.find('\x01', at)) text.replace(at, 1, "\\n");
    out << "  s" << s << " [label=" << text << (s == 0 ? ", penwidth=2" : "")
        << (g.outDegree(s) == 0 ? ", style=filled, fillcolor=\"#f4cccc\"" : "") << "];\n";
  }
  for (StateId s = 0; s < g.size(); ++s) {
    for (auto e = g.first[s]; e < g.first[s + 1]; ++e) {
      out << "  s" << s << " -> s" << g.succ[e] << " [label=" << quoted(net.transitionName(g.via[e])) << "];\n";
    }
  }
  out << "}\n";
  return ExploreStop::Done;
}

}  // namespace gdpn::net
