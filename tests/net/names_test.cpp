// Names (net/names.h): a page type's names and locations are stored once; every instance's
// qualified names and declaration locations are built from them.

#include <gtest/gtest.h>

#include <map>

#include "gdpn/net/builder.h"
#include "gdpn/net/compile.h"
#include "support/spec_helpers.h"

namespace gdpn::net {
namespace {

using namespace gdpn::testing;

/// A location in a model file with a long path, so that a copy per instance would show.
SourceLoc at(int line) { return {"/a/rather/long/path/to/the/model.gdpn.yaml", line, 3}; }

PlaceSpec placeAt(std::string name, int line) {
  auto p = place(std::move(name));
  p.loc = at(line);
  return p;
}

TransitionSpec transitionAt(std::string name, int line) {
  auto t = transition(std::move(name), 1.0);
  t.loc = at(line);
  return t;
}

InstanceSpec instance(std::string name, std::string type) { return {std::move(name), std::move(type), {}, {}, {}}; }

/// Three levels of page types under a page: main > top1, top2 (top) > mid1, mid2 (mid) > leaf1, leaf2 (leaf).
NetSpec nested() {
  PageSpec leaf;
  leaf.name = "leaf";
  leaf.places = {placeAt("a", 1), placeAt("b", 2)};
  leaf.transitions = {transitionAt("t", 3)};
  PageSpec mid;
  mid.name = "mid";
  mid.places = {placeAt("m", 4)};
  mid.transitions = {transitionAt("u", 5)};
  mid.instances = {instance("leaf1", "leaf"), instance("leaf2", "leaf")};
  PageSpec top;
  top.name = "top";
  top.places = {placeAt("x", 6)};
  top.instances = {instance("mid1", "mid"), instance("mid2", "mid")};
  PageSpec main;
  main.name = "main";
  main.places = {placeAt("p", 7)};
  main.transitions = {transitionAt("v", 8)};
  main.instances = {instance("top1", "top"), instance("top2", "top")};
  NetSpec spec;
  spec.page_types = {leaf, mid, top};
  spec.pages = {main};
  return spec;
}

TEST(Names, EveryInstanceIsDeclaredWhereItsPageTypeDeclaresIt) {
  core::Diagnostics diags;
  const auto net = compile(nested(), diags);
  ASSERT_TRUE(net) << diags.str();
  // main: 1 + 2 tops * (1 + 2 mids * (1 + 2 leaves * 2)) places
  ASSERT_EQ(net->places().size(), 1u + 2 * (1 + 2 * (1 + 2 * 2)));
  ASSERT_EQ(net->transitions().size(), 1u + 2 * (2 * (1 + 2 * 1)));
  const std::map<std::string, int> place_line{{"a", 1}, {"b", 2}, {"m", 4}, {"x", 6}, {"p", 7}};
  const std::map<std::string, int> transition_line{{"t", 3}, {"u", 5}, {"v", 8}};
  for (PlaceId p{0}; p < net->places().size(); ++p) {
    const std::string local(net->placeLocalName(p));
    EXPECT_EQ(net->placeLoc(p), at(place_line.at(local))) << net->placeName(p);
  }
  for (TransitionId t{0}; t < net->transitions().size(); ++t) {
    const std::string local(net->transitionLocalName(t));
    EXPECT_EQ(net->transitionLoc(t), at(transition_line.at(local))) << net->transitionName(t);
  }
}

TEST(Names, NestedInstancesAreNamedByTheirPath) {
  core::Diagnostics diags;
  const auto net = compile(nested(), diags);
  ASSERT_TRUE(net) << diags.str();
  // declaration order: a page's places, its instances', then its transitions
  EXPECT_EQ(net->placeName(PlaceId{0}), "main/p");
  EXPECT_EQ(net->placeName(PlaceId{1}), "main/top1/x");
  EXPECT_EQ(net->placeName(PlaceId{2}), "main/top1/mid1/m");
  EXPECT_EQ(net->placeName(PlaceId{3}), "main/top1/mid1/leaf1/a");
  EXPECT_EQ(net->placeName(PlaceId{6}), "main/top1/mid1/leaf2/b");
  EXPECT_EQ(net->placeName(static_cast<PlaceId>(net->places().size() - 1)), "main/top2/mid2/leaf2/b");
  EXPECT_EQ(net->transitionName(TransitionId{0}), "main/top1/mid1/leaf1/t");
  EXPECT_EQ(net->transitionName(TransitionId{2}), "main/top1/mid1/u");
  EXPECT_EQ(net->transitionName(static_cast<TransitionId>(net->transitions().size() - 1)), "main/v");
  std::string appended = "at ";
  net->appendPlaceName(appended, PlaceId{3});
  EXPECT_EQ(appended, "at main/top1/mid1/leaf1/a");
  EXPECT_EQ(net->placeLocalName(PlaceId{3}), "a");
  // every name leads back to its construct; parts of a path lead nowhere
  for (PlaceId p{0}; p < net->places().size(); ++p) EXPECT_EQ(net->findPlace(net->placeName(p)), p);
  for (TransitionId t{0}; t < net->transitions().size(); ++t) {
    EXPECT_EQ(net->findTransition(net->transitionName(t)), t);
  }
  EXPECT_FALSE(net->findPlace("main/top1/mid1"));
  EXPECT_FALSE(net->findPlace("top1/mid1/m"));
  EXPECT_FALSE(net->findPlace("main/top1/mid1/leaf1/t"));
  EXPECT_FALSE(net->findTransition("main/top3/mid1/u"));
  EXPECT_FALSE(net->findPlace("a"));
}

TEST(Names, BuilderNamesSplitAtTheLastSlash) {
  NetBuilder b;
  const auto abc = b.addPlace("a/b/c", at(1));
  const auto x = b.addPlace("x");
  const auto y = b.addPlace("/y");
  const auto abd = b.addPlace("a/b/d");
  const auto twin = b.addPlace("x");
  const auto t = b.addTransition("a/b/t", {}, 0, 1.0, at(2));
  const auto u = b.addTransition("u");
  const auto net = b.freeze();
  EXPECT_EQ(net->placeName(abc), "a/b/c");
  EXPECT_EQ(net->placeName(x), "x");
  EXPECT_EQ(net->placeName(y), "/y");
  EXPECT_EQ(net->placeName(abd), "a/b/d");
  EXPECT_EQ(net->placeName(twin), "x");
  EXPECT_EQ(net->transitionName(t), "a/b/t");
  EXPECT_EQ(net->transitionName(u), "u");
  EXPECT_EQ(net->findPlace("a/b/c"), abc);
  EXPECT_EQ(net->findPlace("a/b/d"), abd);
  EXPECT_EQ(net->findPlace("x"), x);  // the first of twins
  EXPECT_EQ(net->findPlace("/y"), y);
  EXPECT_FALSE(net->findPlace("y"));
  EXPECT_FALSE(net->findPlace("a/b"));
  EXPECT_EQ(net->findTransition("a/b/t"), t);
  EXPECT_EQ(net->findTransition("u"), u);
  EXPECT_EQ(net->placeLoc(abc), at(1));
  EXPECT_EQ(net->transitionLoc(t), at(2));
  EXPECT_EQ(net->placeLoc(x), SourceLoc{});
}

/// A page with `n` instances of a cell of 3 places and 2 transitions.
std::shared_ptr<const Net> cells(int n) {
  PageSpec cell;
  cell.name = "cell";
  cell.places = {placeAt("buffer", 1), placeAt("machine", 2), placeAt("done", 3)};
  cell.transitions = {transitionAt("load", 4), transitionAt("unload", 5)};
  PageSpec main;
  main.name = "main";
  for (int i = 0; i < n; ++i) main.instances.push_back(instance("c" + std::to_string(i), "cell"));
  NetSpec spec;
  spec.page_types = {cell};
  spec.pages = {main};
  core::Diagnostics diags;
  auto net = compile(spec, diags);
  EXPECT_TRUE(net) << diags.str();
  return net;
}

TEST(Names, AnInstanceAddsLessThan200BytesOfNames) {
  const auto small = cells(1000), large = cells(2000);
  ASSERT_TRUE(small && large);
  const double added = 1000.0;
  // the names and locations: a scope and its index, not a copy of the cell's names
  const double names = static_cast<double>(large->names().memoryBytes() - small->names().memoryBytes()) / added;
  EXPECT_LT(names, 200.0);
  // the whole net: the flat places and transitions themselves, and less than 200 bytes more
  const double whole = static_cast<double>(large->memoryBytes() - small->memoryBytes()) / added;
  EXPECT_LT(whole, static_cast<double>(3 * sizeof(Place) + 2 * sizeof(Transition)) + 200.0);
  EXPECT_EQ(large->placeName(PlaceId{3 * 1999 + 2}), "main/c1999/done");
}

}  // namespace
}  // namespace gdpn::net
