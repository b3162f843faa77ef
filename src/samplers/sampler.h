// Sample generation (lrt draft ch. 7). Every value a sampler returns is a pure function of (pixel,
// sample index, dimension, seed): startPixelSample positions it, so the image does not depend on
// the order in which pixels are rendered or on how they are split among threads.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

#include "core/paramset.h"
#include "core/spectrum.h"
#include "core/vector.h"

namespace candela {

class Filter;

struct CameraSample {
  Point2f pFilm;   // raster position
  Point2f pLens;   // [0,1)^2
  Float time = 0;  // [0,1), mapped onto the shutter interval by the camera
  Float filterWeight = 1;
};

// What one pixel sample gave, for adaptive sampling's decision.
struct PixelSampleResult {
  Spectrum L;
  uint64_t surfaceId = 0;  // the surface the camera ray hit, as the renderer numbers them; 0: none
};

class Sampler {
 public:
  virtual ~Sampler() = default;
  virtual int samplesPerPixel() const = 0;
  // A fresh sampler with the same parameters and seed, for another thread.
  virtual std::unique_ptr<Sampler> clone() const = 0;
  virtual void startPixelSample(const Point2i& pixel, int sampleIndex) = 0;
  virtual Float get1D() = 0;
  virtual Point2f get2D() = 0;
  // Pass over the next values, for a caller that would not read them: the values after them are
  // those that follow get1D / get2D. By default drawn and dropped; a sampler that can skip the
  // work overrides (the Halton sampler).
  virtual void skip1D() { get1D(); }
  virtual void skip2D() { get2D(); }
  // The position within the pixel (the first dimensions of each sample).
  virtual Point2f getPixel2D() = 0;

  // Adaptive sampling (pbrt-v2's AdaptiveSampler): a renderer that supports it takes samples
  // [0, initialSamplesPerPixel()) of a pixel first, and the rest up to samplesPerPixel() only
  // when needsMoreSamples says so for what the first ones gave. The decision depends on the
  // pixel's own samples only, so the image stays independent of the rendering order. Other
  // samplers take every sample: these defaults.
  virtual int initialSamplesPerPixel() const { return samplesPerPixel(); }
  virtual bool needsMoreSamples(std::span<const PixelSampleResult> /*initial*/) const {
    return false;
  }
};

using SamplerWarning = std::function<void(const FileLoc&, const std::string&)>;

// The camera sample for one pixel sample (pbrt 4e §5.2.2): the film position is the pixel centre
// plus an offset drawn from the filter, whose weight goes with it to the film; then time, then
// the lens position, in that order of dimensions. Without `lens` the lens dimensions are still
// taken (the later ones keep their numbers) but pLens is left at (0, 0), for a camera that does
// not read it; a sampler may then skip computing them.
CameraSample getCameraSample(Sampler& sampler, const Point2i& pixel, const Filter& filter,
                             bool lens = true);

// Passes over the dimensions getCameraSample takes after the pixel's (time, lens), for a sample
// started again after its camera sample was taken: the values after are the same.
inline void skipCameraSample(Sampler& sampler) {
  sampler.skip1D();
  sampler.skip2D();
}

// The sampler named by a Sampler statement: pbrt-v2's "random", "stratified", "lowdiscrepancy",
// "halton", "bestcandidate" and "adaptive", and pbrt-v3's "02sequence", "maxmindist" and "sobol".
// sppOverride > 0 replaces the scene's sample count (the stratified sampler picks xsamples x
// ysamples = sppOverride, as square as it divides; the adaptive sampler takes it as maxsamples).
// Counts the (0,2)-sequence, max-min-distance and Sobol' samplers cannot use are rounded up to a
// power of two with a warning, to warn or, when it is empty, to standard error. Unknown names and
// bad counts are SceneErrors at loc. Counts a scene leaves out are its dialect's: pbrt-v2's
// (halton 4 samples, stratified 2 x 2) or pbrt-v3's (halton 16, stratified 4 x 4); the others
// agree.
enum class SamplerDefaults { PbrtV2, PbrtV3 };
std::unique_ptr<Sampler> createSampler(const std::string& name, const ParamSet& params,
                                       uint64_t seed, int sppOverride, const FileLoc& loc,
                                       const SamplerWarning& warn = {},
                                       SamplerDefaults defaults = SamplerDefaults::PbrtV2);

}  // namespace candela
