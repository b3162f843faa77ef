// Isotropic BSDFs tabulated as Fourier series in the azimuth difference (pbrt 3e §8.6; Jakob et
// al. 2014, "A Comprehensive Framework for Rendering Layered Materials"), in the binary format
// of their layerlab tool. Little-endian, on a little-endian host:
//   header (64 bytes): "SCATFUN", version byte 1, then uint32 flags (1: a BSDF; 2: harmonic
//     extrapolation, unsupported), nMu, nCoeffs, mMax, nChannels (1: luminance; 3: Y, R, B),
//     nBases (1; more are textured files, unsupported), nMetadataBytes, nParameters,
//     nParameterValues, then float32 eta, alpha[2] and two unused floats;
//   float32 mu[nMu] (the zenith cosines, ascending; 0 appears twice to split the two sides);
//   uint32 parameter sample counts [nParameters], float32 parameter values [nParameterValues];
//   float32 cdf[nMu * nMu]: row o, the integral of a_0 over mu_i up to each node at mu_o node o
//     (recomputed here with this spline, so that sampling and pdf agree to rounding);
//   uint32 (offset, length) pairs [nMu * nMu], the cell of nodes (mu_i i, mu_o o) at o * nMu + i;
//   float32 coefficients[nCoeffs]: a cell's series, channel c at offset + c * length;
//   nMetadataBytes of text.
// A cell holds a_k with f(mu_i, mu_o, phi) |mu_i| = sum_k a_k cos(k phi) (pbrt 3e §8.6), where
// mu_i is the cosine of the reversed incident direction: mu_i mu_o < 0 is reflection. eta is the
// relative index of refraction below the surface over above it.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "reflection/catmull_rom.h"

namespace candela {

class FourierBsdfTable {
 public:
  // Bounds that keep a corrupt header from asking for absurd memory: the published tables have
  // a few hundred nodes and orders.
  static constexpr uint32_t kMaxNodes = 1 << 14, kMaxOrders = 1 << 12;

  struct Contents {
    Float eta = 1;
    int mMax = 0, nChannels = 1;
    std::vector<Float> mu;
    std::vector<uint32_t> offsets, lengths;  // per cell o * nMu + i
    std::vector<Float> coefficients;
  };
  // Throws std::invalid_argument saying what is inconsistent.
  explicit FourierBsdfTable(Contents c);

  int nMu() const { return int(c_.mu.size()); }
  int mMax() const { return c_.mMax; }
  int nChannels() const { return c_.nChannels; }
  Float eta() const { return c_.eta; }
  std::span<const Float> mu() const { return c_.mu; }
  // The series at nodes (mu_i i, mu_o o); channel c's m coefficients start at c * m.
  const Float* coefficients(int i, int o, int* m) const {
    size_t cell = size_t(o) * c_.mu.size() + size_t(i);
    *m = int(c_.lengths[cell]);
    return c_.coefficients.data() + c_.offsets[cell];
  }
  // For sampling mu_i given mu_o: one row per mu_o node holding a_0 of the first channel as a
  // function of mu_i (the file's layout), with its integrals.
  CatmullRomRows incidentRows() const { return {c_.mu, c_.mu, a0ByOutgoing_, cdfByOutgoing_}; }

 private:
  Contents c_;
  std::vector<Float> a0ByOutgoing_, cdfByOutgoing_;
};

// Reads a file in the format above; throws FileError naming the path and what is wrong.
FourierBsdfTable readFourierBsdf(const std::string& path);
// The same for a file's bytes already in memory; path names it in errors.
FourierBsdfTable parseFourierBsdf(std::string_view bytes, const std::string& path);

}  // namespace candela
