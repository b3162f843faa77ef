#include "textures/texture_params.h"

namespace candela {

std::unique_ptr<TextureMapping2D> createMapping2D(const ParamSet& params,
                                                  const Transform& textureToWorld,
                                                  const FileLoc& loc) {
  std::string type = params.getOneString("mapping", "uv");
  if (type == "uv") {
    Float su = params.getOneFloat("uscale", params.getOneFloat("su", 1));
    Float sv = params.getOneFloat("vscale", params.getOneFloat("sv", 1));
    Float du = params.getOneFloat("udelta", params.getOneFloat("du", 0));
    Float dv = params.getOneFloat("vdelta", params.getOneFloat("dv", 0));
    return std::make_unique<UVMapping2D>(su, sv, du, dv);
  }
  if (type == "spherical") return std::make_unique<SphericalMapping2D>(inverse(textureToWorld));
  if (type == "cylindrical") return std::make_unique<CylindricalMapping2D>(inverse(textureToWorld));
  if (type == "planar")
    return std::make_unique<PlanarMapping2D>(params.getOneVector3f("v1", Vector3f(1, 0, 0)),
                                             params.getOneVector3f("v2", Vector3f(0, 1, 0)),
                                             params.getOneFloat("udelta", 0),
                                             params.getOneFloat("vdelta", 0), Transform());
  throw SceneError(
      params.locationOf("mapping", loc),
      "unknown texture mapping '" + type + "' (known: uv, spherical, cylindrical, planar)");
}

}  // namespace candela
