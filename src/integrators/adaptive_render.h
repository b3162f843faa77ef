// Noise-driven adaptive sampling (render_options.h: AdaptiveSampling): every pixel's first
// samples, then passes that add samples only to the pixels whose noise, estimated from their own
// samples, is still above the threshold. Decisions are made between passes, each from one pixel's
// sums alone, so the image does not depend on threads, tiles, the crop window or a farm's tiles.
#pragma once

#include <vector>

#include "film/film.h"
#include "integrators/progressive_render.h"

namespace candela {

// The sample counts at which pixels are checked, the last being samplesPerPixel: the minimum
// (16 by default), then steps of the larger of the minimum and an eighth of the count so far,
// rounded up to eights (the camera rays' groups), so that a pixel overshoots its stop by at most
// about an eighth of its samples and a render of thousands of samples makes few dozen passes.
std::vector<int> adaptivePassEnds(int samplesPerPixel, const AdaptiveSampling& adaptive);

// Renders samplesPerPixel adaptively into film through renderPass (which must honour
// RenderOptions::pixels), by renderPasses: options.afterPass and options.timeBudget apply as
// there, and the render stops (StopReason::NoiseThreshold) once no pixel is left above the
// threshold. leading: passes taken first by every pixel (path guiding's training passes, of
// doubling counts); no pixel is judged before the last of them ends, nor before the minimum.
ProgressiveResult renderAdaptive(const RenderPass& renderPass, const Film& film,
                                 int samplesPerPixel, const ProgressiveOptions& options,
                                 const std::vector<int>& leading = {});

}  // namespace candela
