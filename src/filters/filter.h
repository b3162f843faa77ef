// Pixel reconstruction filters (lrt draft §7.7). Samples are placed by importance sampling the
// filter (pbrt 4e §8.8) rather than splatted to neighbouring pixels, so each pixel depends only on
// its own samples: the image is the same bits for any tile size, thread count or crop window.
// (Light splatted from other pixels' samples, as bdpt's t = 1 strategy makes, goes to a separate
// SplatBuffer that weights it by f / ∫f.)
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/bounds.h"
#include "core/paramset.h"
#include "core/sampling.h"

namespace candela {

struct FilterSample {
  Point2f p;     // offset from the pixel centre, within the radius
  Float weight;  // f(p) / pdf(p); constant for filters without negative lobes
};

class Filter {
 public:
  explicit Filter(const Vector2f& radius) : radius_(radius) {}
  virtual ~Filter() = default;
  Filter(const Filter&) = delete;
  Filter& operator=(const Filter&) = delete;

  const Vector2f& radius() const { return radius_; }
  virtual Float evaluate(const Point2f& p) const = 0;
  // Offset distributed in proportion to |f|, from a tabulated distribution built on first use;
  // filters whose |f| has a closed-form inverse sample it directly.
  virtual FilterSample sample(const Point2f& u) const;
  // The integral of f over its support, by numerical quadrature on the table.
  Float integral() const;
  // The same quadrature over the part of the support inside `offsets` (offsets from the centre):
  // the table cells whose centres lie in it. Over the whole support it equals integral().
  Float integralOver(const Bounds2f& offsets) const;

  // The sampling table's resolution (cells per axis over [-r, r]).
  int tableWidth() const { return nx_; }
  int tableHeight() const { return ny_; }

 protected:
  // Concrete filters call this at the end of their constructor.
  void buildSamplingTable();

 private:
  Vector2f radius_;
  std::vector<Float> table_;  // f on a grid over [-r, r]^2
  // Its summed-area table, (nx + 1) x (ny + 1): integralOver in constant time per query (splat
  // buffers ask once for every pixel near the image's edge).
  std::vector<double> prefix_;
  int nx_ = 0, ny_ = 0;
  std::unique_ptr<Distribution2D> distribution_;
  Float integral_ = 0;
};

// The filter named by a PixelFilter statement: "box", "gaussian", "mitchell", "triangle" or
// "sinc", with pbrt-v2's parameter names and defaults. An unknown name or a bad value is a
// SceneError at loc.
std::unique_ptr<Filter> createFilter(const std::string& name, const ParamSet& params,
                                     const FileLoc& loc);

}  // namespace candela
