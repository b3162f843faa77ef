// Image error against a reference, and the error a render can estimate from its own per-pixel
// variance when there is no reference. Channels R, G, B over the film's pixel bounds.
#pragma once

#include "core/image_buffer.h"
#include "film/film.h"

namespace candela {

// relMSE's denominator offset: (x - ref)^2 / (ref^2 + kRelMseEpsilon).
inline constexpr double kRelMseEpsilon = 1e-2;

struct ErrorMetrics {
  double mse = 0;
  double relmse = 0;
  double rmse = 0;
  double maxAbsError = 0;
  // Half-width of a 95% confidence interval of relMSE from the per-pixel variances: for an
  // unbiased estimator each pixel's squared error has mean var and variance ~2 var^2 (normal
  // errors), summed over the pixels.
  double relmseCi95 = 0;
  // The relMSE the per-pixel variances predict: mean of var / (ref^2 + eps).
  double relmseFromVariance = 0;
};

// Against a reference image: a full-frame reference (fullWidth x fullHeight of the film) or one
// that covers exactly the film's pixel bounds. Throws std::invalid_argument when its size fits
// neither or it lacks R, G, B.
ErrorMetrics compareToReference(const Film& film, const ImageBuffer& reference);

// Without a reference: relMSE predicted from the variances, with the image itself standing in for
// the reference in the denominators. mse/rmse are the mean variance; maxAbsError is 0. Infinite
// while any pixel has fewer than two samples.
ErrorMetrics estimateFromVariance(const Film& film);

// One pixel's relMSE as its own samples predict it: the mean over R, G, B of var / (value^2 +
// kRelMseEpsilon), the pixel's value standing in for the reference. Infinite with fewer than two
// samples. Its square root is the pixel's noise as adaptive sampling measures it.
double estimatePixelRelMse(const Film& film, const Point2i& pixel);

// Two finished images of one size (R, G, B looked up by name), as `candela compare` measures
// renderers against each other: relMSE against the mean of one or two references; with two
// (independent renders of the same scene) also their own noise, the relMSE their mean adds to
// any image measured against it, E[(r1 - r2)^2] / 4 per value, which `relmse` then has taken
// off (relmseRaw keeps it). outlierShare is the fraction of relMSE (before that correction) in
// the worstPixels pixels of largest relative squared error summed over R, G, B: fireflies show
// as a few pixels holding most of it. Throws std::invalid_argument for mismatched images.
struct ImageComparison {
  double relmse = 0, relmseRaw = 0, referenceNoise = 0, mse = 0;
  double outlierShare = 0;
  int worstPixels = 0;
  double mean[3] = {0, 0, 0}, referenceMean[3] = {0, 0, 0};
};
ImageComparison compareImages(const ImageBuffer& image, const ImageBuffer& reference,
                              const ImageBuffer* secondReference, int worstPixels);

}  // namespace candela
