// Texture coordinate generation (lrt draft §11.3): 2D mappings give (s, t) and their screen-space
// derivatives, from which textures size their filters; the 3D mapping gives a texture-space point
// and the derivatives of that point.
#pragma once

#include "core/interaction.h"
#include "core/transform.h"

namespace candela {

struct TexCoord2D {
  Point2f st;
  Float dsdx = 0, dsdy = 0, dtdx = 0, dtdy = 0;
};

class TextureMapping2D {
 public:
  virtual ~TextureMapping2D() = default;
  virtual TexCoord2D map(const SurfaceInteraction& si) const = 0;
};

// s = su u + du, t = sv v + dv (§11.3.1); derivatives by the chain rule.
class UVMapping2D : public TextureMapping2D {
 public:
  UVMapping2D(Float su = 1, Float sv = 1, Float du = 0, Float dv = 0)
      : su_(su), sv_(sv), du_(du), dv_(dv) {}
  TexCoord2D map(const SurfaceInteraction& si) const override;

 private:
  Float su_, sv_, du_, dv_;
};

// The direction of the texture-space point from the origin as sphere coordinates (§11.3.2):
// s = theta / pi (theta from +z), t = phi / 2pi (phi from +x towards +y, in [0, 2pi)).
// Derivatives are exact first-order ones (the Jacobian of theta and phi applied to the
// transformed dpdx, dpdy) rather than the draft's forward differences, so the phi seam needs no
// fix-up; at the poles, where phi is undefined, t's derivatives are 0.
class SphericalMapping2D : public TextureMapping2D {
 public:
  explicit SphericalMapping2D(const Transform& worldToTexture) : worldToTexture_(worldToTexture) {}
  TexCoord2D map(const SurfaceInteraction& si) const override;

 private:
  Transform worldToTexture_;
};

// s = (pi + atan2(y, x)) / 2pi, t = z of the unit direction (§11.3.3); exact derivatives as for
// the spherical mapping.
class CylindricalMapping2D : public TextureMapping2D {
 public:
  explicit CylindricalMapping2D(const Transform& worldToTexture)
      : worldToTexture_(worldToTexture) {}
  TexCoord2D map(const SurfaceInteraction& si) const override;

 private:
  Transform worldToTexture_;
};

// s = ds + q.vs, t = dt + q.vt for the texture-space point q (§11.3.4), exact derivatives. (The
// draft, pbrt-v2 and pbrt-v3 project the world-space point, and createMapping2D passes the
// identity for that; the transform is here for callers that want the plane to move.)
class PlanarMapping2D : public TextureMapping2D {
 public:
  PlanarMapping2D(const Vector3f& vs, const Vector3f& vt, Float ds, Float dt,
                  const Transform& worldToTexture)
      : vs_(vs), vt_(vt), ds_(ds), dt_(dt), worldToTexture_(worldToTexture) {}
  TexCoord2D map(const SurfaceInteraction& si) const override;

 private:
  Vector3f vs_, vt_;
  Float ds_, dt_;
  Transform worldToTexture_;
};

struct TexCoord3D {
  Point3f p;
  Vector3f dpdx, dpdy;
};

// The texture-space point q = worldToTexture(p) (§11.3.5), its derivatives transformed exactly
// (the transform is linear; the draft's forward difference is not needed). worldToTexture is
// the CTM at the Texture statement itself, as pbrt-v2 and v3 use it (not its inverse), so a scaled
// solid texture shrinks rather than grows.
class TextureMapping3D {
 public:
  explicit TextureMapping3D(const Transform& worldToTexture) : worldToTexture_(worldToTexture) {}
  TexCoord3D map(const SurfaceInteraction& si) const;

 private:
  Transform worldToTexture_;
};

}  // namespace candela
