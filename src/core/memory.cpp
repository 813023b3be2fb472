#include "gdpn/core/memory.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace gdpn::core {

void adviseHugePages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = kHugePageBytes;
  if (data == nullptr || bytes < kHuge) return;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  // a hint: a kernel without transparent huge pages refuses it, and nothing changes
  if (end > begin) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

void* allocateLarge(std::size_t bytes) {
  if (bytes < kHugePageBytes) {
    if (void* p = std::malloc(std::max<std::size_t>(bytes, 1))) return p;
    throw std::bad_alloc();
  }
  const std::size_t whole = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
  if (whole < bytes) throw std::bad_alloc();  // rounded past the largest size
  void* p = std::aligned_alloc(kHugePageBytes, whole);
  if (p == nullptr) throw std::bad_alloc();
  adviseHugePages(p, whole);
  return p;
}

void returnFreedMemory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

std::size_t secondLevelCacheFrom(long reported) {
  constexpr long kLeast = long{256} << 10, kMost = long{4} << 20;
  if (reported <= 0) return std::size_t{1} << 20;
  return static_cast<std::size_t>(std::clamp(reported, kLeast, kMost));
}

std::size_t secondLevelCacheBytes() {
#if defined(_SC_LEVEL2_CACHE_SIZE)
  return secondLevelCacheFrom(sysconf(_SC_LEVEL2_CACHE_SIZE));
#else
  return secondLevelCacheFrom(0);
#endif
}

std::uint64_t memAvailableIn(std::string_view meminfo) {
  constexpr std::string_view kKey = "MemAvailable:";
  for (std::size_t at = 0; at < meminfo.size();) {
    const std::size_t end = std::min(meminfo.find('\n', at), meminfo.size());
    std::string_view line = meminfo.substr(at, end - at);
    at = end + 1;
    if (!line.starts_with(kKey)) continue;
    line.remove_prefix(kKey.size());
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    std::uint64_t kib = 0;
    const auto [rest, ec] = std::from_chars(line.data(), line.data() + line.size(), kib);
    if (ec != std::errc() || std::string_view(rest, static_cast<std::size_t>(line.data() + line.size() - rest)) != " kB") return 0;
    if (kib > std::numeric_limits<std::uint64_t>::max() / 1024) return 0;
    return kib * 1024;
  }
  return 0;
}

namespace {

std::string readText(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::optional<std::uint64_t> number(std::string_view text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.remove_suffix(1);
  std::uint64_t v = 0;
  const auto [rest, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || rest != text.data() + text.size()) return std::nullopt;
  return v;
}

// the room under the limit of this process's control group: v2 (0::PATH) or v1's memory
// controller (N:memory:PATH), in the group's own folder or, in a container whose group is
// the root of what it sees, at the top
std::optional<std::uint64_t> ownCgroupRoom() {
  const std::string groups = readText("/proc/self/cgroup");
  std::string_view rest = groups;
  while (!rest.empty()) {
    const std::size_t end = std::min(rest.find('\n'), rest.size());
    const std::string_view line = rest.substr(0, end);
    rest.remove_prefix(std::min(end + 1, rest.size()));
    const std::size_t first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string_view::npos || second == std::string_view::npos) continue;
    const std::string_view controllers = line.substr(first + 1, second - first - 1);
    const std::string path(line.substr(second + 1));
    const bool v2 = line.substr(0, first) == "0" && controllers.empty();
    if (!v2 && controllers != "memory") continue;
    const std::string top = v2 ? "/sys/fs/cgroup" : "/sys/fs/cgroup/memory";
    const char* limit = v2 ? "/memory.max" : "/memory.limit_in_bytes";
    const char* usage = v2 ? "/memory.current" : "/memory.usage_in_bytes";
    for (const std::string& folder : {top + path, top}) {
      const std::string l = readText(folder + limit);
      if (l.empty()) continue;
      return cgroupRoom(l, readText(folder + usage));
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::uint64_t> cgroupRoom(std::string_view limit, std::string_view usage) {
  const auto l = number(limit), u = number(usage);
  if (!l || !u || *l >= (std::uint64_t{1} << 62)) return std::nullopt;
  return *l - std::min(*l, *u);
}

std::uint64_t availableMemory() {
  std::uint64_t bytes = memAvailableIn(readText("/proc/meminfo"));
  if (bytes == 0) {
    const long pages = sysconf(_SC_AVPHYS_PAGES), size = sysconf(_SC_PAGESIZE);
    if (pages > 0 && size > 0) bytes = static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(size);
  }
  if (const auto room = ownCgroupRoom(); room && bytes != 0) bytes = std::min(bytes, *room);
  return bytes;
}

}  // namespace gdpn::core
