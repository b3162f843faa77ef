// The absorption coefficient sigma_a of a hair fibre (per unit radius: the transmittance of a
// chord of length l is exp(-sigma_a l)) from the quantities artists set (Chiang et al. 2016 §4.2;
// pbrt 4e §9.9.8).
#pragma once

#include "core/spectrum.h"

namespace candela::hair {

// The RGB absorption of unit concentrations of the two melanins, as pbrt 4e §9.9.8 prints them
// for Chiang et al. 2016's melanin parameterisation: eumelanin (brown-black) 0.419 0.697 1.37,
// pheomelanin (red-yellow) 0.187 0.4 1.05.
inline constexpr Spectrum kEumelaninSigmaA{0.419f, 0.697f, 1.37f};
inline constexpr Spectrum kPheomelaninSigmaA{0.187f, 0.4f, 1.05f};

// ce kEumelaninSigmaA + cp kPheomelaninSigmaA.
Spectrum sigmaAFromConcentration(Float eumelanin, Float pheomelanin);
// Chiang et al.'s inversion (§4.2, eq. 9): the sigma_a whose multiply scattered albedo of a fibre
// assembly is about the colour c (per channel, in (0, 1]) for azimuthal roughness beta_n:
// (ln c / (5.969 - 0.215 b + 2.532 b^2 - 10.73 b^3 + 5.574 b^4 + 0.245 b^5))^2.
Spectrum sigmaAFromReflectance(const Spectrum& c, Float betaN);

}  // namespace candela::hair
