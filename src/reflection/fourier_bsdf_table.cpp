#include "reflection/fourier_bsdf_table.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "core/error.h"
#include "core/read_file.h"

namespace candela {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

}  // namespace

FourierBsdfTable::FourierBsdfTable(Contents c) : c_(std::move(c)) {
  size_t n = c_.mu.size();
  require(n >= 2 && n <= kMaxNodes,
          "nMu = " + std::to_string(n) + " is not in [2, " + std::to_string(kMaxNodes) + "]");
  require(c_.nChannels == 1 || c_.nChannels == 3,
          "nChannels = " + std::to_string(c_.nChannels) + " (only 1 and 3 are defined)");
  require(
      c_.mMax >= 1 && uint32_t(c_.mMax) <= kMaxOrders,
      "mMax = " + std::to_string(c_.mMax) + " is not in [1, " + std::to_string(kMaxOrders) + "]");
  require(std::isfinite(c_.eta) && c_.eta > 0, "eta is not a positive number");
  for (size_t i = 0; i < n; ++i) {
    require(std::isfinite(c_.mu[i]) && std::abs(c_.mu[i]) <= 1,
            "mu[" + std::to_string(i) + "] is not a cosine in [-1, 1]");
    require(i == 0 || c_.mu[i] >= c_.mu[i - 1], "the mu nodes are not in ascending order");
    // A node may repeat once (the split at mu = 0), never twice: the splines need each
    // interval's neighbours to be apart.
    require(i < 2 || c_.mu[i] > c_.mu[i - 2], "a mu node appears more than twice");
  }
  require(c_.mu.front() < c_.mu.back(), "the mu nodes span no interval");
  require(c_.offsets.size() == n * n && c_.lengths.size() == n * n,
          "the offset table does not have nMu * nMu entries");
  for (size_t cell = 0; cell < n * n; ++cell) {
    std::string where = "the cell of mu_i node " + std::to_string(cell % n) + " and mu_o node " +
                        std::to_string(cell / n);
    require(c_.lengths[cell] <= uint32_t(c_.mMax),
            where + " has " + std::to_string(c_.lengths[cell]) + " coefficients, more than mMax");
    require(uint64_t(c_.offsets[cell]) + uint64_t(c_.lengths[cell]) * uint64_t(c_.nChannels) <=
                c_.coefficients.size(),
            where + " reaches past the end of the coefficients");
  }
  for (Float a : c_.coefficients) require(std::isfinite(a), "a coefficient is NaN or infinite");

  // Rows by mu_o of a_0(mu_i, mu_o) and their integrals over mu_i, for sampling mu_i.
  a0ByOutgoing_.assign(n * n, 0);
  cdfByOutgoing_.assign(n * n, 0);
  for (size_t o = 0; o < n; ++o) {
    for (size_t i = 0; i < n; ++i) {
      int m;
      const Float* a = coefficients(int(i), int(o), &m);
      a0ByOutgoing_[o * n + i] = m > 0 ? a[0] : 0;
    }
    integrateCatmullRom(c_.mu, std::span<const Float>(a0ByOutgoing_).subspan(o * n, n),
                        std::span<Float>(cdfByOutgoing_).subspan(o * n, n));
  }
}

namespace {

constexpr size_t kHeaderBytes = 64;
constexpr uint32_t kFlagBsdf = 1, kFlagExtrapolated = 2;

// Reads little-endian fields from the file's bytes; the caller has checked the sizes.
struct ByteReader {
  std::string_view bytes;
  size_t at = 0;
  uint32_t u32() {
    uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    at += 4;
    return v;
  }
  Float f32() {
    float v;
    std::memcpy(&v, bytes.data() + at, 4);
    at += 4;
    return v;
  }
  template <typename T, typename Read>
  std::vector<T> array(size_t count, Read read) {
    std::vector<T> v(count);
    for (T& x : v) x = read();
    return v;
  }
};

}  // namespace

FourierBsdfTable readFourierBsdf(const std::string& path) {
  return parseFourierBsdf(readWholeFile(path), path);
}

FourierBsdfTable parseFourierBsdf(std::string_view bytes, const std::string& path) {
  const uint64_t size = bytes.size();
  if (size < kHeaderBytes)
    throw FileError(path, "too short for a Fourier BSDF header (" + std::to_string(size) +
                              " bytes; the header has 64)");
  if (bytes.substr(0, 7) != "SCATFUN")
    throw FileError(path, "not a Fourier BSDF file (it does not start with \"SCATFUN\")");
  if (uint8_t(bytes[7]) != 1)
    throw FileError(path, "Fourier BSDF file version " + std::to_string(uint8_t(bytes[7])) +
                              " is not supported (only version 1)");
  ByteReader h{bytes, 8};
  uint32_t flags = h.u32(), nMu = h.u32(), nCoeffs = h.u32(), mMax = h.u32(), nChannels = h.u32(),
           nBases = h.u32(), nMetadata = h.u32(), nParameters = h.u32(), nParameterValues = h.u32();
  Float eta = h.f32();
  if (!(flags & kFlagBsdf)) throw FileError(path, "the Fourier BSDF file holds no BSDF (flags)");
  if (flags & kFlagExtrapolated)
    throw FileError(path, "Fourier BSDF files with harmonic extrapolation are not supported");
  if (nBases != 1)
    throw FileError(path, "Fourier BSDF file has " + std::to_string(nBases) +
                              " basis functions; only untextured files (1) are supported");
  if (nChannels != 1 && nChannels != 3)
    throw FileError(path, "Fourier BSDF file has " + std::to_string(nChannels) +
                              " channels; only 1 and 3 are defined");
  if (nMu < 2 || nMu > FourierBsdfTable::kMaxNodes)
    throw FileError(path, "Fourier BSDF header's nMu = " + std::to_string(nMu) + " is not in [2, " +
                              std::to_string(FourierBsdfTable::kMaxNodes) + "]");
  if (mMax < 1 || mMax > FourierBsdfTable::kMaxOrders)
    throw FileError(path, "Fourier BSDF header's mMax = " + std::to_string(mMax) +
                              " is not in [1, " + std::to_string(FourierBsdfTable::kMaxOrders) +
                              "]");
  // Every count is below 2^32 and nMu below 2^14: the sum cannot overflow 64 bits.
  uint64_t cells = uint64_t(nMu) * nMu;
  uint64_t expected =
      kHeaderBytes +
      4 * (uint64_t(nMu) + nParameters + nParameterValues + cells + 2 * cells + uint64_t(nCoeffs)) +
      nMetadata;
  if (size != expected)
    throw FileError(path, "Fourier BSDF file has " + std::to_string(size) +
                              " bytes but its header's sizes add up to " +
                              std::to_string(expected) +
                              (size < expected ? " (the file is truncated)" : ""));
  ByteReader r{bytes, kHeaderBytes};
  FourierBsdfTable::Contents c;
  c.eta = eta;
  c.mMax = int(mMax);
  c.nChannels = int(nChannels);
  c.mu = r.array<Float>(nMu, [&] { return r.f32(); });
  r.at += 4 * (size_t(nParameters) + nParameterValues);
  // The file's integrals over mu_i are recomputed by FourierBsdfTable with its own spline (so
  // that sampling and pdf agree to rounding), but must be numbers.
  for (uint64_t k = 0; k < cells; ++k)
    if (!std::isfinite(r.f32()))
      throw FileError(path, "Fourier BSDF file's cdf table holds a NaN or infinity");
  c.offsets.resize(cells);
  c.lengths.resize(cells);
  for (uint64_t k = 0; k < cells; ++k) {
    c.offsets[k] = r.u32();
    c.lengths[k] = r.u32();
  }
  c.coefficients = r.array<Float>(nCoeffs, [&] { return r.f32(); });
  try {
    return FourierBsdfTable(std::move(c));
  } catch (const std::invalid_argument& e) {
    throw FileError(path, std::string("invalid Fourier BSDF file: ") + e.what());
  }
}

}  // namespace candela
