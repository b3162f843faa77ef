// lrt's tone-mapping operators (lrt draft §8.4), for the preview only: the EXR keeps the
// scene-linear radiance. Each operator scales every pixel's RGB by a factor of its luminance so
// that the display range [0, 1] holds the image; the display transform comes after.
#pragma once

#include <string>

#include "core/image_buffer.h"
#include "core/paramset.h"

namespace candela {

// Names: maxwhite, contrast, highcontrast, nonlinear. Unknown names are a SceneError at loc.
// Luminance is taken in cd/m^2 as the draft does: Y = 683 * y(RGB).
void applyToneMap(ImageBuffer& image, const std::string& name, const ParamSet& params,
                  const FileLoc& loc);

// Ashikhmin's capacity function with natural logarithms, which make its pieces meet at Y = 1 and
// Y = 7.2444 (the draft prints log10 and jumps there). Exposed for tests.
double highContrastCapacity(double Y);

}  // namespace candela
