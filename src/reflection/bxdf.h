// BxDFs in the local shading frame where n = (0,0,1) (lrt draft §9.1). Directions are unit and
// point away from the surface.
#pragma once

#include "core/spectrum.h"
#include "core/vector.h"

namespace candela {

enum BxDFType : int {
  kReflection = 1 << 0,
  kTransmission = 1 << 1,
  kDiffuse = 1 << 2,
  kGlossy = 1 << 3,
  kSpecular = 1 << 4,
  kAllBxDF = kReflection | kTransmission | kDiffuse | kGlossy | kSpecular,
};

inline Float cosTheta(const Vector3f& w) { return w.z; }
inline Float absCosTheta(const Vector3f& w) { return std::abs(w.z); }
inline bool sameHemisphere(const Vector3f& a, const Vector3f& b) { return a.z * b.z > 0; }

class BxDF {
 public:
  explicit BxDF(BxDFType type) : type_(type) {}
  virtual ~BxDF() = default;
  BxDFType type() const { return type_; }
  bool matches(int flags) const { return (type_ & flags) == type_; }

  virtual Spectrum f(const Vector3f& wo, const Vector3f& wi) const = 0;
  // Samples wi given wo; the default draws a cosine-weighted direction on wo's side.
  virtual Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                           BxDFType* sampledType = nullptr) const;
  virtual Float pdf(const Vector3f& wo, const Vector3f& wi) const;

 private:
  BxDFType type_;
};

// Lambert's perfectly diffuse reflection, f = R / pi (lrt draft §9.3).
class LambertianReflection : public BxDF {
 public:
  explicit LambertianReflection(const Spectrum& r)
      : BxDF(BxDFType(kReflection | kDiffuse)), r_(r) {}
  Spectrum f(const Vector3f&, const Vector3f&) const override { return r_ * kInvPi; }

 private:
  Spectrum r_;
};

}  // namespace candela
