// The invariants of a hierarchical model solved once per page type equal those of the flat
// net solved part by part, and the cycle bounds the report draws from them agree too.

#include <gtest/gtest.h>

#include <string>

#include "gdpn/model/model.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/invariants.h"

namespace gdpn::model {
namespace {

/// A line of `n` producer/consumer cells (a page type of 3 places and 2 transitions), each fed
/// from the top page's `feed` when `linked`, else each on its own.
std::string cells(int n, bool linked) {
  std::string s = "gdpn: 1\npages:\n  main:\n    places:\n      feed: {tokens: 3}\n    transitions:\n";
  s += "      start: {duration: 1}\n    instances:\n";
  for (int i = 0; i < n; ++i) s += "      c" + std::to_string(i) + ": cell\n";
  s += "    arcs:\n      - feed -> start\n";
  for (int i = 0; i < n; ++i) s += linked ? "      - start -> c" + std::to_string(i) + "/buffer\n" : "";
  s += linked ? "" : "      - start -> feed\n";
  s += "page_types:\n  cell:\n    references: [buffer]\n    places:\n      ready: {tokens: 1}\n"
       "      buffer: {capacity: 2}\n      free: {tokens: 1}\n    transitions:\n      produce: {duration: 2}\n"
       "      consume: {duration: {uniform: [1, 3]}}\n    arcs:\n      - ready -> produce\n      - produce -> buffer\n"
       "      - produce -> ready\n      - buffer -> consume\n      - free -> consume\n      - consume -> free\n";
  return s;
}

std::shared_ptr<const net::Net> compileText(const std::string& text, const std::string& name) {
  core::Diagnostics diags;
  auto m = parseModel(text, name, diags);
  EXPECT_TRUE(m) << diags.str();
  if (!m) return nullptr;
  auto n = net::compile(m->net, diags);
  EXPECT_TRUE(n) << diags.str();
  return n;
}

std::shared_ptr<const net::Net> compileFile(const std::string& relative) {
  core::Diagnostics diags;
  auto m = loadModel(std::string(GDPN_SOURCE_DIR) + "/" + relative, diags);
  EXPECT_TRUE(m) << diags.str();
  if (!m) return nullptr;
  auto n = net::compile(m->net, diags);
  EXPECT_TRUE(n) << diags.str();
  return n;
}

void expectAlike(const net::Net& net) {
  net::InvariantOptions flat;
  flat.reuse_alike = false;
  const auto a = net::invariants(net);
  const auto b = net::invariants(net, flat);
  ASSERT_TRUE(a.complete);
  ASSERT_TRUE(b.complete);
  ASSERT_EQ(a.p.size(), b.p.size());
  for (std::size_t i = 0; i < a.p.size(); ++i) EXPECT_EQ(a.p[i].weights, b.p[i].weights);
  ASSERT_EQ(a.t.size(), b.t.size());
  for (std::size_t i = 0; i < a.t.size(); ++i) EXPECT_EQ(a.t[i].weights, b.t[i].weights);
  EXPECT_EQ(a.bound, b.bound);
  EXPECT_EQ(a.conservative, b.conservative);
  EXPECT_EQ(a.structurally_bounded, b.structurally_bounded);
  EXPECT_EQ(a.consistent, b.consistent);
  for (const auto& y : a.p) EXPECT_TRUE(net::isPInvariant(net, y));
  for (const auto& x : a.t) EXPECT_TRUE(net::isTInvariant(net, x));
  std::vector<double> seconds;
  for (const auto& t : net.transitions()) seconds.push_back(net::meanSeconds(t.duration));
  const auto ca = net::cycleBounds(net, a, seconds);
  const auto cb = net::cycleBounds(net, b, seconds);
  ASSERT_EQ(ca.size(), cb.size());
  for (std::size_t i = 0; i < ca.size(); ++i) {
    EXPECT_EQ(ca[i].transitions, cb[i].transitions);
    EXPECT_EQ(ca[i].seconds, cb[i].seconds);
    EXPECT_EQ(ca[i].tokens, cb[i].tokens);
  }
}

TEST(InvariantsByPageType, TheHierarchicalExamplesGiveTheFlatNetsInvariantsAndBounds) {
  for (const char* file : {"examples/factory/factory.gdpn.yaml", "examples/basics/two_cells/two_cells.gdpn.yaml"}) {
    SCOPED_TRACE(file);
    const auto net = compileFile(file);
    ASSERT_TRUE(net);
    expectAlike(*net);
  }
}

TEST(InvariantsByPageType, CellsOnTheirOwnAndCellsFedFromOnePlaceGiveTheFlatNetsAnswer) {
  for (bool linked : {false, true}) {
    SCOPED_TRACE(linked ? "linked" : "on their own");
    const auto net = compileText(cells(12, linked), "cells.gdpn.yaml");
    ASSERT_TRUE(net);
    expectAlike(*net);
    // each cell's ready and free hold their token; the feed keeps its own only on its own
    const auto inv = net::invariants(*net);
    std::vector<std::string> p;
    for (const auto& y : inv.p) {
      ASSERT_EQ(y.weights.size(), 1u);
      p.push_back(net->placeName(net->placeSlots()[y.weights[0].first].place));
    }
    ASSERT_EQ(p.size(), linked ? 24u : 25u);
    EXPECT_EQ(p[0], linked ? "main/c0/ready" : "main/feed");
    EXPECT_EQ(p.back(), "main/c11/free");
    // and each cell's produce and consume make a T-invariant
    EXPECT_EQ(inv.t.size(), linked ? 12u : 13u);
  }
}

}  // namespace
}  // namespace gdpn::model
