#pragma once
/// \file
/// Large arrays: the first touch of each 4 KiB page costs a page fault, which on a virtual
/// machine can cost more than filling the page. Arrays of many megabytes (a net of a million
/// places) ask the kernel for 2 MiB pages instead where it allows them (Linux transparent
/// huge pages in "madvise" mode); elsewhere this is a plain reserve. And how much memory the
/// system has to give, for limits that end a search before the system kills it.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <optional>
#include <string_view>
#include <vector>

namespace gdpn::core {

/// The size of a huge page where the system offers them, bytes (2 MiB).
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

/// Asks for huge pages for the whole 2 MiB pages inside [data, data + bytes); a hint only,
/// ignored where no such page lies inside and where the system does not offer them.
void adviseHugePages(const void* data, std::size_t bytes);

/// `bytes` of memory to give back with std::free: from 2 MiB on, starting on a 2 MiB boundary,
/// rounded up to whole 2 MiB pages and advised to lie on huge pages (so that every page of it
/// can, not only the whole ones inside an unaligned block; a virtual machine here took 12 us
/// a small page and 0.25 ms a huge one); below, from malloc. Throws std::bad_alloc when none
/// is given.
void* allocateLarge(std::size_t bytes);

/// Gives the memory freed so far back to the system (the C library keeps freed blocks for
/// reuse): before a search that will hold much, so that what reading the model left behind
/// does not add to its peak.
void returnFreedMemory();

/// A standard allocator that takes its blocks from allocateLarge(): for a std::vector that is
/// grown and probed at random (a hash table of millions of entries).
template <class T>
struct LargeAllocator {
  static_assert(alignof(T) <= alignof(std::max_align_t), "blocks under 2 MiB come from malloc");
  /// The elements it makes room for.
  using value_type = T;
  /// It holds nothing: any two give back each other's blocks.
  LargeAllocator() = default;
  /// The same for another element type (as containers rebind it).
  template <class U>
  LargeAllocator(const LargeAllocator<U>&) noexcept {}  // NOLINT(google-explicit-constructor)
  /// Room for `n` elements.
  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocateLarge(n * sizeof(T)));
  }
  /// Gives back what allocate() gave.
  void deallocate(T* p, std::size_t) noexcept { std::free(p); }
  /// Always equal: a block from one is given back by any other.
  template <class U>
  bool operator==(const LargeAllocator<U>&) const noexcept {
    return true;
  }
};

/// The core's second-level data cache, bytes: secondLevelCacheFrom() of the system's figure.
std::size_t secondLevelCacheBytes();

/// A second-level cache size from what the system reports, bytes: 1 MiB where it reports
/// none (0 or less), else held within 256 KiB to 4 MiB (virtual machines report sizes no core
/// has, such as a third-level cache of 508 MiB).
std::size_t secondLevelCacheFrom(long reported);

/// `v.reserve(n)`, then adviseHugePages() over the reserved storage.
template <class T>
void reserveLarge(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  adviseHugePages(v.data(), v.capacity() * sizeof(T));
}

/// The memory the system can give now without swapping, bytes: Linux's MemAvailable (free
/// memory and caches it can drop), else the free physical pages, and no more than the room
/// left under the process's control group's limit (a container's); 0 where it cannot tell.
std::uint64_t availableMemory();

/// The room left under a control group's memory limit, bytes, from the text of its limit
/// file (cgroup v2 memory.max: a number or "max"; v1 memory.limit_in_bytes: a number, 2^62
/// and more meaning none) and of its usage file; nullopt where there is no limit or either
/// text is not a number.
std::optional<std::uint64_t> cgroupRoom(std::string_view limit, std::string_view usage);

/// MemAvailable in the text of /proc/meminfo ("MemAvailable:   123456 kB"), bytes; 0 where
/// the line is missing or malformed.
std::uint64_t memAvailableIn(std::string_view meminfo);

}  // namespace gdpn::core
