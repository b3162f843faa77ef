// BxDFs in the local shading frame where n = (0,0,1), s = x, t = y (lrt draft §9.1). Directions
// are unit and point away from the surface. A BxDF evaluates as if wo and wi were on the sides it
// models; the BSDF decides between reflection and transmission with the geometric normal.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/rng.h"
#include "core/spectrum.h"
#include "core/vector.h"

namespace candela {

// Each BxDF is one of diffuse/glossy/specular and models reflection, transmission, or (a few
// that choose between them themselves: a rough dielectric, hair, Fourier tables) both
// (lrt draft §9.1).
enum BxDFType : int {
  kReflection = 1 << 0,
  kTransmission = 1 << 1,
  kDiffuse = 1 << 2,
  kGlossy = 1 << 3,
  kSpecular = 1 << 4,
  kAllTypes = kDiffuse | kGlossy | kSpecular,
  kAllReflection = kReflection | kAllTypes,
  kAllTransmission = kTransmission | kAllTypes,
  kAllBxDF = kAllReflection | kAllTransmission,
};

// Shading-frame trigonometry (lrt draft §9.1). sin^2 is clamped at 0 against rounding; cos/sin of
// phi are defined as (1, 0) at the pole instead of dividing 0 by 0 (lrt draft §23).
inline Float cosTheta(const Vector3f& w) { return w.z; }
inline Float absCosTheta(const Vector3f& w) { return std::abs(w.z); }
inline Float sin2Theta(const Vector3f& w) { return std::max(Float(0), w.x * w.x + w.y * w.y); }
inline Float sinTheta(const Vector3f& w) { return std::sqrt(sin2Theta(w)); }
inline Float cosPhi(const Vector3f& w) {
  Float s = sinTheta(w);
  return s == 0 ? 1 : clamp(w.x / s, -1, 1);
}
inline Float sinPhi(const Vector3f& w) {
  Float s = sinTheta(w);
  return s == 0 ? 0 : clamp(w.y / s, -1, 1);
}
inline bool sameHemisphere(const Vector3f& a, const Vector3f& b) { return a.z * b.z > 0; }
// Mirror direction about the normal, and the same direction seen from the other side.
inline Vector3f reflectAboutNormal(const Vector3f& w) { return {-w.x, -w.y, w.z}; }
inline Vector3f otherHemisphere(const Vector3f& w) { return {w.x, w.y, -w.z}; }

class BxDF {
 public:
  explicit BxDF(BxDFType type) : type_(type) {}
  virtual ~BxDF() = default;
  BxDFType type() const { return type_; }
  bool matches(int flags) const { return (type_ & flags) == type_; }

  virtual Spectrum f(const Vector3f& wo, const Vector3f& wi) const = 0;
  // Samples wi given wo and returns f(wo, wi); *pdf = 0 when no direction was produced. For
  // delta distributions the value is the delta's weight and *pdf = 1 (lrt draft §9.2). The
  // default draws a cosine-weighted direction on wo's side (lrt draft §15.2).
  virtual Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                           BxDFType* sampledType = nullptr) const;
  // Density of sampleF's wi in solid angle; 0 for delta distributions.
  virtual Float pdf(const Vector3f& wo, const Vector3f& wi) const;

  // The weight by which a BSDF picks this component to sample, when every component it could
  // pick has one: proportional to the share of the light arriving along wo that the component
  // scatters (a smooth dielectric's Fresnel reflectance for its reflection, the rest for its
  // refraction), so that each pick's value over its probability stays near 1. nullopt: no such
  // estimate, and the BSDF picks uniformly (lrt draft §15.5's choice).
  virtual std::optional<Float> selectionWeight(const Vector3f&) const { return std::nullopt; }
  // Whether sampleF chooses between lobes of its own after drawing a direction's parameters (a
  // rough dielectric reflects or refracts at the microfacet it drew), and so needs a third
  // uniform value; sampleChoosing then takes it. The BSDF passes what is left of the value that
  // picked the component, which is uniform again and independent of u.
  virtual bool choosesLobe() const { return false; }
  virtual Spectrum sampleChoosing(const Vector3f& wo, Vector3f* wi, Float uChoice, const Point2f& u,
                                  Float* pdf, BxDFType* sampledType = nullptr) const {
    (void)uChoice;
    return sampleF(wo, wi, u, pdf, sampledType);
  }

  // Hemispherical-directional reflectance rho_hd(wo) = integral of f |cos theta_i| (lrt draft
  // §9.1), estimated by Monte Carlo over sampleF with the given canonical samples; BxDFs with a
  // closed form override it and ignore the samples.
  virtual Spectrum rho(const Vector3f& wo, std::span<const Point2f> u) const;
  // Hemispherical-hemispherical reflectance rho_hh: wo uniform over the hemisphere (u1), wi by
  // sampleF (u2). The draft printed the uniform pdf as 2 pi; it is 1 / (2 pi) (lrt draft §15.4).
  virtual Spectrum rho(std::span<const Point2f> u1, std::span<const Point2f> u2) const;
  // The same for the part of a BxDF that models both sides which reflects (reflection true) or
  // transmits: what a BSDF asked for one side sums. Monte Carlo over sampleF, counting only the
  // samples on that side of the surface.
  Spectrum rhoOneSide(const Vector3f& wo, std::span<const Point2f> u, bool reflection) const;
  Spectrum rhoOneSide(std::span<const Point2f> u1, std::span<const Point2f> u2,
                      bool reflection) const;

 private:
  BxDFType type_;
};

// n x n jittered samples on [0,1)^2, one per stratum, in random order (lrt draft §7.3).
std::vector<Point2f> stratifiedSamples2D(int n, RNG& rng);
// rho_hd and rho_hh with sqrtSamples^2 jittered samples (per dimension pair) drawn from rng.
Spectrum rhoStratified(const BxDF& bxdf, const Vector3f& wo, int sqrtSamples, RNG& rng);
Spectrum rhoStratified(const BxDF& bxdf, int sqrtSamples, RNG& rng);

// Lambert's perfectly diffuse reflection, f = R / pi, whose reflectance is R in closed form
// (lrt draft §9.3). Final, so that a BSDF made of it alone calls it without virtual dispatch.
class LambertianReflection final : public BxDF {
 public:
  explicit LambertianReflection(const Spectrum& r)
      : BxDF(BxDFType(kReflection | kDiffuse)), r_(r), f_(r * kInvPi) {}
  Spectrum f(const Vector3f&, const Vector3f&) const override { return f_; }
  Spectrum rho(const Vector3f&, std::span<const Point2f>) const override { return r_; }
  Spectrum rho(std::span<const Point2f>, std::span<const Point2f>) const override { return r_; }
  // f for any pair of directions on its side.
  const Spectrum& value() const { return f_; }

 private:
  Spectrum r_, f_;
};

}  // namespace candela
