// A BxDF times a spectrum, for mixing materials (pbrt-v2's "mix"): the scale multiplies values,
// never the pdf, so sampling stays that of the wrapped BxDF.
#pragma once

#include <algorithm>

#include "reflection/bxdf.h"

namespace candela {

class ScaledBxDF : public BxDF {
 public:
  ScaledBxDF(const BxDF* bxdf, const Spectrum& scale)
      : BxDF(bxdf->type()), bxdf_(bxdf), scale_(scale) {}
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override {
    return scale_ * bxdf_->f(wo, wi);
  }
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override {
    return scale_ * bxdf_->sampleF(wo, wi, u, pdf, sampledType);
  }
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override { return bxdf_->pdf(wo, wi); }
  std::optional<Float> selectionWeight(const Vector3f& wo) const override {
    std::optional<Float> w = bxdf_->selectionWeight(wo);
    if (w) *w *= std::max(Float(0), scale_.average());
    return w;
  }
  bool choosesLobe() const override { return bxdf_->choosesLobe(); }
  Spectrum sampleChoosing(const Vector3f& wo, Vector3f* wi, Float uChoice, const Point2f& u,
                          Float* pdf, BxDFType* sampledType = nullptr) const override {
    return scale_ * bxdf_->sampleChoosing(wo, wi, uChoice, u, pdf, sampledType);
  }
  Spectrum rho(const Vector3f& wo, std::span<const Point2f> u) const override {
    return scale_ * bxdf_->rho(wo, u);
  }
  Spectrum rho(std::span<const Point2f> u1, std::span<const Point2f> u2) const override {
    return scale_ * bxdf_->rho(u1, u2);
  }

 private:
  const BxDF* bxdf_;
  Spectrum scale_;
};

}  // namespace candela
