// Unbiased transmittance and free-flight sampling through a Medium (pbrt 3e §15.2; Woodcock et
// al.'s delta tracking, Novák et al.'s ratio tracking). Homogeneous media use their closed forms;
// the others track with the scalar majorant μ̄ = the largest channel of Medium::majorant over
// the segment: tentative collisions at exponential(μ̄) distances, at each of which the fictitious
// "null" coefficient σn = μ̄ - σt (per channel, >= 0) lets the path go on.
//
// Every routine works on the ray's parametric segment [0, tMax] (ray.d of any length; distances
// are t·|d|) clipped to the medium's extent, and draws its random numbers from rng.
#pragma once

#include "core/ray.h"
#include "core/rng.h"
#include "core/spectrum.h"
#include "media/medium.h"

namespace candela {

// T(0, tMax) = exp(-∫σt): closed form for homogeneous media, ratio tracking otherwise (each
// tentative collision multiplies by σn/μ̄ = 1 - σt/μ̄, an unbiased estimate of the exponential).
Spectrum trackedTransmittance(const Medium& medium, const Ray& ray, RNG& rng);

// Ray marching of the optical depth (for reference): exp(-opticalDepth) with nSteps midpoint
// steps over the segment inside the medium; biased, converges as nSteps grows.
Spectrum marchedTransmittance(const Medium& medium, const Ray& ray, int nSteps);

// One free flight along the ray from t = 0 toward tMax (pbrt 3e §15.2.1; spectral tracking in
// the manner of Kutz et al. 2017 for chromatic coefficients). The estimator of the radiance
// arriving at ray.o is: emitted + weight · (radiance scattered toward ray.o at ray(t) when
// scattered, else the radiance arriving from ray(tMax)).
struct FreeFlight {
  bool scattered = false;
  Float t = 0;               // the scattering point's ray parameter (when scattered)
  Spectrum weight{1};        // multiplies the path throughput
  Spectrum emitted{0};       // the medium's own emission collected along the way (pre-weighted)
  MediumPoint coefficients;  // at the scattering point (when scattered)
};
// throughput (the path's, >= 0): the channels are favoured in proportion to it, as Kutz et al.
// and pbrt 4e do, so that a channel the path still carries is not starved by one it has lost;
// any throughput gives an unbiased estimate.
FreeFlight sampleFreeFlight(const Medium& medium, const Ray& ray, RNG& rng,
                            const Spectrum& throughput = Spectrum(1));

}  // namespace candela
