#include "parser/scene_dialect.h"

namespace candela {

SceneDialect detectSceneDialect(const SceneDescription& desc) {
  bool usesMedia = !desc.media.empty() || !desc.camera.medium.empty();
  for (const ShapeDesc& s : desc.shapes)
    usesMedia = usesMedia || !s.insideMedium.empty() || !s.outsideMedium.empty();
  for (const LightDesc& l : desc.lights) usesMedia = usesMedia || !l.outsideMedium.empty();
  return !desc.integrator.name.empty() || usesMedia ? SceneDialect::PbrtV3 : SceneDialect::PbrtV2;
}

bool materialHasPbrtV3Parameters(const MaterialDesc& m) {
  const std::string& n = m.name;
  bool microfacet = n == "metal" || n == "plastic" || n == "substrate" || n == "uber" ||
                    n == "translucent" || n == "glass";
  if (!microfacet) return false;
  if (m.params.find("remaproughness")) return true;
  bool anisotropicInV3Only = n == "metal" || n == "uber" || n == "glass";
  return anisotropicInV3Only && (m.params.find("uroughness") || m.params.find("vroughness"));
}

std::optional<SceneDialect> parseSceneDialect(const std::string& name) {
  if (name == "pbrt-v2") return SceneDialect::PbrtV2;
  if (name == "pbrt-v3") return SceneDialect::PbrtV3;
  return std::nullopt;
}

}  // namespace candela
