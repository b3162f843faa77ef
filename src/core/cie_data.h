// The CIE 1931 colour matching functions sampled at 1 nm, 360-830 nm (lrt draft §5.1.2: CIEstart,
// CIEend, CIE_X/Y/Z). Used to turn measured spectra in scene files into XYZ and then RGB.
#pragma once

#include "core/common.h"

namespace candela {

inline constexpr int kCieLambdaStart = 360;  // nm
inline constexpr int kCieLambdaEnd = 830;    // nm, inclusive
inline constexpr int kCieSamples = kCieLambdaEnd - kCieLambdaStart + 1;

// Value i is at wavelength kCieLambdaStart + i nm.
extern const Float kCieX[kCieSamples];
extern const Float kCieY[kCieSamples];
extern const Float kCieZ[kCieSamples];

}  // namespace candela
