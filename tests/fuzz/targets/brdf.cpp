#include <optional>

#include "core/error.h"
#include "fuzz/targets/fuzz_targets.h"
#include "fuzz/targets/lookup_directions.h"
#include "parser/spectrum_input.h"
#include "reflection/irregular_brdf.h"

namespace candela::fuzz {

// A table the reader accepts gives finite, non-negative values for every pair of directions.
void brdf(std::string_view input) {
  SpectrumToRGB toRGB = [](std::span<const Float> lambda, std::span<const Float> values) {
    std::vector<SpectrumSample> s;
    for (size_t i = 0; i < lambda.size(); ++i) s.push_back({lambda[i], values[i]});
    return spectrumSamplesToRGB(std::move(s), SpectrumUse::Reflectance);
  };
  std::optional<IrregularBrdfTable> table;
  try {
    table = parseIrregularBrdf(input, "fuzz.brdf", toRGB);
  } catch (const FileError&) {
    return;
  }
  checkLookups([&](const Vector3f& wo, const Vector3f& wi) { return table->lookup(wo, wi); },
               "a .brdf lookup is negative or not finite");
}

}  // namespace candela::fuzz
