// Camera rays traced in groups: for the path integrator on an aggregate that traces coherent rays
// faster together (Embree without user geometry), the renderer takes a pixel's camera samples
// eight at a time, traces their rays together and starts each path from its ray's hit. The
// paths are those of one sample at a time, to the bit; with Embree's packets the image is the
// same bits for any thread count, tile size and split of the samples into ranges.
#include <gtest/gtest.h>

#include <cstring>

#include "support/render_scene.h"

namespace candela {
namespace {

// Another aggregate's hits, one ray at a time, with the renderer told whether to group rays.
class OneRayAtATime : public Aggregate {
 public:
  OneRayAtATime(const Aggregate& inner, bool grouped) : inner_(inner), grouped_(grouped) {}
  Bounds3f worldBound() const override { return inner_.worldBound(); }
  bool intersect(const Ray& ray, SurfaceInteraction* isect) const override {
    return inner_.intersect(ray, isect);
  }
  bool intersectP(const Ray& ray) const override { return inner_.intersectP(ray); }
  bool tracesCoherentRaysFaster() const override { return grouped_; }
  AggregateStats stats() const override { return inner_.stats(); }

 private:
  const Aggregate& inner_;
  bool grouped_;
};

// The Cornell box at 16 x 16 with the given sampler (12 samples: the last group is partial) and
// camera statement.
std::string boxText(const std::string& sampler, const std::string& camera) {
  std::string s = test::cornellBoxText(16, "SurfaceIntegrator \"path\" \"integer maxdepth\" [6]");
  auto replace = [&](const std::string& from, const std::string& to) {
    size_t at = s.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    s.replace(at, from.size(), to);
  };
  replace("Sampler \"stratified\" \"integer xsamples\" [8] \"integer ysamples\" [8]",
          "Sampler \"" + sampler + "\"");
  replace("Camera \"perspective\" \"float fov\" [39.3]", camera);
  return s;
}

struct Render {
  test::RenderedScene built;
  RenderResult result;
};

// Renders text with the job's own aggregate (wrap false) or through OneRayAtATime, in the given
// sample ranges one after another into one film.
Render render(const std::string& text, std::optional<bool> wrapGrouped, int threads, int tile,
              const std::vector<std::pair<int, int>>& ranges = {{0, -1}}) {
  BuildOptions b;
  b.sppOverride = 12;
  b.seed = 5;
  Render r{test::buildSceneText(text, b), {}};
  RenderJob& job = r.built.job();
  std::optional<OneRayAtATime> wrapper;
  if (wrapGrouped) wrapper.emplace(*job.aggregate, *wrapGrouped);
  Scene scene(wrapper ? &*wrapper : job.aggregate.get(), job.scene->lights(), job.scene->volume());
  scene.setNeedsRayDifferentials(job.scene->needsRayDifferentials());
  scene.setMedia(job.scene->media());
  test::PixelPasses renderer(job);
  for (auto [first, end] : ranges) {
    RenderOptions o{threads, tile, true};
    o.firstSample = first;
    o.endSample = end;
    r.result.add(renderer.render(scene, *job.film, o));
  }
  return r;
}

bool sameBits(const ImageBuffer& a, const ImageBuffer& b) {
  return a.data.size() == b.data.size() &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

const char* const kPinhole = "Camera \"perspective\" \"float fov\" [39.3]";
const char* const kLens =
    "Camera \"perspective\" \"float fov\" [39.3] \"float lensradius\" [20] "
    "\"float focaldistance\" [800]";

// Grouped, each path starts from the hit the group's query found; with hits found one ray at a
// time these are intersect's own, so the image must be the one-sample-at-a-time image, bit for
// bit: the samplers give each sample its values again past its camera sample, and the path
// integrator starting from a given hit is the one that finds it.
TEST(CameraRayGroups, GroupedSamplesGiveTheSameBitsAsOneSampleAtATime) {
  for (const char* sampler : {"halton", "random", "stratified", "sobol", "lowdiscrepancy"})
    for (const char* camera : {kPinhole, kLens}) {
      SCOPED_TRACE(std::string(sampler) + ", " + camera);
      std::string text = boxText(sampler, camera);
      Render grouped = render(text, true, 1, 16), alone = render(text, false, 1, 16);
      const ImageBuffer& g = grouped.built.film().image();
      EXPECT_TRUE(sameBits(g, alone.built.film().image()));
      EXPECT_EQ(grouped.result.samples, alone.result.samples);
      EXPECT_EQ(grouped.result.rays.cameraRays, alone.result.rays.cameraRays);
      EXPECT_EQ(grouped.result.rays.intersectionRays, alone.result.rays.intersectionRays);
      EXPECT_EQ(grouped.result.rays.shadowRays, alone.result.rays.shadowRays);
      double sum = 0;
      for (float v : g.data) sum += v;
      EXPECT_GT(sum, 0);  // not two black images
    }
}

// With Embree's packets the hits are the packets' (which can differ from intersect's where two
// triangles tie), but a group is the same eight samples whatever renders them: the same bits for
// 1 and 2 threads, tiles of 16 and 5, and the samples taken whole or as ranges [0, 5), [5, 12)
// that cut a group.
TEST(CameraRayGroups, PacketsGiveTheSameBitsForAnyThreadCountTileAndSampleRange) {
  for (const char* camera : {kPinhole, kLens}) {
    SCOPED_TRACE(camera);
    std::string text = boxText("halton", camera);
    Render whole = render(text, std::nullopt, 1, 16);
    ASSERT_TRUE(whole.built.job().aggregate->tracesCoherentRaysFaster());
    Render split = render(text, std::nullopt, 2, 5, {{0, 5}, {5, 12}});
    EXPECT_TRUE(sameBits(whole.built.film().image(), split.built.film().image()));
    EXPECT_EQ(whole.result.samples, split.result.samples);
  }
}

}  // namespace
}  // namespace candela
