// Lafortune's generalised cosine lobes (lrt draft §9.5): a Lambertian term plus lobes
// (cx wo.x wi.x + cy wo.y wi.y + cz wo.z wi.z)^e with spectral coefficients and exponents;
// (-1, -1, 1) is the Phong lobe around the mirror direction. The model is reciprocal.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "reflection/bxdf.h"

namespace candela {

struct LafortuneLobe {
  Spectrum cx, cy, cz, exponent;
};

// Like the draft, the lobes are not copied: the caller keeps them alive (static data, or the same
// arena as the BxDF). The draft's type parameter is kept: lobes with large exponents are glossy.
class Lafortune : public BxDF {
 public:
  Lafortune(const Spectrum& diffuse, std::span<const LafortuneLobe> lobes,
            BxDFType type = BxDFType(kReflection | kGlossy))
      : BxDF(type), diffuse_(diffuse), lobes_(lobes) {}
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
  // A mixture of cosine sampling for the diffuse term and a cos^e lobe around each lobe's axis
  // (cx wo.x, cy wo.y, cz wo.z), weighted by rough albedos; lobe samples below the surface fail.
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override;

 private:
  static constexpr int kMaxSampledLobes = 8;
  struct SamplingLobe {
    Vector3f axis;  // unit
    Float exponent, weight;
  };
  // Mixture weights for wo: [0] diffuse, [1..n] lobes; false when every weight is zero.
  bool samplingLobes(const Vector3f& wo, SamplingLobe* lobes, Float* diffuseWeight,
                     int* count) const;

  Spectrum diffuse_;
  std::span<const LafortuneLobe> lobes_;
};

// A Lafortune fit to measured data: diffuse reflectance plus lobes (static storage).
struct LafortuneFit {
  Spectrum diffuse;
  std::span<const LafortuneLobe> lobes;
};

// The draft's fits by material name (lrt draft §10.9, Cornell measurements for Marschner et al.
// 1999). Only "clay" has its coefficients printed in the draft; felt, primer, skin, bluepaint and
// brushedmetal are named there without coefficients, so they return nullopt like unknown names.
std::optional<LafortuneFit> lafortuneFit(std::string_view name);

}  // namespace candela
