#include "textures/noise.h"

#include <array>
#include <cstdint>

namespace candela {

namespace {

// Ken Perlin's permutation of 0..255 (the table of his reference implementation, which the
// draft uses). Lookups wrap with & 255 instead of duplicating the table.
constexpr std::array<uint8_t, 256> kPerm = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180};

// The lattice point's gradient, one of the 12 cube-edge directions (h = 12..15 repeat four of
// them), dotted with the offset (dx, dy, dz) from that point (§11.7.1).
Float gradient(int x, int y, int z, Float dx, Float dy, Float dz) {
  int h = kPerm[(kPerm[(kPerm[x & 255] + y) & 255] + z) & 255] & 15;
  Float u = (h < 8 || h == 12 || h == 13) ? dx : dy;
  Float v = (h < 4 || h == 12 || h == 13) ? dy : dz;
  return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

// 6t^5 - 15t^4 + 10t^3: zero first and second derivatives at 0 and 1, so noise is C2 across
// cell faces.
Float fade(Float t) { return t * t * t * (t * (t * 6 - 15) + 10); }

// The lattice cell of x (its index mod 256) and the offset of x inside it. The index is taken
// in floating point so that huge coordinates never overflow an int.
void cell(Float x, int* index, Float* offset) {
  Float f = std::floor(x);
  *offset = x - f;
  int i = int(std::fmod(f, Float(256)));
  *index = i < 0 ? i + 256 : i;
}

}  // namespace

Float noise(Float x, Float y, Float z) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return 0;
  int ix, iy, iz;
  Float dx, dy, dz;
  cell(x, &ix, &dx);
  cell(y, &iy, &dy);
  cell(z, &iz, &dz);
  Float w000 = gradient(ix, iy, iz, dx, dy, dz);
  Float w100 = gradient(ix + 1, iy, iz, dx - 1, dy, dz);
  Float w010 = gradient(ix, iy + 1, iz, dx, dy - 1, dz);
  Float w110 = gradient(ix + 1, iy + 1, iz, dx - 1, dy - 1, dz);
  Float w001 = gradient(ix, iy, iz + 1, dx, dy, dz - 1);
  Float w101 = gradient(ix + 1, iy, iz + 1, dx - 1, dy, dz - 1);
  Float w011 = gradient(ix, iy + 1, iz + 1, dx, dy - 1, dz - 1);
  Float w111 = gradient(ix + 1, iy + 1, iz + 1, dx - 1, dy - 1, dz - 1);
  Float wx = fade(dx), wy = fade(dy), wz = fade(dz);
  Float y0 = lerp(wy, lerp(wx, w000, w100), lerp(wx, w010, w110));
  Float y1 = lerp(wy, lerp(wx, w001, w101), lerp(wx, w011, w111));
  return lerp(wz, y0, y1);
}

Float smoothStep(Float lo, Float hi, Float value) {
  Float v = clamp((value - lo) / (hi - lo), 0, 1);
  return v * v * (3 - 2 * v);
}

Float fbmOctaves(const Vector3f& dpdx, const Vector3f& dpdy, int maxOctaves) {
  Float s2 = std::max(dpdx.lengthSquared(), dpdy.lengthSquared());
  if (std::isnan(s2) || std::isinf(s2)) return 0;
  Float n = 1 - Float(0.5) * std::log2(s2);  // +inf for a zero footprint
  return clamp(n, Float(0), Float(std::max(maxOctaves, 0)));
}

Float fbm(const Point3f& p, const Vector3f& dpdx, const Vector3f& dpdy, Float omega,
          int maxOctaves) {
  Float octaves = fbmOctaves(dpdx, dpdy, maxOctaves);
  int whole = int(octaves);
  Float sum = 0, lambda = 1, amplitude = 1;
  for (int i = 0; i < whole; ++i) {
    sum += amplitude * noise(p * lambda);
    lambda *= 1.99f;
    amplitude *= omega;
  }
  if (whole < maxOctaves)
    sum += amplitude * smoothStep(.3f, .7f, octaves - Float(whole)) * noise(p * lambda);
  return sum;
}

Float turbulence(const Point3f& p, const Vector3f& dpdx, const Vector3f& dpdy, Float omega,
                 int maxOctaves, ClampedOctaves clamped) {
  Float octaves = fbmOctaves(dpdx, dpdy, maxOctaves);
  int whole = int(octaves);
  Float sum = 0, lambda = 1, amplitude = 1;
  for (int i = 0; i < whole; ++i) {
    sum += amplitude * std::abs(noise(p * lambda));
    lambda *= 1.99f;
    amplitude *= omega;
  }
  // The partial octave fades from its mean to its value; later octaves are their mean. pbrt's
  // (pbrt 3e §10.6.4) takes 0.2 for the mean, adds the partial octave even when none is dropped
  // and starts the dropped octaves at the partial octave's amplitude.
  const bool asPbrt = clamped == ClampedOctaves::AsPbrt;
  if (whole < maxOctaves || asPbrt) {
    const Float mean = asPbrt ? Float(0.2) : kMeanAbsNoise;
    Float w = smoothStep(.3f, .7f, octaves - Float(whole));
    sum += amplitude * lerp(w, mean, std::abs(noise(p * lambda)));
    if (!asPbrt) amplitude *= omega;
    for (int i = asPbrt ? whole : whole + 1; i < maxOctaves; ++i) {
      sum += amplitude * mean;
      amplitude *= omega;
    }
  }
  return sum;
}

}  // namespace candela
