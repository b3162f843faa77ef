// The BxDFs and incident directions the statistical tests run over: a short list for every run
// and the full sweep (incident angles from the normal to 89.9 degrees, from both sides,
// roughness 1e-3 to 1, eta 1.0001 to 10) for the Long suites.
#pragma once

#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/memory.h"
#include "reflection/brdf_to_btdf.h"
#include "reflection/bsdf.h"
#include "reflection/disney_clearcoat.h"
#include "reflection/disney_diffuse.h"
#include "reflection/disney_fresnel.h"
#include "reflection/fresnel_blend.h"
#include "reflection/irregular_brdf.h"
#include "reflection/lafortune.h"
#include "reflection/merl_brdf.h"
#include "reflection/microfacet.h"
#include "reflection/oren_nayar.h"
#include "reflection/specular.h"
#include "reflection/trowbridge_reitz_bxdfs.h"
#include "reflection/trowbridge_reitz_dielectric.h"
#include "support/disney_material.h"

namespace candela::testcases {

// A direction at polar angle thetaDeg (> 90 is below the surface) and azimuth phiDeg.
inline Vector3f direction(double thetaDeg, double phiDeg = 0) {
  double t = thetaDeg * M_PI / 180, p = phiDeg * M_PI / 180;
  return Vector3f(Float(std::sin(t) * std::cos(p)), Float(std::sin(t) * std::sin(p)),
                  Float(std::cos(t)));
}

// Concatenation through a stream (GCC 12 warns falsely on chains of string operator+).
template <typename... Args>
std::string cat(const Args&... args) {
  std::ostringstream s;
  (s << ... << args);
  return s.str();
}

// A BxDF with the arena that owns it and its parts, and the outgoing direction to test.
struct BxDFCase {
  std::string name;
  std::shared_ptr<MemoryArena> arena;
  const BxDF* bxdf = nullptr;
  Vector3f wo;
  bool isBRDF = true;
};

// A smooth synthetic MERL-layout table: a diffuse base and a lobe in theta_h, tinted per channel.
inline const MerlBrdfTable& syntheticMerlTable() {
  static const MerlBrdfTable table = [] {
    const int nh = 30, nd = 30, np = 60;
    size_t n = size_t(nh) * nd * np;
    std::vector<double> rgb(3 * n);
    for (int ih = 0; ih < nh; ++ih)
      for (int id = 0; id < nd; ++id)
        for (int ip = 0; ip < np; ++ip) {
          double u = (ih + 0.5) / nh, thetaH = u * u * M_PI / 2;
          double thetaD = (id + 0.5) / nd * M_PI / 2;
          double lobe = 2 * std::pow(std::cos(thetaH), 40) * (1 + 0.3 * std::sin(thetaD));
          size_t i = (size_t(ih) * nd + id) * np + ip;
          for (int c = 0; c < 3; ++c) rgb[c * n + i] = (0.05 + 0.05 * c) + lobe;
        }
    return MerlBrdfTable(nh, nd, np, rgb);
  }();
  return table;
}

// Scattered samples of a Lambertian-plus-Phong BRDF, like a measured data set.
inline const IrregularBrdfTable& syntheticIrregularTable() {
  static const IrregularBrdfTable table = [] {
    std::vector<IrregularBrdfSample> samples;
    RNG rng(77);
    for (int i = 0; i < 1000; ++i) {
      auto dir = [&] {
        Float z = rng.uniformFloat(), phi = 2 * kPi * rng.uniformFloat();
        Float s = std::sqrt(1 - z * z);
        return Vector3f(s * std::cos(phi), s * std::sin(phi), z);
      };
      Vector3f wi = dir(), wo = dir();
      Float c = std::max(Float(0), dot(reflectAboutNormal(wo), wi));
      Float v = 0.1f + 3 * std::pow(c, 20);
      samples.push_back({wi, wo, Spectrum(v, 0.8f * v, 0.6f * v)});
    }
    return IrregularBrdfTable(std::move(samples));
  }();
  return table;
}

// Builds one case; make() receives the case's arena.
inline BxDFCase makeCase(std::string name, const Vector3f& wo,
                         const std::function<const BxDF*(MemoryArena&)>& make) {
  BxDFCase c;
  c.name = std::move(name);
  c.arena = std::make_shared<MemoryArena>();
  c.bxdf = make(*c.arena);
  c.wo = wo;
  c.isBRDF = (c.bxdf->type() & kReflection) != 0;
  return c;
}

inline const BxDF* blinnMicrofacet(MemoryArena& a, Float exponent, const Fresnel* fr = nullptr) {
  if (!fr) fr = a.make<FresnelNoOp>();
  return a.make<MicrofacetReflection>(Spectrum(1), fr, a.make<BlinnDistribution>(exponent));
}
inline const BxDF* anisoMicrofacet(MemoryArena& a, Float ex, Float ey) {
  return a.make<MicrofacetReflection>(Spectrum(1), a.make<FresnelNoOp>(),
                                      a.make<AnisotropicDistribution>(ex, ey));
}
// pbrt-v3's Trowbridge-Reitz reflection and transmission (index 1 outside, eta inside).
inline const BxDF* trReflection(MemoryArena& a, Float ax, Float ay, const Fresnel* fr = nullptr) {
  if (!fr) fr = a.make<FresnelNoOp>();
  return a.make<TrowbridgeReitzReflection>(Spectrum(1), fr,
                                           a.make<TrowbridgeReitzDistribution>(ax, ay));
}
inline const BxDF* trTransmission(MemoryArena& a, Float ax, Float ay, Float eta) {
  return a.make<TrowbridgeReitzTransmission>(Spectrum(1),
                                             a.make<TrowbridgeReitzDistribution>(ax, ay), 1.f, eta);
}
// pbrt-v3's rough glass as one BxDF choosing by the microfacet's Fresnel term (tinted r, t).
inline const BxDF* trDielectric(MemoryArena& a, Float ax, Float ay, Float eta,
                                const Spectrum& r = Spectrum(1), const Spectrum& t = Spectrum(1)) {
  return a.make<TrowbridgeReitzDielectric>(r, t, a.make<TrowbridgeReitzDistribution>(ax, ay), 1.f,
                                           eta);
}
inline const BxDF* phongLafortune(MemoryArena& a, Float exponent) {
  auto* lobe = a.make<LafortuneLobe>(
      LafortuneLobe{Spectrum(-1), Spectrum(-1), Spectrum(1), Spectrum(exponent)});
  return a.make<Lafortune>(Spectrum(0.2f), std::span<const LafortuneLobe>(lobe, 1));
}
inline const BxDF* clay(MemoryArena& a) {
  LafortuneFit fit = *lafortuneFit("clay");
  return a.make<Lafortune>(fit.diffuse, fit.lobes);
}

// Sampled (non-delta) BxDFs for the chi-square test. full = the Long sweep.
inline std::vector<BxDFCase> sampledCases(bool full) {
  std::vector<BxDFCase> cases;
  auto add = [&](std::string name, const Vector3f& wo,
                 const std::function<const BxDF*(MemoryArena&)>& make) {
    cases.push_back(makeCase(std::move(name), wo, make));
  };
  if (!full) {
    add("Lambertian_30", direction(30),
        [](MemoryArena& a) { return a.make<LambertianReflection>(Spectrum(0.5f)); });
    add("Lambertian_below_150", direction(150, 40),
        [](MemoryArena& a) { return a.make<LambertianReflection>(Spectrum(0.5f)); });
    add("OrenNayar_s30_60", direction(60, 10),
        [](MemoryArena& a) { return a.make<OrenNayar>(Spectrum(0.5f), 30); });
    add("Blinn_e1_0", direction(0), [](MemoryArena& a) { return blinnMicrofacet(a, 1); });
    add("Blinn_e10_45", direction(45, 20), [](MemoryArena& a) { return blinnMicrofacet(a, 10); });
    add("Blinn_e1000_89p9", direction(89.9, 70),
        [](MemoryArena& a) { return blinnMicrofacet(a, 1000); });
    add("Blinn_e100_inside_110", direction(110, 200), [](MemoryArena& a) {
      return blinnMicrofacet(a, 100, a.make<FresnelDielectric>(1.f, 1.5f));
    });
    add("Aniso_10_100_30", direction(30, 30),
        [](MemoryArena& a) { return anisoMicrofacet(a, 10, 100); });
    add("Aniso_1000_1_80", direction(80, 60),
        [](MemoryArena& a) { return anisoMicrofacet(a, 1000, 1); });
    add("Aniso_1_1_0", direction(0), [](MemoryArena& a) { return anisoMicrofacet(a, 1, 1); });
    add("FresnelBlend_Blinn20_45", direction(45), [](MemoryArena& a) {
      return a.make<FresnelBlend>(Spectrum(0.5f), Spectrum(0.04f), a.make<BlinnDistribution>(20));
    });
    add("FresnelBlend_Aniso5_50_75", direction(75, 10), [](MemoryArena& a) {
      return a.make<FresnelBlend>(Spectrum(0.5f), Spectrum(0.2f),
                                  a.make<AnisotropicDistribution>(5, 50));
    });
    add("Clay_30", direction(30), [](MemoryArena& a) { return clay(a); });
    add("Clay_80", direction(80, 45), [](MemoryArena& a) { return clay(a); });
    add("Phong50_60", direction(60, 120), [](MemoryArena& a) { return phongLafortune(a, 50); });
    add("BTDF_Blinn30_40", direction(40),
        [](MemoryArena& a) { return a.make<BRDFToBTDF>(blinnMicrofacet(a, 30)); });
    add("BTDF_Lambertian_below_120", direction(120), [](MemoryArena& a) {
      return a.make<BRDFToBTDF>(a.make<LambertianReflection>(Spectrum(0.5f)));
    });
    add("MERL_synthetic_50", direction(50, 30),
        [](MemoryArena& a) { return a.make<MeasuredBRDF>(&syntheticMerlTable()); });
    add("Irregular_synthetic_20", direction(20),
        [](MemoryArena& a) { return a.make<IrregularMeasuredBRDF>(&syntheticIrregularTable()); });
    add("TR_0p3_30", direction(30, 30), [](MemoryArena& a) { return trReflection(a, 0.3f, 0.3f); });
    add("TR_0p05_0p5_60", direction(60, 40),
        [](MemoryArena& a) { return trReflection(a, 0.05f, 0.5f); });
    add("TR_0p01_80", direction(80, 10),
        [](MemoryArena& a) { return trReflection(a, 0.01f, 0.01f); });
    add("TR_1_0", direction(0), [](MemoryArena& a) { return trReflection(a, 1, 1); });
    add("TR_0p2_inside_120", direction(120, 200), [](MemoryArena& a) {
      return trReflection(a, 0.2f, 0.2f, a.make<FresnelDielectric>(1.f, 1.5f));
    });
    add("TRTransmission_0p2_40", direction(40, 15),
        [](MemoryArena& a) { return trTransmission(a, 0.2f, 0.2f, 1.5f); });
    add("TRTransmission_0p5_0p05_inside_150", direction(150, 60),
        [](MemoryArena& a) { return trTransmission(a, 0.5f, 0.05f, 1.5f); });
    add("TRTransmission_0p3_inside_grazing_100", direction(100, 5),
        [](MemoryArena& a) { return trTransmission(a, 0.3f, 0.3f, 1.33f); });
    add("TRTransmission_0p02_0", direction(0),
        [](MemoryArena& a) { return trTransmission(a, 0.02f, 0.02f, 2.42f); });
    add("TRDielectric_0p2_40", direction(40, 15),
        [](MemoryArena& a) { return trDielectric(a, 0.2f, 0.2f, 1.5f); });
    add("TRDielectric_0p5_0p05_inside_150", direction(150, 60),
        [](MemoryArena& a) { return trDielectric(a, 0.5f, 0.05f, 1.5f); });
    add("TRDielectric_0p3_inside_grazing_100", direction(100, 5),
        [](MemoryArena& a) { return trDielectric(a, 0.3f, 0.3f, 1.33f); });
    add("TRDielectric_tinted_0p1_70", direction(70, 25), [](MemoryArena& a) {
      return trDielectric(a, 0.1f, 0.1f, 1.5f, Spectrum(0.3f), Spectrum(0.9f, 0.5f, 0.2f));
    });
    add("TRFresnelBlend_0p1_0p4_50", direction(50, 70), [](MemoryArena& a) {
      return a.make<TrowbridgeReitzFresnelBlend>(Spectrum(0.5f), Spectrum(0.2f),
                                                 a.make<TrowbridgeReitzDistribution>(0.1f, 0.4f));
    });
    // The Disney lobes (materials/disney.h): the diffuse family is cosine-sampled, the clearcoat
    // through GTR1, the specular lobe is Trowbridge-Reitz reflection with the Disney Fresnel.
    add("DisneyDiffuse_30", direction(30, 10),
        [](MemoryArena& a) { return a.make<DisneyDiffuse>(Spectrum(0.8f)); });
    add("DisneyRetro_r1_80", direction(80, 20),
        [](MemoryArena& a) { return a.make<DisneyRetroReflection>(Spectrum(0.8f), 1.f); });
    add("DisneyFakeSubsurface_r0p5_below_100", direction(100, 30),
        [](MemoryArena& a) { return a.make<DisneyFakeSubsurface>(Spectrum(0.8f), 0.5f); });
    add("DisneySheen_60", direction(60, 40),
        [](MemoryArena& a) { return a.make<DisneySheen>(Spectrum(1)); });
    add("DisneyClearcoat_gloss1_30", direction(30, 50),
        [](MemoryArena& a) { return a.make<DisneyClearcoat>(1.f, 1.f); });
    add("DisneyClearcoat_gloss0_85", direction(85, 60),
        [](MemoryArena& a) { return a.make<DisneyClearcoat>(1.f, 0.f); });
    add("DisneyClearcoat_gloss0p5_below_140", direction(140, 70),
        [](MemoryArena& a) { return a.make<DisneyClearcoat>(1.f, 0.5f); });
    add("DisneySpecular_metallic0p5_0p2_0p4_45", direction(45, 80), [](MemoryArena& a) {
      return trReflection(a, 0.2f, 0.4f,
                          a.make<DisneyFresnel>(Spectrum(0.9f, 0.6f, 0.3f), 0.5f, 1.5f));
    });
    return cases;
  }
  // The sweep: incident angles from the normal to 89.9 degrees, above and (for the microfacet
  // models, also with a dielectric seen from inside) below the surface.
  const double thetas[] = {0, 10, 30, 50, 70, 85, 89.9};
  const Float roughness[] = {1e-3f, 1e-2f, 0.1f, 0.3f, 1};
  const Float etas[] = {1.0001f, 1.333f, 1.5f, 2.42f, 10};
  for (double t : thetas) {
    std::string ts = std::to_string(int(t * 10));
    add(cat("Lambertian_", ts), direction(t),
        [](MemoryArena& a) { return a.make<LambertianReflection>(Spectrum(0.5f)); });
    add(cat("OrenNayar_", ts), direction(180 - t, 33),
        [](MemoryArena& a) { return a.make<OrenNayar>(Spectrum(0.5f), 20); });
    add(cat("Clay_", ts), direction(t, 15), [](MemoryArena& a) { return clay(a); });
    add(cat("MERL_", ts), direction(t, 5),
        [](MemoryArena& a) { return a.make<MeasuredBRDF>(&syntheticMerlTable()); });
    for (int ri = 0; ri < 5; ++ri) {
      Float r = roughness[ri];
      std::string rs = cat("r", int(std::round(-std::log10(r) * 10)));
      add(cat("Blinn_", rs, "_", ts), direction(t, 25),
          [r](MemoryArena& a) { return blinnMicrofacet(a, 1 / r); });
      // Inside a dielectric; eta (only in f, which the draws check against f()) cycles with r.
      Float eta = etas[ri];
      add(cat("Blinn_inside_", rs, "_eta", eta, "_", ts), direction(180 - t, 25),
          [r, eta](MemoryArena& a) {
            return blinnMicrofacet(a, 1 / r, a.make<FresnelDielectric>(1.f, eta));
          });
      add(cat("Aniso_", rs, "_", ts), direction(t, 35),
          [r](MemoryArena& a) { return anisoMicrofacet(a, 1 / r, 0.1f / r); });
      add(cat("FresnelBlend_", rs, "_", ts), direction(t, 50), [r](MemoryArena& a) {
        return a.make<FresnelBlend>(Spectrum(0.5f), Spectrum(0.05f),
                                    a.make<AnisotropicDistribution>(1 / r, 0.3f / r));
      });
      add(cat("BTDF_Blinn_", rs, "_", ts), direction(180 - t, 80),
          [r](MemoryArena& a) { return a.make<BRDFToBTDF>(blinnMicrofacet(a, 1 / r)); });
      // Trowbridge-Reitz alpha is a slope, far narrower than Blinn's 1 / e at the same r: from
      // 0.01 up. Refraction at eta -> 1 bends every microfacet's ray alike, a delta in the
      // limit: from 1.1 up. The indices pair with the roughnesses shifted by one, so that
      // eta 10 meets alpha 0.01, not 1: at alpha 1 the harness's cubature misses 1.5e-4 of the pdf
      // (at 70 degrees; a 300 x 300 midpoint rule per cell finds 1.00003 and agrees with 2e7
      // samples), which the failed-sample cell counts as 147 missing failures.
      Float alpha = std::max(r, 0.01f), etaT = std::max(etas[(ri + 4) % 5], 1.1f);
      add(cat("TR_", rs, "_", ts), direction(t, 35),
          [alpha](MemoryArena& a) { return trReflection(a, alpha, 0.3f * alpha + 0.01f); });
      add(cat("TRTransmission_", rs, "_eta", etaT, "_", ts), direction(t, 45),
          [alpha, etaT](MemoryArena& a) { return trTransmission(a, alpha, alpha, etaT); });
      add(cat("TRTransmission_inside_", rs, "_eta", etaT, "_", ts), direction(180 - t, 45),
          [alpha, etaT](MemoryArena& a) { return trTransmission(a, alpha, alpha, etaT); });
      // The dielectric at 89.9 degrees puts both its lobes' peaks against the horizon, on the
      // histogram's cell border, where the cubature overestimates the pdf's integral (1.0007
      // for alpha 1, eta 2.42, against 0.99957 of the samples succeeding): the BSDF cases below
      // take it, in a frame tilted off the histogram's axes.
      if (t < 89)
        add(cat("TRDielectric_", rs, "_eta", etaT, "_", ts), direction(t, 55),
            [alpha, etaT](MemoryArena& a) { return trDielectric(a, alpha, alpha, etaT); });
      add(cat("TRDielectric_inside_", rs, "_eta", etaT, "_", ts), direction(180 - t, 55),
          [alpha, etaT](MemoryArena& a) { return trDielectric(a, alpha, alpha, etaT); });
    }
  }
  add("Blinn_e10000_30", direction(30), [](MemoryArena& a) { return blinnMicrofacet(a, 1e4f); });
  return cases;
}

// A BSDF (several components, a shading frame not aligned with the world axes) and the world-space
// outgoing direction to test.
struct BSDFCase {
  std::string name;
  std::shared_ptr<MemoryArena> arena;
  std::shared_ptr<const test::DisneyFixture> material;  // when the BSDF is a material's
  const BSDF* bsdf = nullptr;
  Vector3f wo;
};

// Whole "disney" materials: parameter sets covering every lobe, with an incident direction each.
struct DisneyCase {
  std::string name;
  test::DisneyParams params;
  double thetaDeg, phiDeg;
};
inline std::vector<DisneyCase> disneyCases() {
  std::vector<DisneyCase> cases;
  auto add = [&](std::string name, double theta, double phi,
                 const std::function<void(test::DisneyParams&)>& set) {
    test::DisneyParams p;
    set(p);
    cases.push_back({std::move(name), p, theta, phi});
  };
  add("defaults_40", 40, 20, [](test::DisneyParams&) {});
  add("anisotropic_60", 60, 70, [](test::DisneyParams& p) {
    p.anisotropic = 0.9f;
    p.roughness = 0.3f;
    p.specularTint = 1;
    p.color = Spectrum(0.8f, 0.3f, 0.1f);
  });
  add("metallic_20", 20, 10, [](test::DisneyParams& p) {
    p.metallic = 1;
    p.roughness = 0.2f;
    p.color = Spectrum(0.9f, 0.7f, 0.3f);
  });
  add("half_metallic_sheen_80", 80, 45, [](test::DisneyParams& p) {
    p.metallic = 0.5f;
    p.sheen = 1;
    p.sheenTint = 0.3f;
    p.roughness = 0.7f;
  });
  add("clearcoat_30", 30, 100, [](test::DisneyParams& p) {
    p.clearcoat = 1;
    p.clearcoatGloss = 0.6f;
    p.roughness = 0.4f;
  });
  add("thin_transmission_50", 50, 130, [](test::DisneyParams& p) {
    p.thin = true;
    p.specTrans = 0.6f;
    p.flatness = 0.5f;
    p.diffTrans = 1.2f;
    p.roughness = 0.5f;
  });
  add("thin_transmission_below_150", 150, 200, [](test::DisneyParams& p) {
    p.thin = true;
    p.specTrans = 0.3f;
    p.flatness = 1;
    p.roughness = 0.8f;
  });
  add("glass_35", 35, 250, [](test::DisneyParams& p) {
    p.specTrans = 1;
    p.roughness = 0.3f;
    p.color = Spectrum(0.9f);
  });
  add("glass_inside_160", 160, 300, [](test::DisneyParams& p) {
    p.specTrans = 0.8f;
    p.roughness = 0.5f;
    p.eta = 1.33f;
  });
  return cases;
}

inline std::vector<BSDFCase> bsdfCases() {
  std::vector<BSDFCase> cases;
  auto add = [&](std::string name, double thetaDeg, double phiDeg,
                 const std::function<void(MemoryArena&, BSDF*)>& fill) {
    BSDFCase c;
    c.name = std::move(name);
    c.arena = std::make_shared<MemoryArena>();
    SurfaceInteraction si;
    Vector3f n = normalize(Vector3f(0.3f, -0.2f, 1));
    si.n = si.shading.n = Normal3f(n.x, n.y, n.z);
    si.shading.dpdu = Vector3f(1, 0.5f, 0);
    BSDF* b = c.arena->make<BSDF>(si);
    fill(*c.arena, b);
    c.bsdf = b;
    c.wo = b->localToWorld(direction(thetaDeg, phiDeg));
    cases.push_back(std::move(c));
  };
  add("Plastic_60", 60, 30, [](MemoryArena& a, BSDF* b) {
    b->add(a.make<LambertianReflection>(Spectrum(0.5f)));
    b->add(blinnMicrofacet(a, 100, a.make<FresnelDielectric>(1.f, 1.5f)));
  });
  add("GlassWithDiffuse_20", 20, 0, [](MemoryArena& a, BSDF* b) {
    b->add(a.make<SpecularReflection>(Spectrum(1), a.make<FresnelDielectric>(1.f, 1.5f)));
    b->add(a.make<SpecularTransmission>(Spectrum(1), 1.f, 1.5f));
    b->add(a.make<LambertianReflection>(Spectrum(0.5f)));
  });
  add("Translucent_below_130", 130, 60, [](MemoryArena& a, BSDF* b) {
    b->add(a.make<LambertianReflection>(Spectrum(0.3f)));
    b->add(a.make<BRDFToBTDF>(a.make<LambertianReflection>(Spectrum(0.3f))));
    b->add(blinnMicrofacet(a, 10));
    b->add(a.make<BRDFToBTDF>(blinnMicrofacet(a, 40)));
  });
  // pbrt-v3's rough glass: reflection and refraction sharing one distribution.
  for (double theta : {35.0, 160.0})
    add(cat("RoughGlass_", int(theta)), theta, 30, [](MemoryArena& a, BSDF* b) {
      auto* d = a.make<TrowbridgeReitzDistribution>(0.25f, 0.25f);
      b->add(
          a.make<TrowbridgeReitzReflection>(Spectrum(1), a.make<FresnelDielectric>(1.f, 1.5f), d));
      b->add(a.make<TrowbridgeReitzTransmission>(Spectrum(1), d, 1.f, 1.5f));
    });
  // The same glass as one BxDF that reflects or refracts by its microfacet's Fresnel term; the
  // BSDF hands it what is left of u0 after the (one-way) pick.
  for (double theta : {35.0, 160.0})
    add(cat("RoughDielectric_", int(theta)), theta, 30,
        [](MemoryArena& a, BSDF* b) { b->add(trDielectric(a, 0.25f, 0.25f, 1.5f)); });
  // At grazing incidence (the sweep's cases that its local histogram cannot integrate).
  add("RoughDielectric_a1_eta2p42_89p9", 89.9, 55,
      [](MemoryArena& a, BSDF* b) { b->add(trDielectric(a, 1, 1, 2.42f)); });
  add("RoughDielectric_a0p3_eta1p5_89p9", 89.9, 55,
      [](MemoryArena& a, BSDF* b) { b->add(trDielectric(a, 0.3f, 0.3f, 1.5f)); });
  for (const DisneyCase& d : disneyCases()) {
    BSDFCase c;
    c.name = "Disney_" + d.name;
    c.arena = std::make_shared<MemoryArena>();
    c.material = std::make_shared<test::DisneyFixture>(d.params);
    c.bsdf = c.material->bsdf(*c.arena);
    c.wo = c.bsdf->localToWorld(direction(d.thetaDeg, d.phiDeg));
    cases.push_back(std::move(c));
  }
  return cases;
}

}  // namespace candela::testcases
