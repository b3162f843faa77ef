// Live and peak heap bytes of the whole process, counted by replacing the global operator new and
// delete (heap_counter.cpp). Linking heap_counter.cpp into an executable is what turns counting on.
#pragma once

#include <cstddef>

namespace candela::bench {

// Bytes currently allocated through operator new (as malloc_usable_size reports them: the
// request rounded up to the allocator's chunk size, which is what the process actually holds).
std::size_t liveHeapBytes();
// The most live bytes since the last resetHeapPeak.
std::size_t peakHeapBytes();
// Starts a new peak from the current live bytes.
void resetHeapPeak();

}  // namespace candela::bench
