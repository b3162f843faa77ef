#include "materials/fourier.h"

#include "core/scene_path.h"
#include "materials/material_inputs.h"
#include "reflection/fourier_bxdf.h"

namespace candela {

const BSDF* FourierMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  bsdf->add(arena.make<FourierBSDF>(table_.get()));
  return bsdf;
}

std::unique_ptr<Material> createFourierMaterial(MaterialInputs& in) {
  std::string filename = in.params().getOneString("bsdffile", "");
  FileLoc loc = in.locationOf("bsdffile");
  if (filename.empty()) throw SceneError(loc, "fourier needs \"string bsdffile\"");
  std::string path = resolveScenePath(filename, loc.file);
  try {
    return std::make_unique<FourierMaterial>(in.fourierTable(path), in.bumpMap());
  } catch (const FileError& e) {
    throw SceneError(loc, e.what());
  }
}

}  // namespace candela
