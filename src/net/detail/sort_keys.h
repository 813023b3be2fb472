#pragma once
// Internal: no promises. Sorting of 64-bit ready-set keys.

#include <cstdint>
#include <vector>

namespace gdpn::net::detail {

/// Sorts `keys` ascending. Already sorted input costs one pass; large unsorted input is
/// radix-sorted on the bytes that differ (`scratch` is reused storage).
void sortKeys(std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& scratch);

}  // namespace gdpn::net::detail
