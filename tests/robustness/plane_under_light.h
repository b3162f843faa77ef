// Test helper: the radiance of a Lambertian plane under an isotropic point light at height h,
// (Kd / pi) I h / (h^2 + r^2)^(3/2) at distance r from the light's foot. A sphere light of
// radiance L and radius R wholly above the plane irradiates it as a point light of intensity
// pi L R^2 at its centre (pbrt 3e §12.5's cone of directions: pi sin^2 theta_max cos theta). The
// scenes view the square [-w, w]^2 around the foot from above with an orthographic camera, a box
// filter and spp samples uniform over each pixel.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "film/film.h"

namespace candela::test {

struct PlaneUnderLight {
  double kd = 0.5, intensity = 1, height = 1, halfWidth = 2;
  int spp = 64;
  double radiance(double x, double y) const {
    return kd / M_PI * intensity * height / std::pow(height * height + x * x + y * y, 1.5);
  }
};

// Every pixel against the mean of the closed form over the pixel, within 5 of its standard
// errors (the closed form's spread over the pixel / sqrt(spp); p = 6e-7 per pixel) plus 1e-5 of
// rounding; returns the largest deviation in standard errors. The closed form is radially
// symmetric, so the image's orientation does not matter.
inline double worstPixelAgainstClosedForm(const Film& film, const PlaneUnderLight& light,
                                          const std::string& what) {
  ImageBuffer image = film.image();
  const int q = 32;
  double worst = 0, w = light.halfWidth;
  for (int py = 0; py < image.height; ++py)
    for (int px = 0; px < image.width; ++px) {
      double sum = 0, sum2 = 0;
      for (int j = 0; j < q; ++j)
        for (int i = 0; i < q; ++i) {
          double x = -w + 2 * w * (px + (i + 0.5) / q) / image.width;
          double y = -w + 2 * w * (py + (j + 0.5) / q) / image.height;
          double l = light.radiance(x, y);
          sum += l;
          sum2 += l * l;
        }
      double mean = sum / (q * q), spread = std::sqrt(std::max(0.0, sum2 / (q * q) - mean * mean));
      double sigma = spread / std::sqrt(double(light.spp)) + 1e-5 * mean;
      double got = image.at(px, py, 1);
      EXPECT_TRUE(std::isfinite(got)) << what;
      EXPECT_LE(std::abs(got - mean), 5 * sigma)
          << what << ": pixel (" << px << ", " << py << ") " << got << ", closed form " << mean;
      worst = std::max(worst, std::abs(got - mean) / sigma);
    }
  return worst;
}

}  // namespace candela::test
