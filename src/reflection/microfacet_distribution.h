// Microfacet normal distributions for the Torrance-Sparrow model (lrt draft §9.4.3-9.4.4) and
// their importance sampling (lrt draft §15.3). D is normalised over projected area,
// integral of D(wh) cos theta_h dwh = 1 (lrt draft eq. 9.4.9); sampling draws half vectors from
// a separate solid-angle density pdfWh, and the draft's pdfs lacked its 1 / (2 pi) (lrt draft
// §24). Both are symmetric about the surface: they use |cos theta_h|.
#pragma once

#include "reflection/bxdf.h"

namespace candela {

class MicrofacetDistribution {
 public:
  virtual ~MicrofacetDistribution() = default;
  virtual Float d(const Vector3f& wh) const = 0;
  // A half vector in the +z hemisphere with solid-angle density pdfWh.
  virtual Vector3f sampleWh(const Point2f& u) const = 0;
  virtual Float pdfWh(const Vector3f& wh) const = 0;

  // wi = wo reflected about a sampled half vector turned to wo's side; *pdf is its density,
  // pdfWh / (4 |wo . wh|) by the change of variables from half vector to direction (lrt draft
  // §15.3.1). wi may land on the other side of the surface; callers reject it.
  Vector3f sampleWi(const Vector3f& wo, const Point2f& u, Float* pdf) const;
  // The density of sampleWi's result, for any wi.
  Float pdf(const Vector3f& wo, const Vector3f& wi) const;
};

// The half vector (wo + wi) / |wo + wi|, normalised in double; false when wi = -wo. The
// microfacet BxDFs' f and the distributions' pdf take it from here: cos^e theta_h with e up to
// 1e5 turns a float normalisation's rounding into a relative error of 1e-3, and f and pdf
// rounding differently made f |cos| / pdf 1.8 for samples of exponent 1e7 (an albedo of 1.39).
bool halfVector(const Vector3f& wo, const Vector3f& wi, Vector3f* wh);

// Blinn's D = (e + 2) / (2 pi) cos^e theta_h (lrt draft eq. 9.4.9); sampling draws
// cos theta_h = u^(1 / (e + 1)), density (e + 1) / (2 pi) cos^e theta_h. The draft's roughness r
// maps to e = 1 / r.
class BlinnDistribution final : public MicrofacetDistribution {
 public:
  explicit BlinnDistribution(Float exponent) : e_(std::max(Float(0), exponent)) {}
  Float d(const Vector3f& wh) const override;
  Vector3f sampleWh(const Point2f& u) const override;
  Float pdfWh(const Vector3f& wh) const override;
  Float exponent() const { return e_; }

 private:
  Float e_;
};

// Ashikhmin and Shirley's anisotropic distribution (lrt draft §9.4.4): exponent ex along x and ey
// along y, e(phi) = ex cos^2 phi + ey sin^2 phi. Over projected area
// integral dphi / (e(phi) + 2) = 2 pi / sqrt((ex + 2)(ey + 2)), so
// D = sqrt((ex + 2)(ey + 2)) / (2 pi) cos^e(phi) theta_h; the draft's D had no 1 / (2 pi).
// Sampling is Ashikhmin and Shirley's quadrant by quadrant inversion with density
// sqrt((ex + 1)(ey + 1)) / (2 pi) cos^e(phi) theta_h (the draft misprinted the square root as a
// product, lrt draft §24).
class AnisotropicDistribution final : public MicrofacetDistribution {
 public:
  AnisotropicDistribution(Float ex, Float ey)
      : ex_(std::max(Float(0), ex)), ey_(std::max(Float(0), ey)) {}
  Float d(const Vector3f& wh) const override;
  Vector3f sampleWh(const Point2f& u) const override;
  Float pdfWh(const Vector3f& wh) const override;

 private:
  // e(phi) without computing phi: cos^2 phi = x^2 / sin^2 theta (lrt draft §9.4.4).
  Float exponent(const Vector3f& wh) const;
  Float ex_, ey_;
};

}  // namespace candela
