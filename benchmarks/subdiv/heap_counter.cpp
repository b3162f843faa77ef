// Replacing operator new and delete here, in the executable, replaces them for the whole process:
// the shared libraries (OpenSubdiv's libosdCPU, libstdc++) call them through the dynamic symbol
// table, which binds to the executable's definitions first. So both producers' allocations are
// counted the same way, through the same counters. malloc's own bookkeeping and anything a library
// gets from malloc directly are not counted; neither producer's data structures do that.
#include "heap_counter.h"

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace candela::bench {

namespace {

std::atomic<std::size_t> live{0}, peak{0};

void counted(void* p) {
  std::size_t size = malloc_usable_size(p);
  std::size_t now = live.fetch_add(size, std::memory_order_relaxed) + size;
  std::size_t before = peak.load(std::memory_order_relaxed);
  while (now > before && !peak.compare_exchange_weak(before, now, std::memory_order_relaxed)) {
  }
}

void* allocate(std::size_t size, std::size_t alignment) {
  // malloc(0) may return null, which new must not.
  if (size == 0) size = 1;
  void* p = nullptr;
  if (alignment <= alignof(std::max_align_t)) {
    p = std::malloc(size);
  } else if (posix_memalign(&p, alignment, size) != 0) {
    p = nullptr;
  }
  if (p) counted(p);
  return p;
}

void* allocateOrThrow(std::size_t size, std::size_t alignment) {
  // The standard new loops on the new-handler before giving up.
  while (true) {
    if (void* p = allocate(size, alignment)) return p;
    std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

void release(void* p) {
  if (!p) return;
  live.fetch_sub(malloc_usable_size(p), std::memory_order_relaxed);
  std::free(p);
}

}  // namespace

std::size_t liveHeapBytes() { return live.load(std::memory_order_relaxed); }
std::size_t peakHeapBytes() { return peak.load(std::memory_order_relaxed); }
void resetHeapPeak() {
  peak.store(live.load(std::memory_order_relaxed), std::memory_order_relaxed);
}

}  // namespace candela::bench

using candela::bench::allocate;
using candela::bench::allocateOrThrow;
using candela::bench::release;

constexpr std::size_t kDefault = alignof(std::max_align_t);

void* operator new(std::size_t n) { return allocateOrThrow(n, kDefault); }
void* operator new[](std::size_t n) { return allocateOrThrow(n, kDefault); }
void* operator new(std::size_t n, std::align_val_t a) { return allocateOrThrow(n, std::size_t(a)); }
void* operator new[](std::size_t n, std::align_val_t a) {
  return allocateOrThrow(n, std::size_t(a));
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return allocate(n, kDefault); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  return allocate(n, kDefault);
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate(n, std::size_t(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate(n, std::size_t(a));
}

// The size comes from malloc_usable_size, so every form of delete is the same.
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
