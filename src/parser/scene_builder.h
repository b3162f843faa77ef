// The scene API's state machine (lrt draft App. B; pbrt-v2/v3 api.cpp semantics): options block,
// world block, current transformation matrix (a start/end pair for motion blur), graphics-state
// stack, named coordinate systems, materials, textures, media and object instances. It only
// records plain descriptions (parser/scene_description.h); the factories create objects later.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "parser/parser_target.h"
#include "parser/scene_description.h"
#include "parser/scoped_names.h"

namespace candela {

using WarningCallback = std::function<void(const FileLoc&, const std::string&)>;

class SceneBuilder : public ParserTarget {
 public:
  using WarningCallback = candela::WarningCallback;

  // onWorldEnd receives the description of each frame at its WorldEnd; the builder then returns
  // to the options block (keeping the rendering options) so several frames per file work.
  SceneBuilder(std::function<void(SceneDescription&&)> onWorldEnd, WarningCallback warn);

  void identity(const FileLoc& loc) override;
  void translate(Float dx, Float dy, Float dz, const FileLoc& loc) override;
  void scale(Float sx, Float sy, Float sz, const FileLoc& loc) override;
  void rotate(Float angleDeg, Float ax, Float ay, Float az, const FileLoc& loc) override;
  void lookAt(Float ex, Float ey, Float ez, Float lx, Float ly, Float lz, Float ux, Float uy,
              Float uz, const FileLoc& loc) override;
  void transform(const Float m[16], const FileLoc& loc) override;
  void concatTransform(const Float m[16], const FileLoc& loc) override;
  void coordinateSystem(const std::string& name, const FileLoc& loc) override;
  void coordSysTransform(const std::string& name, const FileLoc& loc) override;
  void activeTransformAll(const FileLoc& loc) override;
  void activeTransformStartTime(const FileLoc& loc) override;
  void activeTransformEndTime(const FileLoc& loc) override;
  void transformTimes(Float start, Float end, const FileLoc& loc) override;
  void transformBegin(const FileLoc& loc) override;
  void transformEnd(const FileLoc& loc) override;
  void reverseOrientation(const FileLoc& loc) override;

  void camera(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void sampler(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void pixelFilter(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void film(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void accelerator(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void surfaceIntegrator(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void volumeIntegrator(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void integrator(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void renderer(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void toneMap(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void searchPath(const std::string& path, const FileLoc& loc) override;
  void makeNamedMedium(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void mediumInterface(const std::string& inside, const std::string& outside,
                       const FileLoc& loc) override;

  void worldBegin(const FileLoc& loc) override;
  void worldEnd(const FileLoc& loc) override;
  void attributeBegin(const FileLoc& loc) override;
  void attributeEnd(const FileLoc& loc) override;
  void texture(const std::string& name, const std::string& type, const std::string& className,
               ParamSet params, const FileLoc& loc) override;
  void material(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void makeNamedMaterial(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void namedMaterial(const std::string& name, const FileLoc& loc) override;
  void bumpMap(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void lightSource(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void areaLightSource(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void shape(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void volume(const std::string& name, ParamSet params, const FileLoc& loc) override;
  void objectBegin(const std::string& name, const FileLoc& loc) override;
  void objectEnd(const FileLoc& loc) override;
  void objectInstance(const std::string& name, const FileLoc& loc) override;

  void endOfInput(const FileLoc& loc) override;

  // Frames handed to onWorldEnd so far.
  int framesCompleted() const { return frames_; }

 private:
  // Attribute state (lrt draft App. B, GraphicsState), saved by AttributeBegin.
  struct GraphicsState {
    int material = -1;
    std::optional<PluginDesc> areaLight, bumpMap;
    bool reverseOrientation = false;
    std::string insideMedium, outsideMedium;
    FileLoc mediumLoc;  // of the MediumInterface statement that set them
  };
  enum class PushKind { Attribute, Transform, Object };
  struct Pushed {
    PushKind kind;
    FileLoc loc;
    std::array<Transform, 2> ctm;
    int activeBits;
    GraphicsState state;               // restored by AttributeEnd / ObjectEnd only
    size_t textureMark, materialMark;  // so are the named textures and materials
  };
  enum class Block { Options, World };

  void requireOptions(const char* statement, const FileLoc& loc) const;
  void requireWorld(const char* statement, const FileLoc& loc) const;
  void push(PushKind kind, const FileLoc& loc);
  void pop(PushKind kind, const char* statement, const FileLoc& loc);
  // CTM = CTM * t for the active transforms; make() may throw std::domain_error.
  void apply(const std::function<Transform()>& make, const FileLoc& loc, bool replace = false);
  AnimatedTransformDesc animatedCtm() const;
  PluginDesc plugin(const std::string& name, ParamSet params, const FileLoc& loc) const;
  void option(PluginDesc& slot, const char* statement, const std::string& name, ParamSet params,
              const FileLoc& loc);
  void resetForNextFrame();
  int attributeDepth() const;
  // The texture names params' "texture" items use, as defined here.
  TextureBindings bindTextures(const ParamSet& params) const;
  // A mix's "string namedmaterial1/2", as defined here.
  std::map<std::string, int> bindNamedMaterials(const ParamSet& params) const;

  std::function<void(SceneDescription&&)> onWorldEnd_;
  WarningCallback warn_;

  Block block_ = Block::Options;
  FileLoc worldBeginLoc_;
  std::array<Transform, 2> ctm_;  // [0] at the start time, [1] at the end time
  int activeBits_ = 3;            // bit 0: start transform, bit 1: end transform
  GraphicsState state_;
  std::vector<Pushed> stack_;
  std::map<std::string, std::array<Transform, 2>> namedCoordinateSystems_;
  ScopedNames textureNames_;        // "float:name" / "spectrum:name" -> index into textures
  ScopedNames namedMaterialNames_;  // name -> index into materials
  std::map<std::string, int> instanceNames_;  // name -> index into instanceDefinitions
  int currentInstance_ = -1;                  // open ObjectBegin, or -1
  SceneDescription desc_;
  int frames_ = 0;
};

}  // namespace candela
