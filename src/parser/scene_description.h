// What SceneBuilder hands over at WorldEnd: plain descriptions (plug-in name, parameters,
// transform, source location). Nothing here is created yet; the factories create only what the
// scene uses (DESIGN.md, data flow step 2).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/paramset.h"
#include "core/transform.h"

namespace candela {

// A transform that may change over the shutter interval (TransformTimes / ActiveTransform).
struct AnimatedTransformDesc {
  Transform start, end;
  Float startTime = 0, endTime = 1;
  bool isAnimated() const { return start != end; }
};

// The definition each texture name means at a statement (pbrt 3e App. B: named textures are
// graphics state, so a statement sees the definitions in effect where it is written): name ->
// index into SceneDescription::textures, for the names the statement's "texture" parameters use.
struct TextureBindings {
  std::map<std::string, int> floats, spectra;
};

struct PluginDesc {
  std::string name;  // plug-in name: "sphere", "matte", "perspective", ...
  ParamSet params;
  FileLoc loc;
  // Set by SceneBuilder on textures, materials and shapes. Absent (descriptions made by hand): a
  // name means its latest definition before the statement, or the latest of all for a material
  // or shape.
  std::optional<TextureBindings> textures = std::nullopt;
};

struct CameraDesc : PluginDesc {
  AnimatedTransformDesc cameraToWorld;  // the inverse of the CTM at the Camera statement
  std::string medium;                   // pbrt-v3 camera medium ("" = none)
  FileLoc mediumLoc;                    // the MediumInterface statement that named it
};

struct MaterialDesc : PluginDesc {
  std::optional<PluginDesc> bumpMap;  // lrt's BumpMap statement in effect, if any
  // A mix's named materials as in effect at its statement (pbrt-v3: named materials are graphics
  // state too): name -> index into SceneDescription::materials. Absent: SceneDescription's
  // namedMaterials.
  std::optional<std::map<std::string, int>> namedMaterials;
};

struct TextureDesc : PluginDesc {  // PluginDesc::name is the texture class ("imagemap", ...)
  std::string textureName;         // the name materials refer to
  std::string type;                // "float" or "spectrum" ("color" is read as "spectrum")
  Transform textureToWorld;        // the CTM at the Texture statement
};

struct ShapeDesc : PluginDesc {
  AnimatedTransformDesc objectToWorld;
  bool reverseOrientation = false;
  int material = -1;                    // index into SceneDescription::materials; -1 = default
  std::optional<PluginDesc> areaLight;  // AreaLightSource in effect
  std::string insideMedium, outsideMedium;
  FileLoc mediumLoc;  // the MediumInterface statement in effect
};

struct LightDesc : PluginDesc {
  AnimatedTransformDesc lightToWorld;
  std::string outsideMedium;
  FileLoc mediumLoc;  // the MediumInterface statement in effect
};

struct VolumeDesc : PluginDesc {
  Transform volumeToWorld;
};

struct MediumDesc : PluginDesc {
  std::string mediumName;
  Transform mediumToWorld;
};

// ObjectBegin ... ObjectEnd: shapes in the instance's own space (their transforms are relative to
// the CTM at ObjectBegin's ... end, as pbrt: the shapes keep the full CTM at their statement).
struct InstanceDefinition {
  std::string name;
  FileLoc loc;
  std::vector<ShapeDesc> shapes;
};

struct InstanceUse {
  std::string name;  // an InstanceDefinition
  AnimatedTransformDesc instanceToWorld;
  FileLoc loc;
};

struct SceneDescription {
  // Options block; a default-constructed PluginDesc (empty name) means "not given".
  CameraDesc camera;
  PluginDesc film, sampler, filter, accelerator, surfaceIntegrator, volumeIntegrator, integrator,
      renderer, toneMap;
  Float transformStartTime = 0, transformEndTime = 1;
  std::vector<std::string> searchPath;

  // World block.
  std::vector<MaterialDesc> materials;        // every Material / MakeNamedMaterial statement
  std::map<std::string, int> namedMaterials;  // name -> index into materials, as at WorldEnd
  std::vector<TextureDesc> textures;          // in statement order; later ones shadow earlier
  std::vector<ShapeDesc> shapes;
  std::vector<LightDesc> lights;
  std::vector<VolumeDesc> volumes;
  std::vector<MediumDesc> media;
  std::vector<InstanceDefinition> instanceDefinitions;
  std::vector<InstanceUse> instanceUses;
  FileLoc worldEndLoc;
};

}  // namespace candela
