#include "textures/bump_map_plugins.h"

#include "textures/solid_textures.h"

namespace candela {

namespace {

// Height fields of lrt's BumpMap statement (lrt draft Appendix C), scaled by "scale".
class ScaledFloatTexture : public Texture<Float> {
 public:
  ScaledFloatTexture(std::unique_ptr<Texture<Float>> t, Float s) : t_(std::move(t)), s_(s) {}
  Float evaluate(const SurfaceInteraction& si) const override { return s_ * t_->evaluate(si); }

 private:
  std::unique_ptr<Texture<Float>> t_;
  Float s_;
};

constexpr ParamSpec kWindyBump[] = {
    {"scale", "float", "1", "", "", kLrt, "height scale"},
    {"stretch", "float", "1", "", "positive and finite", kLrt, "feature size"}};
constexpr ParamSpec kBumpyBump[] = {
    {"scale", "float", "1", "", "", kLrt, "height scale"},
    {"octaves", "integer", "6", "", "", kLrt, "noise octaves"},
    {"omega", "float", "0.5", "", "", kLrt, "amplitude falloff per octave"}};

std::unique_ptr<Texture<Float>> createWindyBump(const ParamSet& p, const FileLoc& loc) {
  Float s = p.getOneFloat("scale", 1);
  Float stretch = p.getOneFloat("stretch", 1, ValueRange::positive(), loc);
  return std::make_unique<ScaledFloatTexture>(
      std::make_unique<WindyTexture<Float>>(TextureMapping3D(scale(stretch, stretch, stretch))), s);
}

std::unique_ptr<Texture<Float>> createBumpyBump(const ParamSet& p, const FileLoc&) {
  Float s = p.getOneFloat("scale", 1);
  return std::make_unique<ScaledFloatTexture>(
      std::make_unique<FBmTexture<Float>>(TextureMapping3D(Transform()), p.getOneInt("octaves", 6),
                                          p.getOneFloat("omega", 0.5f)),
      s);
}

constexpr BumpMapPlugin kBumpMaps[] = {
    {{"bump map", "windy", kLrt, "wind-rippled height field (lrt draft Appendix C)", kWindyBump},
     createWindyBump},
    {{"bump map", "bumpy", kLrt, "fractal Brownian motion height field (lrt draft Appendix C)",
      kBumpyBump},
     createBumpyBump},
};

}  // namespace

std::span<const BumpMapPlugin> bumpMapPlugins() { return kBumpMaps; }

}  // namespace candela
