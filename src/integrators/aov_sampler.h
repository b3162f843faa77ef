// First-hit AOVs of a camera ray (albedo, normal, depth, position). Traced as a ray of its own so
// that the integrators stay unaware of AOVs and the beauty image is the same with or without them.
#pragma once

#include "core/memory.h"
#include "core/ray.h"
#include "film/aov.h"
#include "scene/scene.h"

namespace candela {

AovSample sampleAovs(const Scene& scene, const RayDifferential& cameraRay, MemoryArena& arena,
                     RayStats& stats);

}  // namespace candela
