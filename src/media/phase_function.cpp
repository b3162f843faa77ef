#include "media/phase_function.h"

#include <cmath>

#include "core/sampling.h"

namespace candela {

namespace {

Float henyeyGreensteinValue(Float cosTheta, Float g) {
  Float denom = 1 + g * g - 2 * g * cosTheta;
  return kInv4Pi * (1 - g * g) / (denom * std::sqrt(std::max(denom, Float(0))));
}

// k of Schlick's approximation for a given g (pbrt 2e §11.1.1).
Float schlickK(Float g) { return Float(1.55) * g - Float(0.55) * g * g * g; }

Float schlickValue(Float cosTheta, Float k) {
  Float d = 1 - k * cosTheta;
  return kInv4Pi * (1 - k * k) / (d * d);
}

// Below this |g| (or |k|) the distributions are isotropic to float precision and their inverses
// divide by nearly zero.
constexpr Float kNearlyIsotropic = Float(1e-3);

// cos θ distributed as Henyey–Greenstein, by inverting its CDF in cos θ.
Float sampleHenyeyGreensteinCos(Float g, Float u) {
  if (std::abs(g) < kNearlyIsotropic) return 1 - 2 * u;
  Float s = (1 - g * g) / (1 - g + 2 * g * u);
  return clamp((1 + g * g - s * s) / (2 * g), Float(-1), Float(1));
}

// cos θ distributed as Schlick's function: F(c) = (1 - k^2) / (2k) (1 / (1 - kc) - 1 / (1 + k)).
Float sampleSchlickCos(Float k, Float u) {
  if (std::abs(k) < kNearlyIsotropic) return 1 - 2 * u;
  Float x = 2 * k * u / (1 - k * k) + 1 / (1 + k);
  return clamp((1 - 1 / x) / k, Float(-1), Float(1));
}

}  // namespace

PhaseFunction PhaseFunction::henyeyGreenstein(Float g) {
  return PhaseFunction(Kind::HenyeyGreenstein, g);
}

PhaseFunction PhaseFunction::schlick(Float g) { return PhaseFunction(Kind::Schlick, g); }

Float PhaseFunction::evaluate(Float cosTheta) const {
  switch (kind_) {
    case Kind::Isotropic:
      return kInv4Pi;
    case Kind::HenyeyGreenstein:
      return henyeyGreensteinValue(cosTheta, g_);
    case Kind::Schlick:
      return schlickValue(cosTheta, schlickK(g_));
    case Kind::Rayleigh:
      return Float(3) / (16 * kPi) * (1 + cosTheta * cosTheta);
    case Kind::MieHazy:
      return kInv4Pi * (Float(0.5) + Float(4.5) * std::pow(Float(0.5) * (1 + cosTheta), Float(8)));
    case Kind::MieMurky:
      return kInv4Pi *
             (Float(0.5) + Float(16.5) * std::pow(Float(0.5) * (1 + cosTheta), Float(32)));
  }
  return 0;
}

Float PhaseFunction::sample(const Vector3f& wo, const Point2f& u, Vector3f* wi, Float* pdf) const {
  Float cosTheta;
  switch (kind_) {
    case Kind::Isotropic:
      cosTheta = 1 - 2 * u[0];
      break;
    case Kind::HenyeyGreenstein:
      cosTheta = sampleHenyeyGreensteinCos(g_, u[0]);
      break;
    case Kind::Schlick:
      cosTheta = sampleSchlickCos(schlickK(g_), u[0]);
      break;
    default: {
      // Uniform directions, weighted by the function's value over the uniform density.
      *wi = sampleUniformSphere(u);
      *pdf = uniformSpherePdf();
      return p(wo, *wi) / *pdf;
    }
  }
  // θ is measured from the direction of travel after scattering, wo; wi points back against the
  // direction of travel before it.
  Float sinTheta = std::sqrt(std::max(Float(0), 1 - cosTheta * cosTheta));
  Float phi = 2 * kPi * u[1];
  Vector3f v1, v2;
  coordinateSystem(wo, &v1, &v2);
  Vector3f travelIn =
      v1 * (sinTheta * std::cos(phi)) + v2 * (sinTheta * std::sin(phi)) + wo * cosTheta;
  *wi = -travelIn;
  *pdf = evaluate(cosTheta);
  return 1;
}

Float PhaseFunction::pdf(const Vector3f& wo, const Vector3f& wi) const {
  switch (kind_) {
    case Kind::Isotropic:
    case Kind::HenyeyGreenstein:
    case Kind::Schlick:
      return p(wo, wi);
    default:
      return uniformSpherePdf();
  }
}

}  // namespace candela
