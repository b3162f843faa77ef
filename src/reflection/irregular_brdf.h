// Isotropic BRDFs measured at scattered direction pairs, in pbrt-v2's text format (the
// "measured" material's .brdf files): numbers separated by white space, '#' to the end of a line
// a comment; first the count n of wavelengths, then the n wavelengths (nm), then records of
// theta_i phi_i theta_o phi_o (radians) followed by the n spectral BRDF values. Lookups
// interpolate the nearest samples found with a kd-tree over an embedding of direction pairs.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "reflection/bxdf.h"
#include "reflection/point_kdtree.h"

namespace candela {

struct IrregularBrdfSample {
  Vector3f wi, wo;  // both in the +z hemisphere
  Spectrum value;
};

// The table with its search structure. Immutable once made; materials share one per file.
class IrregularBrdfTable {
 public:
  // Pairs in (pair embedding) space whose value are interpolated for each lookup.
  static constexpr int kNeighbours = 8;

  explicit IrregularBrdfTable(std::vector<IrregularBrdfSample> samples);
  // f(wo, wi), averaged over both orders of the pair so that it is exactly reciprocal; 0 unless
  // both are on the same side (two-sided).
  Spectrum lookup(const Vector3f& wo, const Vector3f& wi) const;
  // Interpolation in one order only, (a, b) taken as (wi, wo) of the samples; the difference
  // between the two orders measures how far the data are from reciprocal.
  Spectrum lookupOrdered(const Vector3f& a, const Vector3f& b) const;
  const std::vector<IrregularBrdfSample>& samples() const { return samples_; }

  // An isotropic pair seen from a frame that puts a at azimuth 0 and b at azimuth in [0, pi]:
  // (a.x, a.z, b.x, b.y, b.z) there. Distances are chord lengths between directions.
  static PointKdTree<5>::Point embed(const Vector3f& a, const Vector3f& b);

 private:
  std::vector<IrregularBrdfSample> samples_;
  PointKdTree<5> tree_;  // point 2k is sample k as (wi, wo), point 2k + 1 as (wo, wi)
};

// Turns spectral samples (wavelengths in nm, values) into RGB. The scene reader's reflectance
// conversion (scene/spectrum_input.h, SpectrumUse::Reflectance) is the one to pass; reflection
// sits below the scene module and does not call it itself.
using SpectrumToRGB =
    std::function<Spectrum(std::span<const Float> lambdaNm, std::span<const Float> values)>;

// Reads a pbrt-v2 .brdf text file; throws FileError naming the path (and the record) when it
// cannot be read or is malformed. Negative RGB results (out of gamut) are clamped to 0.
IrregularBrdfTable readIrregularBrdf(const std::string& path, const SpectrumToRGB& toRGB);

// The table as a BxDF, sampled by the default cosine-weighted hemisphere (pdf consistent).
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
