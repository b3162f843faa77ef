// The BSDF of a tabulated Fourier file (pbrt 3e §8.6): both reflection and transmission in one
// BxDF, glossy. Evaluation interpolates each channel's series between the 4 x 4 nearest
// (mu_i, mu_o) nodes with Catmull-Rom weights and sums it at the azimuth difference; three
// channels are Y, R and B, from which G follows. Sampling (pbrt 3e §8.6.2) draws mu_i from the
// spline of a_0 over mu_i at the given mu_o, then phi from the interpolated luminance series, so
// the density is proportional to f |cos theta_i| up to interpolation.
#pragma once

#include "reflection/bxdf.h"
#include "reflection/fourier_bsdf_table.h"

namespace candela {

class FourierBSDF : public BxDF {
 public:
  explicit FourierBSDF(const FourierBsdfTable* table)
      : BxDF(BxDFType(kReflection | kTransmission | kGlossy)), table_(table) {}
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
  // *sampledType is the lobe the direction fell in: reflection or transmission, glossy.
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override;

 private:
  const FourierBsdfTable* table_;
};

}  // namespace candela
