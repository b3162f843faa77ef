#include "reflection/bsdf.h"

namespace candela {

int BSDF::countMatching(int flags) const {
  int n = 0;
  for (int i = 0; i < count_; ++i)
    if (bxdfs_[i]->matches(flags)) ++n;
  return n;
}

namespace {
// Whether b models a pair of directions that reflect (or else transmit).
bool models(const BxDF& b, bool reflect) {
  return (b.type() & (reflect ? kReflection : kTransmission)) != 0;
}
}  // namespace

Spectrum BSDF::mixtureF(const Vector3f& woW, const Vector3f& wiW, int flags) const {
  Vector3f wi = worldToLocal(wiW), wo = worldToLocal(woW);
  if (wo.z == 0) return Spectrum(0);
  bool reflect = reflects(woW, wiW);
  Spectrum f(0);
  for (int i = 0; i < count_; ++i) {
    const BxDF* b = bxdfs_[i];
    if (b->matches(flags) && models(*b, reflect)) f += b->f(wo, wi);
  }
  return f;
}

Spectrum BSDF::mixtureSampleF(const Vector3f& woW, Vector3f* wiW, Float u1, const Point2f& u2,
                              Float* pdf, int flags, BxDFType* sampledType) const {
  int matching = countMatching(flags);
  *pdf = 0;
  if (sampledType) *sampledType = BxDFType(0);
  if (matching == 0) return Spectrum(0);
  int comp = std::min(int(u1 * matching), matching - 1);
  const BxDF* bxdf = nullptr;
  for (int i = 0, count = comp; i < count_; ++i)
    if (bxdfs_[i]->matches(flags) && count-- == 0) {
      bxdf = bxdfs_[i];
      break;
    }
  Vector3f wo = worldToLocal(woW), wi;
  if (wo.z == 0) return Spectrum(0);
  BxDFType type = bxdf->type();
  Spectrum f = bxdf->sampleF(wo, &wi, u2, pdf, &type);
  if (sampledType) *sampledType = type;
  if (*pdf == 0) return Spectrum(0);
  *wiW = localToWorld(wi);
  if (!(bxdf->type() & kSpecular) && matching > 1) {
    for (int i = 0; i < count_; ++i)
      if (bxdfs_[i] != bxdf && bxdfs_[i]->matches(flags)) *pdf += bxdfs_[i]->pdf(wo, wi);
  }
  if (matching > 1) *pdf /= Float(matching);
  if (!(bxdf->type() & kSpecular)) {
    // The whole BSDF's value at wi. One component's is what its sampleF returned (its contract),
    // kept only on the side the geometric normal gives the pair, as f() keeps it.
    if (matching > 1)
      f = mixtureF(woW, *wiW, flags);
    else if (!models(*bxdf, reflects(woW, *wiW)))
      f = Spectrum(0);
  }
  return f;
}

Float BSDF::mixturePdf(const Vector3f& woW, const Vector3f& wiW, int flags) const {
  Vector3f wo = worldToLocal(woW), wi = worldToLocal(wiW);
  if (wo.z == 0) return 0;
  Float pdf = 0;
  int matching = 0;
  for (int i = 0; i < count_; ++i)
    if (bxdfs_[i]->matches(flags)) {
      ++matching;
      pdf += bxdfs_[i]->pdf(wo, wi);
    }
  return matching > 0 ? pdf / Float(matching) : 0;
}

Spectrum BSDF::rho(const Vector3f& woW, std::span<const Point2f> u, int flags) const {
  Vector3f wo = worldToLocal(woW);
  Spectrum r(0);
  for (int i = 0; i < count_; ++i)
    if (bxdfs_[i]->matches(flags)) r += bxdfs_[i]->rho(wo, u);
  return r;
}

Spectrum BSDF::rho(std::span<const Point2f> u1, std::span<const Point2f> u2, int flags) const {
  Spectrum r(0);
  for (int i = 0; i < count_; ++i)
    if (bxdfs_[i]->matches(flags)) r += bxdfs_[i]->rho(u1, u2);
  return r;
}

}  // namespace candela
