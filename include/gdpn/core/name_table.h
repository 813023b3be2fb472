#pragma once
/// \file
/// NameTable: an index from names to dense ids that stores only the ids. The names live in
/// the caller's own arrays (a net's places, a page's constructs), so a table of a million
/// names costs 8 bytes a name and no allocation per name. Open addressing with linear probing;
/// the caller passes `nameOf(id)` to every call, which must give back the name stored under id.

#include <algorithm>
#include <bit>
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "gdpn/core/memory.h"

namespace gdpn::core {

/// Name -> id index over names held elsewhere (see the file comment).
class NameTable {
 public:
  /// Makes room for `n` names without growing again.
  void reserve(std::size_t n) {
    if (n * 2 > slots_.size()) rehash(std::bit_ceil(n * 2 < 16 ? std::size_t{16} : n * 2));
  }

  /// Number of names in the table.
  [[nodiscard]] std::size_t size() const { return size_; }

  /// Removes every name, keeping the memory.
  void clear() {
    std::fill(slots_.begin(), slots_.end(), Slot{});
    size_ = 0;
  }

  /// The id stored under `name`, if any.
  template <class NameOf>
  [[nodiscard]] std::optional<std::uint32_t> find(std::string_view name, NameOf&& nameOf) const {
    if (slots_.empty()) return std::nullopt;
    const std::uint32_t h = hashOf(name);
    for (std::size_t i = h & mask(); slots_[i].id != kEmpty; i = (i + 1) & mask()) {
      if (slots_[i].hash == h && nameOf(slots_[i].id) == name) return slots_[i].id;
    }
    return std::nullopt;
  }

  /// Starts fetching the table slot where `name` would be, for a find() a little later: a
  /// loop over many names that prefetches a few ahead waits for memory once, not per name.
  void prefetch(std::string_view name) const {
    if (!slots_.empty()) __builtin_prefetch(&slots_[hashOf(name) & mask()]);
  }

  /// Stores `id` under `name` unless the name is there already. Returns the id under the
  /// name and whether it was new.
  template <class NameOf>
  std::pair<std::uint32_t, bool> insert(std::string_view name, std::uint32_t id, NameOf&& nameOf) {
    if ((size_ + 1) * 2 > slots_.size()) rehash(slots_.empty() ? 16 : slots_.size() * 2);
    return insertHashed(name, hashOf(name), id, nameOf);
  }

  /// Inserts ids 0 .. n-1 under their names, in order, calling `onDuplicate(id, first)` for
  /// an id whose name is there already under `first`. Faster than n insert() calls on large
  /// tables: it hashes every name first and fetches each table slot ahead of its use.
  template <class NameOf, class OnDuplicate>
  void insertAll(std::uint32_t n, NameOf&& nameOf, OnDuplicate&& onDuplicate) {
    reserve(size_ + n);
    std::vector<std::uint32_t> hashes(n);
    for (std::uint32_t id = 0; id < n; ++id) hashes[id] = hashOf(nameOf(id));
    constexpr std::uint32_t kAhead = 16;
    for (std::uint32_t id = 0; id < n; ++id) {
      if (id + kAhead < n) __builtin_prefetch(&slots_[hashes[id + kAhead] & mask()]);
      const auto [first, fresh] = insertHashed(nameOf(id), hashes[id], id, nameOf);
      if (!fresh) onDuplicate(id, first);
    }
  }

  /// Bytes held by the table.
  [[nodiscard]] std::size_t memoryBytes() const { return slots_.capacity() * sizeof(Slot); }

 private:
  template <class NameOf>
  std::pair<std::uint32_t, bool> insertHashed(std::string_view name, std::uint32_t h, std::uint32_t id, NameOf&& nameOf) {
    std::size_t i = h & mask();
    for (; slots_[i].id != kEmpty; i = (i + 1) & mask()) {
      if (slots_[i].hash == h && nameOf(slots_[i].id) == name) return {slots_[i].id, false};
    }
    slots_[i] = {id, h};
    ++size_;
    return {id, true};
  }

  static constexpr std::uint32_t kEmpty = 0xffffffffu;
  struct Slot {
    std::uint32_t id = kEmpty;
    std::uint32_t hash = 0;
  };

  static std::uint32_t hashOf(std::string_view name) {
    const std::uint64_t h = std::hash<std::string_view>{}(name);
    return static_cast<std::uint32_t>(h ^ (h >> 32));
  }
  [[nodiscard]] std::size_t mask() const { return slots_.size() - 1; }

  void rehash(std::size_t capacity) {
    std::vector<Slot> old;
    reserveLarge(old, capacity);
    old.resize(capacity);
    old.swap(slots_);
    for (const Slot& s : old) {
      if (s.id == kEmpty) continue;
      std::size_t i = s.hash & mask();
      while (slots_[i].id != kEmpty) i = (i + 1) & mask();
      slots_[i] = s;
    }
  }

  std::vector<Slot> slots_;
  std::size_t size_ = 0;
};

}  // namespace gdpn::core
