#include "materials/measured.h"

#include "core/scene_path.h"
#include "materials/material_inputs.h"

namespace candela {

const BSDF* MeasuredMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  if (merl_)
    bsdf->add(arena.make<MeasuredBRDF>(merl_.get()));
  else
    bsdf->add(arena.make<IrregularMeasuredBRDF>(irregular_.get()));
  return bsdf;
}

// A MERL binary table or pbrt-v2's irregular (Marschner) sample file, told apart by content.
std::unique_ptr<Material> createMeasuredMaterial(MaterialInputs& in) {
  std::string filename = in.params().getOneString("filename", "");
  if (filename.empty()) throw SceneError(in.location(), "measured needs \"string filename\"");
  FileLoc loc = in.locationOf("filename");
  std::string path = resolveScenePath(filename, loc.file);
  const Texture<Float>* bump = in.bumpMap();
  try {
    if (isMerlBrdfFile(path)) return std::make_unique<MeasuredMaterial>(in.merlTable(path), bump);
    return std::make_unique<MeasuredMaterial>(in.irregularTable(path), bump);
  } catch (const FileError& e) {
    throw SceneError(loc, e.what());
  }
}

}  // namespace candela
