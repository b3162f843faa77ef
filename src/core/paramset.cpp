#include "core/paramset.h"

#include <utility>

namespace candela {

const char* paramTypeName(ParamType type) {
  switch (type) {
    case ParamType::Integer:
      return "integer";
    case ParamType::Float:
      return "float";
    case ParamType::Point2:
      return "point2";
    case ParamType::Vector2:
      return "vector2";
    case ParamType::Point3:
      return "point3";
    case ParamType::Vector3:
      return "vector3";
    case ParamType::Normal3:
      return "normal3";
    case ParamType::Spectrum:
      return "spectrum";
    case ParamType::Bool:
      return "bool";
    case ParamType::String:
      return "string";
    case ParamType::Texture:
      return "texture";
  }
  return "unknown";
}

int ParamItem::valueCount() const {
  switch (type) {
    case ParamType::Integer:
      return int(ints.size());
    case ParamType::Bool:
      return int(bools.size());
    case ParamType::String:
    case ParamType::Texture:
      return int(strings.size());
    default:
      return int(floats.size());
  }
}

namespace {

// How many numbers make one value of a float-backed type.
int floatsPerValue(ParamType type) {
  switch (type) {
    case ParamType::Point2:
    case ParamType::Vector2:
      return 2;
    case ParamType::Point3:
    case ParamType::Vector3:
    case ParamType::Normal3:
    case ParamType::Spectrum:
      return 3;
    default:
      return 1;
  }
}

// The type as written when it says more than the enum ("rgb" for a spectrum item).
std::string describe(const ParamItem& item) {
  std::string written = item.typeName.empty() ? paramTypeName(item.type) : item.typeName;
  return "\"" + written + " " + item.name + "\"";
}

[[noreturn]] void typeMismatch(const ParamItem& item, const char* expected) {
  throw SceneError(item.loc, "parameter " + describe(item) + " has type '" +
                                 paramTypeName(item.type) + "', expected '" + expected + "'");
}

}  // namespace

void ParamSet::add(ParamItem item) {
  for (ParamItem& existing : items_)
    if (existing.name == item.name) {
      existing = std::move(item);
      return;
    }
  items_.push_back(std::move(item));
}

void ParamSet::recordQueries(std::shared_ptr<std::set<std::string>> names) {
  queried_ = std::move(names);
}

void ParamSet::noteQuery(const std::string& name) const {
  if (queried_) queried_->insert(name);
}

const ParamItem* ParamSet::find(const std::string& name) const {
  noteQuery(name);
  for (const ParamItem& item : items_)
    if (item.name == name) {
      item.lookedUp = true;
      return &item;
    }
  return nullptr;
}

void ParamSet::requireInRange(const std::string& name, double value, const ValueRange& range,
                              const FileLoc& fallback) const {
  if (!range.contains(value))
    throw SceneError(locationOf(name, fallback), "\"" + name + "\" must be " + range.describe() +
                                                     " (got " + formatNumber(value) + ")");
}

Float ParamSet::getOneFloat(const std::string& name, Float def, const ValueRange& range,
                            const FileLoc& fallback) const {
  Float v = getOneFloat(name, def);
  requireInRange(name, v, range, fallback);
  return v;
}

int ParamSet::getOneInt(const std::string& name, int def, const ValueRange& range,
                        const FileLoc& fallback) const {
  int v = getOneInt(name, def);
  requireInRange(name, v, range, fallback);
  return v;
}

std::string ParamSet::getOneString(const std::string& name, const std::string& def,
                                   const std::vector<std::string>& oneOf,
                                   const FileLoc& fallback) const {
  std::string v = getOneString(name, def);
  for (const std::string& known : oneOf)
    if (v == known) return v;
  std::string list;
  for (const std::string& known : oneOf) list += (list.empty() ? "" : ", ") + known;
  throw SceneError(locationOf(name, fallback),
                   "\"" + name + "\" must be one of " + list + " (got \"" + v + "\")");
}

FileLoc ParamSet::locationOf(const std::string& name, const FileLoc& fallback) const {
  noteQuery(name);
  for (const ParamItem& item : items_)
    if (item.name == name) return item.loc;
  return fallback;
}

// The item called name, checked to be of the given type (nullptr when absent).
const ParamItem* ParamSet::findTyped(const std::string& name, ParamType type) const {
  const ParamItem* item = find(name);
  if (item && item->type != type) typeMismatch(*item, paramTypeName(type));
  return item;
}

// The item called name holding exactly one value of the given type (nullptr when absent).
const ParamItem* ParamSet::findSingle(const std::string& name, ParamType type) const {
  const ParamItem* item = findTyped(name, type);
  if (item) {
    int n = item->valueCount() / floatsPerValue(type);
    if (n != 1 || item->valueCount() % floatsPerValue(type) != 0)
      throw SceneError(item->loc, "parameter " + describe(*item) +
                                      " needs exactly one value, found " + std::to_string(n));
  }
  return item;
}

Float ParamSet::getOneFloat(const std::string& name, Float def) const {
  const ParamItem* item = findSingle(name, ParamType::Float);
  return item ? item->floats[0] : def;
}

int ParamSet::getOneInt(const std::string& name, int def) const {
  const ParamItem* item = findSingle(name, ParamType::Integer);
  return item ? item->ints[0] : def;
}

bool ParamSet::getOneBool(const std::string& name, bool def) const {
  const ParamItem* item = findSingle(name, ParamType::Bool);
  return item ? bool(item->bools[0]) : def;
}

std::string ParamSet::getOneString(const std::string& name, const std::string& def) const {
  const ParamItem* item = findSingle(name, ParamType::String);
  return item ? item->strings[0] : def;
}

Point3f ParamSet::getOnePoint3f(const std::string& name, const Point3f& def) const {
  const ParamItem* item = findSingle(name, ParamType::Point3);
  return item ? Point3f(item->floats[0], item->floats[1], item->floats[2]) : def;
}

Vector3f ParamSet::getOneVector3f(const std::string& name, const Vector3f& def) const {
  const ParamItem* item = findSingle(name, ParamType::Vector3);
  return item ? Vector3f(item->floats[0], item->floats[1], item->floats[2]) : def;
}

Normal3f ParamSet::getOneNormal3f(const std::string& name, const Normal3f& def) const {
  const ParamItem* item = findSingle(name, ParamType::Normal3);
  return item ? Normal3f(item->floats[0], item->floats[1], item->floats[2]) : def;
}

Spectrum ParamSet::getOneSpectrum(const std::string& name, const Spectrum& def) const {
  const ParamItem* item = findSingle(name, ParamType::Spectrum);
  return item ? Spectrum(item->floats[0], item->floats[1], item->floats[2]) : def;
}

std::string ParamSet::getTexture(const std::string& name) const {
  // A material asks for a texture first and for a constant value when there is none (pbrt's
  // GetSpectrumTexture), so another type here is no error and does not count as a use.
  noteQuery(name);
  for (const ParamItem& item : items_)
    if (item.name == name && item.type == ParamType::Texture) {
      item.lookedUp = true;
      if (item.strings.size() != 1)
        throw SceneError(item.loc, "parameter " + describe(item) +
                                       " needs exactly one texture name, found " +
                                       std::to_string(item.strings.size()));
      return item.strings[0];
    }
  return "";
}

std::vector<Float> ParamSet::getFloatArray(const std::string& name) const {
  const ParamItem* item = findTyped(name, ParamType::Float);
  return item ? item->floats : std::vector<Float>{};
}

std::vector<int> ParamSet::getIntArray(const std::string& name) const {
  const ParamItem* item = findTyped(name, ParamType::Integer);
  return item ? item->ints : std::vector<int>{};
}

std::vector<std::string> ParamSet::getStringArray(const std::string& name) const {
  const ParamItem* item = findTyped(name, ParamType::String);
  return item ? item->strings : std::vector<std::string>{};
}

// The numbers of a float-backed item as tuples of n (a partial tuple is an error).
const std::vector<Float>* ParamSet::tuples(const std::string& name, ParamType type) const {
  const ParamItem* item = findTyped(name, type);
  if (!item) return nullptr;
  int n = floatsPerValue(type);
  if (item->floats.size() % n != 0)
    throw SceneError(item->loc, "parameter " + describe(*item) + " needs a multiple of " +
                                    std::to_string(n) + " numbers, found " +
                                    std::to_string(item->floats.size()));
  return &item->floats;
}

std::vector<Point2f> ParamSet::getPoint2fArray(const std::string& name) const {
  std::vector<Point2f> out;
  const ParamItem* item = find(name);
  if (!item) return out;
  // pbrt-v2 meshes give texture coordinates as "float uv" / "float st": flat (u, v) pairs.
  if (item->type == ParamType::Float) {
    if (item->floats.size() % 2 != 0)
      throw SceneError(item->loc, "parameter " + describe(*item) +
                                      " needs (u, v) pairs: an even count of numbers, found " +
                                      std::to_string(item->floats.size()));
    for (size_t i = 0; i < item->floats.size(); i += 2)
      out.emplace_back(item->floats[i], item->floats[i + 1]);
    return out;
  }
  const std::vector<Float>* f = tuples(name, ParamType::Point2);
  for (size_t i = 0; i < f->size(); i += 2) out.emplace_back((*f)[i], (*f)[i + 1]);
  return out;
}

std::vector<Point3f> ParamSet::getPoint3fArray(const std::string& name) const {
  std::vector<Point3f> out;
  if (const std::vector<Float>* f = tuples(name, ParamType::Point3))
    for (size_t i = 0; i < f->size(); i += 3) out.emplace_back((*f)[i], (*f)[i + 1], (*f)[i + 2]);
  return out;
}

std::vector<Vector3f> ParamSet::getVector3fArray(const std::string& name) const {
  std::vector<Vector3f> out;
  if (const std::vector<Float>* f = tuples(name, ParamType::Vector3))
    for (size_t i = 0; i < f->size(); i += 3) out.emplace_back((*f)[i], (*f)[i + 1], (*f)[i + 2]);
  return out;
}

std::vector<Normal3f> ParamSet::getNormal3fArray(const std::string& name) const {
  std::vector<Normal3f> out;
  if (const std::vector<Float>* f = tuples(name, ParamType::Normal3))
    for (size_t i = 0; i < f->size(); i += 3) out.emplace_back((*f)[i], (*f)[i + 1], (*f)[i + 2]);
  return out;
}

std::vector<Spectrum> ParamSet::getSpectrumArray(const std::string& name) const {
  std::vector<Spectrum> out;
  if (const std::vector<Float>* f = tuples(name, ParamType::Spectrum))
    for (size_t i = 0; i < f->size(); i += 3) out.emplace_back((*f)[i], (*f)[i + 1], (*f)[i + 2]);
  return out;
}

void ParamSet::forEachUnused(const std::function<void(const ParamItem&)>& warn) const {
  // Names beginning with '_' are exempt (lrt draft App. B, ReportUnused).
  for (const ParamItem& item : items_)
    if (!item.lookedUp && (item.name.empty() || item.name[0] != '_')) warn(item);
}

}  // namespace candela
