#include "parser/working_color_space.h"

namespace candela {

namespace {

void convert(ParamSet& params, const ColorMatrix& m) {
  std::vector<ParamItem> items = params.items();
  for (ParamItem& item : items) {
    if (item.type != ParamType::Spectrum) continue;
    for (size_t i = 0; i + 2 < item.floats.size(); i += 3) {
      Float r = item.floats[i], g = item.floats[i + 1], b = item.floats[i + 2];
      for (int row = 0; row < 3; ++row)
        item.floats[i + row] = m[3 * row] * r + m[3 * row + 1] * g + m[3 * row + 2] * b;
    }
    params.add(item);
  }
}

void convert(PluginDesc& d, const ColorMatrix& m) { convert(d.params, m); }

void convert(ShapeDesc& s, const ColorMatrix& m) {
  convert(s.params, m);
  if (s.areaLight) convert(*s.areaLight, m);
}

}  // namespace

SceneDescription convertColors(const SceneDescription& desc, const ColorMatrix& m) {
  SceneDescription out = desc;
  for (PluginDesc* d : {static_cast<PluginDesc*>(&out.camera), &out.film, &out.sampler, &out.filter,
                        &out.accelerator, &out.surfaceIntegrator, &out.volumeIntegrator,
                        &out.integrator, &out.renderer, &out.toneMap})
    convert(*d, m);
  for (auto& mat : out.materials) {
    convert(mat, m);
    if (mat.bumpMap) convert(*mat.bumpMap, m);
  }
  for (auto& t : out.textures) convert(t, m);
  for (auto& s : out.shapes) convert(s, m);
  for (auto& l : out.lights) convert(l, m);
  for (auto& v : out.volumes) convert(v, m);
  for (auto& md : out.media) convert(md, m);
  for (auto& def : out.instanceDefinitions)
    for (auto& s : def.shapes) convert(s, m);
  return out;
}

}  // namespace candela
