#include "filters/sinc_filter.h"

namespace candela {

LanczosSincFilter::LanczosSincFilter(const Vector2f& radius, Float tau)
    : Filter(radius), tau_(tau) {
  buildSamplingTable();
}

Float LanczosSincFilter::windowedSinc(Float x) const {
  x = std::abs(x);
  if (x < 1e-5f) return 1;  // both factors tend to 1; avoids 0/0 (lrt draft §7.7.5)
  if (x > 1) return 0;
  Float px = kPi * x;
  Float sinc = std::sin(px * tau_) / (px * tau_);
  Float lanczos = std::sin(px) / px;
  return sinc * lanczos;
}

Float LanczosSincFilter::evaluate(const Point2f& p) const {
  return windowedSinc(p.x / radius().x) * windowedSinc(p.y / radius().y);
}

}  // namespace candela
