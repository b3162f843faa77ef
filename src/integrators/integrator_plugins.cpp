// The integrator and renderer tables. Each parameter list is what the entry's create function
// reads (integrator_params.cpp, photon_map_params.cpp, sppm/sppm_params.cpp,
// metropolis/metropolis_params.cpp),
// with the defaults and rules written there; test_plugin_tables.cpp holds the two together.
#include "integrators/integrator_plugins.h"

namespace candela {

namespace {

// SurfaceIntegrator is the statement of pbrt-v2 and the lrt draft.
constexpr unsigned kSurface = kPbrtV2 | kLrt;

// Each: name, type, default, pbrt-v3's default, rule, dialects, meaning.

// A shared parameter in a plug-in of fewer dialects, declared with the plug-in's.
constexpr ParamSpec in(ParamSpec spec, unsigned dialects) {
  spec.dialects = dialects;
  return spec;
}

// Integrators that recurse once per specular level take at most 1000 (integrator_params.cpp).
constexpr ParamSpec kRecursiveMaxDepth{"maxdepth",
                                       "integer",
                                       "5",
                                       "",
                                       "within [0, 1000]",
                                       kAllDialects,
                                       "most levels of specular recursion"};
constexpr ParamSpec kPathMaxDepth{
    "maxdepth", "integer", "5", "", "at least 0", kAllDialects, "most bounces of a path"};
constexpr ParamSpec kLightStrategy{"lightsamplestrategy",
                                   "string",
                                   "uniform",
                                   "(spatial; bvh past 4096 lights)",
                                   "one of uniform, power, spatial, bvh",
                                   kPbrtV3,
                                   "how each light sample chooses its light"};

constexpr ParamSpec kWhitted[] = {kRecursiveMaxDepth};

constexpr ParamSpec kDirectLighting[] = {
    kRecursiveMaxDepth,
    {"strategy", "string", "all", "", "one of all, one", kAllDialects,
     "sample every light, or one chosen by chance"},
};

constexpr ParamSpec kGuiding = {
    "guiding",
    "bool",
    "false",
    "",
    "",
    kCandela,
    "path guiding: directions learned in the first passes (Müller et al. 2017)"};

constexpr ParamSpec kPath[] = {
    kPathMaxDepth,
    // Absent outside pbrt-v3 scenes: pbrt-v2's roulette, which every path faces (path.h); given,
    // pbrt-v3's in any dialect, so no constant is pbrt-v2's default.
    {"rrthreshold", "float", "(pbrt-v2's roulette)", "1", "non-negative and finite", kPbrtV3,
     "throughput below which pbrt-v3's Russian roulette starts"},
    kLightStrategy,
    kGuiding,
};

constexpr ParamSpec kVolPath[] = {
    in(kPathMaxDepth, kPbrtV3),
    {"rrthreshold", "float", "1", "", "non-negative and finite", kPbrtV3,
     "throughput below which Russian roulette starts"},
    kLightStrategy,
    kGuiding,
};

constexpr ParamSpec kAmbientOcclusion[] = {
    {"nsamples", "integer", "2048", "", "at least 1", kSurface, "directions per camera hit"},
    {"maxdist", "float", "(unbounded)", "", "greater than 0", kSurface, "length of the probe rays"},
    {"cossample", "bool", "true", "", "", kCandela,
     "cosine-weighted directions; false: uniform ones, pbrt-v2's"},
};

constexpr ParamSpec kAo[] = {
    {"nsamples", "integer", "64", "", "at least 1", kPbrtV3, "directions per camera hit"},
    {"cossample", "bool", "true", "", "", kPbrtV3,
     "cosine-weighted directions; false: uniform ones"},
};

constexpr ParamSpec kBdpt[] = {
    in(kPathMaxDepth, kPbrtV3),
    {"visualizestrategies", "bool", "false", "", "", kPbrtV3,
     "also write one image per strategy (s, t)"},
    {"visualizeweights", "bool", "false", "", "", kPbrtV3,
     "also write the MIS-weighted image per strategy (wins over visualizestrategies)"},
    {"lightsamplestrategy", "string", "power", "", "one of uniform, power, spatial, bvh", kPbrtV3,
     "how light subpaths choose their light"},
    // Read only when lightsamplestrategy is absent.
    {"lightsampler", "string", "(lightsamplestrategy)", "", "one of uniform, power, spatial, bvh",
     kCandela, "candela's earlier name for lightsamplestrategy"},
};

constexpr ParamSpec kBidirectional[] = {
    {"maxdepth", "integer", "5", "", "at least 0", kSurface, "most bounces of a path"},
};

constexpr ParamSpec kIrradianceCache[] = {
    {"maxerror", "float", "0.2", "", "non-negative and finite", kLrt,
     "scale of a sample's radius of validity (0: no caching)"},
    {"minweight", "float", "0.5", "", "non-negative and finite", kPbrtV2,
     "least weight of a sample that interpolates"},
    {"minpixelspacing", "float", "2.5", "", "non-negative and finite", kPbrtV2,
     "least radius of a sample, in pixels (at most maxpixelspacing)"},
    {"maxpixelspacing", "float", "15", "", "positive and finite", kPbrtV2,
     "largest radius of a sample, in pixels"},
    {"maxangledifference", "float", "10", "", "within (0, 90]", kPbrtV2,
     "largest angle, in degrees, between the normals of a sample and its user"},
    {"nsamples", "integer", "4096", "", "at least 1", kSurface, "rays per irradiance estimate"},
    {"nfilter", "integer", "8", "", "at least 0", kLrt,
     "brightest values dropped from each estimate (at most nsamples - 1)"},
    {"maxspeculardepth", "integer", "5", "", "within [0, 1000]", kSurface,
     "most levels of specular recursion"},
    {"maxindirectdepth", "integer", "3", "", "at least 0", kSurface,
     "most diffuse bounces of an estimate's paths"},
};

constexpr ParamSpec kIgi[] = {
    {"nlights", "integer", "64", "", "at least 1", kSurface,
     "light paths per set (nlights * nsets at most 2^30)"},
    {"nsets", "integer", "4", "", "at least 1", kSurface, "sets of virtual point lights"},
    {"rrthreshold", "float", "0.0001", "", "at least 0", kSurface,
     "contribution below which a virtual light faces roulette"},
    in(kRecursiveMaxDepth, kSurface),
    {"glimit", "float", "10", "", "greater than 0", kSurface, "bound on the geometric term"},
    {"gathersamples", "integer", "16", "", "at least 0", kSurface,
     "rays at the camera vertex that make up for the bound"},
};

constexpr ParamSpec kDipoleSubsurface[] = {
    in(kRecursiveMaxDepth, kSurface),
    {"maxerror", "float", "0.05", "", "non-negative and finite", kSurface,
     "error bound of the octree's clustered irradiance"},
    {"minsampledistance", "float", "0.25", "", "positive and finite", kSurface,
     "spacing of the irradiance sample points"},
    {"pointsfile", "string", "(none)", "", "", kSurface,
     "file of sample points (x y z nx ny nz area offset), in place of placing them"},
};

constexpr ParamSpec kPhotonMap[] = {
    {"causticphotons", "integer", "20000", "", "at least 0", kSurface,
     "photons wanted in the caustic map"},
    {"indirectphotons", "integer", "100000", "", "at least 0", kSurface,
     "photons wanted in the indirect map"},
    {"directphotons", "integer", "100000", "", "at least 0", kLrt,
     "photons wanted in the direct map (with directwithphotons)"},
    {"nused", "integer", "50", "", "at least 1", kSurface, "photons per density estimate"},
    {"nfilter", "integer", "0", "", "at least 0", kLrt,
     "brightest photons dropped from each estimate"},
    {"maxphotondepth", "integer", "5", "", "at least 1", kSurface,
     "most surface interactions of a photon path"},
    {"finalgathersamples", "integer", "32", "", "at least 1", kSurface,
     "final gather rays per point"},
    {"maxspeculardepth", "integer", "5", "", "within [0, 1000]", kPbrtV2,
     "most levels of specular recursion"},
    // The lrt draft's name; giving both is an error.
    {"maxdepth", "integer", "(maxspeculardepth)", "", "within [0, 1000]", kLrt,
     "the lrt draft's name for maxspeculardepth"},
    {"maxdist", "float", "0.1", "", "positive and finite", kSurface,
     "largest photon search radius"},
    {"gatherangle", "float", "10", "", "within (0, 180)", kSurface,
     "half-angle, in degrees, of the photon-guided gather cones"},
    // The lrt draft writes the flags as integers 0 or 1.
    {"finalgather", "bool", "true", "", "", kSurface, "gather indirect light with rays"},
    {"directwithphotons", "bool", "false", "", "", kLrt,
     "direct lighting from the direct map, not from light samples"},
};

constexpr ParamSpec kSppm[] = {
    {"numiterations", "integer", "64", "", "at least 1", kPbrtV3,
     "photon passes (--spp replaces it, --quick divides it by 16)"},
    {"maxdepth", "integer", "5", "", "at least 0", kPbrtV3, "most bounces of a path"},
    {"photonsperiteration", "integer", "-1", "", "at least -1", kPbrtV3,
     "photons per pass; -1: the image's pixel count (0 is an error)"},
    {"radius", "float", "1", "", "positive and finite", kPbrtV3,
     "initial search radius, in scene units"},
    {"imagewritefrequency", "integer", "2147483647", "", "", kPbrtV3,
     "accepted and ignored (the passes report the converging image)"},
};

constexpr ParamSpec kMlt[] = {
    {"maxdepth", "integer", "5", "", "at least 0", kPbrtV3, "most scattering events of a path"},
    {"bootstrapsamples", "integer", "100000", "", "at least 1", kPbrtV3,
     "paths per depth that estimate the image's brightness and pick the chains' starts"},
    {"chains", "integer", "1000", "", "at least 1", kPbrtV3, "Markov chains, run in parallel"},
    {"mutationsperpixel", "integer", "100", "", "at least 1", kPbrtV3,
     "proposals per pixel over all chains (--spp replaces it)"},
    {"largestepprobability", "float", "0.3", "", "within [0, 1]", kPbrtV3,
     "probability that a proposal is a fresh path"},
    {"sigma", "float", "0.01", "", "positive and finite", kPbrtV3,
     "standard deviation of a small step in primary sample space"},
};

constexpr ParamSpec kMetropolis[] = {
    {"maxdepth", "integer", "7", "", "at least 0", kPbrtV2, "most scattering events of a path"},
    {"bootstrapsamples", "integer", "100000", "", "at least 1", kPbrtV2,
     "paths that estimate the image's brightness and pick the chains' starts"},
    {"samplesperpixel", "integer", "100", "", "at least 1", kPbrtV2,
     "proposals per pixel (--spp replaces it)"},
    {"largestepprobability", "float", "0.25", "", "within [0, 1]", kPbrtV2,
     "probability that a proposal is a fresh path"},
    {"maxconsecutiverejects", "integer", "512", "", "at least 1", kPbrtV2,
     "rejections in a row after which a proposal is accepted"},
    {"chains", "integer", "1000", "", "at least 1", kCandela,
     "Markov chains, each from one bootstrap path"},
    {"bidirectional", "bool", "true", "", "", kPbrtV2, "bdpt's paths; false: unidirectional ones"},
    {"dodirectseparately", "bool", "true", "", "", kPbrtV2,
     "direct lighting by the directlighting integrator, outside the chains"},
    {"directsamples", "integer", "4", "", "at least 1", kPbrtV2,
     "that integrator's samples per pixel"},
};

// In name order, as the unknown-name error lists them.
const IntegratorPlugin kIntegrators[] = {
    {{"integrator", "ambientocclusion", kSurface,
      "fraction of unoccluded directions at the first hit (pbrt-v2's, not in pbrt 2e)",
      kAmbientOcclusion},
     createAmbientOcclusionIntegrator},
    {{"integrator", "ao", kPbrtV3,
      "unnormalised cosine-weighted visibility at the first hit (pbrt-v3's, not in pbrt 3e)", kAo},
     createAoIntegrator},
    {{"integrator", "bdpt", kPbrtV3, "bidirectional path tracing (pbrt 3e §16.3)", kBdpt},
     createBdptIntegrator},
    {{"integrator", "bidirectional", kSurface,
      "bidirectional path tracing (the lrt draft; pbrt 3e §16.3)", kBidirectional},
     createBidirectionalIntegrator},
    {{"integrator", "dipolesubsurface", kSurface,
      "subsurface scattering by the dipole diffusion approximation (pbrt 2e §16.5)",
      kDipoleSubsurface},
     createDipoleSubsurfaceIntegrator},
    {{"integrator", "directlighting", kAllDialects,
      "direct lighting and specular recursion (pbrt 2e §15.1, pbrt 3e §14.3)", kDirectLighting},
     createDirectLightingIntegrator},
    {{"integrator", "exphotonmap", kSurface,
      "photon mapping with final gathering, pbrt-v2's other name (pbrt 2e §15.6)", kPhotonMap},
     createPhotonMapIntegrator},
    {{"integrator", "igi", kSurface, "instant global illumination (pbrt 2e §15.4)", kIgi},
     createIgiIntegrator},
    {{"integrator", "irradiancecache", kSurface,
      "irradiance caching (pbrt 2e §15.5, the lrt draft §16.5)", kIrradianceCache},
     createIrradianceCacheIntegrator},
    {{"integrator", "mlt", kPbrtV3,
      "Metropolis light transport over bdpt's paths, the whole image (pbrt 3e §16.4)", kMlt},
     nullptr,
     createMltRenderer},
    {{"integrator", "path", kAllDialects, "path tracing (pbrt 2e §15.3, pbrt 3e §14.5)", kPath},
     createPathIntegrator},
    {{"integrator", "photonmap", kSurface, "photon mapping with final gathering (pbrt 2e §15.6)",
      kPhotonMap},
     createPhotonMapIntegrator},
    {{"integrator", "sppm", kPbrtV3,
      "stochastic progressive photon mapping, the whole image (pbrt 3e §16.2)", kSppm},
     nullptr,
     createSppmIntegrator},
    {{"integrator", "volpath", kPbrtV3, "path tracing through participating media (pbrt 3e §15.2)",
      kVolPath},
     createVolPathIntegrator},
    {{"integrator", "whitted", kAllDialects, "Whitted-style ray tracing (pbrt 2e §1.3.6)",
      kWhitted},
     createWhittedIntegrator},
};

const IntegratorPlugin kRenderers[] = {
    {{"renderer", "metropolis", kPbrtV2,
      "Metropolis light transport, the whole image (pbrt 2e §15.7)", kMetropolis},
     nullptr,
     createMetropolisIntegrator},
    // No create function: createWholeImageIntegrator gives none, and the sampler renderer runs.
    {{"renderer",
      "sampler",
      kPbrtV2,
      "each pixel's samples traced by the scene's surface integrator (pbrt 2e §1.3)",
      {}}},
};

}  // namespace

std::span<const IntegratorPlugin> integratorPlugins() { return kIntegrators; }

std::span<const IntegratorPlugin> rendererPlugins() { return kRenderers; }

}  // namespace candela
