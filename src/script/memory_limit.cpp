// What scripts may take: Python's allocators wrapped to count and bound what they hold.

#include "memory_limit.h"

#include <Python.h>
#include <malloc.h>

#include <atomic>
#include <cstdint>

namespace gdpn::script::detail {
namespace {

// the raw domain runs without the GIL too: every count is atomic
std::atomic<std::int64_t> g_held{0};  // bytes (may dip below 0: blocks from before the wrapping)
std::atomic<std::int64_t> g_cap{0};  // bytes (0: no bound)
std::atomic<bool> g_hit{false};
PyMemAllocatorEx g_raw{};          // Python's own raw allocator, wrapped
PyObjectArenaAllocator g_arena{};  // Python's own arena allocator, wrapped

/// Whether `n` more bytes fit; records a refusal.
bool fits(std::size_t n) {
  const std::int64_t cap = g_cap.load(std::memory_order_relaxed);
  if (cap == 0) return true;
  const std::int64_t held = g_held.load(std::memory_order_relaxed);
  if (n <= static_cast<std::size_t>(INT64_MAX) && held + static_cast<std::int64_t>(n) <= cap) return true;
  g_hit.store(true, std::memory_order_relaxed);
  return false;
}

void count(void* p) {
  if (p) g_held.fetch_add(static_cast<std::int64_t>(malloc_usable_size(p)), std::memory_order_relaxed);
}
void uncount(void* p) {
  if (p) g_held.fetch_sub(static_cast<std::int64_t>(malloc_usable_size(p)), std::memory_order_relaxed);
}

void* rawMalloc(void* ctx, std::size_t n) {
  (void)ctx;
  if (!fits(n)) return nullptr;
  void* p = g_raw.malloc(g_raw.ctx, n);
  count(p);
  return p;
}
void* rawCalloc(void* ctx, std::size_t count_, std::size_t size) {
  (void)ctx;
  if (size != 0 && count_ > SIZE_MAX / size) return nullptr;
  if (!fits(count_ * size)) return nullptr;
  void* p = g_raw.calloc(g_raw.ctx, count_, size);
  count(p);
  return p;
}
void* rawRealloc(void* ctx, void* old, std::size_t n) {
  (void)ctx;
  const std::size_t before = old ? malloc_usable_size(old) : 0;
  if (n > before && !fits(n - before)) return nullptr;
  void* p = g_raw.realloc(g_raw.ctx, old, n);
  if (!p && n != 0) return nullptr;  // the old block stays, and counted
  g_held.fetch_sub(static_cast<std::int64_t>(before), std::memory_order_relaxed);
  count(p);
  return p;
}
void rawFree(void* ctx, void* p) {
  (void)ctx;
  uncount(p);
  g_raw.free(g_raw.ctx, p);
}

void* arenaAlloc(void* ctx, std::size_t n) {
  (void)ctx;
  if (!fits(n)) return nullptr;
  void* p = g_arena.alloc(g_arena.ctx, n);
  if (p) g_held.fetch_add(static_cast<std::int64_t>(n), std::memory_order_relaxed);
  return p;
}
void arenaFree(void* ctx, void* p, std::size_t n) {
  (void)ctx;
  if (p) g_held.fetch_sub(static_cast<std::int64_t>(n), std::memory_order_relaxed);
  g_arena.free(g_arena.ctx, p, n);
}

}  // namespace

void installMemoryLimit() {
  static bool done = false;
  if (done) return;
  done = true;
  PyMem_GetAllocator(PYMEM_DOMAIN_RAW, &g_raw);
  PyMemAllocatorEx raw{nullptr, rawMalloc, rawCalloc, rawRealloc, rawFree};
  PyMem_SetAllocator(PYMEM_DOMAIN_RAW, &raw);
  PyObject_GetArenaAllocator(&g_arena);
  PyObjectArenaAllocator arena{nullptr, arenaAlloc, arenaFree};
  PyObject_SetArenaAllocator(&arena);
}

std::int64_t memoryHeld() { return g_held.load(std::memory_order_relaxed); }
void setMemoryCap(std::int64_t bytes) { g_cap.store(bytes, std::memory_order_relaxed); }
bool memoryLimitHit() { return g_hit.load(std::memory_order_relaxed); }
void clearMemoryLimitHit() { g_hit.store(false, std::memory_order_relaxed); }

MemoryLimitLifted::MemoryLimitLifted() : saved_(g_cap.exchange(0)) {}
MemoryLimitLifted::~MemoryLimitLifted() { g_cap.store(saved_); }

}  // namespace gdpn::script::detail
