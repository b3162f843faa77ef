// The range a numeric scene parameter must lie in, with the one sentence that says so: every
// factory words a rule the same way ("\"nsamples\" must be at least 1 (got 0)"), through
// ParamSet's range-checked getters, which report it at the value's file:line:col.
#pragma once

#include <string>

namespace candela {

class ValueRange {
 public:
  static ValueRange any() { return {Kind::Any, 0, 0}; }
  static ValueRange finite() { return {Kind::Finite, 0, 0}; }
  static ValueRange positive() { return {Kind::Positive, 0, 0}; }          // > 0 and finite
  static ValueRange nonNegative() { return {Kind::NonNegative, 0, 0}; }    // >= 0 and finite
  static ValueRange atLeast(double n) { return {Kind::AtLeast, n, 0}; }    // >= n
  static ValueRange greaterThan(double n) { return {Kind::Above, n, 0}; }  // > n
  static ValueRange within(double lo, double hi) { return {Kind::Closed, lo, hi}; }  // [lo, hi]
  static ValueRange between(double lo, double hi) { return {Kind::Open, lo, hi}; }   // (lo, hi)
  static ValueRange aboveUpTo(double lo, double hi) {
    return {Kind::LeftOpen, lo, hi};
  }  // (lo, hi]

  bool contains(double v) const;
  // What a value must be, completing "must be ...": "at least 1", "positive and finite",
  // "within [0, 1]", "within (-1, 1)".
  std::string describe() const;

 private:
  enum class Kind { Any, Finite, Positive, NonNegative, AtLeast, Above, Closed, Open, LeftOpen };
  ValueRange(Kind kind, double lo, double hi) : kind_(kind), lo_(lo), hi_(hi) {}
  Kind kind_;
  double lo_, hi_;
};

// A number as a message shows it: integers without a fraction, others with up to 6 digits.
std::string formatNumber(double v);

}  // namespace candela
