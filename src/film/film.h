// The film: pixel storage for the cropped region of the image (lrt draft §8.1). Each pixel is
// written only by the task rendering it, so no locking is needed and the sum order is fixed.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/bounds.h"
#include "core/image_buffer.h"
#include "core/spectrum.h"
#include "film/aov.h"
#include "film/splat_buffer.h"
#include "filters/filter.h"

namespace candela {

class Film {
 public:
  // cropWindow in NDC [x0, x1] x [y0, y1]; pixel bounds per the lrt draft §8.1: x from
  // ceil(xres * x0) to ceil(xres * x1), likewise in y. The window is clamped to [0, 1] and its
  // corners ordered first; a window that covers no pixel leaves pixelBounds() empty.
  Film(const Point2i& fullResolution, const Bounds2f& cropWindow, std::unique_ptr<Filter> filter,
       std::string filename);
  // The pixel bounds a film of this resolution and crop window has, without making it.
  static Bounds2i pixelBoundsOf(const Point2i& fullResolution, const Bounds2f& cropWindow);
  const Point2i& fullResolution() const { return fullResolution_; }
  const Bounds2i& pixelBounds() const { return pixelBounds_; }
  const Filter& filter() const { return *filter_; }
  const std::string& filename() const { return filename_; }
  const Bounds2f& cropWindow() const { return cropWindow_; }

  // pbrt-v3's Film "scale": every pixel value (the samples' mean and the splats) is multiplied by
  // it; the variance by its square.
  void setScale(Float scale) { scale_ = scale; }
  Float scale() const { return scale_; }
  // pbrt-v3's Film "maxsampleluminance": a sample or splat whose luminance (Spectrum::y) exceeds
  // it is scaled down to that luminance before it is added. Set before enableSplats.
  void setMaxSampleLuminance(Float maxY) { maxSampleLuminance_ = maxY; }
  Float maxSampleLuminance() const { return maxSampleLuminance_; }
  // pbrt-v3's Film "diagonal" in millimetres (its realistic camera's film size; kept for one).
  void setDiagonal(Float mm) { diagonalMm_ = mm; }
  Float diagonal() const { return diagonalMm_; }

  // Extra layers to write (AovFlag bits); allocates their storage.
  void enableAovs(unsigned flags);
  unsigned aovs() const { return aovFlags_; }
  // The first-hit AOVs of one sample (only when kAovGeometric bits are enabled).
  void addAovSample(const Point2i& pixel, const AovSample& s, Float weight);

  // Light splatted from other pixels' samples (see SplatBuffer): allocated on first call. Each
  // pixel's value gains the splats' sum times fullResolution's pixel count over the number of
  // light paths the renderer reported with addLightPaths. Splats land within sampledArea (in
  // raster space; by default the full image; see SplatBuffer for the image edges).
  SplatBuffer& enableSplats();
  SplatBuffer& enableSplats(const Bounds2f& sampledArea);
  // The raster area whose pixels' filters reach: the full image grown by the filter's radius less
  // half a pixel. A renderer that places its own film points there (Metropolis) splats every
  // pixel exactly as the pixel's own filtered samples would, up to the image edges.
  Bounds2f filterSupportArea() const;
  SplatBuffer* splats() { return splats_.get(); }
  void addLightPaths(uint64_t n) { lightPaths_ += n; }
  // What a splat sum is multiplied by: full-resolution pixels / light paths (0 before any).
  double splatScale() const {
    return lightPaths_ ? double(fullResolution_.x) * double(fullResolution_.y) / double(lightPaths_)
                       : 0;
  }

  // weight is the filter sample's weight; alpha 1 where a surface was hit. L is clamped to
  // maxSampleLuminance first.
  void addSample(const Point2i& pixel, const Spectrum& L, Float alpha, Float weight);
  // Replaces whatever the pixel holds by one sample of weight 1: for renderers that keep their
  // own per-pixel estimate and write it out whole (SPPM; not clamped, as pbrt-v3 sets its image
  // directly). Ignored outside the pixel bounds.
  void setPixel(const Point2i& pixel, const Spectrum& L, Float alpha);
  // Weighted mean radiance of a pixel (black if it has no samples), plus its splats.
  Spectrum pixelValue(const Point2i& pixel) const;
  Float pixelAlpha(const Point2i& pixel) const;
  // Estimated variance of pixelValue (the variance of the weighted mean, from the samples' spread),
  // per channel; 0 with fewer than two samples.
  Spectrum pixelVariance(const Point2i& pixel) const;
  long pixelSampleCount(const Point2i& pixel) const;
  // R, G, B, A and the enabled AOV channels of the pixel bounds, top row first.
  ImageBuffer image() const;

  // What a pixel's samples added up to, from which its value, alpha and variance follow. A render
  // split by sample range (`--sample-range`) is put together by adding its pieces' sums.
  struct PixelSums {
    double rgbSum[3] = {0, 0, 0};
    double alphaSum = 0;
    double weightSum = 0;
    // For the variance of the weighted mean: sums of w^2 L^2, w^2 L and w^2.
    double w2L2Sum[3] = {0, 0, 0};
    double w2LSum[3] = {0, 0, 0};
    double w2Sum = 0;
    long count = 0;
  };
  // Zero sums outside the pixel bounds.
  PixelSums pixelSums(const Point2i& pixel) const;
  // Adds sums to a pixel's, as if its samples had been added here. Ignored outside the bounds.
  void addPixelSums(const Point2i& pixel, const PixelSums& sums);

 private:
  using Pixel = PixelSums;
  void accumulate(const Point2i& pixel, const Spectrum& L, Float alpha, Float weight);
  void writeAovs(const Point2i& p, float* out) const;
  size_t offset(const Point2i& p) const;  // p must be inside pixelBounds_
  Pixel& at(const Point2i& p) { return pixels_[offset(p)]; }
  const Pixel& at(const Point2i& p) const { return pixels_[offset(p)]; }

  Point2i fullResolution_;
  Bounds2f cropWindow_;
  Bounds2i pixelBounds_;
  std::unique_ptr<Filter> filter_;
  std::string filename_;
  std::vector<Pixel> pixels_;
  // Per-pixel first-hit sums, allocated only when such AOVs are enabled.
  struct AovPixel {
    double albedo[3] = {0, 0, 0};
    double normal[3] = {0, 0, 0};
    double position[3] = {0, 0, 0};
    double hitWeight = 0;
    Float depth = kInfinity;  // the nearest, as the lrt draft's film keeps it
  };
  unsigned aovFlags_ = 0;
  std::vector<AovPixel> aovPixels_;
  std::unique_ptr<SplatBuffer> splats_;
  uint64_t lightPaths_ = 0;
  Float scale_ = 1, maxSampleLuminance_ = kInfinity, diagonalMm_ = 35;
};

// The full resolution and crop window (NDC) that a Film statement's parameters give, as
// createFilm reads them; cropOverride replaces the scene's window. SceneErrors as createFilm.
struct FilmFrame {
  Point2i resolution;
  Bounds2f cropWindow;
};
FilmFrame filmFrame(const ParamSet& params, const FileLoc& loc,
                    std::optional<Bounds2f> cropOverride);

// The film named by a Film statement ("image"), with pbrt-v2's parameters: xresolution 640,
// yresolution 480, cropwindow [0 1 0 1], filename "candela.exr" (a filename given in the scene
// is kept as written), and pbrt-v3's: scale 1, maxsampleluminance (infinite), diagonal 35 (mm).
// cropOverride (the command line's) replaces the scene's cropwindow.
std::unique_ptr<Film> createFilm(const std::string& name, const ParamSet& params,
                                 std::unique_ptr<Filter> filter, const FileLoc& loc,
                                 std::optional<Bounds2f> cropOverride);

}  // namespace candela
