// How every face analyses a coloured model (session::analysedNet): unfolded where unfolding
// can, else over markings with values with a note saying why, and never unfolded when asked.
// tests/data/colour/serial_numbers.gdpn.yaml cannot be unfolded (a million serials, strings):
// its state space against a search of the same net written out here by hand.

#include <gtest/gtest.h>

#include <array>
#include <deque>
#include <set>
#include <tuple>

#include "gdpn/model/model.h"
#include "gdpn/session/analysis_request.h"

namespace gdpn::session {
namespace {

std::optional<net::NetSpec> spec(const std::string& name) {
  core::Diagnostics diags;
  auto m = model::loadModel(std::string(GDPN_SOURCE_DIR) + "/tests/data/colour/" + name, diags);
  EXPECT_TRUE(m) << diags.str();
  if (!m) return std::nullopt;
  return std::move(m->net);
}

/// The serial-numbers net searched by hand: (next serial, per part: stamped?, its serial);
/// stamp (n < 40) takes a part from the belt and gives it serial n, recycle puts a stamped
/// part back on the belt. States, edges (one per enabled binding), dead markings.
std::array<std::uint64_t, 3> serialNumbersByHand() {
  using State = std::tuple<int, std::array<bool, 2>, std::array<int, 2>>;
  std::set<State> seen;
  std::deque<State> todo;
  const State first{0, {false, false}, {0, 0}};
  seen.insert(first);
  todo.push_back(first);
  std::uint64_t edges = 0, dead = 0;
  while (!todo.empty()) {
    const auto [n, stamped, serial] = todo.front();
    todo.pop_front();
    std::vector<State> next;
    for (std::size_t p = 0; p < 2; ++p) {
      if (!stamped[p] && n < 40) {
        auto s = stamped;
        auto v = serial;
        s[p] = true;
        v[p] = n;
        next.emplace_back(n + 1, s, v);
      }
      if (stamped[p]) {
        auto s = stamped;
        s[p] = false;
        next.emplace_back(n, s, serial);
      }
    }
    edges += next.size();
    dead += next.empty();
    for (const auto& s : next) {
      if (seen.insert(s).second) todo.push_back(s);
    }
  }
  return {seen.size(), edges, dead};
}

TEST(ColourSearch, WhatCannotBeUnfoldedIsSearchedOverValuesWithANote) {
  const auto s = spec("serial_numbers.gdpn.yaml");
  ASSERT_TRUE(s);
  core::Diagnostics diags;
  const auto analysed = analysedNet(*s, diags);
  ASSERT_TRUE(analysed) << diags.str();
  EXPECT_TRUE(analysed->native);
  EXPECT_FALSE(diags.hasErrors());
  EXPECT_NE(diags.str().find("serial_numbers.gdpn.yaml:"), std::string::npos) << diags.str();
  EXPECT_NE(diags.str().find("note: analysed over markings with values, without unfolding: place 'next' holds values "
                             "of 'Serial', 1000000 of them"),
            std::string::npos)
      << diags.str();
  AnalysisRequest request;
  request.max_memory_mib = 512;
  const auto answer = analyze(*analysed, "serial_numbers.gdpn.yaml", request);
  const net::StateSpace& space = answer.analysis.space;
  const auto [states, edges, dead] = serialNumbersByHand();
  ASSERT_TRUE(space.complete);
  EXPECT_EQ(space.states, states);
  EXPECT_EQ(space.edges, edges);
  EXPECT_EQ(space.dead_markings, dead);
  EXPECT_TRUE(space.deadlock);
  // the shortest way to a dead marking: 40 stamps, each part recycled after each of its own
  EXPECT_EQ(space.deadlock_path.size(), 80u);
  ASSERT_EQ(space.deadlock_bindings.size(), 80u);
  EXPECT_EQ(space.deadlock_bindings[0].rfind("n=0, p={serial = 0, line = \"", 0), 0u) << space.deadlock_bindings[0];
  ASSERT_EQ(space.dead_marking.size(), 2u);
  EXPECT_EQ(space.dead_marking[0], "main/next = 1'40");
  // every bound counts all the values of a place
  EXPECT_EQ(space.max_marking, 3);
  EXPECT_EQ(space.max_value_count, 1);
  EXPECT_FALSE(space.reversible);
}

TEST(ColourSearch, UnfoldableNetsAreUnfoldedUnlessAskedNotTo) {
  const auto s = spec("philosophers.gdpn.yaml");
  ASSERT_TRUE(s);
  core::Diagnostics diags;
  const auto unfolded = analysedNet(*s, diags);
  ASSERT_TRUE(unfolded) << diags.str();
  EXPECT_FALSE(unfolded->native);
  EXPECT_TRUE(unfolded->expansion());
  EXPECT_EQ(diags.str(), "");
  const auto native = analysedNet(*s, diags, ColourSearch::Native);
  ASSERT_TRUE(native) << diags.str();
  EXPECT_TRUE(native->native);
  EXPECT_TRUE(native->net->colouring());
  // both searches find the same graph
  AnalysisRequest request;
  request.max_memory_mib = 512;
  const auto a = analyze(*unfolded, "p", request).analysis.space;
  const auto b = analyze(*native, "p", request).analysis.space;
  EXPECT_EQ(a.states, b.states);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.deadlock, b.deadlock);
  EXPECT_EQ(a.max_marking, b.max_marking);
}

TEST(ColourSearch, AskedToUnfoldWhatCannotBeItSaysWhy) {
  const auto s = spec("serial_numbers.gdpn.yaml");
  ASSERT_TRUE(s);
  core::Diagnostics diags;
  EXPECT_FALSE(analysedNet(*s, diags, ColourSearch::Unfold));
  EXPECT_NE(diags.str().find("error: place 'next' holds values of 'Serial', 1000000 of them"), std::string::npos)
      << diags.str();
}

}  // namespace
}  // namespace gdpn::session
