#include "cameras/lens_file.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace candela {

std::vector<LensInterface> readLensFile(const std::string& path) {
  if (path.find('\0') != std::string::npos)
    throw FileError(path.substr(0, path.find('\0')), "NUL in file name");
  // Only regular files: a device such as /dev/zero would never end.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw FileError(path,
                    std::filesystem::exists(path, ec) ? "not a regular file" : "no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open file");
  std::vector<LensInterface> interfaces;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    auto fail = [&](const std::string& what) {
      throw FileError(path + ":" + std::to_string(lineNo), what);
    };
    if (size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::vector<double> v;
    size_t i = 0;
    while (i < line.size()) {
      if (std::strchr(" \t\r,\f\v", line[i])) {
        ++i;
        continue;
      }
      size_t end = i;
      while (end < line.size() && !std::strchr(" \t\r,\f\v", line[end])) ++end;
      const char* first = line.data() + i + (line[i] == '+' ? 1 : 0);
      double x = 0;
      auto [ptr, err] = std::from_chars(first, line.data() + end, x);
      if (err != std::errc() || ptr != line.data() + end || !std::isfinite(x))
        fail("expected a number, found '" + line.substr(i, std::min<size_t>(end - i, 40)) + "'");
      v.push_back(x);
      i = end;
    }
    if (v.empty()) continue;
    if (v.size() != 4)
      fail(
          "expected 4 numbers (curvature radius, thickness, index of refraction, aperture "
          "diameter), found " +
          std::to_string(v.size()));
    if (v[1] < 0) fail("negative thickness " + std::to_string(v[1]));
    if (v[2] < 0) fail("negative index of refraction " + std::to_string(v[2]));
    if (!(v[3] > 0)) fail("the aperture diameter must be positive, got " + std::to_string(v[3]));
    // A spherical cap is at most as wide as its sphere.
    if (v[0] != 0 && v[3] > 2 * std::abs(v[0]))
      fail("aperture diameter " + std::to_string(v[3]) + " exceeds the sphere's diameter " +
           std::to_string(2 * std::abs(v[0])));
    LensInterface e;
    e.curvatureRadius = v[0] * 1e-3;
    e.thickness = v[1] * 1e-3;
    e.eta = v[2] == 0 ? 1 : v[2];
    e.apertureRadius = v[3] * 0.5e-3;
    interfaces.push_back(e);
  }
  if (in.bad()) throw FileError(path, "read error");
  if (interfaces.empty()) throw FileError(path, "no lens interfaces");
  return interfaces;
}

}  // namespace candela
