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

int BSDF::selection(const Vector3f& wo, int flags, Selection* out) const {
  int n = 0;
  bool weighted = true;
  Float total = 0;
  for (int i = 0; i < count_; ++i) {
    if (!bxdfs_[i]->matches(flags)) continue;
    out->bxdf[n] = bxdfs_[i];
    if (weighted) {
      std::optional<Float> w = bxdfs_[i]->selectionWeight(wo);
      weighted = w.has_value() && *w >= 0 && std::isfinite(*w);
      if (weighted) total += out->probability[n] = *w;
    }
    ++n;
  }
  // Weights that cannot be normalised (all zero: nothing to scatter) leave the uniform choice.
  out->weighted = weighted && n > 1 && total > 0 && std::isfinite(total);
  if (out->weighted)
    for (int i = 0; i < n; ++i) out->probability[i] /= total;
  return n;
}

Spectrum BSDF::mixtureSampleF(const Vector3f& woW, Vector3f* wiW, Float u1, const Point2f& u2,
                              Float* pdf, int flags, BxDFType* sampledType) const {
  *pdf = 0;
  if (sampledType) *sampledType = BxDFType(0);
  Vector3f wo = worldToLocal(woW), wi;
  Selection sel;
  int matching = selection(wo, flags, &sel);
  if (matching == 0) return Spectrum(0);
  // The pick, and what is left of u1 after it, uniform again on [0, 1).
  int comp;
  Float uRest;
  if (!sel.weighted) {
    comp = std::min(int(u1 * matching), matching - 1);
    uRest = u1 * matching - comp;
  } else {
    // The first component whose share of [0, 1) holds u1; rounding that leaves u1 past the
    // last share gives it to the last component that has one.
    int last = matching - 1;
    while (sel.probability[last] == 0) --last;  // total > 0: one has a share
    Float below = 0;
    comp = last;
    for (int i = 0; i < last; ++i) {
      if (sel.probability[i] == 0) continue;
      if (u1 < below + sel.probability[i]) {
        comp = i;
        break;
      }
      below += sel.probability[i];
    }
    uRest = (u1 - below) / sel.probability[comp];
  }
  uRest = std::clamp(uRest, Float(0), kOneMinusEpsilon);
  const BxDF* bxdf = sel.bxdf[comp];
  if (wo.z == 0) return Spectrum(0);
  BxDFType type = bxdf->type();
  Spectrum f = bxdf->choosesLobe() ? bxdf->sampleChoosing(wo, &wi, uRest, u2, pdf, &type)
                                   : bxdf->sampleF(wo, &wi, u2, pdf, &type);
  if (sampledType) *sampledType = type;
  if (*pdf == 0) return Spectrum(0);
  *wiW = localToWorld(wi);
  bool specular = (bxdf->type() & kSpecular) != 0;
  if (!sel.weighted) {
    if (!specular && matching > 1)
      for (int i = 0; i < matching; ++i)
        if (i != comp) *pdf += sel.bxdf[i]->pdf(wo, wi);
    if (matching > 1) *pdf /= Float(matching);
  } else if (specular) {
    *pdf *= sel.probability[comp];
  } else {
    // The mixture's density: every component's, each by the probability of picking it.
    Float mixture = sel.probability[comp] * *pdf;
    for (int i = 0; i < matching; ++i)
      if (i != comp) mixture += sel.probability[i] * sel.bxdf[i]->pdf(wo, wi);
    *pdf = mixture;
  }
  if (!specular) {
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
  Selection sel;
  int matching = selection(wo, flags, &sel);
  if (matching == 0) return 0;
  Float pdf = 0;
  if (!sel.weighted) {
    for (int i = 0; i < matching; ++i) pdf += sel.bxdf[i]->pdf(wo, wi);
    return pdf / Float(matching);
  }
  for (int i = 0; i < matching; ++i) pdf += sel.probability[i] * sel.bxdf[i]->pdf(wo, wi);
  return pdf;
}

namespace {
// For a BxDF that models both sides, the one side flags ask for: +1 reflection, -1 transmission;
// 0 when flags take it whole or not at all.
int oneSideOf(const BxDF& b, int flags) {
  const int sides = kReflection | kTransmission;
  if ((b.type() & sides) != sides || (flags & sides) == sides || (flags & sides) == 0) return 0;
  if ((b.type() & kAllTypes & flags) != (b.type() & kAllTypes)) return 0;
  return (flags & kReflection) ? 1 : -1;
}
}  // namespace

Spectrum BSDF::rho(const Vector3f& woW, std::span<const Point2f> u, int flags) const {
  Vector3f wo = worldToLocal(woW);
  Spectrum r(0);
  for (int i = 0; i < count_; ++i) {
    if (bxdfs_[i]->matches(flags))
      r += bxdfs_[i]->rho(wo, u);
    else if (int side = oneSideOf(*bxdfs_[i], flags))
      r += bxdfs_[i]->rhoOneSide(wo, u, side > 0);
  }
  return r;
}

Spectrum BSDF::rho(std::span<const Point2f> u1, std::span<const Point2f> u2, int flags) const {
  Spectrum r(0);
  for (int i = 0; i < count_; ++i) {
    if (bxdfs_[i]->matches(flags))
      r += bxdfs_[i]->rho(u1, u2);
    else if (int side = oneSideOf(*bxdfs_[i], flags))
      r += bxdfs_[i]->rhoOneSide(u1, u2, side > 0);
  }
  return r;
}

}  // namespace candela
