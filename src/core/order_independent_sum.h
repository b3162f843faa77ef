// A sum of non-negative values that many threads add to at once and that comes out the same bits
// whatever order the additions took: each value is cut into two fixed-point integers (units of
// 2^-8 and, for the remainder, of 2^-40), and integer addition is associative. Floating-point
// atomics would make a learned distribution (path guiding) depend on the thread schedule, and
// with it the image. Values are clamped to [0, 2^32]; below 2^-40 they are lost. The two counters
// then hold 2^24 values of the largest size, 2^32 of any size, before they could overflow.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>

namespace candela {

class OrderIndependentSum {
 public:
  OrderIndependentSum() = default;
  OrderIndependentSum(const OrderIndependentSum& other)
      : coarse_(other.coarse_.load(std::memory_order_relaxed)),
        fine_(other.fine_.load(std::memory_order_relaxed)) {}
  OrderIndependentSum& operator=(const OrderIndependentSum& other) {
    coarse_.store(other.coarse_.load(std::memory_order_relaxed), std::memory_order_relaxed);
    fine_.store(other.fine_.load(std::memory_order_relaxed), std::memory_order_relaxed);
    return *this;
  }

  // Thread-safe. NaN counts as 0.
  void add(double value) {
    if (!(value > 0)) return;
    value = std::min(value, 0x1p32);
    // Both steps are exact: scaling by a power of two, and the remainder of a floor.
    double coarse = std::floor(value * 0x1p8);
    double fine = std::floor((value - coarse * 0x1p-8) * 0x1p40);
    if (coarse > 0) coarse_.fetch_add(uint64_t(coarse), std::memory_order_relaxed);
    if (fine > 0) fine_.fetch_add(uint64_t(fine), std::memory_order_relaxed);
  }
  double value() const {
    return double(coarse_.load(std::memory_order_relaxed)) * 0x1p-8 +
           double(fine_.load(std::memory_order_relaxed)) * 0x1p-40;
  }
  void reset() {
    coarse_.store(0, std::memory_order_relaxed);
    fine_.store(0, std::memory_order_relaxed);
  }

 private:
  std::atomic<uint64_t> coarse_{0}, fine_{0};
};

}  // namespace candela
