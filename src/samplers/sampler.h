// Sample generation (lrt draft ch. 7). Every value a sampler returns is a pure function of (pixel,
// sample index, dimension, seed): startPixelSample positions it, so the image does not depend on
// the order in which pixels are rendered or on how they are split among threads.
#pragma once

#include <memory>

#include "core/vector.h"

namespace candela {

struct CameraSample {
  Point2f pFilm;  // raster position
  Point2f pLens;  // [0,1)^2
  Float time = 0; // [0,1), mapped onto the shutter interval by the camera
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

}  // namespace candela
