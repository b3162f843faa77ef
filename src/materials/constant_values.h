// Material parameters that may be a texture or constant values: the constant ones are checked
// against a rule when the material is read (a texture's values are its own), with ParamSet's one
// wording at the value's location.
#pragma once

#include <string>

#include "core/paramset.h"
#include "core/value_range.h"

namespace candela {

// Every value of a constant (not a texture reference) parameter name in range; nothing to check
// when it is absent or a texture. Colours are checked channel by channel.
inline void requireConstantValues(const ParamSet& params, const std::string& name,
                                  const ValueRange& range) {
  const ParamItem* item = params.find(name);
  if (!item || item->type == ParamType::Texture) return;
  for (Float v : item->floats) params.requireInRange(name, v, range, item->loc);
}

}  // namespace candela
