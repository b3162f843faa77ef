// Rendering in passes of doubling sample counts (1, 2, 4, ... spp in total), so that error can be
// measured against run time while the render goes on, and the render can stop on a time budget or
// an error target. Every pass adds the next sample indices to the same film, so the final image is
// bit-identical to a one-pass render of the same samples.
#pragma once

#include <functional>

#include "integrators/render_options.h"

namespace candela {

// renderPass(options) renders samples [options.firstSample, options.endSample) of every pixel.
using RenderPass = std::function<RenderResult(const RenderOptions&)>;

ProgressiveResult renderProgressive(const RenderPass& renderPass, int samplesPerPixel,
                                    const ProgressiveOptions& options);

}  // namespace candela
