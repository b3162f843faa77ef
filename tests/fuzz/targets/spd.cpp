#include <cmath>

#include "core/error.h"
#include "fuzz/targets/fuzz_targets.h"
#include "parser/parser.h"
#include "parser/scene_builder.h"
#include "parser/spectrum_input.h"

namespace candela::fuzz {

namespace {

// Whether the scene reader refuses the spectrum file with a located error.
bool sceneRefuses(std::string_view input, const char* param) {
  SceneFileReader readFile = [&](const std::string&) { return std::string(input); };
  auto ignore = [](const FileLoc&, const std::string&) {};
  SceneBuilder builder([](SceneDescription&&) {}, ignore);
  std::string scene = "WorldBegin\nLightSource \"point\" \"spectrum " + std::string(param) +
                      "\" \"f.spd\"\nWorldEnd\n";
  try {
    parseString(scene, "/fuzz/main.pbrt", builder, ignore, readFile);
  } catch (const SceneError& e) {
    return e.location().line == 2;
  }
  return false;
}

}  // namespace

// A spectrum the reader accepts has samples, and converts to a finite colour, or else the scene
// reader refuses it at the parameter that names the file.
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
    bool finite = std::isfinite(s[0]) && std::isfinite(s[1]) && std::isfinite(s[2]);
    const char* param = use == SpectrumUse::Illuminant ? "I" : "scale";
    if (!finite && !sceneRefuses(input, param))
      broken("a spectrum file with a non-finite colour is not refused where the scene names it");
  }
}

}  // namespace candela::fuzz
