// The factors of the hair scattering model of Chiang et al. 2016 ("A Practical and Controllable
// Hair and Fur Model for Production Path Tracing"), as in Pharr's "The Implementation of a Hair
// Scattering Model" (pbrt-v3's hair chapter, §1.2-1.5). A lobe p counts the internal paths: R (p =
// 0, reflected at the surface), TT (1), TRT (2), and one lobe for all longer paths (p = 3). Each
// lobe is a product of a longitudinal term Mp (of the angles to the fibre's normal plane), an
// attenuation Ap and an azimuthal term Np (of the angle around the fibre). h in [-1, 1] is the
// offset across the fibre where the ray meets its circular cross-section, gamma_o = asin(h).
#pragma once

#include <array>

#include "core/spectrum.h"

namespace candela::hair {

inline constexpr int kMaxLobe = 3;  // R, TT, TRT explicit; kMaxLobe sums the rest
using LobeSpectra = std::array<Spectrum, kMaxLobe + 1>;
using LobeWeights = std::array<Float, kMaxLobe + 1>;

// Variance v of the R lobe's Mp for longitudinal roughness beta_m in (0, 1]; TT uses v / 4 and
// TRT and beyond 4 v (Chiang et al. §4.1, eq. 7: a fit making beta_m perceptually linear).
double longitudinalVariance(Float betaM);
// Scale s of the logistic Np for azimuthal roughness beta_n in (0, 1] (Chiang et al. §4.1, eq. 8).
Float azimuthalScale(Float betaN);

// The modified Bessel function I0 and its logarithm (the latter finite for arguments whose I0
// overflows, where it uses the asymptotic expansion e^x / sqrt(2 pi x) (1 + 1/(8x) + ...)).
double besselI0(double x);
double logBesselI0(double x);

// d'Eon et al. 2011's normalised longitudinal lobe around the specular cone sin(theta_i) =
// -sin(theta_o): csch(1/v) / (2v) exp(-sin_i sin_o / v) I0(cos_i cos_o / v). Its integral over
// theta_i of Mp cos(theta_i) is 1. For v <= 0.1 it is evaluated in log space, where the factors
// separately overflow (pbrt 4e §9.9.3).
double longitudinalScattering(double cosThetaI, double cosThetaO, double sinThetaI,
                              double sinThetaO, double v);
// Draws sin(theta_i) (cos theta_i >= 0) with density Mp cos(theta_i) in theta_i given theta_o,
// from two uniform numbers (d'Eon et al. 2011's sampling of the spherical Gaussian around the
// cone; pbrt 4e §9.9.7). u1 is kept above 1e-5: below it the log's argument loses every digit.
void sampleLongitudinal(double sinThetaO, double cosThetaO, double v, Float u1, Float u2,
                        double* sinThetaI, double* cosThetaI);

// The logistic distribution of scale s, its CDF, and its restriction to [a, b] renormalised
// (pbrt 4e §9.9.5).
Float logistic(Float x, Float s);
Float logisticCDF(Float x, Float s);
Float trimmedLogistic(Float x, Float s, Float a, Float b);
// Inverts the trimmed logistic's CDF at u in [0, 1).
Float sampleTrimmedLogistic(Float u, Float s, Float a, Float b);

// The azimuth change of lobe p for the refraction angle gamma_t inside: 2p gamma_t - 2 gamma_o +
// p pi (pbrt 4e §9.9.5).
Float azimuthalShift(int p, Float gammaO, Float gammaT);
// Np: the trimmed logistic of the azimuth difference phi = phi_i - phi_o around lobe p's shift,
// wrapped to [-pi, pi]; integrates to 1 over phi.
Float azimuthalScattering(Float phi, int p, Float s, Float gammaO, Float gammaT);

// Ap for p = 0..kMaxLobe: Fresnel reflectance f at the surface (incidence cosine cos(theta_o)
// cos(gamma_o), the true index eta), each internal crossing attenuated by the transmittance T;
// the last term is the geometric series of all longer paths (pbrt 4e §9.9.4).
LobeSpectra attenuation(Float cosThetaO, Float eta, Float h, const Spectrum& transmittance);

}  // namespace candela::hair
