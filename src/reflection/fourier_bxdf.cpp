#include "reflection/fourier_bxdf.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "reflection/fourier_series.h"

namespace candela {

namespace {

// Rec. 709 luminance weights, with which the three-channel files store Y = wR R + wG G + wB B.
constexpr Float kLumR = 0.212671f, kLumG = 0.715160f, kLumB = 0.072169f;

// The table's angles of a pair of directions: mu_i is the cosine of the reversed incident
// direction (pbrt 3e §8.6), cosPhi the cosine of the azimuth between -wi and wo (1 at a pole).
struct FourierAngles {
  Float muI, muO;
  double cosPhi;
};
FourierAngles anglesOf(const Vector3f& wo, const Vector3f& wi) {
  double ax = -double(wi.x), ay = -double(wi.y), bx = wo.x, by = wo.y;
  double la = ax * ax + ay * ay, lb = bx * bx + by * by;
  double c = la > 0 && lb > 0 ? (ax * bx + ay * by) / std::sqrt(la * lb) : 1.0;
  return {-wi.z, wo.z, std::clamp(c, -1.0, 1.0)};
}

// The 4 x 4 spline weights around (mu_i, mu_o); false outside the table.
struct CellWeights {
  int offI, offO;
  Float wI[4], wO[4];
};
bool cellWeights(const FourierBsdfTable& t, Float muI, Float muO, CellWeights* w) {
  return catmullRomWeights(t.mu(), muI, &w->offI, w->wI) &&
         catmullRomWeights(t.mu(), muO, &w->offO, w->wO);
}

// Each channel's interpolated series summed at cosPhi (interpolating the sums equals summing
// the interpolated series, and needs no storage).
std::array<Float, 3> interpolatedSeries(const FourierBsdfTable& t, const CellWeights& w,
                                        double cosPhi, int channels) {
  std::array<Float, 3> v = {0, 0, 0};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      Float weight = w.wI[a] * w.wO[b];
      if (weight == 0) continue;
      int m;
      const Float* ak = t.coefficients(w.offI + a, w.offO + b, &m);
      for (int c = 0; c < channels; ++c) v[c] += weight * evaluateFourier(ak + c * m, m, cosPhi);
    }
  return v;
}

// Only a corrupt table's coefficients (near the float range) or a direction all but in the
// surface's plane (1 / |mu_i| beyond it) overflow: such a value or density counts as none, so
// that no infinity reaches the integrators.
Spectrum finiteOrNone(const Spectrum& f) { return f.isFinite() ? f : Spectrum(0); }
Float finiteOrNone(Float pdf) { return std::isfinite(pdf) ? pdf : 0; }

// f from the summed series: divided by |mu_i| (the table holds f |mu_i|), scaled by
// (eta_o / eta_i)^2 across the surface as radiance is (pbrt 3e §8.2.3), with eta the index
// below over the one above.
Spectrum valueFromSeries(const FourierBsdfTable& t, const std::array<Float, 3>& s, Float muI,
                         Float muO) {
  if (muI == 0 || !(s[0] > 0)) return Spectrum(0);
  Float scale = 1 / std::abs(muI);
  if (muI * muO > 0) {
    // mu_i > 0: the light arrives from below (index eta) and leaves above (index 1).
    Float etaRatio = muI > 0 ? 1 / t.eta() : t.eta();
    scale *= etaRatio * etaRatio;
  }
  if (t.nChannels() == 1) return finiteOrNone(Spectrum(s[0] * scale));
  Float y = s[0], r = s[1], b = s[2];
  Float g = (y - kLumR * r - kLumB * b) / kLumG;
  return finiteOrNone(Spectrum(std::max(Float(0), r * scale), std::max(Float(0), g * scale),
                               std::max(Float(0), b * scale)));
}

}  // namespace

Spectrum FourierBSDF::f(const Vector3f& wo, const Vector3f& wi) const {
  FourierAngles a = anglesOf(wo, wi);
  CellWeights w;
  if (!cellWeights(*table_, a.muI, a.muO, &w)) return Spectrum(0);
  return valueFromSeries(*table_, interpolatedSeries(*table_, w, a.cosPhi, table_->nChannels()),
                         a.muI, a.muO);
}

Float FourierBSDF::pdf(const Vector3f& wo, const Vector3f& wi) const {
  // The sampler's density over (mu_i, phi) is a_0(mu_i) / A(mu_o) for mu_i, where A is the
  // integral of a_0 over mu_i, times Y(phi) / (2 pi a_0) for phi; dmu dphi is solid angle.
  FourierAngles a = anglesOf(wo, wi);
  Float integral;
  Float a0 = evaluateCatmullRom2D(table_->incidentRows(), a.muO, a.muI, &integral);
  if (!(a0 > 0) || !(integral > 0)) return 0;
  CellWeights w;
  if (!cellWeights(*table_, a.muI, a.muO, &w)) return 0;
  Float y = interpolatedSeries(*table_, w, a.cosPhi, 1)[0];
  return y > 0 ? finiteOrNone(y / (2 * kPi * integral)) : 0;
}

Spectrum FourierBSDF::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdfOut,
                              BxDFType* sampledType) const {
  *pdfOut = 0;
  Float muO = wo.z, muI, a0, pdfMu;
  if (!sampleCatmullRom2D(table_->incidentRows(), muO, u[1], &muI, &a0, &pdfMu) || !(a0 > 0))
    return Spectrum(0);
  // The luminance series interpolated at (mu_i, mu_o), for sampling phi.
  CellWeights w;
  if (!cellWeights(*table_, muI, muO, &w)) return Spectrum(0);
  std::array<Float, FourierBsdfTable::kMaxOrders> ak;
  std::fill_n(ak.begin(), table_->mMax(), Float(0));
  int mUsed = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      Float weight = w.wI[a] * w.wO[b];
      if (weight == 0) continue;
      int m;
      const Float* c = table_->coefficients(w.offI + a, w.offO + b, &m);
      mUsed = std::max(mUsed, m);
      for (int k = 0; k < m; ++k) ak[size_t(k)] += weight * c[k];
    }
  Float phi, y, pdfPhi;
  if (!sampleFourier(ak.data(), mUsed, u[0], &phi, &y, &pdfPhi) || !(pdfPhi > 0))
    return Spectrum(0);
  // -wi has zenith cosine mu_i and azimuth phi_o + phi.
  Float sinI = std::sqrt(std::max(Float(0), 1 - muI * muI));
  Float cosO = cosPhi(wo), sinO = sinPhi(wo), c = std::cos(phi), s = std::sin(phi);
  *wi = Vector3f(-sinI * (cosO * c - sinO * s), -sinI * (sinO * c + cosO * s), -muI);
  Float pdf = finiteOrNone(pdfMu * pdfPhi);
  if (pdf == 0) return Spectrum(0);
  *pdfOut = pdf;
  if (sampledType) *sampledType = BxDFType((muI * muO > 0 ? kTransmission : kReflection) | kGlossy);
  return f(wo, *wi);
}

}  // namespace candela
