#include "parser/scene_builder.h"

#include <stdexcept>

namespace candela {

namespace {

// Deeper AttributeBegin/TransformBegin nesting than this is surely broken input.
constexpr size_t kMaxNesting = 100000;

bool isFinite(const Matrix4x4& m) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (!std::isfinite(m.m[i][j])) return false;
  return true;
}

// pbrt writes matrices column-major (the translation is in m[12..14]), i.e. the transpose of the
// row-major Matrix4x4 (pbrt-v2 api.cpp, pbrtTransform).
Matrix4x4 fromFileOrder(const Float m[16]) {
  return Matrix4x4(m[0], m[4], m[8], m[12], m[1], m[5], m[9], m[13], m[2], m[6], m[10], m[14], m[3],
                   m[7], m[11], m[15]);
}

std::string firstDefined(const FileLoc& loc) { return " (first defined at " + loc.str() + ")"; }

const char* pushName(int kind) {
  static const char* names[] = {"AttributeBegin", "TransformBegin", "ObjectBegin"};
  return names[kind];
}

}  // namespace

SceneBuilder::SceneBuilder(std::function<void(SceneDescription&&)> onWorldEnd, WarningCallback warn)
    : onWorldEnd_(std::move(onWorldEnd)), warn_(std::move(warn)) {}

// ---- Block checks and the graphics-state stack -------------------------------------------------

void SceneBuilder::requireOptions(const char* statement, const FileLoc& loc) const {
  // lrt draft App. B: VERIFY_OPTIONS.
  if (block_ == Block::World)
    throw SceneError(loc, std::string("'") + statement +
                              "' is a rendering option and must come before WorldBegin (the "
                              "world block began at " +
                              worldBeginLoc_.str() + ")");
}

void SceneBuilder::requireWorld(const char* statement, const FileLoc& loc) const {
  // lrt draft App. B: VERIFY_WORLD.
  if (block_ == Block::Options)
    throw SceneError(loc, std::string("'") + statement +
                              "' is only allowed in the world block, after WorldBegin");
}

void SceneBuilder::push(PushKind kind, const FileLoc& loc) {
  if (stack_.size() >= kMaxNesting)
    throw SceneError(loc, std::string(pushName(int(kind))) + " nested more than " +
                              std::to_string(kMaxNesting) + " levels deep");
  stack_.push_back(
      {kind, loc, ctm_, activeBits_, state_, textureNames_.mark(), namedMaterialNames_.mark()});
}

void SceneBuilder::pop(PushKind kind, const char* statement, const FileLoc& loc) {
  if (stack_.empty())
    throw SceneError(loc,
                     std::string("'") + statement + "' without a matching " + pushName(int(kind)));
  const Pushed& top = stack_.back();
  if (top.kind != kind)
    throw SceneError(loc, std::string("'") + statement + "' does not match the " +
                              pushName(int(top.kind)) + " at " + top.loc.str());
  ctm_ = top.ctm;
  activeBits_ = top.activeBits;
  if (kind != PushKind::Transform) {
    state_ = top.state;
    textureNames_.restore(top.textureMark);
    namedMaterialNames_.restore(top.materialMark);
  }
  stack_.pop_back();
}

void SceneBuilder::apply(const std::function<Transform()>& make, const FileLoc& loc, bool replace) {
  try {
    Transform t = make();
    std::array<Transform, 2> next = ctm_;
    for (int i = 0; i < 2; ++i)
      if (activeBits_ & (1 << i)) next[i] = replace ? t : ctm_[i] * t;
    for (const Transform& n : next)
      if (!isFinite(n.matrix()) || !isFinite(n.inverseMatrix()))
        throw SceneError(loc, "the transformation overflows (infinite or NaN matrix entries)");
    ctm_ = next;
  } catch (const std::domain_error& e) {
    throw SceneError(loc, std::string("invalid transformation: ") + e.what());
  }
}

AnimatedTransformDesc SceneBuilder::animatedCtm() const {
  AnimatedTransformDesc a;
  a.start = ctm_[0];
  a.end = ctm_[1];
  a.startTime = desc_.transformStartTime;
  a.endTime = desc_.transformEndTime;
  return a;
}

PluginDesc SceneBuilder::plugin(const std::string& name, ParamSet params,
                                const FileLoc& loc) const {
  PluginDesc p;
  p.name = name;
  p.params = std::move(params);
  p.loc = loc;
  return p;
}

// ---- Transformations (lrt draft App. B; pbrt post-multiplies: CTM = CTM * T) --------------------

void SceneBuilder::identity(const FileLoc& loc) {
  apply([] { return Transform(); }, loc, true);
}

void SceneBuilder::translate(Float dx, Float dy, Float dz, const FileLoc& loc) {
  apply([&] { return candela::translate(Vector3f(dx, dy, dz)); }, loc);
}

void SceneBuilder::scale(Float sx, Float sy, Float sz, const FileLoc& loc) {
  apply([&] { return candela::scale(sx, sy, sz); }, loc);
}

void SceneBuilder::rotate(Float angleDeg, Float ax, Float ay, Float az, const FileLoc& loc) {
  apply([&] { return candela::rotate(angleDeg, Vector3f(ax, ay, az)); }, loc);
}

void SceneBuilder::lookAt(Float ex, Float ey, Float ez, Float lx, Float ly, Float lz, Float ux,
                          Float uy, Float uz, const FileLoc& loc) {
  apply(
      [&] {
        return candela::lookAt(Point3f(ex, ey, ez), Point3f(lx, ly, lz), Vector3f(ux, uy, uz));
      },
      loc);
}

void SceneBuilder::transform(const Float m[16], const FileLoc& loc) {
  apply([&] { return Transform(fromFileOrder(m)); }, loc, true);
}

void SceneBuilder::concatTransform(const Float m[16], const FileLoc& loc) {
  apply([&] { return Transform(fromFileOrder(m)); }, loc);
}

void SceneBuilder::coordinateSystem(const std::string& name, const FileLoc&) {
  namedCoordinateSystems_[name] = ctm_;
}

void SceneBuilder::coordSysTransform(const std::string& name, const FileLoc& loc) {
  auto it = namedCoordinateSystems_.find(name);
  if (it == namedCoordinateSystems_.end()) {
    // pbrt-v2 warns and leaves the CTM unchanged.
    if (warn_) warn_(loc, "unknown coordinate system '" + name + "'; CTM left unchanged");
    return;
  }
  ctm_ = it->second;
}

void SceneBuilder::activeTransformAll(const FileLoc&) { activeBits_ = 3; }
void SceneBuilder::activeTransformStartTime(const FileLoc&) { activeBits_ = 1; }
void SceneBuilder::activeTransformEndTime(const FileLoc&) { activeBits_ = 2; }

void SceneBuilder::transformTimes(Float start, Float end, const FileLoc& loc) {
  requireOptions("TransformTimes", loc);
  if (end < start)
    throw SceneError(loc, "TransformTimes end time " + std::to_string(end) +
                              " is before start time " + std::to_string(start));
  desc_.transformStartTime = start;
  desc_.transformEndTime = end;
}

void SceneBuilder::transformBegin(const FileLoc& loc) {
  requireWorld("TransformBegin", loc);
  push(PushKind::Transform, loc);
}

void SceneBuilder::transformEnd(const FileLoc& loc) {
  requireWorld("TransformEnd", loc);
  pop(PushKind::Transform, "TransformEnd", loc);
}

void SceneBuilder::reverseOrientation(const FileLoc& loc) {
  requireWorld("ReverseOrientation", loc);
  state_.reverseOrientation = !state_.reverseOrientation;
}

// ---- Rendering options ---------------------------------------------------------------------

void SceneBuilder::option(PluginDesc& slot, const char* statement, const std::string& name,
                          ParamSet params, const FileLoc& loc) {
  requireOptions(statement, loc);
  slot = plugin(name, std::move(params), loc);
}

void SceneBuilder::camera(const std::string& name, ParamSet params, const FileLoc& loc) {
  requireOptions("Camera", loc);
  // The CTM is world-to-camera; the "camera" coordinate system is its inverse (lrt draft App. B).
  CameraDesc c;
  static_cast<PluginDesc&>(c) = plugin(name, std::move(params), loc);
  c.cameraToWorld = animatedCtm();
  c.cameraToWorld.start = inverse(ctm_[0]);
  c.cameraToWorld.end = inverse(ctm_[1]);
  c.medium = state_.outsideMedium;  // pbrt-v3: the camera is in the current outside medium
  c.mediumLoc = state_.mediumLoc;
  namedCoordinateSystems_["camera"] = {c.cameraToWorld.start, c.cameraToWorld.end};
  desc_.camera = std::move(c);
}

void SceneBuilder::sampler(const std::string& n, ParamSet p, const FileLoc& loc) {
  option(desc_.sampler, "Sampler", n, std::move(p), loc);
}
void SceneBuilder::pixelFilter(const std::string& n, ParamSet p, const FileLoc& loc) {
  option(desc_.filter, "PixelFilter", n, std::move(p), loc);
}
void SceneBuilder::film(const std::string& n, ParamSet p, const FileLoc& loc) {
  option(desc_.film, "Film", n, std::move(p), loc);
}
void SceneBuilder::accelerator(const std::string& n, ParamSet p, const FileLoc& loc) {
  option(desc_.accelerator, "Accelerator", n, std::move(p), loc);
}
void SceneBuilder::surfaceIntegrator(const std::string& n, ParamSet p, const FileLoc& loc) {
  option(desc_.surfaceIntegrator, "SurfaceIntegrator", n, std::move(p), loc);
}
void SceneBuilder::volumeIntegrator(const std::string& n, ParamSet p, const FileLoc& loc) {
  option(desc_.volumeIntegrator, "VolumeIntegrator", n, std::move(p), loc);
}
void SceneBuilder::integrator(const std::string& n, ParamSet p, const FileLoc& loc) {
  option(desc_.integrator, "Integrator", n, std::move(p), loc);
}
void SceneBuilder::renderer(const std::string& n, ParamSet p, const FileLoc& loc) {
  option(desc_.renderer, "Renderer", n, std::move(p), loc);
}
void SceneBuilder::toneMap(const std::string& n, ParamSet p, const FileLoc& loc) {
  option(desc_.toneMap, "ToneMap", n, std::move(p), loc);
}

void SceneBuilder::searchPath(const std::string& path, const FileLoc& loc) {
  requireOptions("SearchPath", loc);
  // lrt draft App. C: colon-separated; '&' stands for the previous search path.
  std::vector<std::string> next;
  size_t start = 0;
  while (start <= path.size()) {
    size_t colon = path.find(':', start);
    if (colon == std::string::npos) colon = path.size();
    std::string entry = path.substr(start, colon - start);
    if (entry == "&")
      next.insert(next.end(), desc_.searchPath.begin(), desc_.searchPath.end());
    else if (!entry.empty())
      next.push_back(entry);
    start = colon + 1;
  }
  desc_.searchPath = std::move(next);
}

void SceneBuilder::makeNamedMedium(const std::string& name, ParamSet params, const FileLoc& loc) {
  // pbrt-v3: allowed in both blocks; "string type" names the medium's kind.
  MediumDesc m;
  std::string type = params.getOneString("type", "");
  if (type.empty())
    throw SceneError(loc, "MakeNamedMedium '" + name + "' needs a \"string type\" parameter");
  static_cast<PluginDesc&>(m) = plugin(type, std::move(params), loc);
  m.mediumName = name;
  m.mediumToWorld = ctm_[0];
  for (MediumDesc& existing : desc_.media)
    if (existing.mediumName == name) {
      if (warn_) warn_(loc, "named medium '" + name + "' redefined");
      existing = std::move(m);
      return;
    }
  desc_.media.push_back(std::move(m));
}

void SceneBuilder::mediumInterface(const std::string& inside, const std::string& outside,
                                   const FileLoc& loc) {
  state_.insideMedium = inside;
  state_.outsideMedium = outside;
  state_.mediumLoc = loc;
}

// ---- World block ---------------------------------------------------------------------------

void SceneBuilder::worldBegin(const FileLoc& loc) {
  if (block_ == Block::World)
    throw SceneError(loc, "'WorldBegin' inside the world block that began at " +
                              worldBeginLoc_.str() + " (missing WorldEnd?)");
  block_ = Block::World;
  worldBeginLoc_ = loc;
  ctm_ = {Transform(), Transform()};  // lrt draft App. B: the CTM is reset; "world" = identity
  namedCoordinateSystems_["world"] = ctm_;
}

void SceneBuilder::worldEnd(const FileLoc& loc) {
  requireWorld("WorldEnd", loc);
  // An open ObjectBegin is on the stack too, so each open block is reported once.
  while (!stack_.empty()) {
    const Pushed& top = stack_.back();
    if (warn_)
      warn_(top.loc, std::string(pushName(int(top.kind))) + " is not closed at WorldEnd (" +
                         loc.str() + ")");
    stack_.pop_back();
  }
  desc_.worldEndLoc = loc;
  for (const auto& [name, def] : namedMaterialNames_.current())
    desc_.namedMaterials[name] = def.index;
  SceneDescription done = std::move(desc_);
  resetForNextFrame();
  // The rendering options stay for the next frame (lrt keeps its GraphicsOptions).
  desc_.camera = done.camera;
  desc_.film = done.film;
  desc_.sampler = done.sampler;
  desc_.filter = done.filter;
  desc_.accelerator = done.accelerator;
  desc_.surfaceIntegrator = done.surfaceIntegrator;
  desc_.volumeIntegrator = done.volumeIntegrator;
  desc_.integrator = done.integrator;
  desc_.renderer = done.renderer;
  desc_.toneMap = done.toneMap;
  desc_.transformStartTime = done.transformStartTime;
  desc_.transformEndTime = done.transformEndTime;
  desc_.searchPath = done.searchPath;
  ++frames_;
  onWorldEnd_(std::move(done));
}

void SceneBuilder::resetForNextFrame() {
  // lrt draft App. B, WorldEnd: reset the CTM and forget the named coordinate systems.
  desc_ = SceneDescription();
  block_ = Block::Options;
  ctm_ = {Transform(), Transform()};
  activeBits_ = 3;
  state_ = GraphicsState();
  stack_.clear();
  namedCoordinateSystems_.clear();
  textureNames_.clear();
  namedMaterialNames_.clear();
  instanceNames_.clear();
  currentInstance_ = -1;
}

void SceneBuilder::attributeBegin(const FileLoc& loc) {
  requireWorld("AttributeBegin", loc);
  push(PushKind::Attribute, loc);
}

void SceneBuilder::attributeEnd(const FileLoc& loc) {
  requireWorld("AttributeEnd", loc);
  pop(PushKind::Attribute, "AttributeEnd", loc);
}

void SceneBuilder::endOfInput(const FileLoc& loc) {
  if (block_ == Block::World)
    throw SceneError(loc, "end of input inside the world block that began at " +
                              worldBeginLoc_.str() + ": WorldEnd is missing");
}

// ---- Materials and textures ------------------------------------------------------------------

int SceneBuilder::attributeDepth() const {
  int depth = 0;
  for (const Pushed& p : stack_) depth += p.kind != PushKind::Transform;
  return depth;
}

TextureBindings SceneBuilder::bindTextures(const ParamSet& params) const {
  // Both types are looked up: which one a parameter needs is known only to its factory, which
  // also reports names bound to neither.
  TextureBindings b;
  for (const ParamItem& item : params.items()) {
    if (item.type != ParamType::Texture) continue;
    for (const std::string& texName : item.strings) {
      if (const ScopedNames::Definition* f = textureNames_.find("float:" + texName))
        b.floats[texName] = f->index;
      if (const ScopedNames::Definition* s = textureNames_.find("spectrum:" + texName))
        b.spectra[texName] = s->index;
    }
  }
  return b;
}

std::map<std::string, int> SceneBuilder::bindNamedMaterials(const ParamSet& params) const {
  std::map<std::string, int> b;
  for (const ParamItem& item : params.items()) {
    if (item.type != ParamType::String || item.name.rfind("namedmaterial", 0) != 0) continue;
    for (const std::string& n : item.strings)
      if (const ScopedNames::Definition* d = namedMaterialNames_.find(n)) b[n] = d->index;
  }
  return b;
}

void SceneBuilder::texture(const std::string& name, const std::string& type,
                           const std::string& className, ParamSet params, const FileLoc& loc) {
  requireWorld("Texture", loc);
  std::string kind = type;
  if (kind == "color") kind = "spectrum";  // pbrt-v2 writes "color"
  if (kind != "float" && kind != "spectrum")
    throw SceneError(
        loc, "texture type must be \"float\", \"spectrum\" or \"color\", found \"" + type + "\"");
  TextureDesc t;
  static_cast<PluginDesc&>(t) = plugin(className, std::move(params), loc);
  t.textures = bindTextures(t.params);  // before the name is defined: a texture cannot name itself
  t.textureName = name;
  t.type = kind;
  t.textureToWorld = ctm_[0];
  // Redefining a name inside an attribute block only shadows the outer definition until the
  // block ends, as in pbrt-v3; in the same block the earlier definition becomes unreachable.
  if (auto previous =
          textureNames_.define(kind + ":" + name, int(desc_.textures.size()), attributeDepth());
      previous && warn_)
    warn_(loc, kind + " texture '" + name + "' redefined in the same attribute block" +
                   firstDefined(desc_.textures[previous->index].loc));
  desc_.textures.push_back(std::move(t));
}

void SceneBuilder::material(const std::string& name, ParamSet params, const FileLoc& loc) {
  requireWorld("Material", loc);
  MaterialDesc m;
  static_cast<PluginDesc&>(m) = plugin(name, std::move(params), loc);
  m.textures = bindTextures(m.params);
  m.namedMaterials = bindNamedMaterials(m.params);
  m.bumpMap = state_.bumpMap;
  state_.material = int(desc_.materials.size());
  desc_.materials.push_back(std::move(m));
}

void SceneBuilder::makeNamedMaterial(const std::string& name, ParamSet params, const FileLoc& loc) {
  requireWorld("MakeNamedMaterial", loc);
  // pbrt-v2/v3: the material's kind is the "string type" parameter.
  std::string type = params.getOneString("type", "");
  if (type.empty())
    throw SceneError(loc, "MakeNamedMaterial '" + name + "' needs a \"string type\" parameter");
  MaterialDesc m;
  static_cast<PluginDesc&>(m) = plugin(type, std::move(params), loc);
  m.textures = bindTextures(m.params);
  m.namedMaterials = bindNamedMaterials(m.params);
  m.bumpMap = state_.bumpMap;
  if (auto previous =
          namedMaterialNames_.define(name, int(desc_.materials.size()), attributeDepth());
      previous && warn_)
    warn_(loc, "named material '" + name + "' redefined in the same attribute block" +
                   firstDefined(desc_.materials[previous->index].loc));
  desc_.materials.push_back(std::move(m));
}

void SceneBuilder::namedMaterial(const std::string& name, const FileLoc& loc) {
  requireWorld("NamedMaterial", loc);
  const ScopedNames::Definition* def = namedMaterialNames_.find(name);
  if (!def)
    throw SceneError(loc, "unknown named material '" + name + "' (not made by MakeNamedMaterial)");
  state_.material = def->index;
}

void SceneBuilder::bumpMap(const std::string& name, ParamSet params, const FileLoc& loc) {
  requireWorld("BumpMap", loc);
  // lrt: the bump map is part of the graphics state and applies with the current material, so
  // the material in effect gets a copy carrying it.
  state_.bumpMap = plugin(name, std::move(params), loc);
  if (state_.material < 0) {
    if (warn_) warn_(loc, "BumpMap before any Material applies to no material until one is given");
    return;
  }
  MaterialDesc m = desc_.materials[state_.material];
  m.bumpMap = state_.bumpMap;
  state_.material = int(desc_.materials.size());
  desc_.materials.push_back(std::move(m));
}

// ---- Lights, shapes, volumes -----------------------------------------------------------------

void SceneBuilder::lightSource(const std::string& name, ParamSet params, const FileLoc& loc) {
  requireWorld("LightSource", loc);
  LightDesc l;
  static_cast<PluginDesc&>(l) = plugin(name, std::move(params), loc);
  l.lightToWorld = animatedCtm();
  l.outsideMedium = state_.outsideMedium;
  l.mediumLoc = state_.mediumLoc;
  desc_.lights.push_back(std::move(l));
}

void SceneBuilder::areaLightSource(const std::string& name, ParamSet params, const FileLoc& loc) {
  requireWorld("AreaLightSource", loc);
  state_.areaLight = plugin(name, std::move(params), loc);
}

void SceneBuilder::shape(const std::string& name, ParamSet params, const FileLoc& loc) {
  requireWorld("Shape", loc);
  ShapeDesc s;
  static_cast<PluginDesc&>(s) = plugin(name, std::move(params), loc);
  s.textures = bindTextures(s.params);  // "alpha", "shadowalpha"
  s.objectToWorld = animatedCtm();
  s.reverseOrientation = state_.reverseOrientation;
  s.material = state_.material;
  s.areaLight = state_.areaLight;
  s.insideMedium = state_.insideMedium;
  s.outsideMedium = state_.outsideMedium;
  s.mediumLoc = state_.mediumLoc;
  if (currentInstance_ >= 0) {
    if (s.areaLight) {
      // pbrt-v3 refuses area lights in instances: one instance would be many lights.
      if (warn_) warn_(loc, "area lights are not supported in object instances; ignored");
      s.areaLight.reset();
    }
    desc_.instanceDefinitions[currentInstance_].shapes.push_back(std::move(s));
  } else {
    desc_.shapes.push_back(std::move(s));
  }
}

void SceneBuilder::volume(const std::string& name, ParamSet params, const FileLoc& loc) {
  requireWorld("Volume", loc);
  VolumeDesc v;
  static_cast<PluginDesc&>(v) = plugin(name, std::move(params), loc);
  v.volumeToWorld = ctm_[0];
  desc_.volumes.push_back(std::move(v));
}

// ---- Object instancing (lrt draft App. B, ObjectBegin/End/Instance) ---------------------------

void SceneBuilder::objectBegin(const std::string& name, const FileLoc& loc) {
  requireWorld("ObjectBegin", loc);
  if (currentInstance_ >= 0)
    throw SceneError(loc, "ObjectBegin '" + name + "' inside the definition of '" +
                              desc_.instanceDefinitions[currentInstance_].name + "' (begun at " +
                              desc_.instanceDefinitions[currentInstance_].loc.str() +
                              "): object definitions cannot nest");
  // pbrt-v2/v3: ObjectBegin also begins an attribute block.
  push(PushKind::Object, loc);
  InstanceDefinition def;
  def.name = name;
  def.loc = loc;
  if (auto it = instanceNames_.find(name); it != instanceNames_.end()) {
    if (warn_)
      warn_(loc, "object '" + name + "' redefined (first defined at " +
                     desc_.instanceDefinitions[it->second].loc.str() + ")");
    currentInstance_ = it->second;
    desc_.instanceDefinitions[currentInstance_] = std::move(def);
    return;
  }
  currentInstance_ = int(desc_.instanceDefinitions.size());
  instanceNames_[name] = currentInstance_;
  desc_.instanceDefinitions.push_back(std::move(def));
}

void SceneBuilder::objectEnd(const FileLoc& loc) {
  requireWorld("ObjectEnd", loc);
  if (currentInstance_ < 0) throw SceneError(loc, "'ObjectEnd' without a matching ObjectBegin");
  pop(PushKind::Object, "ObjectEnd", loc);
  currentInstance_ = -1;
}

void SceneBuilder::objectInstance(const std::string& name, const FileLoc& loc) {
  requireWorld("ObjectInstance", loc);
  if (currentInstance_ >= 0)
    throw SceneError(loc, "ObjectInstance '" + name + "' inside the definition of '" +
                              desc_.instanceDefinitions[currentInstance_].name +
                              "': instances cannot be used inside ObjectBegin/ObjectEnd");
  if (instanceNames_.find(name) == instanceNames_.end())
    throw SceneError(loc, "unknown object '" + name + "' (not defined by ObjectBegin)");
  InstanceUse use;
  use.name = name;
  use.instanceToWorld = animatedCtm();
  use.loc = loc;
  desc_.instanceUses.push_back(std::move(use));
}

}  // namespace candela
