// A set of BxDFs at a surface point with its shading frame (lrt draft §10.1). The geometric
// normal decides whether a pair of directions is reflection or transmission, which avoids light
// leaks through shading normals (Veach's fix).
#pragma once

#include "core/interaction.h"
#include "reflection/bxdf.h"

namespace candela {

class BSDF {
 public:
  static constexpr int kMaxBxDFs = 8;
  explicit BSDF(const SurfaceInteraction& si, Float eta = 1);
  void add(const BxDF* b) {
    if (count_ < kMaxBxDFs) bxdfs_[count_++] = b;
  }
  int numComponents(int flags = kAllBxDF) const;
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
  Spectrum f(const Vector3f& woW, const Vector3f& wiW, int flags = kAllBxDF) const;
  // Picks a matching component with u1, samples it with u2, and (for non-specular picks) returns
  // the full mixture's value and pdf.
  Spectrum sampleF(const Vector3f& woW, Vector3f* wiW, Float u1, const Point2f& u2, Float* pdf,
                   int flags = kAllBxDF, BxDFType* sampledType = nullptr) const;
  // Mixture pdf over the matching components (the draft averages over all; the matching count is
  // what sampleF uses, so that is the consistent choice).
  Float pdf(const Vector3f& woW, const Vector3f& wiW, int flags = kAllBxDF) const;
  // Sums of the matching components' reflectances rho_hd(wo) and rho_hh (lrt draft §10.1).
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
  bool reflects(const Vector3f& woW, const Vector3f& wiW) const;

  Vector3f ns_, ss_, ts_;
  Normal3f ng_;
  const BxDF* bxdfs_[kMaxBxDFs] = {};
  int count_ = 0;
};

}  // namespace candela
