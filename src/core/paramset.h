// Typed parameter lists of scene statements ("float radius" [1], "rgb Kd" [.5 .5 .5], ...), as the
// lrt draft's ParamSet (§B.3). Every item remembers where it was written and whether any factory
// looked it up, so unused parameters can be reported with their location.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/spectrum.h"
#include "core/value_range.h"
#include "core/vector.h"

namespace candela {

enum class ParamType {
  Integer,
  Float,
  Point2,
  Vector2,
  Point3,    // "point" and "point3"
  Vector3,   // "vector" and "vector3"
  Normal3,   // "normal" and "normal3"
  Spectrum,  // "color"/"rgb", "xyz", "spectrum", "blackbody": converted to RGB when parsed
  Bool,
  String,
  Texture
};

struct ParamItem {
  ParamType type;
  std::string name;
  std::string typeName;  // as written: "rgb", "point3", ...
  FileLoc loc;
  std::vector<Float> floats;  // Float, Point*, Vector*, Normal3 (flattened), Spectrum (RGB triples)
  std::vector<int> ints;
  std::vector<bool> bools;
  std::vector<std::string> strings;  // String and Texture
  mutable bool lookedUp = false;

  // Number of values stored: ints, bools, strings or floats (tuples count each number).
  int valueCount() const;
};

// The canonical type name: "integer", "float", "point3", "spectrum", ...
const char* paramTypeName(ParamType type);

class ParamSet {
 public:
  // Adds or replaces (same name) an item.
  void add(ParamItem item);
  bool empty() const { return items_.empty(); }
  const std::vector<ParamItem>& items() const { return items_; }

  // Single values: the default when the name is absent. A present item of another type, or with
  // more than one value, is a SceneError at the item's location.
  Float getOneFloat(const std::string& name, Float def) const;
  int getOneInt(const std::string& name, int def) const;
  bool getOneBool(const std::string& name, bool def) const;
  std::string getOneString(const std::string& name, const std::string& def) const;
  Point3f getOnePoint3f(const std::string& name, const Point3f& def) const;
  Vector3f getOneVector3f(const std::string& name, const Vector3f& def) const;
  Normal3f getOneNormal3f(const std::string& name, const Normal3f& def) const;
  Spectrum getOneSpectrum(const std::string& name, const Spectrum& def) const;
  // The texture name of a "texture" item, or "" when absent or of another type (a material then
  // asks for a constant value of the same name).
  std::string getTexture(const std::string& name) const;

  // Range-checked single values: the value, or def when the name is absent; outside range a
  // SceneError at the value's location (fallback when absent), worded one way for every
  // parameter: "\"nsamples\" must be at least 1 (got 0)".
  Float getOneFloat(const std::string& name, Float def, const ValueRange& range,
                    const FileLoc& fallback) const;
  int getOneInt(const std::string& name, int def, const ValueRange& range,
                const FileLoc& fallback) const;
  // One of the given names: "\"strategy\" must be one of all, one (got \"some\")".
  std::string getOneString(const std::string& name, const std::string& def,
                           const std::vector<std::string>& oneOf, const FileLoc& fallback) const;
  // The same rule for a value derived from the parameter name (or checked after reading it).
  void requireInRange(const std::string& name, double value, const ValueRange& range,
                      const FileLoc& fallback) const;

  // Arrays: empty when absent.
  std::vector<Float> getFloatArray(const std::string& name) const;
  std::vector<int> getIntArray(const std::string& name) const;
  std::vector<std::string> getStringArray(const std::string& name) const;
  std::vector<Point2f> getPoint2fArray(const std::string& name) const;  // also from float pairs
  std::vector<Point3f> getPoint3fArray(const std::string& name) const;
  std::vector<Vector3f> getVector3fArray(const std::string& name) const;
  std::vector<Normal3f> getNormal3fArray(const std::string& name) const;
  std::vector<Spectrum> getSpectrumArray(const std::string& name) const;

  // The item called name (nullptr when absent); counts as a use.
  const ParamItem* find(const std::string& name) const;
  // Where the item was written, for errors about its value (the default when absent).
  FileLoc locationOf(const std::string& name, const FileLoc& fallback) const;

  // Calls warn(item) for each item no getter has asked for.
  void forEachUnused(const std::function<void(const ParamItem&)>& warn) const;

  // From now on every name a getter, find, getTexture or locationOf asks for, present or not, is
  // added to *names (shared by copies of this set); null stops it. For the test that checks each
  // plug-in's declared parameters against what it reads (tests/unit/test_plugin_tables.cpp).
  void recordQueries(std::shared_ptr<std::set<std::string>> names);

 private:
  const ParamItem* findTyped(const std::string& name, ParamType type) const;
  const ParamItem* findSingle(const std::string& name, ParamType type) const;
  const std::vector<Float>* tuples(const std::string& name, ParamType type) const;

  void noteQuery(const std::string& name) const;

  std::vector<ParamItem> items_;
  std::shared_ptr<std::set<std::string>> queried_;
};

}  // namespace candela
