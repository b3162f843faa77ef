// The named scattering media pbrt-v2's "subsurface" material accepts through "string name"
// (pbrt 2e §16.5): the measurements of Jensen, Marschner, Levoy and Hanrahan 2001, "A Practical
// Model for Subsurface Light Transport", Table 1, and pbrt-v2's 35 media from Narasimhan et al.
// 2006, in mm^-1 (the material's "scale" converts to scene units).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/spectrum.h"

namespace candela {

struct MeasuredSubsurface {
  Spectrum sigmaPrimeS;  // reduced scattering coefficient, mm^-1 (R, G, B)
  Spectrum sigmaA;       // absorption coefficient, mm^-1 (R, G, B)
};

// The medium of that name (case-sensitive, as pbrt-v2), or nothing.
std::optional<MeasuredSubsurface> measuredSubsurface(const std::string& name);
// Every known name, in table order.
std::vector<std::string> measuredSubsurfaceNames();

}  // namespace candela
