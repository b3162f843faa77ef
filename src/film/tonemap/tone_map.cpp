#include "film/tonemap/tone_map.h"

#include <cmath>
#include <vector>

namespace candela {

namespace {

constexpr double kLumensPerWatt = 683;

double luminance(const ImageBuffer& img, int x, int y) {
  return kLumensPerWatt *
         (0.212671 * img.at(x, y, 0) + 0.715160 * img.at(x, y, 1) + 0.072169 * img.at(x, y, 2));
}

std::vector<double> luminances(const ImageBuffer& img) {
  std::vector<double> Y(size_t(img.width) * img.height);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      Y[size_t(y) * img.width + x] = std::max(0.0, luminance(img, x, y));
  return Y;
}

// exp(mean(log Y)) over the pixels with Y > 0 (the log-average "world adaptation" luminance).
double logAverage(const std::vector<double>& Y) {
  double sum = 0;
  long n = 0;
  for (double v : Y)
    if (v > 0) sum += std::log(v), ++n;
  return n > 0 ? std::exp(sum / double(n)) : 1;
}

void scalePixels(ImageBuffer& img, const std::vector<double>& scale) {
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) *= float(scale[size_t(y) * img.width + x]);
}

// Box averages of Y over (2r+1)^2 windows, clamped at the borders, from a summed-area table.
class BoxAverages {
 public:
  BoxAverages(const std::vector<double>& Y, int w, int h)
      : w_(w), h_(h), sat_(size_t(w + 1) * (h + 1), 0) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        sat_[idx(x + 1, y + 1)] =
            Y[size_t(y) * w + x] + sat_[idx(x, y + 1)] + sat_[idx(x + 1, y)] - sat_[idx(x, y)];
  }
  double average(int x, int y, int r) const {
    int x0 = std::max(0, x - r), x1 = std::min(w_, x + r + 1);
    int y0 = std::max(0, y - r), y1 = std::min(h_, y + r + 1);
    double s = sat_[idx(x1, y1)] - sat_[idx(x0, y1)] - sat_[idx(x1, y0)] + sat_[idx(x0, y0)];
    return s / double((x1 - x0) * (y1 - y0));
  }

 private:
  size_t idx(int x, int y) const { return size_t(y) * (w_ + 1) + x; }
  int w_, h_;
  std::vector<double> sat_;
};

}  // namespace

double highContrastCapacity(double Y) {
  if (Y < 0.0034) return Y / 0.0014;
  if (Y < 1) return 2.4483 + std::log(Y / 0.0034) / 0.4027;
  if (Y < 7.2444) return 16.563 + (Y - 1) / 0.4027;
  return 32.0693 + std::log(Y / 7.2444) / 0.0556;
}

void applyToneMap(ImageBuffer& img, const std::string& name, const ParamSet& params,
                  const FileLoc& loc) {
  if (img.channelCount() < 3) return;
  std::vector<double> Y = luminances(img);
  const double maxDisplayY = params.getOneFloat("maxdisplayY", 100);
  std::vector<double> scale(Y.size(), 1);
  double Ymax = 0;
  for (double v : Y) Ymax = std::max(Ymax, v);
  if (name == "maxwhite") {
    // The brightest pixel goes to display white.
    double s = Ymax > 0 ? 1 / Ymax : 1;
    for (double& v : scale) v = s * kLumensPerWatt;
  } else if (name == "contrast") {
    // Ward's contrast-based factor: just noticeable differences preserved between the world
    // adaptation luminance and the display's (Blackwell's threshold model).
    double Yda = params.getOneFloat("displayadaptationY", 50);
    double Ywa = logAverage(Y);
    double s = std::pow((1.219 + std::pow(Yda, 0.4)) / (1.219 + std::pow(Ywa, 0.4)), 2.5);
    for (double& v : scale) v = s * kLumensPerWatt / maxDisplayY;
  } else if (name == "nonlinear") {
    // Reinhard et al.'s global operator with the key value 0.18 and a white point (in
    // scaled luminance) that maps to 1: the largest by default.
    double Ywa = logAverage(Y);
    double white = params.getOneFloat("maxY", 0);
    double Lwhite = white > 0 ? 0.18 * white * kLumensPerWatt / Ywa : 0.18 * Ymax / Ywa;
    for (size_t i = 0; i < Y.size(); ++i) {
      if (Y[i] <= 0) continue;
      double Lm = 0.18 * Y[i] / Ywa;
      double Ld = Lm * (1 + Lm / (Lwhite * Lwhite)) / (1 + Lm);
      scale[i] = Ld / Y[i] * kLumensPerWatt;
    }
  } else if (name == "highcontrast") {
    // Ashikhmin's operator: the capacity curve maps a local adaptation luminance to display
    // luminance. The local adaptation is a box average whose size grows until the local contrast
    // between it and the next larger average exceeds 0.5 (the draft uses a MIP pyramid; box
    // averages over a summed-area table give the same quantity at 1-pixel steps).
    double Ymin = Ymax;
    for (double v : Y)
      if (v > 0) Ymin = std::min(Ymin, v);
    double cMin = highContrastCapacity(Ymin), cMax = highContrastCapacity(Ymax);
    BoxAverages box(Y, img.width, img.height);
    const int maxRadius = 32;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        size_t i = size_t(y) * img.width + x;
        if (Y[i] <= 0 || cMax <= cMin) continue;
        double Ya = box.average(x, y, 0);
        for (int r = 1; r <= maxRadius; ++r) {
          double b1 = box.average(x, y, r), b2 = box.average(x, y, 2 * r);
          if (b1 > 0 && std::abs((b1 - b2) / b1) > 0.5) break;
          Ya = b1;
        }
        double Td = maxDisplayY * (highContrastCapacity(Ya) - cMin) / (cMax - cMin);
        scale[i] = Ya > 0 ? Td / Ya * kLumensPerWatt / maxDisplayY : 0;
      }
  } else {
    throw SceneError(loc, "unknown tone map '" + name +
                              "' (known: maxwhite, contrast, highcontrast, nonlinear)");
  }
  scalePixels(img, scale);
}

}  // namespace candela
