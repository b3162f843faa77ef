// pbrt-v3 conformance: each scene of tests/data/conformance/pbrt-v3 (scenes this project wrote,
// with pbrt-v3's renders of them; its README says how they were made) rendered by the candela
// command four times (seeds 1 to 4) and compared with pbrt-v3's own render of it, region by region,
// with a tolerance taken from the renders' spread (support/reference_agreement.h). Family-wise
// significance 0.001 per scene (Šidák over its 16 regions x 3 channels); the seeds are fixed, so a
// pass is reproducible. The normal suite renders 32 samples per pixel, Long/ 256.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "film/output/image_output.h"
#include "support/reference_agreement.h"
#include "support/tail_probabilities.h"
#include "support/temp_dir.h"

namespace candela::test {
namespace {

namespace fs = std::filesystem;

const fs::path kConformanceDir = fs::path(CANDELA_TEST_DATA_DIR) / "conformance" / "pbrt-v3";

struct ConformanceCase {
  std::string scene;
  int samplesPerPixel;
};

void PrintTo(const ConformanceCase& c, std::ostream* os) {
  *os << c.scene << " at " << c.samplesPerPixel << " spp";
}

std::string caseName(const testing::TestParamInfo<ConformanceCase>& info) {
  std::string name = info.param.scene;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

// The reference's samples per pixel: the scene's Sampler line.
int referenceSamples(const fs::path& scene) {
  std::ifstream in(scene);
  std::stringstream text;
  text << in.rdbuf();
  std::smatch match;
  const std::string s = text.str();
  if (!std::regex_search(s, match, std::regex(R"("integer pixelsamples"\s*\[\s*(\d+)\s*\])")))
    throw std::runtime_error(scene.string() + " has no pixelsamples");
  return std::stoi(match[1]);
}

// Options that switch on pbrt-v3's behaviour where candela deliberately differs
// (docs/pbrt-differences.md, "Deliberate differences"): the scene is compared as pbrt-v3 renders
// it; the size of the difference is measured separately.
std::string deliberateDifferenceOptions(const std::string& scene) {
  // The plastic coat's Fresnel with pbrt's reversed indices (pbrt-v3 issue #210).
  if (scene == "materials-a" || scene == "materials-b") return " --coat-fresnel pbrt";
  // The hyperboloid's normal from the p1-p2 segment's direction, off the fitted surface.
  if (scene == "hyperboloid-uv" || scene == "hyperboloid-checker")
    return " --hyperboloid-normal pbrt";
  // The wrinkled sphere's octaves dropped by the footprint: 0.2 each, the partial one's twice.
  if (scene == "procedural") return " --turbulence pbrt";
  return "";
}

ImageBuffer render(const fs::path& scene, int spp, int seed, const fs::path& out) {
  std::ostringstream cmd;
  cmd << '"' << CANDELA_BINARY << "\" -q --preview none --spp " << spp << " --seed " << seed
      << deliberateDifferenceOptions(scene.stem().string()) << " -o \"" << out.string() << "\" \""
      << scene.string() << "\" 2>\"" << out.string() << ".log\"";
  const int status = std::system(cmd.str().c_str());
  if (status != 0) {
    std::ifstream log(out.string() + ".log");
    std::stringstream text;
    text << log.rdbuf();
    throw std::runtime_error("candela failed on " + scene.string() + ":\n" + text.str());
  }
  return readImage(out.string());
}

// Parts of scenes that still render differently, and why: each is a defect to fix or a
// deliberate difference that docs/pbrt-differences.md lists. Regions are (x, y) on the 4 x 4 grid,
// y down: their differences are reported, not failed. A difference confined to a few pixels names
// their 4 x 4 pixel blocks instead (x, y on the 32 x 32 block grid), which are left out of the
// comparison, while the rest of their regions are still compared.
struct KnownDifference {
  std::set<std::pair<int, int>> regions;
  std::string reason;
  std::set<std::pair<int, int>> blocks = {};
};
// The blocks (x, y) with x0 <= x <= x1 and y0 <= y <= y1.
std::set<std::pair<int, int>> blocksIn(int x0, int x1, int y0, int y1) {
  std::set<std::pair<int, int>> blocks;
  for (int x = x0; x <= x1; ++x)
    for (int y = y0; y <= y1; ++y) blocks.insert({x, y});
  return blocks;
}
// The blocks around the cone's apex in quadrics-uv and quadrics-checker.
const std::set<std::pair<int, int>> kConeApexBlocks = blocksIn(15, 16, 15, 16);
// The blocks of the pixel column at the right hyperboloid's left silhouette.
const std::set<std::pair<int, int>> kHyperboloidSilhouetteBlocks = blocksIn(25, 26, 6, 10);
const std::map<std::string, KnownDifference> kKnownDifferences = {
    // The apex is at the image's centre, pixels (63..64, 63..64): the corner of four regions.
    {"quadrics-uv",
     {{},
      "the cone's apex: pbrt-v3 darkens the few pixels at the tip (u and v by one factor in each "
      "pixel: 0.52 at (63, 63), 0.46 at (64, 63)); a convex surface under a uniform sky reflects "
      "its albedo up to the tip, as candela's does (docs/pbrt-differences.md)",
      kConeApexBlocks}},
    {"quadrics-checker", {{}, "the cone's apex, as in quadrics-uv", kConeApexBlocks}},
    // Pixels (102..104, 26..43): blocks 25..26 across, 6..10 down.
    {"hyperboloid-uv",
     {{},
      "with pbrt's normal, one pixel column at the right hyperboloid's left silhouette is 6-9% "
      "brighter than pbrt-v3's, in both normal modes (cause not found)",
      kHyperboloidSilhouetteBlocks}},
    {"hyperboloid-checker", {{}, "as in hyperboloid-uv", kHyperboloidSilhouetteBlocks}},
    {"procedural",
     {{{0, 2}, {1, 2}, {0, 3}, {1, 3}},
      "the marble sphere: candela keeps the book's colour spline; pbrt-v3 extrapolates it "
      "(pbrt-v3 issue #252), a deliberate difference"}},
};

class PbrtV3Conformance : public testing::TestWithParam<ConformanceCase> {};

TEST_P(PbrtV3Conformance, AgreesWithPbrtV3sRender) {
  const ConformanceCase& c = GetParam();
  const fs::path scene = kConformanceDir / "scenes" / (c.scene + ".pbrt");
  const fs::path reference = kConformanceDir / "refs" / (c.scene + ".exr");
  // In the repository: a missing file is a broken checkout, not a reason to skip.
  ASSERT_TRUE(fs::exists(scene) && fs::exists(reference)) << "no " << scene << " or " << reference;
  // Named after the test and the process: suites run at once on one machine never share it.
  TempDir temp("conformance");
  const fs::path dir = temp.path("");

  // Four renders, not two: three degrees of freedom in each block's noise estimate, and half the
  // noise in their mean (support/reference_agreement.h).
  std::vector<ImageBuffer> renders;
  for (int seed = 1; seed <= 4; ++seed)
    renders.push_back(
        render(scene, c.samplesPerPixel, seed, dir / ("seed" + std::to_string(seed) + ".exr")));
  std::vector<const ImageBuffer*> renderPointers;
  for (const ImageBuffer& r : renders) renderPointers.push_back(&r);
  ImageBuffer ref = readImage(reference.string());

  const auto known = kKnownDifferences.find(c.scene);
  ReferenceAgreementOptions options;
  options.samplesPerPixel = c.samplesPerPixel;
  options.referenceSamplesPerPixel = referenceSamples(scene);
  if (known != kKnownDifferences.end()) options.excludedBlocks = known->second.blocks;
  ReferenceAgreement agreement = compareWithReference(renderPointers, ref, options);
  const double level = stats::sidak(0.001, int(agreement.regions.size()));
  auto isKnown = [&](const ReferenceRegion& region) {
    return known != kKnownDifferences.end() &&
           known->second.regions.count({region.regionX, region.regionY});
  };
  int failed = 0, knownFailed = 0;
  for (const ReferenceRegion& region : agreement.regions)
    if (region.pValue < level) {
      ++failed;
      if (isKnown(region))
        ++knownFailed;
      else
        ADD_FAILURE() << c.scene << ": " << agreement.describe(region);
    }
  if (known != kKnownDifferences.end())
    std::cout << c.scene << ": known differences, not counted: " << known->second.reason << " ("
              << known->second.blocks.size() << " blocks left out; " << knownFailed
              << " region channels differ at this sample count)\n";
  const ReferenceRegion& worst = agreement.worst();
  std::cout << c.scene << " at " << c.samplesPerPixel << " spp: mean ratio " << agreement.meanRatio
            << ", relMSE " << agreement.relMse << ", worst region p " << worst.pValue << " (F "
            << worst.ratio << ", dof " << worst.degreesOfFreedom << ", "
            << worst.denominatorDegreesOfFreedom << "), " << failed << " of "
            << agreement.regions.size() << " regions differ\n";
}

const char* const kScenes[] = {
    "camera-dof",          "camera-environment", "camera-orthographic",
    "camera-screenwindow", "combining",          "hyperboloid-checker",
    "hyperboloid-uv",      "imagemap",           "light-area-disk-twosided",
    "light-area-sphere",   "light-distant",      "light-goniometric",
    "light-infinite-map",  "light-point",        "light-projection",
    "light-spot",          "mappings",           "materials-a",
    "materials-b",         "procedural",         "quadrics-checker",
    "quadrics-uv"};

std::vector<ConformanceCase> cases(int spp) {
  std::vector<ConformanceCase> out;
  for (const char* s : kScenes) out.push_back({s, spp});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Scenes, PbrtV3Conformance, testing::ValuesIn(cases(32)), caseName);
INSTANTIATE_TEST_SUITE_P(Long, PbrtV3Conformance, testing::ValuesIn(cases(256)), caseName);

}  // namespace
}  // namespace candela::test
