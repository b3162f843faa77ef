// Final gathering (pbrt 2e §15.6.3): the photon-guided cone mixture is a density, and the MIS
// combination with BSDF sampling is unbiased: inside a closed diffuse sphere whose radiance
// photons all carry Lo = 1, the gathered radiance is rho.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "accel/primitive.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "materials/material.h"
#include "support/render_scene.h"
#include "transport/final_gather.h"

namespace candela {
namespace {

TEST(PhotonConeDirections, MixtureIntegratesToOneAndSamplesLieInTheirCone) {
  std::vector<Vector3f> axes = {normalize(Vector3f(0, 0, 1)), normalize(Vector3f(1, 0, 1)),
                                normalize(Vector3f(0.2f, 0.1f, 1))};
  const Float cosAngle = std::cos(Float(30) * kPi / 180);
  PhotonConeDirections cones(axes, cosAngle);
  // Midpoint rule over (cos theta, phi), which is uniform in solid angle.
  const int nz = 1000, nphi = 2000;
  double sum = 0;
  for (int i = 0; i < nz; ++i)
    for (int j = 0; j < nphi; ++j) {
      Float z = -1 + 2 * (i + Float(0.5)) / nz, phi = 2 * kPi * (j + Float(0.5)) / nphi;
      Float r = std::sqrt(std::max(Float(0), 1 - z * z));
      sum += cones.pdf(Vector3f(r * std::cos(phi), r * std::sin(phi), z));
    }
  // The rims of the cones cut the grid cells: a discretisation error of about 1e-3.
  EXPECT_NEAR(sum * 4 * kPi / (double(nz) * nphi), 1.0, 5e-3);

  RNG rng(11);
  for (int i = 0; i < 1000; ++i) {
    int cone;
    Vector3f w =
        cones.sample(rng.uniformFloat(), Point2f(rng.uniformFloat(), rng.uniformFloat()), &cone);
    ASSERT_GE(cone, 0);
    ASSERT_LT(cone, 3);
    EXPECT_NEAR(w.length(), 1, 1e-5);
    EXPECT_GE(dot(w, axes[cone]), cosAngle - 1e-5f);
    EXPECT_GT(cones.pdf(w, cone), 0);
    // Away from the rim the known cone changes nothing.
    if (dot(w, axes[cone]) > cosAngle + 1e-4f) {
      EXPECT_EQ(cones.pdf(w, cone), cones.pdf(w));
    }
  }
  EXPECT_EQ(PhotonConeDirections({}, cosAngle).pdf(Vector3f(0, 0, 1)), 0);
}

// Inside a unit sphere of matte Kd = 0.5, with radiance photons of Lo = 1 all over it.
class GatherInSphere : public ::testing::Test {
 protected:
  void SetUp() override {
    scene_ = test::buildSceneText(
        "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\"\n"
        "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
        "Sampler \"random\" \"integer pixelsamples\" [1]\nSurfaceIntegrator \"path\"\n"
        "WorldBegin\nMaterial \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\nReverseOrientation\n"
        "Shape \"sphere\" \"float radius\" [1]\nWorldEnd\n");
    // A Fibonacci lattice on the sphere, normals inward.
    std::vector<RadiancePhoton> photons;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
      Float z = 1 - 2 * (i + Float(0.5)) / n, phi = Float(2.399963) * i;
      Float r = std::sqrt(1 - z * z);
      Point3f p(r * std::cos(phi), r * std::sin(phi), z);
      photons.push_back(RadiancePhoton{p, Normal3f(-p.x, -p.y, -p.z), Spectrum(1)});
    }
    radiance_ = RadiancePhotonMap(std::move(photons));
  }

  // The mean and standard error of nEstimates final-gather estimates at the sphere's point
  // toward +z, seen from the centre.
  void gather(std::span<const Vector3f> photonDirs, int nEstimates, double* mean, double* stderr_) {
    const Scene& scene = *scene_.job().scene;
    RayStats stats;
    SurfaceInteraction isect;
    ASSERT_TRUE(scene.intersect(Ray(Point3f(0, 0, 0), Vector3f(0, 0, 1)), &isect, stats));
    MemoryArena bsdfArena, arena;
    const BSDF* bsdf = isect.primitive->material->getBSDF(isect, bsdfArena);
    std::unique_ptr<Sampler> sampler = scene_.job().sampler->clone();
    IntegratorContext ctx{*sampler, arena, stats};
    FinalGatherSettings settings;
    settings.samplesPerStrategy = 4;
    settings.cosGatherAngle = std::cos(Float(10) * kPi / 180);
    PhotonConeDirections cones(photonDirs, settings.cosGatherAngle);
    double sum = 0, sum2 = 0;
    for (int i = 0; i < nEstimates; ++i) {
      sampler->startPixelSample(Point2i(i % 64, i / 64), 0);
      double v = finalGather(isect, *bsdf, cones, radiance_, scene, ctx, settings)[0];
      arena.reset();
      sum += v;
      sum2 += v * v;
    }
    *mean = sum / nEstimates;
    *stderr_ = std::sqrt(std::max(0.0, sum2 / nEstimates - *mean * *mean) / nEstimates);
  }

  test::RenderedScene scene_;
  RadiancePhotonMap radiance_;
};

TEST_F(GatherInSphere, BsdfSamplingAloneGivesRho) {
  double mean, se;
  gather({}, 4000, &mean, &se);
  // Lo = 1 everywhere and cosine-weighted sampling: every sample is exactly rho.
  EXPECT_NEAR(mean, 0.5, 1e-4);
  EXPECT_LT(se, 1e-4);
}

TEST_F(GatherInSphere, MisWithPhotonConesGivesRho) {
  // Photon directions (toward where light came from, here the inside of the sphere at -z),
  // some of them under the surface, where the BSDF is 0.
  std::vector<Vector3f> dirs;
  RNG rng(5);
  for (int i = 0; i < 50; ++i) {
    Vector3f w = sampleUniformSphere(Point2f(rng.uniformFloat(), rng.uniformFloat()));
    dirs.push_back(i % 5 == 0 ? w : faceForward(w, Vector3f(0, 0, -1)));
  }
  double mean, se;
  gather(dirs, 4000, &mean, &se);
  // Unbiased: within 4 standard errors (a two-sided 6e-5 chance of failing if correct).
  EXPECT_GT(se, 0);
  EXPECT_NEAR(mean, 0.5, 4 * se);
  EXPECT_LT(se, 0.01);
}

}  // namespace
}  // namespace candela
