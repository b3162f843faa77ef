// Perlin gradient noise and the spectral sums built on it (lrt draft §11.7): noise is zero at
// every integer lattice point, smooth (C2, from the quintic weight 6t^5 - 15t^4 + 10t^3) and
// band-limited to a frequency of about 1, so sums of scaled copies can drop the octaves that
// would alias ("clamping", §11.2.2).
#pragma once

#include "core/compatibility.h"

#include "core/vector.h"

namespace candela {

// Noise at (x, y, z); the two-argument form samples the z = 0.5 slice (as the draft's polka dots
// do). Non-finite coordinates give 0, the mean of the noise.
Float noise(Float x, Float y, Float z = 0.5f);
inline Float noise(const Point3f& p) { return noise(p.x, p.y, p.z); }

// Smooth Hermite step from 0 at lo to 1 at hi, clamped outside.
Float smoothStep(Float lo, Float hi, Float value);

// The (fractional) number of octaves FBm may sum before the finest one would alias, for a
// footprint spanned by dpdx and dpdy (§11.7.3: 2^(n-1) s = 1, so n = 1 - log2(s^2)/2), kept in
// [0, maxOctaves]. A zero footprint allows all octaves; a non-finite one allows none.
Float fbmOctaves(const Vector3f& dpdx, const Vector3f& dpdy, int maxOctaves);

// Fractional Brownian motion: sum over octaves i of omega^i noise(1.99^i p), with the partial
// last octave faded in by smoothStep(.3, .7, fraction) (§11.7.3). The lacunarity 1.99 rather
// than 2 keeps the octaves' zero lattices from lining up.
Float fbm(const Point3f& p, const Vector3f& dpdx, const Vector3f& dpdy, Float omega,
          int maxOctaves);

// The mean of |noise| over space, measured (tests/unit/test_noise.cpp checks it): what clamping
// substitutes for the octaves of turbulence that are dropped.
inline constexpr Float kMeanAbsNoise = 0.218f;

// Turbulence: FBm of |noise| (pbrt-v2's "wrinkled"), the octaves the footprint drops replaced as
// `clamped` says.
Float turbulence(const Point3f& p, const Vector3f& dpdx, const Vector3f& dpdy, Float omega,
                 int maxOctaves, ClampedOctaves clamped = ClampedOctaves::Mean);

}  // namespace candela
