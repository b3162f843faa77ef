// Where the build follows one pbrt's behaviour or another's: the scene's dialect and every switch
// by which candela can reproduce pbrt where it deliberately differs (docs/pbrt-differences.md).
// One object, handed whole to the build (BuildOptions::compatibility) and on to the plug-ins
// that ask, instead of a field per switch on every path.
#pragma once

#include <optional>

namespace candela {

// Which pbrt's scene format a file is written for, where the two give one statement different
// meanings (parser/scene_dialect.h detects it).
enum class SceneDialect { PbrtV2, PbrtV3 };

// plastic's coat: index 1 outside and 1.5 inside, or pbrt's FresnelDielectric(1.5, 1), which puts
// the index outside (pbrt-v3 issue #210; materials/plastic.h).
enum class CoatFresnel { Exact, ReversedAsPbrt };

// The hyperboloid's normal. Exact: the fitted surface's. SegmentAsPbrt: dp/dv is the p1-p2
// segment's direction turned by phi, as pbrt-v2 and v3 compute it (pbrt 3e §3.5.3); it is tangent
// only where the segment is a ruling of the surface, so elsewhere the normal leans off it.
enum class HyperboloidNormal { Exact, SegmentAsPbrt };

// What the octaves of turbulence that the footprint drops contribute (textures/noise.h).
enum class ClampedOctaves {
  // Their mean, omega^i kMeanAbsNoise each, once: the texture's average does not change with the
  // footprint.
  Mean,
  // pbrt-v2's, pbrt-v3's and pbrt-v4's: 0.2 each, the dropped octaves' sum starting at the
  // partial octave's amplitude, whose mean so counts twice (and once even when no octave is
  // dropped). A surface whose footprint drops octaves is brighter by about 0.2 omega^n.
  AsPbrt,
};

// The code that refines "loopsubdiv" shapes: ours (the draft's algorithm, shapes/loop_subdiv.h) or
// OpenSubdiv 3.5 (Sdc::SCHEME_LOOP, VTX_BOUNDARY_EDGE_ONLY); both give the same surface.
enum class LoopProducer { Book, OpenSubdiv };

struct CompatibilityProfile {
  // --dialect; nullopt: detected from the scene (and, for the microfacet materials, from each
  // material's parameters). The samplers' defaults and the texture origin follow it too.
  std::optional<SceneDialect> dialect;
  CoatFresnel plasticCoat = CoatFresnel::Exact;                    // --coat-fresnel
  HyperboloidNormal hyperboloidNormal = HyperboloidNormal::Exact;  // --hyperboloid-normal
  ClampedOctaves clampedOctaves = ClampedOctaves::Mean;            // --turbulence
  LoopProducer subdiv = LoopProducer::Book;                        // --subdiv
};

}  // namespace candela
