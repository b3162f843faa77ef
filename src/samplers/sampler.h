// Sample generation (lrt draft ch. 7). Every value a sampler returns is a pure function of (pixel,
// sample index, dimension, seed): startPixelSample positions it, so the image does not depend on
// the order in which pixels are rendered or on how they are split among threads.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/paramset.h"
#include "core/vector.h"

namespace candela {

class Filter;

struct CameraSample {
  Point2f pFilm;   // raster position
  Point2f pLens;   // [0,1)^2
  Float time = 0;  // [0,1), mapped onto the shutter interval by the camera
  Float filterWeight = 1;
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
  // The position within the pixel (the first dimensions of each sample).
  virtual Point2f getPixel2D() = 0;
};

// The camera sample for one pixel sample (pbrt 4e §5.2.2): the film position is the pixel centre
// plus an offset drawn from the filter, whose weight goes with it to the film; then time, then
// the lens position, in that order of dimensions.
CameraSample getCameraSample(Sampler& sampler, const Point2i& pixel, const Filter& filter);

// The sampler named by a Sampler statement: "random" or "stratified". sppOverride > 0 replaces
// the scene's sample count (the stratified sampler picks xsamples x ysamples = sppOverride, as
// square as it divides). Unknown names and bad counts are SceneErrors at loc.
std::unique_ptr<Sampler> createSampler(const std::string& name, const ParamSet& params,
                                       uint64_t seed, int sppOverride, const FileLoc& loc);

}  // namespace candela
