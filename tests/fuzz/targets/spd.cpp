#include <cmath>

#include "core/error.h"
#include "fuzz/targets/fuzz_targets.h"
#include "scene/spectrum_input.h"

namespace candela::fuzz {

// A spectrum the reader accepts has finite samples and converts to finite RGB either way.
void spd(std::string_view input) {
  std::vector<SpectrumSample> samples;
  try {
    samples = parseSpectrumFile(input, "fuzz.spd");
  } catch (const FileError&) {
    return;
  }
  if (samples.empty()) broken("an accepted spectrum without samples");
  for (SpectrumUse use : {SpectrumUse::Reflectance, SpectrumUse::Illuminant}) {
    Spectrum s = spectrumSamplesToRGB(samples, use);
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(s[c])) broken("a spectrum file converts to a non-finite colour");
  }
}

}  // namespace candela::fuzz
