// Ordering that ThreadSanitizer cannot see for itself, declared to it. TSan learns "A happens
// before B" only from synchronisation in instrumented code; oneTBB's scheduler and Embree's
// parallel builds synchronise inside Debian's uninstrumented libtbb and libembree, so work that
// they order (what precedes a parallel loop and each of its bodies, each body and the loop's
// return, a scene's geometry and the bounds callbacks of its build) would be reported as racing.
// Under -fsanitize=thread these calls tell TSan about exactly those orders; elsewhere they are
// empty. A release on an address orders everything before it before every later acquire on it.
#pragma once

#if defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define CANDELA_THREAD_SANITIZER 1
#endif
#endif
#if !defined(CANDELA_THREAD_SANITIZER) && defined(__SANITIZE_THREAD__)
#define CANDELA_THREAD_SANITIZER 1
#endif

#ifdef CANDELA_THREAD_SANITIZER
#include <sanitizer/tsan_interface.h>
#endif

namespace candela {

inline void releaseOrder([[maybe_unused]] const void* address) {
#ifdef CANDELA_THREAD_SANITIZER
  __tsan_release(const_cast<void*>(address));
#endif
}

inline void acquireOrder([[maybe_unused]] const void* address) {
#ifdef CANDELA_THREAD_SANITIZER
  __tsan_acquire(const_cast<void*>(address));
#endif
}

}  // namespace candela
