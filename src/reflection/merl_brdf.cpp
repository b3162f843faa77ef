#include "reflection/merl_brdf.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "core/error.h"
#include "core/read_file.h"

namespace candela {

namespace {

// Published MERL tables have 1.46 million cells; allow larger but refuse absurd headers.
constexpr int64_t kMaxCells = int64_t(1) << 26;

bool readHeader(std::ifstream& in, int32_t dims[3]) {
  return bool(in.read(reinterpret_cast<char*>(dims), 3 * sizeof(int32_t)));
}

bool validDims(const int32_t dims[3]) {
  if (dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0) return false;
  // Two factors below 2^31 fit in int64, and so does that product (if at most kMaxCells) times
  // the third; three at once may not (2^21 x 2^21 x 2^22 wraps to 0).
  int64_t twoDims = int64_t(dims[0]) * dims[1];
  return twoDims <= kMaxCells && twoDims * dims[2] <= kMaxCells;
}

uintmax_t expectedSize(const int32_t dims[3]) {
  return 3 * sizeof(int32_t) + 3 * sizeof(double) * uintmax_t(dims[0]) * dims[1] * dims[2];
}

}  // namespace

HalfDifferenceAngles halfDifferenceAngles(const Vector3f& wo, const Vector3f& wi) {
  Vector3f h = normalize(wo + wi);
  Float thetaH = safeAcos(h.z), phiH = std::atan2(h.y, h.x);
  // Rotate wi so that h becomes +z: by -phi_h about z, then by -theta_h about y.
  Float cp = std::cos(phiH), sp = std::sin(phiH), ct = std::cos(thetaH), st = std::sin(thetaH);
  Vector3f r(wi.x * cp + wi.y * sp, -wi.x * sp + wi.y * cp, wi.z);
  Vector3f d(r.x * ct - r.z * st, r.y, r.x * st + r.z * ct);
  Float thetaD = safeAcos(d.z), phiD = std::atan2(d.y, d.x);
  // wo's difference vector is wi's rotated by pi about h: phi_d is only known modulo pi.
  if (phiD < 0) phiD += kPi;
  if (phiD >= kPi) phiD -= kPi;
  return {thetaH, thetaD, phiD};
}

MerlBrdfTable::MerlBrdfTable(int nThetaH, int nThetaD, int nPhiD, const std::vector<double>& rgb)
    : nThetaH_(nThetaH), nThetaD_(nThetaD), nPhiD_(nPhiD) {
  size_t n = size_t(nThetaH) * size_t(nThetaD) * size_t(nPhiD);
  if (nThetaH <= 0 || nThetaD <= 0 || nPhiD <= 0 || rgb.size() != 3 * n)
    throw std::invalid_argument("MerlBrdfTable: the tables do not match the dimensions");
  values_.resize(n);
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) values_[i][c] = Float(std::max(0.0, rgb[c * n + i]));
}

size_t MerlBrdfTable::cellIndex(const HalfDifferenceAngles& a) const {
  Float u = a.thetaH > 0 ? std::sqrt(a.thetaH / kPiOver2) : 0;
  int ih = clamp(int(u * Float(nThetaH_)), 0, nThetaH_ - 1);
  int id = clamp(int(a.thetaD / kPiOver2 * Float(nThetaD_)), 0, nThetaD_ - 1);
  int ip = clamp(int(a.phiD / kPi * Float(nPhiD_)), 0, nPhiD_ - 1);
  return (size_t(ih) * size_t(nThetaD_) + size_t(id)) * size_t(nPhiD_) + size_t(ip);
}

Spectrum MerlBrdfTable::lookup(const Vector3f& wo, const Vector3f& wi) const {
  if (!sameHemisphere(wo, wi)) return Spectrum(0);
  Vector3f o = wo, i = wi;
  if (o.z < 0) {  // two-sided: the same table seen from below
    o.z = -o.z;
    i.z = -i.z;
  }
  if ((o + i).lengthSquared() == 0) return Spectrum(0);
  return values_[cellIndex(halfDifferenceAngles(o, i))];
}

MerlBrdfTable readMerlBrdf(const std::string& path) {
  return parseMerlBrdf(readWholeFile(path), path);
}

MerlBrdfTable parseMerlBrdf(std::string_view bytes, const std::string& path) {
  int32_t dims[3];
  if (bytes.size() < sizeof dims) throw FileError(path, "too short for a MERL BRDF header");
  std::memcpy(dims, bytes.data(), sizeof dims);
  if (!validDims(dims))
    throw FileError(path, "MERL BRDF header has invalid dimensions " + std::to_string(dims[0]) +
                              " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]));
  if (bytes.size() != expectedSize(dims))
    throw FileError(path, "MERL BRDF file size does not match its header (expected " +
                              std::to_string(expectedSize(dims)) + " bytes)");
  size_t n = size_t(dims[0]) * size_t(dims[1]) * size_t(dims[2]);
  std::vector<double> rgb(3 * n);
  std::memcpy(rgb.data(), bytes.data() + sizeof dims, rgb.size() * sizeof(double));
  const double scale[3] = {MerlBrdfTable::kRedScale, MerlBrdfTable::kGreenScale,
                           MerlBrdfTable::kBlueScale};
  for (int c = 0; c < 3; ++c)
    for (size_t i = 0; i < n; ++i) {
      double& v = rgb[c * n + i];
      if (!std::isfinite(v)) throw FileError(path, "MERL BRDF data holds a NaN or infinity");
      v *= scale[c];
      // The table is kept in floats: a larger value would become infinite there.
      if (v > std::numeric_limits<float>::max())
        throw FileError(path, "MERL BRDF data holds a value beyond the float range");
    }
  return MerlBrdfTable(dims[0], dims[1], dims[2], rgb);
}

bool isMerlBrdfFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  int32_t dims[3];
  if (!in || !readHeader(in, dims) || !validDims(dims)) return false;
  std::error_code ec;
  uintmax_t size = std::filesystem::file_size(path, ec);
  return !ec && size == expectedSize(dims);
}

}  // namespace candela
