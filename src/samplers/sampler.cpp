#include "samplers/sampler.h"

#include "filters/filter.h"
#include "samplers/halton_sampler.h"

namespace candela {

namespace {

// For any sampler type: the Halton sampler's overload below calls its values directly.
template <class S>
CameraSample cameraSample(S& sampler, const Point2i& pixel, const Filter& filter, bool lens) {
  FilterSample fs = filter.sample(sampler.getPixel2D());
  CameraSample cs;
  // Pixel (x, y) covers [x, x+1) x [y, y+1); its centre is at +0.5 (lrt draft §7.1).
  cs.pFilm = Point2f(Float(pixel.x) + 0.5f + fs.p.x, Float(pixel.y) + 0.5f + fs.p.y);
  cs.filterWeight = fs.weight;
  cs.time = sampler.get1D();
  if (lens)
    cs.pLens = sampler.get2D();
  else
    sampler.skip2D();
  return cs;
}

}  // namespace

CameraSample getCameraSample(Sampler& sampler, const Point2i& pixel, const Filter& filter,
                             bool lens) {
  return cameraSample(sampler, pixel, filter, lens);
}

CameraSample getCameraSample(HaltonSampler& sampler, const Point2i& pixel, const Filter& filter,
                             bool lens) {
  return cameraSample(sampler, pixel, filter, lens);
}

}  // namespace candela
