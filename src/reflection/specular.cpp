#include "reflection/specular.h"

namespace candela {

Spectrum SpecularReflection::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f&, Float* pdf,
                                     BxDFType* sampledType) const {
  if (sampledType) *sampledType = type();
  *wi = reflectAboutNormal(wo);
  if (wo.z == 0) {
    *pdf = 0;
    return Spectrum(0);
  }
  *pdf = 1;
  return fresnel_->evaluate(cosTheta(wo)) * r_ / absCosTheta(*wi);
}

std::optional<Float> SpecularReflection::selectionWeight(const Vector3f& wo) const {
  return rho(wo, {}).average();
}

Spectrum SpecularReflection::rho(const Vector3f& wo, std::span<const Point2f>) const {
  return wo.z == 0 ? Spectrum(0) : fresnel_->evaluate(cosTheta(wo)) * r_;
}

bool SpecularTransmission::refract(const Vector3f& wo, Vector3f* wi, Float* etaRatio) const {
  bool entering = wo.z > 0;
  Float etaO = entering ? fresnel_.etaOutside() : fresnel_.etaInside();
  Float etaI = entering ? fresnel_.etaInside() : fresnel_.etaOutside();
  Float eta = etaO / etaI;
  // Snell's law: eta_o sin theta_o = eta_i sin theta_i, with the arithmetic of
  // fresnelDielectric so that both see total internal reflection at the same angles.
  Float sin2I = eta * eta * std::max(Float(0), 1 - wo.z * wo.z);
  if (sin2I >= 1 || wo.z == 0) return false;
  Float cosI = std::sqrt(1 - sin2I);
  *wi = Vector3f(-eta * wo.x, -eta * wo.y, entering ? -cosI : cosI);
  *etaRatio = eta;
  return true;
}

Spectrum SpecularTransmission::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f&, Float* pdf,
                                       BxDFType* sampledType) const {
  if (sampledType) *sampledType = type();
  Float eta;
  if (!refract(wo, wi, &eta)) {
    *pdf = 0;
    return Spectrum(0);
  }
  *pdf = 1;
  Spectrum transmitted = Spectrum(1) - fresnel_.evaluate(cosTheta(wo));
  return t_ * transmitted * (eta * eta / absCosTheta(*wi));
}

std::optional<Float> SpecularTransmission::selectionWeight(const Vector3f& wo) const {
  if (wo.z == 0) return Float(0);
  return (t_ * (Spectrum(1) - fresnel_.evaluate(cosTheta(wo)))).average();
}

Spectrum SpecularTransmission::rho(const Vector3f& wo, std::span<const Point2f>) const {
  Vector3f wi;
  Float eta;
  if (!refract(wo, &wi, &eta)) return Spectrum(0);
  return t_ * (Spectrum(1) - fresnel_.evaluate(cosTheta(wo))) * (eta * eta);
}

}  // namespace candela
