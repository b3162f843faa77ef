// Rendering in passes of sample indices, so that error can be measured against run time while
// the render goes on, and the render can stop on a time budget or an error target. Every pass adds
// the next sample indices to the same film, so the final image is bit-identical to a one-pass
// render of the same samples. Doubling passes (1, 2, 4, ... spp in total) take every pixel;
// adaptive sampling's passes (adaptive_render.h) only the pixels still above a noise threshold.
#pragma once

#include <functional>
#include <vector>

#include "integrators/render_options.h"

namespace candela {

// renderPass(options) renders samples [options.firstSample, options.endSample) of every pixel
// (of options.render.pixels' when set).
using RenderPass = std::function<RenderResult(const RenderOptions&)>;

// 1, 2, 4, ..., samplesPerPixel.
std::vector<int> doublingPassEnds(int samplesPerPixel);

// Passes ending at each of ends in turn. After each pass, continuingShare (when given) says what
// fraction of the pixels the next pass takes (it may change options.render.pixels' mask); the
// time budget predicts the next pass from that share of its samples, and a share of 0 ends the
// render (StopReason::NoiseThreshold). Then options.afterPass may stop it.
ProgressiveResult renderPasses(const RenderPass& renderPass, const std::vector<int>& ends,
                               const ProgressiveOptions& options,
                               const std::function<double()>& continuingShare = {});

// Doubling passes up to samplesPerPixel.
ProgressiveResult renderProgressive(const RenderPass& renderPass, int samplesPerPixel,
                                    const ProgressiveOptions& options);

}  // namespace candela
