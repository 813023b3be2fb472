// The net's ids: a place, a transition, a place slot and a term cannot be taken for one another
// (checked by the compiler: these static_asserts fail the build when a change lets them mix),
// and the finds say "none" with an empty optional, not -1.

#include <gtest/gtest.h>

#include <concepts>
#include <optional>
#include <type_traits>
#include <unordered_set>
#include <vector>

#include "gdpn/net/builder.h"
#include "gdpn/net/id.h"
#include "gdpn/net/net.h"

namespace gdpn::net {
namespace {

template <class A, class B>
concept EqualityWith = requires(A a, B b) { a == b; };
template <class A, class B>
concept OrderedWith = requires(A a, B b) { a < b; };

// one kind is never another, nor made from an integer unasked
static_assert(!std::is_convertible_v<TransitionId, PlaceId>);
static_assert(!std::is_convertible_v<PlaceId, TransitionId>);
static_assert(!std::is_convertible_v<PlaceSlotId, TermId>);
static_assert(!std::is_convertible_v<std::uint32_t, PlaceId>);
static_assert(!std::is_convertible_v<int, TransitionId>);
static_assert(std::is_constructible_v<PlaceId, std::uint32_t>);
static_assert(EqualityWith<PlaceId, PlaceId> && OrderedWith<TermId, TermId>);  // the checks can pass
// two kinds are never compared; an id is never compared with a signed number ("found" is not >= 0)
static_assert(!std::equality_comparable_with<PlaceId, TransitionId>);
static_assert(!std::totally_ordered_with<PlaceSlotId, TermId>);
static_assert(!OrderedWith<PlaceId, int>);
static_assert(!EqualityWith<TransitionId, int>);
static_assert(!OrderedWith<std::optional<PlaceId>, int>);
static_assert(!EqualityWith<std::optional<PlaceSlotId>, std::int64_t>);
static_assert(OrderedWith<PlaceId, std::size_t>);  // a count is unsigned: `p < places.size()`
// an id reads as its index, and costs what the index did
static_assert(std::is_convertible_v<PlaceId, std::uint32_t>);
static_assert(sizeof(PlaceId) == 4 && std::is_trivially_copyable_v<TransitionId>);

/// A function that asks for a place: only a place is accepted (see the static_asserts).
std::uint32_t indexOfPlace(PlaceId p) { return p.index(); }

TEST(Ids, OrderAndHashAsTheirIndices) {
  const PlaceId a{3}, b{7};
  EXPECT_LT(a, b);
  EXPECT_EQ(a, PlaceId{3});
  EXPECT_NE(a, b);
  EXPECT_EQ(indexOfPlace(b), 7u);
  EXPECT_LT(a, 4u);  // an index compares with an unsigned count
  PlaceId c = a;
  EXPECT_EQ(c++, PlaceId{3});
  EXPECT_EQ(++c, PlaceId{5});
  const std::unordered_set<TransitionId> seen{TransitionId{1}, TransitionId{2}, TransitionId{1}};
  EXPECT_EQ(seen.size(), 2u);
  // the trap the docs name: {0} alone is a size, {TransitionId{0}} one id
  EXPECT_EQ(std::vector<TransitionId>{0}.size(), 0u);
  EXPECT_EQ(std::vector<TransitionId>{TransitionId{0}}.size(), 1u);
}

TEST(Ids, RangesWalkEveryIdOnce) {
  std::vector<std::uint32_t> walked;
  for (const PlaceSlotId ps : IdRange<PlaceSlotId>(3, 6)) walked.push_back(ps.index());
  EXPECT_EQ(walked, (std::vector<std::uint32_t>{3, 4, 5}));
  EXPECT_EQ(IdRange<PlaceId>(0).size(), 0u);
  EXPECT_EQ(IdRange<PlaceId>(0).begin(), IdRange<PlaceId>(0).end());
}

TEST(Ids, FindsSayNoneWithAnEmptyOptional) {
  NetBuilder b;
  const PlaceId p = b.addPlace("p");
  const PlaceId q = b.addPlace("q");
  const TransitionId t = b.addTransition("t");
  b.addInput(p, t);
  b.addOutput(t, q);
  const auto net = b.freeze();
  EXPECT_EQ(net->findPlace("q"), q);
  EXPECT_EQ(net->findTransition("t"), t);
  EXPECT_FALSE(net->findPlace("t"));       // a transition's name is not a place's
  EXPECT_FALSE(net->findTransition("p"));
  EXPECT_FALSE(net->findPlace("nowhere"));
  ASSERT_TRUE(net->findPlaceSlot(p, kDefaultSlot));
  EXPECT_FALSE(net->findPlaceSlot(p, SlotId{3}));  // a slot the place does not use
  std::vector<PlaceId> places;
  for (const PlaceId x : net->placeIds()) places.push_back(x);
  EXPECT_EQ(places, (std::vector<PlaceId>{p, q}));
  EXPECT_EQ(net->placeSlotsOf(q).size(), 1u);
  EXPECT_EQ(*net->placeSlotsOf(q).begin(), *net->findPlaceSlot(q, kDefaultSlot));
}

}  // namespace
}  // namespace gdpn::net
