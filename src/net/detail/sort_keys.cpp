#include "sort_keys.h"

#include <algorithm>
#include <array>

namespace gdpn::net::detail {

void sortKeys(std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& scratch) {
  if (std::is_sorted(keys.begin(), keys.end())) return;
  if (keys.size() < 256) {
    std::sort(keys.begin(), keys.end());
    return;
  }
  // LSD radix sort over the bytes in which some keys differ
  std::uint64_t any = 0, all = ~std::uint64_t{0};
  for (auto k : keys) {
    any |= k;
    all &= k;
  }
  const std::uint64_t differ = any ^ all;
  scratch.resize(keys.size());
  for (int shift = 0; shift < 64; shift += 8) {
    if (((differ >> shift) & 0xff) == 0) continue;
    std::array<std::size_t, 257> count{};
    for (auto k : keys) ++count[((k >> shift) & 0xff) + 1];
    for (std::size_t i = 0; i < 256; ++i) count[i + 1] += count[i];
    for (auto k : keys) scratch[count[(k >> shift) & 0xff]++] = k;
    keys.swap(scratch);
  }
}

}  // namespace gdpn::net::detail
