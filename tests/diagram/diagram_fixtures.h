#pragma once
// Test support for the diagram tests: small pages built in code, and per-process temp names.

#include <unistd.h>

#include <filesystem>
#include <string>

#include "gdpn/net/spec.h"

namespace gdpn::diagram::testing {

/// A temp file name unique to this process: `<tmp>/gdpn_diagram_<pid>_<name>`.
inline std::string tempFile(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("gdpn_diagram_" + std::to_string(::getpid()) + "_" + name)).string();
}

/// A place named `name` with `tokens` control tokens, at `at` (editor units) when given.
inline net::PlaceSpec place(const std::string& name, std::int64_t tokens = 0,
                            std::optional<net::EditorPos> at = std::nullopt) {
  net::PlaceSpec p;
  p.name = name;
  if (tokens > 0) p.tokens.push_back({net::kDefaultSlot, tokens, {}});
  p.position = at;
  return p;
}

/// A transition lasting `seconds`, at `at` (editor units) when given.
inline net::TransitionSpec transition(const std::string& name, double seconds = 1.0,
                                      std::optional<net::EditorPos> at = std::nullopt) {
  net::TransitionSpec t;
  t.name = name;
  t.duration.a = seconds;
  t.position = at;
  return t;
}

/// An arc `from -> to` of `kind` with weight `weight` on slot a0.
inline net::ArcSpec arc(const std::string& from, const std::string& to, net::ArcKind kind = net::ArcKind::Normal,
                        std::int64_t weight = 1) {
  net::ArcSpec a;
  a.from = from;
  a.to = to;
  a.kind = kind;
  if (weight != 1) a.weights.push_back({net::kDefaultSlot, weight, {}});
  return a;
}

/// Page `main`: src (1 token) -> go -> mid -> stop -> done in a row, with positions when
/// `placed`; weight 2 on mid -> stop; a test arc gate (1 token) -> stop and an inhibitor arc
/// block -> go from places above the row.
inline net::NetSpec smallNet(bool placed) {
  auto at = [placed](double x, double y) { return placed ? std::optional<net::EditorPos>({x, y}) : std::nullopt; };
  net::PageSpec page;
  page.name = "main";
  page.places = {place("src", 1, at(0, 1)), place("mid", 0, at(2, 1)), place("done", 0, at(4, 1)),
                 place("gate", 1, at(2, 0)), place("block", 0, at(0, 0))};
  page.transitions = {transition("go", 1.0, at(1, 1)), transition("stop", 1.0, at(3, 1))};
  page.arcs = {arc("src", "go"), arc("go", "mid"), arc("mid", "stop", net::ArcKind::Normal, 2), arc("stop", "done"),
               arc("gate", "stop", net::ArcKind::Test), arc("block", "go", net::ArcKind::Inhibitor)};
  net::NetSpec spec;
  spec.pages.push_back(std::move(page));
  return spec;
}

}  // namespace gdpn::diagram::testing
