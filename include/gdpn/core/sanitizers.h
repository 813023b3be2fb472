#pragma once
/// \file
/// Whether this build runs under a sanitizer that changes how memory looks from outside (GCC
/// says so with __SANITIZE_ADDRESS__, clang with __has_feature): resident sizes and address
/// space caps mean other things there.

#if defined(__SANITIZE_ADDRESS__)
#define GDPN_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || __has_feature(thread_sanitizer)
#define GDPN_SANITIZED 1
#endif
#endif
#ifndef GDPN_SANITIZED
/// 1 under AddressSanitizer, MemorySanitizer or ThreadSanitizer (GCC or clang), else 0.
#define GDPN_SANITIZED 0
#endif

namespace gdpn::core {

/// True under AddressSanitizer, MemorySanitizer or ThreadSanitizer.
inline constexpr bool kSanitized = GDPN_SANITIZED != 0;

}  // namespace gdpn::core
