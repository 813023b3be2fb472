// How much memory the system has to give: the default limit of `gdpn analyze`.
#include "gdpn/core/memory.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "gdpn/core/sanitizers.h"

namespace gdpn::core {
namespace {

TEST(Memory, MemAvailableIsReadInBytesFromTheMeminfoText) {
  const char* meminfo =
      "MemTotal:       24567812 kB\n"
      "MemFree:        23111044 kB\n"
      "MemAvailable:   22874512 kB\n"
      "Buffers:           41232 kB\n";
  EXPECT_EQ(memAvailableIn(meminfo), 22874512ull * 1024);
  // the last line, with no line end; a tab before the number
  EXPECT_EQ(memAvailableIn("MemFree: 1 kB\nMemAvailable:\t7 kB"), 7ull * 1024);
}

TEST(Memory, MeminfoWithoutAReadableMemAvailableGivesZero) {
  EXPECT_EQ(memAvailableIn(""), 0u);
  EXPECT_EQ(memAvailableIn("MemTotal:       24567812 kB\n"), 0u);              // an old kernel: no such line
  EXPECT_EQ(memAvailableIn("MemAvailable:   lots kB\n"), 0u);                  // not a number
  EXPECT_EQ(memAvailableIn("MemAvailable:   12 MB\n"), 0u);                    // another unit
  EXPECT_EQ(memAvailableIn("MemAvailable:   99999999999999999999 kB\n"), 0u);  // past 64 bits
  EXPECT_EQ(memAvailableIn("MemAvailable:   18014398509481984 kB\n"), 0u);     // 2^54 KiB: past 64 bits in bytes
  EXPECT_EQ(memAvailableIn("XMemAvailable:  12 kB\n"), 0u);                    // another key
}

TEST(Memory, AControlGroupsLimitLeavesWhatItsUsageHasNotTaken) {
  EXPECT_EQ(cgroupRoom("8589934592\n", "2147483648\n"), std::optional<std::uint64_t>(6442450944));  // 8 GiB, 2 used
  EXPECT_EQ(cgroupRoom("1000", "1500"), std::optional<std::uint64_t>(0));  // over it: nothing left
  EXPECT_EQ(cgroupRoom("max\n", "2147483648\n"), std::nullopt);           // v2: no limit
  EXPECT_EQ(cgroupRoom("9223372036854771712\n", "2487775232\n"), std::nullopt);  // v1: no limit
  EXPECT_EQ(cgroupRoom("", "1"), std::nullopt);
  EXPECT_EQ(cgroupRoom("12 kB", "1"), std::nullopt);
  EXPECT_EQ(cgroupRoom("1000", "x"), std::nullopt);
}

TEST(Memory, ASecondLevelCacheSizeIsTheReportedOneHeldToWhatCoresHave) {
  EXPECT_EQ(secondLevelCacheFrom(1 << 20), std::size_t{1} << 20);
  EXPECT_EQ(secondLevelCacheFrom(1280 << 10), std::size_t{1280} << 10);
  EXPECT_EQ(secondLevelCacheFrom(0), std::size_t{1} << 20);   // not reported
  EXPECT_EQ(secondLevelCacheFrom(-1), std::size_t{1} << 20);  // sysconf's error
  EXPECT_EQ(secondLevelCacheFrom(532676608), std::size_t{4} << 20);  // a VM's 508 MiB
  EXPECT_EQ(secondLevelCacheFrom(4096), std::size_t{256} << 10);
  const std::size_t here = secondLevelCacheBytes();
  EXPECT_GE(here, std::size_t{256} << 10);
  EXPECT_LE(here, std::size_t{4} << 20);
}

#if defined(__linux__) && !GDPN_SANITIZED
/// The flags of the mapping of this process that holds `p` (/proc/self/smaps' VmFlags), and
/// where it starts and ends; empty where there is no such file.
struct Mapping {
  std::uintptr_t begin = 0, end = 0;
  std::string flags;
};
Mapping mappingOf(const void* p) {
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  std::ifstream smaps("/proc/self/smaps");
  Mapping m, found;
  for (std::string line; std::getline(smaps, line);) {
    unsigned long long b = 0, e = 0;
    char dash = 0;
    std::istringstream in(line);
    if (line.rfind("VmFlags:", 0) == 0) {
      if (m.begin <= at && at < m.end) found = {m.begin, m.end, line};
    } else if ((in >> std::hex >> b >> dash >> e) && dash == '-') {
      m = {static_cast<std::uintptr_t>(b), static_cast<std::uintptr_t>(e), {}};
    }
  }
  return found;
}
#endif

TEST(Memory, ALargeBlockLiesOnWholeHugePagesFromItsStart) {
  for (const std::size_t bytes : {kHugePageBytes, kHugePageBytes + 1, std::size_t{9} << 20}) {
    void* p = allocateLarge(bytes);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % kHugePageBytes, 0u) << bytes;
    std::memset(p, 0xab, bytes);  // every byte asked for is there
    EXPECT_EQ(static_cast<unsigned char*>(p)[bytes - 1], 0xab);
#if defined(__linux__) && !GDPN_SANITIZED
    // where the kernel has transparent huge pages, the whole block is advised to lie on them
    // (a block from malloc alone has its first and last 2 MiB on small pages); ASan's
    // allocator maps its own blocks
    if (std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled")) {
      const Mapping m = mappingOf(p);
      if (m.flags.empty()) {
        std::free(p);
        GTEST_SKIP() << "no VmFlags in /proc/self/smaps";
      }
      EXPECT_NE(m.flags.find(" hg"), std::string::npos) << bytes << ": " << m.flags;
      EXPECT_LE(m.begin, reinterpret_cast<std::uintptr_t>(p));
      EXPECT_GE(m.end, reinterpret_cast<std::uintptr_t>(p) + bytes);
    }
#endif
    std::free(p);
  }
  // small ones come from malloc: no rounding up to 2 MiB
  void* small = allocateLarge(1000);
  ASSERT_NE(small, nullptr);
  std::memset(small, 1, 1000);
  std::free(small);
  std::free(allocateLarge(0));
}

TEST(Memory, AVectorWithTheLargeAllocatorStartsOnAHugePageOnceItIsLarge) {
  std::vector<std::uint64_t, LargeAllocator<std::uint64_t>> v(1000, 7);
  EXPECT_EQ(v[999], 7u);
  v.assign(std::size_t{1} << 20, 3);  // 8 MiB
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % kHugePageBytes, 0u);
  EXPECT_EQ(v.back(), 3u);
  EXPECT_THROW(LargeAllocator<std::uint64_t>().allocate(static_cast<std::size_t>(-1) / 4), std::bad_array_new_length);
}

TEST(Memory, ThisMachineHasMemoryToGive) {
  // on Linux from /proc/meminfo, elsewhere from the free pages: more than a MiB either way
  EXPECT_GT(availableMemory(), std::uint64_t{1} << 20);
}

}  // namespace
}  // namespace gdpn::core
