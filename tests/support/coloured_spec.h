#pragma once
// Test support: coloured nets written as specs, one construct a line (as the model file would
// be), so that messages can be told apart.

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gdpn/net/compile.h"

namespace gdpn::testing {

using net::ArcKind;
using net::ArcSpec;
using net::ColourKind;
using net::ColourSetSpec;
using net::Duration;
using net::kDefaultSlot;
using net::Net;
using net::NetSpec;
using net::PageSpec;
using net::PlaceSpec;
using net::SlotCount;
using net::SourceLoc;
using net::TransitionSpec;

inline SourceLoc at(int line, int column = 1) { return SourceLoc{"value.gdpn.yaml", line, column}; }

/// A one-page coloured net, written as the model file would be.
struct Coloured {
  NetSpec spec;
  int line = 1;  // each construct gets its own line, so that messages can be told apart

  Coloured() { spec.pages.push_back(PageSpec{"main", at(1), {}, {}, {}, {}, {}, {}}); }
  PageSpec& page() { return spec.pages[0]; }

  Coloured& set(ColourSetSpec s) {
    s.loc = at(++line);
    spec.colours.push_back(std::move(s));
    return *this;
  }
  Coloured& variable(const std::string& name, const std::string& colour) {
    spec.variables.push_back({name, colour, at(++line)});
    return *this;
  }
  Coloured& place(const std::string& name, const std::string& colour, const std::string& values = {},
                  std::int64_t capacity = -1) {
    PlaceSpec p;
    p.name = name;
    p.loc = at(++line);
    p.colours.push_back({kDefaultSlot, colour, at(line, 10)});
    if (!values.empty()) p.values.push_back({kDefaultSlot, values, at(line, 30)});
    if (capacity >= 0) p.capacity.push_back(SlotCount(kDefaultSlot, capacity));
    page().places.push_back(std::move(p));
    return *this;
  }
  Coloured& control(const std::string& name, std::int64_t tokens) {
    PlaceSpec p;
    p.name = name;
    p.loc = at(++line);
    if (tokens > 0) p.tokens.push_back(SlotCount(kDefaultSlot, tokens));
    page().places.push_back(std::move(p));
    return *this;
  }
  Coloured& transition(const std::string& name, const std::string& when = {}, double seconds = 1.0,
                       std::int64_t servers = 1) {
    TransitionSpec t;
    t.name = name;
    t.loc = at(++line);
    t.duration = Duration(Duration::Law::Fixed, seconds);
    t.servers = servers;
    if (!when.empty()) t.when = {kDefaultSlot, when, at(line, 20)};
    page().transitions.push_back(std::move(t));
    return *this;
  }
  Coloured& arc(const std::string& from, const std::string& to, const std::string& inscription,
                ArcKind kind = ArcKind::Normal) {
    ArcSpec a;
    a.from = from;
    a.to = to;
    a.kind = kind;
    a.loc = at(++line);
    if (!inscription.empty()) a.inscriptions.push_back({kDefaultSlot, inscription, at(line, 40)});
    page().arcs.push_back(std::move(a));
    return *this;
  }
  std::shared_ptr<const Net> compiled() {
    core::Diagnostics diags;
    auto net = compile(spec, diags);
    EXPECT_TRUE(net) << diags.str();
    return net;
  }
  /// What compiling says (the net must not compile).
  std::string refusal() {
    core::Diagnostics diags;
    EXPECT_FALSE(compile(spec, diags));
    return diags.str();
  }
};

inline ColourSetSpec cyclic(const std::string& name, std::vector<std::string> constants) {
  ColourSetSpec s;
  s.name = name;
  s.kind = ColourKind::Enum;
  s.constants = std::move(constants);
  s.cyclic = true;
  return s;
}
inline ColourSetSpec range(const std::string& name, std::int64_t lo, std::int64_t hi) {
  ColourSetSpec s;
  s.name = name;
  s.kind = ColourKind::Integer;
  s.range = true;
  s.lo = lo;
  s.hi = hi;
  return s;
}

}  // namespace gdpn::testing
