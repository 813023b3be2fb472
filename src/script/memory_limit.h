// What scripts may take: a bound on the memory Python allocates, refused at the allocation.

#pragma once

#include <cstdint>

namespace gdpn::script::detail {

/// Wraps Python's raw allocator and its object allocator's arenas (once per process, under the
/// GIL) so that they count what they hold, and refuse an allocation that would take it past
/// the limit: the script gets a MemoryError at the line that asked, not the machine's swap.
/// Memory held by a C library behind Python (NumPy's array buffers) is not counted.
void installMemoryLimit();

/// The bytes Python holds now, as counted since installMemoryLimit() (blocks from before it
/// freed since may make it low, even below 0).
[[nodiscard]] std::int64_t memoryHeld();

/// The most bytes Python may hold (as memoryHeld() counts), 0 for no bound. The engine sets it
/// while a script call runs, to what it held when the engine was made plus the scripts' share.
void setMemoryCap(std::int64_t bytes);

/// Whether an allocation was refused since the last clearMemoryLimitHit().
[[nodiscard]] bool memoryLimitHit();

/// Forgets a refusal (each script call starts clean).
void clearMemoryLimitHit();

/// While it lives, no allocation is refused: reporting a MemoryError needs memory too.
class MemoryLimitLifted {
 public:
  MemoryLimitLifted();
  ~MemoryLimitLifted();
  MemoryLimitLifted(const MemoryLimitLifted&) = delete;
  MemoryLimitLifted& operator=(const MemoryLimitLifted&) = delete;

 private:
  std::int64_t saved_;
};

}  // namespace gdpn::script::detail
