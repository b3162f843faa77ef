#include "filters/gaussian_filter.h"

namespace candela {

GaussianFilter::GaussianFilter(const Vector2f& radius, Float alpha)
    : Filter(radius),
      alpha_(alpha),
      expX_(std::exp(-alpha * radius.x * radius.x)),
      expY_(std::exp(-alpha * radius.y * radius.y)) {
  buildSamplingTable();
}

Float GaussianFilter::gaussian1D(Float x, Float expAtRadius) const {
  return std::max(Float(0), std::exp(-alpha_ * x * x) - expAtRadius);
}

Float GaussianFilter::evaluate(const Point2f& p) const {
  return gaussian1D(p.x, expX_) * gaussian1D(p.y, expY_);
}

}  // namespace candela
