// `--sample-range A-B`: a piece that takes samples A to B of every pixel, for progressive farms.
// The sampler positions every sample by (pixel, index, seed), so the piece takes exactly the
// samples the full render takes at those indices; the film's sums of the pieces add up to the full
// render's (film/film_sums.h).
#pragma once

#include "app/render_piece.h"
#include "assembly/render_job.h"

namespace candela {

// Refuses, before rendering, what a sample range cannot reproduce: a range past the sample count;
// a renderer of the whole image (Metropolis, SPPM) or an integrator that splats light to other
// pixels (bdpt, light tracing), whose images are not sums of their pixels' own samples; the
// adaptive sampler, which decides on later samples from the first ones; and the first-hit AOVs,
// whose sums the piece does not keep. Throws SceneError located at "--sample-range".
void checkSampleRange(const RenderJob& job, const IndexRange& range);

}  // namespace candela
