#pragma once
/// \file
/// The ids of the frozen net's arrays (places, transitions, place slots, terms): one type each,
/// so that a transition cannot be passed, stored or compared where a place is meant.

#include <compare>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>

namespace gdpn::net {

/// An index into one of the frozen net's arrays; `Tag` names which. Made from an integer only
/// on purpose (`PlaceId{3}`); read as its index (`std::uint32_t`) wherever an integer is
/// wanted, so that it indexes arrays and counts. Two ids of different tags cannot be compared,
/// and one is never taken for the other: a function that asks for a `PlaceId` refuses a
/// `TransitionId`. Four bytes, trivially copyable, as the plain index was.
template <class Tag>
class Id {
 public:
  using Value = std::uint32_t;  ///< the index's type

  /// Index 0.
  constexpr Id() noexcept = default;
  /// The id of index `index` (which fits in 32 bits: the net's arrays are that small).
  template <std::integral I>
  constexpr explicit Id(I index) noexcept : value_(static_cast<Value>(index)) {}

  /// The index.
  [[nodiscard]] constexpr Value index() const noexcept { return value_; }
  /// The index, where an integer is wanted (`places[p]`, `p < n`).
  constexpr operator Value() const noexcept { return value_; }  // NOLINT(google-explicit-constructor)

  /// The next id.
  constexpr Id& operator++() noexcept {
    ++value_;
    return *this;
  }
  /// The next id; returns this one.
  constexpr Id operator++(int) noexcept {
    const Id before = *this;
    ++value_;
    return before;
  }

  /// Ids of one kind compare as their indices.
  friend constexpr bool operator==(Id, Id) noexcept = default;
  /// Ids of one kind order as their indices.
  friend constexpr auto operator<=>(Id, Id) noexcept = default;

 private:
  Value value_ = 0;
};

/// Ids of two kinds are never compared: a place is not a transition.
template <class A, class B>
  requires(!std::same_as<A, B>)
bool operator==(Id<A>, Id<B>) = delete;
/// Ids of two kinds are never ordered.
template <class A, class B>
  requires(!std::same_as<A, B>)
auto operator<=>(Id<A>, Id<B>) = delete;

using PlaceId = Id<struct PlaceTag>;            ///< index of a place in `Net::places()`
using TransitionId = Id<struct TransitionTag>;  ///< index of a transition in `Net::transitions()`
using PlaceSlotId = Id<struct PlaceSlotTag>;    ///< index of one (place, slot) pair
using TermId = Id<struct TermTag>;              ///< index of one (arc, slot) condition

/// An id is never compared with a signed number: no id is negative, and `find*() >= 0`, the
/// old test for "found", must not compile now that a find returns an optional.
template <class Tag, std::signed_integral I>
bool operator==(Id<Tag>, I) = delete;
/// An id is never ordered against a signed number (see above).
template <class Tag, std::signed_integral I>
auto operator<=>(Id<Tag>, I) = delete;

/// The ids first..end-1 of one kind, for `for (PlaceId p : net.placeIds())`.
template <class IdType>
class IdRange {
 public:
  /// Walks the ids.
  class Iterator {
   public:
    using value_type = IdType;            ///< an id
    using difference_type = std::ptrdiff_t;  ///< ids apart
    /// At id 0.
    constexpr Iterator() noexcept = default;
    /// At `id`.
    constexpr explicit Iterator(IdType id) noexcept : id_(id) {}
    /// The id.
    constexpr IdType operator*() const noexcept { return id_; }
    /// The next id.
    constexpr Iterator& operator++() noexcept {
      ++id_;
      return *this;
    }
    /// The next id; returns this one.
    constexpr Iterator operator++(int) noexcept {
      const Iterator before = *this;
      ++id_;
      return before;
    }
    /// At the same id.
    friend constexpr bool operator==(Iterator, Iterator) noexcept = default;

   private:
    IdType id_{};
  };

  /// The ids 0..`count`-1.
  constexpr explicit IdRange(std::size_t count) noexcept : IdRange(0, count) {}
  /// The ids `first`..`end`-1.
  constexpr IdRange(std::size_t first, std::size_t end) noexcept
      : first_(static_cast<typename IdType::Value>(first)), end_(static_cast<typename IdType::Value>(end)) {}
  /// The first id.
  [[nodiscard]] constexpr Iterator begin() const noexcept { return Iterator(IdType{first_}); }
  /// Past the last id.
  [[nodiscard]] constexpr Iterator end() const noexcept { return Iterator(IdType{end_}); }
  /// How many ids.
  [[nodiscard]] constexpr std::size_t size() const noexcept { return end_ - first_; }

 private:
  typename IdType::Value first_, end_;
};

}  // namespace gdpn::net

/// Ids hash as their indices.
template <class Tag>
struct std::hash<gdpn::net::Id<Tag>> {
  /// The index's hash.
  std::size_t operator()(gdpn::net::Id<Tag> id) const noexcept { return std::hash<std::uint32_t>{}(id.index()); }
};
