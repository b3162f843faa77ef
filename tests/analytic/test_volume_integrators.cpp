// The volume integrators of the lrt draft (§16.7): single scattering in a homogeneous slab lit by
// a point light against the 1D integral along the ray, computed here by adaptive Simpson; and the
// emission integrator and the renderer's L = T·L_surface + L_volume on closed-form scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/memory.h"
#include "support/render_scene.h"

namespace candela {
namespace {

// A sampler whose 1D values are a fixed offset (the marching offset) followed by zeros, so that
// a sum over offsets k/K + 1/2K is the stratified estimate of the integral over the offset.
class FixedOffsetSampler : public Sampler {
 public:
  explicit FixedOffsetSampler(Float offset) : offset_(offset) {}
  int samplesPerPixel() const override { return 1; }
  std::unique_ptr<Sampler> clone() const override {
    return std::make_unique<FixedOffsetSampler>(offset_);
  }
  void startPixelSample(const Point2i&, int) override { next_ = 0; }
  Float get1D() override { return next_++ == 0 ? offset_ : Float(0.25); }
  Point2f get2D() override { return {0.5f, 0.5f}; }
  Point2f getPixel2D() override { return {0.5f, 0.5f}; }

 private:
  Float offset_;
  int next_ = 0;
};

double adaptiveSimpson(const std::function<double(double)>& f, double a, double b, double fa,
                       double fm, double fb, double whole, double eps, int depth) {
  double m = (a + b) / 2, lm = (a + m) / 2, rm = (m + b) / 2;
  double flm = f(lm), frm = f(rm);
  double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15 * eps)
    return left + right + (left + right - whole) / 15;
  return adaptiveSimpson(f, a, m, fa, flm, fm, left, eps / 2, depth - 1) +
         adaptiveSimpson(f, m, b, fm, frm, fb, right, eps / 2, depth - 1);
}

double integrate(const std::function<double(double)>& f, double a, double b, double eps) {
  double fa = f(a), fb = f(b), fm = f((a + b) / 2);
  return adaptiveSimpson(f, a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), eps, 40);
}

TEST(VolumeIntegrators, SingleScatteringInASlabMatchesTheIntegralAlongTheRay) {
  // Slab z in [0, 1] (wide in x and y), Henyey–Greenstein g = 0.4, a point light inside it.
  const double sigmaA = 0.3, sigmaS = 0.5, g = 0.4, intensity = 2;
  const double light[3] = {0.3, 0.2, 0.5};
  test::RenderedScene built = test::buildSceneText(
      "Film \"image\" \"integer xresolution\" [2] \"integer yresolution\" [2]\n"
      "VolumeIntegrator \"single\" \"float stepsize\" [0.05]\n"
      "WorldBegin\n"
      "Volume \"homogeneous\" \"rgb sigma_a\" [0.3 0.3 0.3] \"rgb sigma_s\" [0.5 0.5 0.5]\n"
      "  \"float g\" [0.4] \"point p0\" [-10 -10 0] \"point p1\" [10 10 1]\n"
      "LightSource \"point\" \"point from\" [0.3 0.2 0.5] \"rgb I\" [2 2 2]\n"
      "Translate 50 50 -50\n"
      "Shape \"sphere\" \"float radius\" [0.1]\n"
      "WorldEnd\n");
  RenderJob& job = built.job();
  ASSERT_NE(job.volumeIntegrator, nullptr);
  const double dir[3] = {0.1 / std::sqrt(1.01), 0, 1 / std::sqrt(1.01)};
  const double origin[3] = {0, 0, -1};
  Ray ray(Point3f(0, 0, -1), Vector3f(Float(dir[0]), Float(dir[1]), Float(dir[2])));

  // The reference: along the ray (unit direction), the slab is entered at s0 and left at s1.
  const double sigmaT = sigmaA + sigmaS, s0 = 1 / dir[2], s1 = 2 / dir[2];
  auto integrand = [&](double s) {
    double x[3], w[3], r2 = 0;
    for (int i = 0; i < 3; ++i) {
      x[i] = origin[i] + s * dir[i];
      w[i] = light[i] - x[i];
      r2 += w[i] * w[i];
    }
    double r = std::sqrt(r2);
    double cosTheta = (w[0] * dir[0] + w[1] * dir[1] + w[2] * dir[2]) / r;  // forward = +1
    double hg = (1 - g * g) / (4 * M_PI * std::pow(1 + g * g - 2 * g * cosTheta, 1.5));
    // Both the point and the light are inside the slab: the whole shadow segment attenuates.
    return std::exp(-sigmaT * (s - s0)) * sigmaS * hg * intensity / r2 * std::exp(-sigmaT * r);
  };
  double reference = integrate(integrand, s0, s1, 1e-12);

  // The estimator averaged over K stratified marching offsets.
  const int K = 64;
  double sum = 0;
  Spectrum transmittance;
  for (int k = 0; k < K; ++k) {
    FixedOffsetSampler sampler((Float(k) + 0.5f) / K);
    sampler.startPixelSample(Point2i(0, 0), 0);
    MemoryArena arena;
    RayStats stats;
    IntegratorContext ctx{sampler, arena, stats};
    Ray r = ray;
    sum += job.volumeIntegrator->Li(r, *job.scene, ctx, &transmittance)[1];
  }
  double estimate = sum / K;
  EXPECT_NEAR(estimate, reference, 1e-4 * reference) << "reference " << reference;
  EXPECT_NEAR(transmittance[0], std::exp(-sigmaT * (s1 - s0)), 1e-6);
}

TEST(VolumeIntegrators, EmissionAlongARayThroughAnEmittingBoxIsLeTimesLength) {
  // Orthographic rays along +z through a non-absorbing box of depth 2 emitting Le = 0.25 per
  // unit length: every pixel is 0.5, whatever the marching offsets (any step sum is exact).
  test::RenderedScene r = test::renderSceneText(
      "Camera \"orthographic\"\n"
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
      "Sampler \"random\" \"integer pixelsamples\" [4]\n"
      "VolumeIntegrator \"emission\" \"float stepsize\" [0.3]\n"
      "WorldBegin\n"
      "Volume \"homogeneous\" \"rgb Le\" [0.25 0.25 0.25] \"point p0\" [-5 -5 1]\n"
      "  \"point p1\" [5 5 3]\n"
      "Translate 0 0 -20\n"
      "Shape \"sphere\" \"float radius\" [0.1]\n"
      "WorldEnd\n");
  const ImageBuffer& image = r.film().image();
  ASSERT_GT(image.data.size(), 0u);
  for (size_t i = 0; i < image.data.size(); i += size_t(image.channelCount()))
    EXPECT_NEAR(image.data[i], 0.5f, 1e-5f) << i;
}

TEST(VolumeIntegrators, SurfaceBehindAnAbsorbingBoxIsAttenuatedByBeersLaw) {
  // A constant sky seen through an absorbing box of depth 2 (σa = 0.4): exp(-0.8) of it; the
  // same scene without the Volume sees the sky unattenuated.
  auto scene = [](const std::string& volume) {
    return "Camera \"orthographic\"\n"
           "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
           "Sampler \"random\" \"integer pixelsamples\" [2]\n"
           "SurfaceIntegrator \"path\"\n"
           "WorldBegin\n"
           "LightSource \"infinite\" \"rgb L\" [1 1 1]\n" +
           volume +
           "Translate 0 0 -20\n"
           "Shape \"sphere\" \"float radius\" [0.1]\n"
           "WorldEnd\n";
  };
  const ImageBuffer clear = test::renderSceneText(scene("")).film().image();
  const ImageBuffer fog =
      test::renderSceneText(scene("Volume \"homogeneous\" \"rgb sigma_a\" [0.4 0.4 0.4] "
                                  "\"point p0\" [-5 -5 1] \"point p1\" [5 5 3]\n"))
          .film()
          .image();
  ASSERT_EQ(clear.data.size(), fog.data.size());
  for (size_t i = 0; i < clear.data.size(); i += size_t(clear.channelCount())) {
    EXPECT_NEAR(clear.data[i], 1, 1e-5f);
    EXPECT_NEAR(fog.data[i], std::exp(-0.8f), 1e-5f) << i;
  }
}

class ShadowRaysThroughTheVolume : public testing::TestWithParam<const char*> {};

TEST_P(ShadowRaysThroughTheVolume, AreAttenuatedByBeersLaw) {
  // A matte wall at z = 5 lit by a point light at z = 2 on the camera's axis, seen through a
  // thin screen window (rays along the axis); an absorbing slab z in [3, 4] lies across both the
  // camera ray and the shadow ray: the wall is exp(-2 σa) as bright as without the slab.
  auto scene = [](const std::string& volume) {
    return std::string(
               "Camera \"orthographic\" \"float screenwindow\" [-1e-3 1e-3 -1e-3 1e-3]\n"
               "Film \"image\" \"integer xresolution\" [2] \"integer yresolution\" [2]\n"
               "Sampler \"random\" \"integer pixelsamples\" [2]\n"
               "SurfaceIntegrator ") +
           GetParam() +
           "\nWorldBegin\n"
           "LightSource \"point\" \"point from\" [0 0 2] \"rgb I\" [3 3 3]\n" +
           volume +
           "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
           "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
           "  \"point P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\n"
           "WorldEnd\n";
  };
  const ImageBuffer clear = test::renderSceneText(scene("")).film().image();
  const ImageBuffer slab =
      test::renderSceneText(scene("Volume \"homogeneous\" \"rgb sigma_a\" [0.3 0.3 0.3] "
                                  "\"point p0\" [-10 -10 3] \"point p1\" [10 10 4]\n"))
          .film()
          .image();
  ASSERT_EQ(clear.data.size(), slab.data.size());
  for (size_t i = 0; i < clear.data.size(); i += size_t(clear.channelCount())) {
    ASSERT_GT(clear.data[i], 0);
    EXPECT_NEAR(slab.data[i] / clear.data[i], std::exp(-0.6f), 1e-5f) << i;
  }
}

INSTANTIATE_TEST_SUITE_P(SurfaceIntegrators, ShadowRaysThroughTheVolume,
                         testing::Values("\"whitted\"", "\"directlighting\"",
                                         "\"directlighting\" \"string strategy\" \"one\"",
                                         "\"path\""));

}  // namespace
}  // namespace candela
