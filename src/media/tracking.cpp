#include "media/tracking.h"

#include <algorithm>
#include <cmath>

namespace candela {

namespace {

// exp(-σ s) per channel, 1 where σ is 0 (also for s = infinity).
Spectrum attenuation(const Spectrum& sigma, Float s) {
  Spectrum r;
  for (int c = 0; c < 3; ++c) r[c] = sigma[c] == 0 ? 1 : std::exp(-sigma[c] * s);
  return r;
}

// An exponential(1) distance.
Float exponentialSample(RNG& rng) { return -std::log(1 - rng.uniformFloat()); }

// The scalar majorant over [t0, t1]; a medium that emits but has σt = 0 there still needs
// tentative collisions to collect its emission, one per segment length on average.
Float scalarMajorant(const Medium& medium, const Ray& ray, Float t0, Float t1, Float length) {
  Float mu = medium.majorant(ray, t0, t1).maxComponent();
  if (!(mu > 0) && medium.emits() && length > 0 && length < kInfinity) mu = 1 / length;
  return std::max(mu, Float(0));
}

// A homogeneous medium's coefficients over [t0, t1], read at the segment's middle: at its ends,
// on the boundary of a bounded region, rounding puts the point outside about half of the time.
MediumPoint homogeneousCoefficients(const Medium& medium, const Ray& ray, Float t0, Float t1) {
  Float t = t1 < kInfinity ? t0 + (t1 - t0) / 2 : t0;  // unbounded media are the same everywhere
  return medium.at(ray(t), ray.time);
}

// Tracking stops after this many tentative collisions (a path with weight 0 then): only a
// majorant far above σt over an unbounded segment gets near it.
constexpr int kMaxCollisions = 1 << 20;

}  // namespace

Spectrum trackedTransmittance(const Medium& medium, const Ray& ray, RNG& rng) {
  Float t0, t1;
  if (!medium.intersectP(ray, &t0, &t1) || !(t1 > t0)) return Spectrum(1);
  Float speed = ray.d.length();
  Float length = (t1 - t0) * speed;
  if (medium.isHomogeneous())
    return attenuation(homogeneousCoefficients(medium, ray, t0, t1).sigmaT(), length);
  Float mu = scalarMajorant(medium, ray, t0, t1, length);
  if (mu == 0) return Spectrum(1);
  // Ratio tracking (Novák et al. 2014; pbrt 3e §15.2.2).
  Spectrum tr(1);
  Float t = t0;
  for (int i = 0; i < kMaxCollisions; ++i) {
    t += exponentialSample(rng) / (mu * speed);
    if (!(t < t1)) return tr;
    Spectrum sigmaT = medium.at(ray(t), ray.time).sigmaT();
    for (int c = 0; c < 3; ++c) tr[c] *= std::max(Float(0), 1 - sigmaT[c] / mu);
    if (tr.isBlack()) return tr;
  }
  return Spectrum(0);
}

Spectrum marchedTransmittance(const Medium& medium, const Ray& ray, int nSteps) {
  Float t0, t1;
  if (!medium.intersectP(ray, &t0, &t1) || !(t1 > t0)) return Spectrum(1);
  Float length = (t1 - t0) * ray.d.length();
  Spectrum tau = medium.opticalDepth(ray, t0, t1, length / Float(std::max(1, nSteps)), 0.5f);
  return exp(-tau);
}

FreeFlight sampleFreeFlight(const Medium& medium, const Ray& ray, RNG& rng,
                            const Spectrum& throughput) {
  FreeFlight f;
  // Channel probabilities: the throughput's share (uniform when it is black or not finite).
  Spectrum channelP(Float(1) / 3);
  Float total = throughput[0] + throughput[1] + throughput[2];
  if (total > 0 && total < kInfinity) channelP = throughput / total;
  auto channelAverage = [&](const Spectrum& s) {
    return channelP[0] * s[0] + channelP[1] * s[1] + channelP[2] * s[2];
  };
  Float t0, t1;
  if (!medium.intersectP(ray, &t0, &t1) || !(t1 > t0)) return f;
  Float speed = ray.d.length();
  if (!(speed > 0)) return f;
  Float length = (t1 - t0) * speed;

  if (medium.isHomogeneous() && !medium.emits()) {
    // Closed form (pbrt 3e §15.2.1): a channel chosen by channelP, its exponential distance; the
    // density of the outcome is the channelP-weighted average over the channels.
    MediumPoint mp = homogeneousCoefficients(medium, ray, t0, t1);
    Spectrum sigmaT = mp.sigmaT();
    Float uChannel = rng.uniformFloat();
    int channel = uChannel < channelP[0] ? 0 : uChannel < channelP[0] + channelP[1] ? 1 : 2;
    if (channelP[channel] == 0) channel = channelP[2] > 0 ? 2 : channelP[1] > 0 ? 1 : 0;
    Float u = exponentialSample(rng);
    Float distance = sigmaT[channel] > 0 ? u / sigmaT[channel] : kInfinity;
    bool scattered = distance < length;
    Float s = scattered ? distance : length;
    Spectrum tr = attenuation(sigmaT, s);
    Float density = scattered ? channelAverage(sigmaT * tr) : channelAverage(tr);
    if (!(density > 0)) {
      f.weight = Spectrum(0);
      return f;
    }
    f.scattered = scattered;
    f.t = t0 + s / speed;
    f.weight = (scattered ? tr * mp.sigmaS : tr) / density;
    f.coefficients = mp;
    return f;
  }

  // Delta tracking with a null-collision choice between scattering and continuing, each with
  // probability proportional to its coefficient's channel average (weighted by channelP and the
  // flight's weight so far); the weight σx / (μ̄ P(x))
  // keeps the estimator unbiased when the channels differ (and is 1 - σa/μ̄ when they don't).
  // Absorption is carried in the weight rather than ending the path.
  Float mu = scalarMajorant(medium, ray, t0, t1, length);
  if (mu == 0) return f;
  Float t = t0;
  bool emits = medium.emits();
  for (int i = 0; i < kMaxCollisions; ++i) {
    t += exponentialSample(rng) / (mu * speed);
    if (!(t < t1)) return f;
    MediumPoint mp = medium.at(ray(t), ray.time);
    // The collision density is μ̄ T̄; the emission term T Le per unit length becomes Le / μ̄.
    if (emits) f.emitted += f.weight * mp.Le / mu;
    Spectrum sigmaN;
    for (int c = 0; c < 3; ++c) sigmaN[c] = std::max(Float(0), mu - mp.sigmaT()[c]);
    Float ps = channelAverage(mp.sigmaS * f.weight), pn = channelAverage(sigmaN * f.weight);
    if (!(ps + pn > 0)) {
      f.weight = Spectrum(0);  // absorbed at the majorant: nothing goes on
      return f;
    }
    Float pScatter = ps / (ps + pn);
    if (rng.uniformFloat() < pScatter) {
      f.scattered = true;
      f.t = t;
      f.weight *= mp.sigmaS / (mu * pScatter);
      f.coefficients = mp;
      return f;
    }
    f.weight *= sigmaN / (mu * (1 - pScatter));
    if (f.weight.isBlack()) return f;
  }
  f.weight = Spectrum(0);
  return f;
}

}  // namespace candela
