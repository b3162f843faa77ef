// Test-only writer of tabulated Fourier BSDF files (the layerlab format that
// reflection/fourier_bsdf_table.h reads), from a BSDF given by its series: for each pair of
// nodes (mu_i, mu_o) the model returns, channel after channel (Y, or Y, R, B), the coefficients
// a_k of f(mu_i, mu_o, phi) |mu_i| = sum_k a_k cos(k phi), mu_i being the cosine of the reversed
// incident direction. The nodes hold mu = 0 twice, as -0.0 and +0.0, so that a model can give
// the limits from either side there (std::signbit tells them apart).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace candela::test {

struct FourierBsdfModel {
  int nChannels = 1;
  int orders = 1;  // coefficients per channel the model returns
  float eta = 1;
  // nChannels * orders coefficients for (mu_i, mu_o).
  std::function<std::vector<double>(double muI, double muO)> coefficients;
};

// -1, ..., -1/nHalf, -0, +0, 1/nHalf, ..., 1: uniform on each side, 2 nHalf + 2 nodes.
std::vector<float> splitUniformNodes(int nHalf);

// The file's bytes. Trailing zero orders of a cell are dropped (a cell of zeros stores none);
// the header's mMax is the longest series kept.
std::string fourierBsdfFileBytes(const FourierBsdfModel& model, const std::vector<float>& mu,
                                 const std::string& metadata = "candela test table");

void writeBytes(const std::string& path, const std::string& bytes);

// Models. With pbrt's convention mu_i mu_o < 0 is reflection; signbit decides at mu = 0.
bool isReflection(double muI, double muO);
// Lambertian reflection of albedo rho: a_0 = rho / pi |mu_i|.
FourierBsdfModel lambertianModel(double rho);
// Per channel c, reflection f = rho_c / pi * K_N(phi) with the Fejer kernel K_N(phi) =
// 1 + 2 sum_{k<N} (1 - k/N) cos(k phi) >= 0, whose mean over phi is 1: a glossy lobe around the
// plane of incidence, forward (phi = 0 is the mirror azimuth), with albedo rho_c at every angle.
// Stored as Y, R, B with Rec. 709 luminance. Not a function of direction at the poles (its
// azimuthal terms do not vanish there, where phi is undefined): tests avoid them.
FourierBsdfModel fejerModel(double rhoR, double rhoG, double rhoB, int n);
// Lambertian reflection (rho) plus a constant transmission tau / pi on the table (before the
// (eta_o / eta_i)^2 radiance scaling), with the given eta.
FourierBsdfModel diffuseTransmitterModel(double rho, double tau, float eta);

}  // namespace candela::test
