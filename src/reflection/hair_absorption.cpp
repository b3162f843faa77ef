#include "reflection/hair_absorption.h"

#include <cmath>

namespace candela::hair {

Spectrum sigmaAFromConcentration(Float eumelanin, Float pheomelanin) {
  return kEumelaninSigmaA * eumelanin + kPheomelaninSigmaA * pheomelanin;
}

Spectrum sigmaAFromReflectance(const Spectrum& c, Float betaN) {
  double b = betaN;
  double d = 5.969 - 0.215 * b + 2.532 * b * b - 10.73 * std::pow(b, 3) + 5.574 * std::pow(b, 4) +
             0.245 * std::pow(b, 5);
  Spectrum s;
  for (int i = 0; i < 3; ++i) {
    double r = std::log(double(c[i])) / d;  // c = 0: infinite absorption
    s[i] = Float(r * r);
  }
  return s;
}

}  // namespace candela::hair
