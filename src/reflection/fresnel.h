// Fresnel reflectance (lrt draft §9.2): exact for dielectrics, the usual approximation for
// conductors, and the draft's approximations that turn a normal-incidence reflectance into an
// index of refraction or an absorption coefficient.
#pragma once

#include "core/spectrum.h"

namespace candela {

// Dielectric reflectance for unpolarised light, (r_par^2 + r_perp^2) / 2, given both cosines
// (>= 0) and the indices on the incident and transmitted sides (lrt draft §9.2, FrDiel).
Float frDielectric(Float cosI, Float cosT, Float etaI, Float etaT);
// Dielectric reflectance at an interface with index etaOutside on the +z side and etaInside on
// the -z side, for a direction with cosine cosThetaI to the normal: a negative cosine means light
// arrives from inside, and past the critical angle the result is 1 (total internal reflection).
Float fresnelDielectric(Float cosThetaI, Float etaOutside, Float etaInside);
// Conductor reflectance for complex index eta + i k, per channel (lrt draft §9.2, FrCond).
Spectrum frConductor(Float cosI, const Spectrum& eta, const Spectrum& k);
// The index, or absorption coefficient, whose normal-incidence reflectance is r (lrt draft §9.2).
// r is clamped to [0, 0.999] so that neither divides by zero (lrt draft §23).
Spectrum fresnelApproxEta(const Spectrum& r);
Spectrum fresnelApproxK(const Spectrum& r);

// A Fresnel function of the cosine between the direction and the (micro)surface normal.
class Fresnel {
 public:
  virtual ~Fresnel() = default;
  virtual Spectrum evaluate(Float cosI) const = 0;
};

// Conductors reflect the same from either side: the cosine's sign is ignored.
class FresnelConductor final : public Fresnel {
 public:
  FresnelConductor(const Spectrum& eta, const Spectrum& k) : eta_(eta), k_(k) {}
  Spectrum evaluate(Float cosI) const override { return frConductor(std::abs(cosI), eta_, k_); }

 private:
  Spectrum eta_, k_;
};

// etaOutside is the index on the +z side of the surface (usually 1), etaInside on the -z side.
class FresnelDielectric final : public Fresnel {
 public:
  FresnelDielectric(Float etaOutside, Float etaInside)
      : etaOutside_(etaOutside), etaInside_(etaInside) {}
  Spectrum evaluate(Float cosI) const override {
    return Spectrum(fresnelDielectric(cosI, etaOutside_, etaInside_));
  }
  Float etaOutside() const { return etaOutside_; }
  Float etaInside() const { return etaInside_; }

 private:
  Float etaOutside_, etaInside_;
};

// Reflects everything: mirrors (lrt draft §10.2).
class FresnelNoOp final : public Fresnel {
 public:
  Spectrum evaluate(Float) const override { return Spectrum(1); }
};

// Indices of refraction and conductor constants from the draft's tables (lrt draft §9.2).
namespace ior {
inline constexpr Float kVacuum = 1, kAir = 1.00029f, kIce = 1.31f, kWater = 1.333f,
                       kFusedQuartz = 1.46f, kGlass = 1.5f, kSapphire = 1.77f, kDiamond = 2.42f;
}
struct ConductorConstants {
  Float eta, k;
};
namespace conductor {
inline constexpr ConductorConstants kGold{0.37f, 2.82f}, kSilver{0.177f, 3.638f},
    kCopper{0.617f, 2.63f}, kSteel{2.485f, 3.433f};
}

}  // namespace candela
