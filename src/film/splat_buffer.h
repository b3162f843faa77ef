// Light splatted onto the film from anywhere in the image (light tracing, the t = 1 strategy of
// bidirectional path tracing; pbrt 3e §16.3.3), kept apart from the pixels' own samples and added
// at the end, scaled by the film's pixel count over the number of light paths (pbrt-v3's
// splatScale 1 / spp when every pixel takes spp samples).
//
// Splats from many threads land on one pixel in no fixed order, and floating-point addition
// depends on order. So each channel is a 64+64-bit fixed-point sum: a splat v is cut into
// hi = floor(16 v) and lo = round(2^32 frac(16 v)), each added with an integer atomic (integer
// addition is associative: the sum is the same bits in any order). The quantum is 2^-36 ≈ 1.5e-11,
// so rounding is at most 2^-37 per splat; a pixel value of at least 1e-4 (after the division by
// the samples per pixel) that gathers up to 10 splats per sample is therefore within 1e-7
// relative. The range: |v| < 2^59 per splat (larger splats are refused and counted), and the
// lo words overflow only after 2^31 splats on one pixel.
//
// Splats come only from raster positions inside the image, so near its edges part of a pixel's
// filter support has no splats: weighting by f / ∫f there would darken the edge pixels by the
// filter mass outside the image (a Gaussian of radius 2 took 8% off the corner regions of a
// 16 x 16 Metropolis render). Each pixel's weights are instead divided by the part of ∫f inside
// the image, so a splatted constant is that constant on every pixel, as the pixels' own samples
// give it.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/bounds.h"
#include "core/spectrum.h"
#include "filters/filter.h"

namespace candela {

class SplatBuffer {
 public:
  // Splats land at raster positions inside `image` (the full image, whatever the crop); those
  // outside pixelBounds are dropped (a crop window keeps only its own pixels). A splat whose
  // luminance exceeds maxLuminance is scaled down to it first (pbrt-v3's film clamp).
  SplatBuffer(const Bounds2i& pixelBounds, const Bounds2f& image, const Filter& filter,
              Float maxLuminance = kInfinity);
  // Adds v to every pixel whose filter support holds pRaster, weighted f(pRaster - centre) / ∫f
  // (the same measurement the pixel's own filter-importance-sampled samples make), ∫f taken over
  // the part of the support inside the image. Thread-safe.
  void add(const Point2f& pRaster, const Spectrum& v);
  // The sum of the splats on a pixel.
  Spectrum sum(const Point2i& pixel) const;
  // Splats refused as too large or not finite.
  uint64_t refused() const { return refused_.load(); }

 private:
  void addToPixel(const Point2i& pixel, const Spectrum& v);
  size_t index(const Point2i& pixel) const;  // pixel must be inside bounds_

  Bounds2i bounds_;
  const Filter& filter_;
  // Per pixel of bounds_, ∫f over the part of its support inside the image.
  std::vector<Float> filterIntegrals_;
  Float maxLuminance_;
  // Per pixel and channel, the hi and lo words (6 atomics a pixel).
  std::unique_ptr<std::atomic<int64_t>[]> words_;
  std::atomic<uint64_t> refused_{0};
};

}  // namespace candela
