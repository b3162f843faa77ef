#include "reflection/lafortune.h"

#include "core/sampling.h"

namespace candela {

namespace {

// Clay (lrt draft §10.9): x and y coefficients are equal; per-channel RGB values.
constexpr LafortuneLobe kClayLobes[3] = {
    {Spectrum(-1.089701f, -1.102701f, -1.107603f), Spectrum(-1.089701f, -1.102701f, -1.107603f),
     Spectrum(-1.354682f, -2.714801f, -1.569866f), Spectrum(17.968505f, 11.024489f, 21.270282f)},
    {Spectrum(-0.733381f, -0.793320f, -0.848205f), Spectrum(-0.733381f, -0.793320f, -0.848205f),
     Spectrum(0.676108f, 0.679314f, 0.726031f), Spectrum(8.219745f, 9.055139f, 11.261951f)},
    {Spectrum(-1.010548f, -1.012378f, -1.011263f), Spectrum(-1.010548f, -1.012378f, -1.011263f),
     Spectrum(0.910783f, 0.885239f, 0.892451f), Spectrum(152.912795f, 141.937171f, 201.046802f)},
};
constexpr Spectrum kClayDiffuse(0.383626f, 0.260749f, 0.274207f);

// Density of a cos^e lobe around a unit axis, (e + 1) / (2 pi) cos^e, zero behind the axis.
Float lobePdf(const Vector3f& axis, Float e, const Vector3f& w) {
  Float c = dot(axis, w);
  return c > 0 ? (e + 1) * kInv2Pi * std::pow(c, e) : 0;
}

}  // namespace

Spectrum Lafortune::f(const Vector3f& wo, const Vector3f& wi) const {
  Spectrum r = diffuse_ * kInvPi;
  for (const LafortuneLobe& l : lobes_) {
    Spectrum v = l.cx * (wo.x * wi.x) + l.cy * (wo.y * wi.y) + l.cz * (wo.z * wi.z);
    // A negative base has no real power: the lobe is zero there (the draft took Pow of it).
    for (int c = 0; c < 3; ++c) r[c] += v[c] > 0 ? std::pow(v[c], l.exponent[c]) : 0;
  }
  return r;
}

bool Lafortune::samplingLobes(const Vector3f& wo, SamplingLobe* out, Float* diffuseWeight,
                              int* count) const {
  *diffuseWeight = std::max(Float(0), diffuse_.average());
  Float total = *diffuseWeight;
  *count = 0;
  for (const LafortuneLobe& l : lobes_) {
    if (*count == kMaxSampledLobes) break;
    // Channel-averaged lobe: (|C wo| cos alpha)^e around axis C wo / |C wo|. Its weight is its
    // peak over wo's hemisphere (where the axis is closest to it: the axis itself, or the
    // horizon when the axis points to the other side) times the lobe's solid angle
    // 2 pi / (e + 1): fit lobes aimed below the surface (clay's first) are then rarely drawn.
    Vector3f c(l.cx.average() * wo.x, l.cy.average() * wo.y, l.cz.average() * wo.z);
    Float len = c.length(), e = std::max(Float(0), l.exponent.average());
    SamplingLobe& s = out[*count];
    s.axis = len > 0 ? c / len : Vector3f(0, 0, 1);
    s.exponent = e;
    Float reach = s.axis.z * wo.z >= 0 ? 1 : sinTheta(s.axis);
    s.weight = len > 0 ? std::min(Float(1e30), std::pow(len * reach, e) * 2 * kPi / (e + 1)) : 0;
    total += s.weight;
    ++*count;
  }
  if (!(total > 0)) return false;
  *diffuseWeight /= total;
  for (int i = 0; i < *count; ++i) out[i].weight /= total;
  return true;
}

Spectrum Lafortune::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdfOut,
                            BxDFType* sampledType) const {
  if (sampledType) *sampledType = type();
  *pdfOut = 0;
  SamplingLobe lobes[kMaxSampledLobes];
  Float diffuseWeight;
  int n;
  if (wo.z == 0 || !samplingLobes(wo, lobes, &diffuseWeight, &n)) return Spectrum(0);
  // Choose a component with u.x (index 0 the diffuse term, i + 1 lobe i), then reuse the
  // remainder of u.x as a fresh uniform number. Rounding can leave u.x past the last weight:
  // the last positive-weight component takes it.
  Float weight[kMaxSampledLobes + 1], start[kMaxSampledLobes + 1];
  weight[0] = diffuseWeight;
  for (int i = 0; i < n; ++i) weight[i + 1] = lobes[i].weight;
  int chosen = -1;
  Float acc = 0;
  for (int i = 0; i <= n; ++i) {
    start[i] = acc;
    if (weight[i] <= 0) continue;
    chosen = i;
    if (u.x < acc + weight[i]) break;
    acc += weight[i];
  }
  Float ux = (u.x - start[chosen]) / weight[chosen];
  Point2f v(clamp(ux, 0, kOneMinusEpsilon), u.y);
  if (chosen == 0) {
    *wi = sampleCosineHemisphere(v);
    if (wo.z < 0) wi->z = -wi->z;
  } else {
    const SamplingLobe& l = lobes[chosen - 1];
    Float cosA = std::pow(v.x, 1 / (l.exponent + 1));
    Vector3f local = sphericalDirection(safeSqrt(1 - cosA * cosA), cosA, 2 * kPi * v.y);
    Vector3f s, t;
    coordinateSystem(l.axis, &s, &t);
    *wi = s * local.x + t * local.y + l.axis * local.z;
  }
  *pdfOut = pdf(wo, *wi);
  if (*pdfOut == 0) return Spectrum(0);
  return f(wo, *wi);
}

Float Lafortune::pdf(const Vector3f& wo, const Vector3f& wi) const {
  if (!sameHemisphere(wo, wi)) return 0;
  SamplingLobe lobes[kMaxSampledLobes];
  Float diffuseWeight;
  int n;
  if (!samplingLobes(wo, lobes, &diffuseWeight, &n)) return 0;
  Float p = diffuseWeight * absCosTheta(wi) * kInvPi;
  for (int i = 0; i < n; ++i)
    if (lobes[i].weight > 0) p += lobes[i].weight * lobePdf(lobes[i].axis, lobes[i].exponent, wi);
  return p;
}

std::optional<LafortuneFit> lafortuneFit(std::string_view name) {
  if (name == "clay") return LafortuneFit{kClayDiffuse, kClayLobes};
  return std::nullopt;
}

}  // namespace candela
