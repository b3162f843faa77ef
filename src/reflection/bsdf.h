// A set of BxDFs at a surface point with its shading frame (lrt draft §10.1). The geometric
// normal decides whether a pair of directions is reflection or transmission, which avoids light
// leaks through shading normals (Veach's fix).
#pragma once

#include "core/interaction.h"
#include "core/sampling.h"
#include "reflection/bxdf.h"

namespace candela {

class BSDF {
 public:
  static constexpr int kMaxBxDFs = 8;
  explicit BSDF(const SurfaceInteraction& si, Float eta_ = 1)
      : eta(eta_), ns_(si.shading.n), ss_(kUninitialized), ts_(kUninitialized), ng_(si.n) {
    // Gram-Schmidt dpdu against the shading normal; any frame when degenerate. Inline: made
    // once per path vertex, where the call was a tenth of its cost.
    Vector3f s = si.shading.dpdu - ns_ * dot(ns_, si.shading.dpdu);
    if (s.lengthSquared() > 1e-20f && std::isfinite(s.lengthSquared())) {
      ss_ = normalize(s);
      ts_ = cross(ns_, ss_);
    } else {
      coordinateSystem(ns_, &ss_, &ts_);
    }
  }
  // A BSDF of one Lambertian component, added here and never joined by another: its value,
  // density and sampled cosines depend on the directions' cosines to the shading normal alone, so
  // any frame about that normal serves, and the one without a square root or a cross product
  // (coordinateSystem; Duff et al. 2017) replaces the Gram-Schmidt frame of dp/du above.
  BSDF(const SurfaceInteraction& si, const LambertianReflection* lone)
      : eta(1), ns_(si.shading.n), ss_(kUninitialized), ts_(kUninitialized), ng_(si.n) {
    coordinateSystem(ns_, &ss_, &ts_);
    add(lone);
  }
  void add(const BxDF* b) {
    if (count_ < kMaxBxDFs) bxdfs_[count_++] = b;
    lambertian_ = nullptr;
  }
  // The same; a BSDF whose only component is Lambertian (matte's) then evaluates, samples and
  // gives densities in closed form, from the cosines alone, with the same results.
  void add(const LambertianReflection* b) {
    add(static_cast<const BxDF*>(b));
    if (count_ == 1) lambertian_ = b;
  }
  // Whether sampleF reads its u1: to pick among components, or for a lone component that
  // chooses lobes of its own. Integrators may skip computing the value otherwise.
  bool readsComponentValue() const {
    return count_ > 1 || (count_ == 1 && bxdfs_[0]->choosesLobe());
  }
  int numComponents(int flags = kAllBxDF) const {
    if (lambertian_) return lambertian_->matches(flags) ? 1 : 0;
    return countMatching(flags);
  }
  // The i-th added BxDF, 0 <= i < numComponents() (for materials that combine BSDFs: mix).
  const BxDF* component(int i) const { return bxdfs_[i]; }
  Vector3f worldToLocal(const Vector3f& v) const {
    return Vector3f(dot(v, ss_), dot(v, ts_), dot(v, ns_));
  }
  Vector3f localToWorld(const Vector3f& v) const {
    return Vector3f(ss_.x * v.x + ts_.x * v.y + ns_.x * v.z,
                    ss_.y * v.x + ts_.y * v.y + ns_.y * v.z,
                    ss_.z * v.x + ts_.z * v.y + ns_.z * v.z);
  }
  Spectrum f(const Vector3f& woW, const Vector3f& wiW, int flags = kAllBxDF) const {
    return lambertian_ ? lambertianF(woW, wiW, flags) : mixtureF(woW, wiW, flags);
  }
  // Picks a matching component with u1, samples it with u2, and (for non-specular picks) returns
  // the full mixture's value and pdf. The pick is uniform, or by the components' selection
  // weights when every matching one has one (a smooth dielectric's reflection and refraction:
  // by Fresnel); a component that chooses lobes of its own gets what is left of u1.
  Spectrum sampleF(const Vector3f& woW, Vector3f* wiW, Float u1, const Point2f& u2, Float* pdf,
                   int flags = kAllBxDF, BxDFType* sampledType = nullptr) const {
    if (lambertian_) return lambertianSampleF(woW, wiW, u2, pdf, flags, sampledType);
    return mixtureSampleF(woW, wiW, u1, u2, pdf, flags, sampledType);
  }
  // Mixture pdf over the matching components, each by the probability sampleF picks it with
  // (the draft averages over all; the matching components are what sampleF picks from).
  Float pdf(const Vector3f& woW, const Vector3f& wiW, int flags = kAllBxDF) const {
    return lambertian_ ? lambertianPdf(woW, wiW, flags) : mixturePdf(woW, wiW, flags);
  }
  // Sums of the matching components' reflectances rho_hd(wo) and rho_hh (lrt draft §10.1); of a
  // component that models both sides, the side flags ask for.
  Spectrum rho(const Vector3f& woW, std::span<const Point2f> u, int flags = kAllBxDF) const;
  Spectrum rho(std::span<const Point2f> u1, std::span<const Point2f> u2,
               int flags = kAllBxDF) const;
  const Normal3f& geometricNormal() const { return ng_; }
  // The normal of the shading frame: the bumped one when the material bump-maps, which is the
  // normal the cosine of the rendering equation is taken against (pbrt 2e's dgShading.nn).
  Normal3f shadingNormal() const { return Normal3f(ns_); }
  const Float eta;

 private:
  // Whether (wo, wi) is a reflection, both on one side of the geometric normal, rather than a
  // transmission: what decides which components model it (Veach's fix for shading normals).
  bool reflects(const Vector3f& woW, const Vector3f& wiW) const {
    return dot(wiW, ng_) * dot(woW, ng_) > 0;
  }
  int countMatching(int flags) const;
  // The matching components in order and, when weighted, the probability sampleF picks each with
  // for wo (local); returns their count.
  struct Selection {
    const BxDF* bxdf[kMaxBxDFs];
    Float probability[kMaxBxDFs];
    bool weighted;
  };
  int selection(const Vector3f& wo, int flags, Selection* out) const;
  // Sums and averages over the matching components, each in the local frame.
  Spectrum mixtureF(const Vector3f& woW, const Vector3f& wiW, int flags) const;
  Spectrum mixtureSampleF(const Vector3f& woW, Vector3f* wiW, Float u1, const Point2f& u2,
                          Float* pdf, int flags, BxDFType* sampledType) const;
  Float mixturePdf(const Vector3f& woW, const Vector3f& wiW, int flags) const;
  // The lone Lambertian component: what the mixture's functions give for it, needing only the
  // directions' cosines to the shading normal (the local z).
  Spectrum lambertianF(const Vector3f& woW, const Vector3f& wiW, int flags) const;
  Spectrum lambertianSampleF(const Vector3f& woW, Vector3f* wiW, const Point2f& u, Float* pdf,
                             int flags, BxDFType* sampledType) const;
  Float lambertianPdf(const Vector3f& woW, const Vector3f& wiW, int flags) const;

  Vector3f ns_, ss_, ts_;
  Normal3f ng_;
  // Only the first count_ entries are set (left uninitialised: a BSDF is made per hit).
  const BxDF* bxdfs_[kMaxBxDFs];
  int count_ = 0;
  const LambertianReflection* lambertian_ = nullptr;  // set iff it is the only component
};

inline Spectrum BSDF::lambertianF(const Vector3f& woW, const Vector3f& wiW, int flags) const {
  if (!lambertian_->matches(flags) || dot(woW, ns_) == 0 || !reflects(woW, wiW)) return Spectrum(0);
  return lambertian_->value();
}

inline Float BSDF::lambertianPdf(const Vector3f& woW, const Vector3f& wiW, int flags) const {
  Float cosO = dot(woW, ns_), cosI = dot(wiW, ns_);
  if (!lambertian_->matches(flags) || cosO == 0) return 0;
  // BxDF::pdf's cosine density on wo's side.
  return cosO * cosI > 0 ? std::abs(cosI) * kInvPi : 0;
}

inline Spectrum BSDF::lambertianSampleF(const Vector3f& woW, Vector3f* wiW, const Point2f& u,
                                        Float* pdf, int flags, BxDFType* sampledType) const {
  *pdf = 0;
  if (sampledType) *sampledType = BxDFType(0);
  Float cosO = dot(woW, ns_);
  if (!lambertian_->matches(flags) || cosO == 0) return Spectrum(0);
  // BxDF::sampleF's cosine-weighted direction on wo's side.
  Vector3f wi = sampleCosineHemisphere(u);
  if (cosO < 0) wi.z = -wi.z;
  *pdf = cosO * wi.z > 0 ? std::abs(wi.z) * kInvPi : 0;
  if (sampledType) *sampledType = lambertian_->type();
  if (*pdf == 0) return Spectrum(0);
  *wiW = localToWorld(wi);
  return reflects(woW, *wiW) ? lambertian_->value() : Spectrum(0);
}

}  // namespace candela
