#pragma once
/// \file
/// Programmer-error checks. Bad input never reaches these: it is reported through Diagnostics.

#include <cstdio>
#include <cstdlib>

/// Aborts with a message when `cond` is false. For broken invariants only, never for input.
#define GDPN_ASSERT(cond, why)                                                        \
  do {                                                                                \
    if (!(cond)) {                                                                    \
      std::fprintf(stderr, "%s:%d: internal error: %s (%s)\n", __FILE__, __LINE__, why, \
                   #cond);                                                            \
      std::abort();                                                                   \
    }                                                                                 \
  } while (false)
