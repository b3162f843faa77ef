// Scattering from a hair fibre (Chiang et al. 2016, after d'Eon et al. 2011 and Marschner et al.
// 2003; pbrt-v3's hair chapter, pbrt 4e §9.9): the sum over lobes p of Mp Ap Np (hair_lobes.h).
// The shading frame's x axis runs along the fibre (the surface's dp/du) and z is the normal;
// theta is the angle to the fibre's normal plane (sin theta = w.x) and phi the angle around the
// fibre, measured from y towards z (as pbrt-v3). h in [-1, 1] is where across the fibre's width the
// point lies.
//
// The hair's S(wo, wi) is defined against |cos theta_i| dw_i about the fibre's normal plane, which
// the model folds into Mp; f = S / |w_i.z| so that the renderer's |cos| against the shading normal
// cancels (Pharr's chapter does the same). The BxDF is glossy reflection and transmission at once:
// hair scatters to both sides of any surface standing in for the fibre.
//
// The scale tilt alpha rotates theta_i per lobe as f evaluates it: R by -2 alpha, TT by alpha, TRT
// by 4 alpha (Mp is evaluated at theta_i + tilt). That rotation has no Jacobian, so with alpha != 0
// a lobe integrates to about Ap cos(theta_o + tilt) / cos(theta_o) rather than Ap, and mass near
// a pole is left out or doubled (averaged over wo and h the furnace moves by 1e-4 .. 7e-3 for
// alpha 2 .. 5). f keeps pbrt-v3's form; pdf() is the exact density of sampleF's directions (Mp
// sampled about the untilted cone, then rotated), which differs from pbrt-v3's pdf (the tilted Mp
// itself) by cos(theta_i + tilt) / cos(theta_i) away from the poles, so that sample weights
// f |cos| / pdf are unbiased for this f. With alpha = 0 the two pdfs are the same.
// f is not reciprocal in general: Ap and Np depend on wo only (the model attenuates along the
// outgoing ray's refracted path), and the tilt breaks Mp's symmetry in theta_i and theta_o.
#pragma once

#include "reflection/bxdf.h"
#include "reflection/hair_lobes.h"

namespace candela {

class HairBxDF : public BxDF {
 public:
  // sigmaA >= 0 per unit fibre radius, eta >= 1, betaM and betaN in (0, 1], alpha in degrees.
  HairBxDF(Float h, Float eta, const Spectrum& sigmaA, Float betaM, Float betaN,
           Float alphaDegrees);

  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
  // Picks lobe p with probability proportional to Ap's luminance, then theta_i from Mp (undoing
  // the lobe's tilt) and phi_i from Np (pbrt 4e §9.9.7). u.x picks the lobe and its remainder
  // samples Np; u.y samples Mp's spread, and a hash of both Mp's rotation about the cone.
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override;

  // The attenuation of each lobe for wo, and the probabilities sampleF picks them with.
  hair::LobeSpectra attenuation(const Vector3f& wo) const;
  hair::LobeWeights lobeProbabilities(const Vector3f& wo) const;

 private:
  struct Outgoing;  // what depends on wo only
  Outgoing outgoing(const Vector3f& wo) const;
  // S = f |w_i.z|: the sum over lobes of Ap Mp Np (Np = 1 / 2 pi for the last lobe).
  Spectrum lobeSum(const Outgoing& o, const Vector3f& wi) const;
  // The density of sampleF's directions when it picks lobe p with probability w[p].
  Float density(const Outgoing& o, const Vector3f& wi, const hair::LobeWeights& w) const;

  Float h_, gammaO_, eta_;
  Spectrum sigmaA_;
  double v_[hair::kMaxLobe + 1];
  Float s_;
  double sinTilt_[hair::kMaxLobe], cosTilt_[hair::kMaxLobe];
};

}  // namespace candela
