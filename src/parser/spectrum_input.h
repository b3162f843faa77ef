// Spectral values in scene files ("spectrum", "xyz", "blackbody" parameters and .spd files) turned
// into scene-linear RGB when the file is read: candela renders in RGB, as lrt does with
// COLOR_SAMPLES = 3 (lrt draft §5.1), and a measured spectrum is projected onto the CIE matching
// functions once (lrt draft §5.1.2) and then to RGB.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/spectrum.h"

namespace candela {

struct SpectrumSample {
  Float lambda;  // nm
  Float value;
};

// What a spectrum describes decides its white point. A reflectance-like spectrum (Kd, eta, k, ...)
// is a ratio and white means "reflects all wavelengths equally", so a constant spectrum becomes
// grey: its colour is adapted from equal-energy white to the RGB space's D65 white (Bradford). An
// emission spectrum (a light's "L" or "I") is converted as measured, so a D65 SPD is white.
enum class SpectrumUse { Reflectance, Illuminant };

// Emission parameters of the lights and volumes of the seeds ("L", "I", "Le") are illuminants;
// every other spectral parameter is reflectance-like.
SpectrumUse spectrumUseForParameter(const std::string& paramName);

// CIE XYZ of the piecewise-linear SPD through the samples (any order; outside the sampled range
// the end values continue), normalised so that a constant SPD of 1 has Y = 1. Empty → black.
void spectrumSamplesToXYZ(std::vector<SpectrumSample> samples, Float xyz[3]);
Spectrum spectrumSamplesToRGB(std::vector<SpectrumSample> samples, SpectrumUse use);

// Planck's law: spectral radiance of a black body at the given temperature, W / (m^2 sr m).
double planck(double lambdaNm, double kelvin);
// A black body's SPD scaled so its peak (Wien's displacement law) is 1, times scale, as an
// illuminant. kelvin must be > 0.
Spectrum blackbodyToRGB(Float kelvin, Float scale);

// Reads a two-column "wavelength value" file ('#' starts a comment; whitespace or commas separate
// numbers). Throws FileError naming the path (and line) when unreadable or malformed.
std::vector<SpectrumSample> readSpectrumFile(const std::string& path);
// The same from the file's text; path is used only in error messages.
std::vector<SpectrumSample> parseSpectrumFile(std::string_view text, const std::string& path);

}  // namespace candela
