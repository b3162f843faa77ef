// Isotropic BRDFs measured at scattered direction pairs, in pbrt-v2's text format (the
// "measured" material's .brdf files): numbers separated by white space, '#' to the end of a line
// a comment; first the count n of wavelengths, then the n wavelengths (nm), then records of
// theta_i phi_i theta_o phi_o (radians) followed by the n spectral BRDF values.
// Lookups follow pbrt 2e §8.6: every pair is reduced to Marschner's point
// (sin theta_i sin theta_o, dphi / pi, cos theta_i cos theta_o), and f is the Gaussian-weighted
// mean of all samples within a radius of that point that grows until enough samples are inside.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "reflection/bxdf.h"
#include "reflection/point_kdtree.h"

namespace candela {

struct IrregularBrdfSample {
  Vector3f wi, wo;  // both in the +z hemisphere
  Spectrum value;   // as measured (not clamped: the book clamps the weighted sum)
};

// One lookup's result with how it was found, for tests and diagnostics.
struct IrregularBrdfEstimate {
  Spectrum value;
  int found = 0;      // samples averaged
  Float radius2 = 0;  // squared search radius the growth stopped at
};

// The table with its search structure. Immutable once made; materials share one per file.
class IrregularBrdfTable {
 public:
  // pbrt 2e §8.6: the squared radius starts at kStartRadius2 and doubles until at least
  // kEnoughSamples samples lie strictly inside it, or until the squared radius just searched
  // exceeds kLastRadius2 (then the samples found, maybe none, are used: 0 when none). Samples are
  // weighted by exp(-kFalloff d^2), d their distance from the query's point.
  static constexpr Float kStartRadius2 = 0.001f;
  static constexpr Float kLastRadius2 = 1.5f;
  static constexpr int kEnoughSamples = 3;
  static constexpr double kFalloff = 100;

  explicit IrregularBrdfTable(std::vector<IrregularBrdfSample> samples);
  // f(wo, wi); 0 unless both are on the same side (two-sided). Exactly reciprocal: both orders
  // reduce to the same point.
  Spectrum lookup(const Vector3f& wo, const Vector3f& wi) const { return estimate(wo, wi).value; }
  IrregularBrdfEstimate estimate(const Vector3f& wo, const Vector3f& wi) const;
  const std::vector<IrregularBrdfSample>& samples() const { return samples_; }

  // Marschner's reduction of an isotropic, reciprocal pair (pbrt 2e §8.6): the products of the
  // polar sines and cosines, and the azimuth difference folded into [0, pi] (isotropy makes its
  // sign irrelevant) over pi. Symmetric in a and b; the same for a pair mirrored below the surface.
  static PointKdTree<3>::Point reduce(const Vector3f& a, const Vector3f& b);

 private:
  std::vector<IrregularBrdfSample> samples_;
  PointKdTree<3> tree_;  // point k is sample k reduced
};

// Turns spectral samples (wavelengths in nm, values) into RGB. The scene reader's reflectance
// conversion (parser/spectrum_input.h, SpectrumUse::Reflectance) is the one to pass; reflection
// sits below the scene module and does not call it itself.
using SpectrumToRGB =
    std::function<Spectrum(std::span<const Float> lambdaNm, std::span<const Float> values)>;

// Reads a pbrt-v2 .brdf text file; throws FileError naming the path (and the record) when it
// cannot be read or is malformed. Out-of-gamut (negative) RGB values are kept: lookups clamp.
IrregularBrdfTable readIrregularBrdf(const std::string& path, const SpectrumToRGB& toRGB);
// The same from the file's text; path is used only in error messages.
IrregularBrdfTable parseIrregularBrdf(std::string_view text, const std::string& path,
                                      const SpectrumToRGB& toRGB);

// The table as a BxDF, sampled by the default cosine-weighted hemisphere as in pbrt 2e.
class IrregularMeasuredBRDF : public BxDF {
 public:
  explicit IrregularMeasuredBRDF(const IrregularBrdfTable* table)
      : BxDF(BxDFType(kReflection | kGlossy)), table_(table) {}
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override {
    return table_->lookup(wo, wi);
  }

 private:
  const IrregularBrdfTable* table_;
};

}  // namespace candela
