// Isotropic BRDFs measured by Matusik et al. (MERL) in their binary format, as pbrt-v2's
// "measured" material reads them: three int32 dimensions (theta_h, theta_d, phi_d; 90 x 90 x 180
// in the published data), then the red, green and blue tables of doubles, each scaled by the
// format's constants 1/1500, 1.15/1500 and 1.66/1500. Cells are indexed by the half and
// difference angles of Rusinkiewicz's parameterisation: theta_h non-linearly (index proportional
// to sqrt(theta_h)), theta_d linearly, phi_d over [0, pi) (reciprocity folds the other half).
// Negative values mark cells without data and read as 0. Little-endian files on a little-endian
// host.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "reflection/bxdf.h"

namespace candela {

// The half vector's polar angle and the difference vector's polar and azimuthal angles (phi_d in
// [0, pi)) of a pair of directions on the same side of the surface.
struct HalfDifferenceAngles {
  Float thetaH, thetaD, phiD;
};
HalfDifferenceAngles halfDifferenceAngles(const Vector3f& wo, const Vector3f& wi);

// The table, scaled to BRDF values. Immutable once made; materials share one per file.
class MerlBrdfTable {
 public:
  // rgb holds the three channel tables one after another, already scaled, nThetaH * nThetaD *
  // nPhiD values each, phi_d fastest.
  MerlBrdfTable(int nThetaH, int nThetaD, int nPhiD, const std::vector<double>& rgb);
  // f(wo, wi); 0 unless both are on the same side (the surface is taken as two-sided).
  Spectrum lookup(const Vector3f& wo, const Vector3f& wi) const;
  // The cell that holds the given angles.
  size_t cellIndex(const HalfDifferenceAngles& a) const;
  int nThetaH() const { return nThetaH_; }
  int nThetaD() const { return nThetaD_; }
  int nPhiD() const { return nPhiD_; }

  static constexpr double kRedScale = 1.0 / 1500, kGreenScale = 1.15 / 1500,
                          kBlueScale = 1.66 / 1500;

 private:
  int nThetaH_, nThetaD_, nPhiD_;
  std::vector<Spectrum> values_;
};

// Reads a MERL binary file; throws FileError naming the path when it cannot be read or its size
// does not match its header.
MerlBrdfTable readMerlBrdf(const std::string& path);
// The same from the file's bytes; path is used only in error messages.
MerlBrdfTable parseMerlBrdf(std::string_view bytes, const std::string& path);
// True when the file starts with three positive dimensions whose tables fill exactly the rest of
// the file: how a "measured" material tells the binary format from pbrt-v2's text format.
bool isMerlBrdfFile(const std::string& path);

// The table as a BxDF, sampled by the default cosine-weighted hemisphere (pdf consistent).
class MeasuredBRDF : public BxDF {
 public:
  explicit MeasuredBRDF(const MerlBrdfTable* table)
      : BxDF(BxDFType(kReflection | kGlossy)), table_(table) {}
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override {
    return table_->lookup(wo, wi);
  }

 private:
  const MerlBrdfTable* table_;
};

}  // namespace candela
