#include "core/value_range.h"

#include <cmath>
#include <cstdio>

namespace candela {

bool ValueRange::contains(double v) const {
  switch (kind_) {
    case Kind::Any:
      return !std::isnan(v);
    case Kind::Finite:
      return std::isfinite(v);
    case Kind::Positive:
      return v > 0 && std::isfinite(v);
    case Kind::NonNegative:
      return v >= 0 && std::isfinite(v);
    case Kind::AtLeast:
      return v >= lo_;
    case Kind::Above:
      return v > lo_;
    case Kind::Closed:
      return v >= lo_ && v <= hi_;
    case Kind::Open:
      return v > lo_ && v < hi_;
    case Kind::LeftOpen:
      return v > lo_ && v <= hi_;
  }
  return false;
}

std::string ValueRange::describe() const {
  switch (kind_) {
    case Kind::Any:
      return "a number";
    case Kind::Finite:
      return "finite";
    case Kind::Positive:
      return "positive and finite";
    case Kind::NonNegative:
      return "non-negative and finite";
    case Kind::AtLeast:
      return "at least " + formatNumber(lo_);
    case Kind::Above:
      return "greater than " + formatNumber(lo_);
    case Kind::Closed:
      return "within [" + formatNumber(lo_) + ", " + formatNumber(hi_) + "]";
    case Kind::Open:
      return "within (" + formatNumber(lo_) + ", " + formatNumber(hi_) + ")";
    case Kind::LeftOpen:
      return "within (" + formatNumber(lo_) + ", " + formatNumber(hi_) + "]";
  }
  return "";
}

std::string formatNumber(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char text[32];
  if (v == std::round(v) && std::fabs(v) < 1e15)
    std::snprintf(text, sizeof text, "%.0f", v);
  else
    std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

}  // namespace candela
