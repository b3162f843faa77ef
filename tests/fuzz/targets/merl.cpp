#include <optional>

#include "core/error.h"
#include "fuzz/targets/fuzz_targets.h"
#include "fuzz/targets/lookup_directions.h"
#include "reflection/merl_brdf.h"

namespace candela::fuzz {

// A table the reader accepts gives finite, non-negative values for every pair of directions.
void merl(std::string_view input) {
  std::optional<MerlBrdfTable> table;
  try {
    table = parseMerlBrdf(input, "fuzz.merl");
  } catch (const FileError&) {
    return;
  }
  checkLookups([&](const Vector3f& wo, const Vector3f& wi) { return table->lookup(wo, wi); },
               "a MERL lookup is negative or not finite");
}

}  // namespace candela::fuzz
