// What the parser calls for each statement of a scene file: the lrt/pbrt scene API (lrt draft
// App. B, pbrt-v2 and pbrt-v3 additions). SceneBuilder implements it; tests can record calls.
#pragma once

#include <string>

#include "core/error.h"
#include "core/paramset.h"

namespace candela {

class ParserTarget {
 public:
  virtual ~ParserTarget() = default;

  // Transformations.
  virtual void identity(const FileLoc& loc) = 0;
  virtual void translate(Float dx, Float dy, Float dz, const FileLoc& loc) = 0;
  virtual void scale(Float sx, Float sy, Float sz, const FileLoc& loc) = 0;
  virtual void rotate(Float angleDeg, Float ax, Float ay, Float az, const FileLoc& loc) = 0;
  virtual void lookAt(Float ex, Float ey, Float ez, Float lx, Float ly, Float lz, Float ux,
                      Float uy, Float uz, const FileLoc& loc) = 0;
  // m is given as written in the file (pbrt: column-major, i.e. the transpose of the matrix).
  virtual void transform(const Float m[16], const FileLoc& loc) = 0;
  virtual void concatTransform(const Float m[16], const FileLoc& loc) = 0;
  virtual void coordinateSystem(const std::string& name, const FileLoc& loc) = 0;
  virtual void coordSysTransform(const std::string& name, const FileLoc& loc) = 0;
  virtual void activeTransformAll(const FileLoc& loc) = 0;
  virtual void activeTransformStartTime(const FileLoc& loc) = 0;
  virtual void activeTransformEndTime(const FileLoc& loc) = 0;
  virtual void transformTimes(Float start, Float end, const FileLoc& loc) = 0;
  virtual void transformBegin(const FileLoc& loc) = 0;
  virtual void transformEnd(const FileLoc& loc) = 0;
  virtual void reverseOrientation(const FileLoc& loc) = 0;

  // Rendering options (before WorldBegin).
  virtual void camera(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void sampler(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void pixelFilter(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void film(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void accelerator(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void surfaceIntegrator(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void volumeIntegrator(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void integrator(const std::string& name, ParamSet params, const FileLoc& loc) = 0;  // v3
  virtual void renderer(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void toneMap(const std::string& name, ParamSet params, const FileLoc& loc) = 0;  // lrt
  virtual void searchPath(const std::string& path, const FileLoc& loc) = 0;                // lrt
  virtual void makeNamedMedium(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void mediumInterface(const std::string& inside, const std::string& outside,
                               const FileLoc& loc) = 0;

  // The world.
  virtual void worldBegin(const FileLoc& loc) = 0;
  virtual void worldEnd(const FileLoc& loc) = 0;
  virtual void attributeBegin(const FileLoc& loc) = 0;
  virtual void attributeEnd(const FileLoc& loc) = 0;
  virtual void texture(const std::string& name, const std::string& type,
                       const std::string& className, ParamSet params, const FileLoc& loc) = 0;
  virtual void material(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void makeNamedMaterial(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void namedMaterial(const std::string& name, const FileLoc& loc) = 0;
  virtual void bumpMap(const std::string& name, ParamSet params, const FileLoc& loc) = 0;  // lrt
  virtual void lightSource(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void areaLightSource(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void shape(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void volume(const std::string& name, ParamSet params, const FileLoc& loc) = 0;
  virtual void objectBegin(const std::string& name, const FileLoc& loc) = 0;
  virtual void objectEnd(const FileLoc& loc) = 0;
  virtual void objectInstance(const std::string& name, const FileLoc& loc) = 0;

  // After the last statement of the last file.
  virtual void endOfInput(const FileLoc& loc) = 0;
};

}  // namespace candela
