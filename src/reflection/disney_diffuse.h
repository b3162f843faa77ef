// The diffuse-like lobes of Disney's principled BRDF (Burley 2012, §5.3 and Appendix B; split
// into base and retro-reflection by Burley 2015, §3). All are reciprocal, depend on wo and wi
// only through theta_o, theta_i and the angle theta_d between wi and the half vector, and are
// drawn by the default cosine-weighted sampling of BxDF. With F_x = (1 - |cos theta_x|)^5 the
// Schlick weight:
//   base       f = C / pi (1 - F_o / 2) (1 - F_i / 2)                       (Burley 2015 eq. 4)
//   retro      f = C / pi R_R (F_o + F_i + F_o F_i (R_R - 1)), R_R = 2 roughness cos^2 theta_d
//                                                                           (Burley 2015 eq. 4)
//   base + retro = C / pi (1 + (F_D90 - 1) F_o)(1 + (F_D90 - 1) F_i), F_D90 = 1/2 + R_R,
//   Burley 2012's diffuse (eq. 3 of its §5.3).
//   subsurface f = 1.25 C / pi (F_ss (1 / (|cos o| + |cos i|) - 1/2) + 1/2),
//              F_ss = (1 + (F_ss90 - 1) F_o)(1 + (F_ss90 - 1) F_i), F_ss90 = roughness
//              cos^2 theta_d: the Hanrahan-Krueger-like flattening (Burley 2012, §5.3).
//   sheen      f = C F_d, F_d = (1 - cos theta_d)^5, no 1 / pi (Burley 2012, §5.3).
#pragma once

#include "reflection/bxdf.h"

namespace candela {

// (1 - c)^5 for c in [0, 1]: the variable part of Schlick's Fresnel approximation.
inline Float schlickWeight(Float c) {
  Float m = clamp(1 - c, 0, 1);
  return (m * m) * (m * m) * m;
}
// cos theta_d = wi . wh for a reflected pair, wh = normalize(wo + wi); 1 when wo = -wi.
Float cosThetaD(const Vector3f& wo, const Vector3f& wi);

// The lobes share their form: a colour C, the roughness (for those that use it), and f.
class DisneyDiffuseLobe : public BxDF {
 public:
  explicit DisneyDiffuseLobe(const Spectrum& c, Float roughness = 0)
      : BxDF(BxDFType(kReflection | kDiffuse)), c_(c), roughness_(roughness) {}

 protected:
  Spectrum c_;
  Float roughness_;
};

class DisneyDiffuse : public DisneyDiffuseLobe {
 public:
  using DisneyDiffuseLobe::DisneyDiffuseLobe;
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
};

class DisneyRetroReflection : public DisneyDiffuseLobe {
 public:
  using DisneyDiffuseLobe::DisneyDiffuseLobe;
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
};

class DisneyFakeSubsurface : public DisneyDiffuseLobe {
 public:
  using DisneyDiffuseLobe::DisneyDiffuseLobe;
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
};

class DisneySheen : public DisneyDiffuseLobe {
 public:
  using DisneyDiffuseLobe::DisneyDiffuseLobe;
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
};

}  // namespace candela
